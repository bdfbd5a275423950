// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkBloomPass
 * @brief   HDR bloom as a render pass: the vtkBloomParameters chain as GLSL passes on float
 *          targets.
 *
 * The delegate renders the scene into a floating-point target (RGBA16F by default, RGBA32F
 * with SetFloatPrecisionTo32Bit()), so nothing above 1 is clipped before the bloom. The pass
 * then evaluates the chain its vtkBloomParameters describe (GetParameters(): the parameters
 * and presets of vtkImageBloom, which a pass and a filter can share) and composites the result
 * into the framebuffer bound when it started, at the renderer's viewport:
 *
 *   threshold -> pyramid down -> per-level separable blur -> upsample-accumulate -> composite.
 *
 * The operators come from vtkBloomChain, the CPU filters' own code, applied with exact texel
 * fetches: the result is vtkImageBloom's on the same float render to float rounding.
 *
 * Only light blooms: what the bright pass lets through (at the defaults, colour above 1, by
 * its excess) and, with SetEmissionSourceToEmitters(), the props given to AddEmitter() or
 * AddScalarRangeEmitter(). The background, the annotations (the delegate's overlay, drawn over
 * the bloom) and everything at or below display white are not light, so a frame with nothing
 * above 1 is the renderer's own frame to float rounding: multisampled edges, translucency,
 * hidden lines, FXAA, layers and picking as the renderer draws them, and the scene's depth
 * under the result for what reads it next.
 *
 * Chain it before vtkToneMappingPass to bloom in linear HDR and tone-map afterwards. The pass
 * needs OpenGL 3.2 and works with any vtkOpenGLRenderWindow (X, OSMesa or EGL); where the
 * context runs compute shaders (OpenGL 4.3, or the ARB extensions that brought them) its passes
 * run as compute shaders. Resources are made on first use and remade when the size, the
 * precision or the parameters change; ReleaseGraphicsResources frees them and forwards to the
 * delegate.
 *
 * docs/rendering.md ("The pass in detail") describes the rest: multisampling, alpha, selective
 * bloom in one or two renders, tiled frames, content-aware work, compute shaders, wide blurs
 * through an FFT, PSF mode, and CaptureResult with ReadSceneImage() and ReadResultImage().
 */

#ifndef vtkBloomPass_h
#define vtkBloomPass_h

#include "vtkBloomFrameReport.h" // For GetLastFrame
#include "vtkBloomParameters.h"  // For GetParameters
#include "vtkImageProcessingPass.h"
#include "vtkRenderingBloomModule.h" // For export macro
#include "vtkSmartPointer.h"         // For the parameters

#include <memory> // For the internal state
#include <string> // For the shader replacements

class vtkActor;
class vtkImageData;
class vtkImageBloom;
class vtkInformationDoubleVectorKey;
class vtkInformationObjectBaseKey;
class vtkOpenGLRenderWindow;
class vtkProp;
class vtkPropCollection;
class vtkRenderState;
class vtkTextureObject;

class VTKRENDERINGBLOOM_EXPORT vtkBloomPass : public vtkImageProcessingPass
{
public:
  static vtkBloomPass* New();
  vtkTypeMacro(vtkBloomPass, vtkImageProcessingPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Render the delegate into a float target, bloom it and composite it.
  void Render(const vtkRenderState* s) override;

  /// Free every texture, framebuffer and shader, and forward to the delegate.
  void ReleaseGraphicsResources(vtkWindow* w) override;

  ///@{
  /**
   * The bloom's parameters (and SetPreset) define the chain. Never null: a new pass holds its
   * own with their defaults, and a null pointer is refused with an error. Setting a filter's
   * parameters shares them: `pass->SetParameters(filter->GetParameters())`.
   */
  void SetParameters(vtkBloomParameters* parameters);
  vtkBloomParameters* GetParameters() { return this->Parameters; }
  ///@}

  /**
   * Share `filter`'s parameters, as SetParameters(filter->GetParameters()). Kept for code
   * written when the pass held a vtkImageBloom; the filter's input and execution options are
   * not used.
   */
  void SetParameters(vtkImageBloom* filter);

  /// As GetParameters()->SetPreset(name), with an unknown name reported by this pass.
  bool SetPreset(const char* name);

  ///@{
  /**
   * Precision of the scene's targets: FLOAT16 (half floats), FLOAT32, or FLOAT_AUTOMATIC (the
   * default): half floats where this pass is the renderer's own and composites the final frame,
   * 32-bit floats where the frame is processed further, by a pass around this one (tone
   * mapping's curve) or by the renderer's FXAA (its edge search), which would turn a half
   * float's rounding into steps of several levels. Any other value is refused with an error.
   * GetLastFrame()->GetFloatPrecision() is what the last render used (16 or 32).
   */
  enum
  {
    FLOAT_AUTOMATIC = 0,
    FLOAT16 = 16,
    FLOAT32 = 32
  };
  void SetFloatPrecision(int bits);
  vtkGetMacro(FloatPrecision, int);
  void SetFloatPrecisionToAutomatic() { this->SetFloatPrecision(FLOAT_AUTOMATIC); }
  void SetFloatPrecisionTo16Bit() { this->SetFloatPrecision(FLOAT16); }
  void SetFloatPrecisionTo32Bit() { this->SetFloatPrecision(FLOAT32); }
  ///@}

  ///@{
  /**
   * Run the chain's passes into its own targets, and the bright region's reduction, as compute
   * shaders where the context runs them (OpenGL 4.3 or its extensions), else as fragment passes;
   * the composite too where the framebuffer's colour buffer can be written as an image
   * (docs/rendering.md, "Compute shaders"). Both agree to float rounding (tested); on NVIDIA's
   * GPUs the compute passes are many times faster (docs/gpu.md). Default on.
   */
  vtkSetMacro(UseComputeShaders, bool);
  vtkGetMacro(UseComputeShaders, bool);
  vtkBooleanMacro(UseComputeShaders, bool);
  ///@}

  ///@{
  /**
   * Where the scene is multisampled (the framebuffer the pass renders into has samples), the
   * bright pass thresholds each sample and takes their mean, before the chain's resample,
   * instead of thresholding the resolved pixel. A thin line or point covering part of a pixel
   * then brings light in proportion to its coverage, as it brings colour to the scene, so its
   * glow stays steady as it moves by a fraction of a pixel; thresholded after the resolve, its
   * pixels glow only while their coverage keeps them above the threshold, and the glow
   * flickers (TestBloomPassMotion, docs/rendering.md). Where every sample of a pixel is alike
   * (inside a surface, and every single-sample scene) the two are the same. Whole-scene bloom
   * only: selective bloom's emission is weighted and masked per pixel. Default on.
   */
  vtkSetMacro(ThresholdSamples, bool);
  vtkGetMacro(ThresholdSamples, bool);
  vtkBooleanMacro(ThresholdSamples, bool);
  ///@}

  ///@{
  /// What may bloom: the whole scene (default) or only the emitter props.
  enum
  {
    EMISSION_SCENE = 0,
    EMISSION_EMITTERS = 1
  };
  vtkSetClampMacro(EmissionSource, int, EMISSION_SCENE, EMISSION_EMITTERS);
  vtkGetMacro(EmissionSource, int);
  void SetEmissionSourceToScene() { this->SetEmissionSource(EMISSION_SCENE); }
  void SetEmissionSourceToEmitters() { this->SetEmissionSource(EMISSION_EMITTERS); }
  ///@}

  ///@{
  /// The props that emit when EmissionSource is EMISSION_EMITTERS.
  void AddEmitter(vtkProp* prop);
  void RemoveEmitter(vtkProp* prop);
  void RemoveAllEmitters();
  vtkPropCollection* GetEmitters() { return this->Emitters; }
  ///@}

  /**
   * A new actor that draws `actor`'s geometry with its colours only where the mapped scalar
   * lies in [range[0], range[1]] (both ends included), and black elsewhere: use it as an
   * emitter to make a scalar range glow. It shares the mapper's input and the actor's transform
   * and property, and maps vectors as the actor does (magnitude or component).
   * - Where the actor colours through a texture (InterpolateScalarsBeforeMapping on, a linear
   *   table), the emitter has a copy of the actor's table, and the range is tested per
   *   fragment on the interpolated scalar. It records the actor and the range
   *   (EMITTER_SOURCE, EMITTER_SCALAR_RANGE): while the actor is in the scene, the pass
   *   writes the range's emission in the actor's own render and does not render the emitter.
   * - Otherwise its table samples the actor's own table over the range, black outside it, and
   *   it is rendered a second time.
   * Returns null when the actor has no mapper with a lookup table or the range is not ordered.
   */
  static vtkSmartPointer<vtkActor> CreateScalarRangeEmitter(vtkActor* actor, const double range[2]);

  /**
   * CreateScalarRangeEmitter(actor, {low, high}) given to AddEmitter, in one call that the
   * Python wrapping reaches (vtkbloom.add_emitter(..., clim=...)). Returns the emitter, which
   * the pass holds until RemoveEmitter, or null where CreateScalarRangeEmitter makes none.
   */
  vtkActor* AddScalarRangeEmitter(vtkActor* actor, double low, double high);

  ///@{
  /**
   * What CreateScalarRangeEmitter records in a texture-coloured emitter's property keys: the
   * actor it was made from and the scalar range. Where that actor is in the scene, its own
   * render writes the range's emission and the emitter is not rendered.
   */
  static vtkInformationObjectBaseKey* EMITTER_SOURCE();
  static vtkInformationDoubleVectorKey* EMITTER_SCALAR_RANGE();
  ///@}

  ///@{
  /**
   * With EMISSION_EMITTERS, write the emission in the scene's own render where the scene
   * allows it (docs/rendering.md, "Selective bloom"; default on). Off, the emitters are always
   * rendered a second time, alone.
   */
  vtkSetMacro(EmitInSceneRender, bool);
  vtkGetMacro(EmitInSceneRender, bool);
  vtkBooleanMacro(EmitInSceneRender, bool);
  ///@}

  ///@{
  /**
   * Whether the bright pass's threshold applies to the emitters (EMISSION_EMITTERS). Off (the
   * default): an emitter is light whatever its colour, LDR included, and its colour enters the
   * bloom whole. On: the parameters' threshold applies to it as to a whole scene.
   */
  vtkSetMacro(ThresholdEmitters, bool);
  vtkGetMacro(ThresholdEmitters, bool);
  vtkBooleanMacro(ThresholdEmitters, bool);
  ///@}

  ///@{
  /**
   * Whether the renderer's background enters the bright pass like a surface of the scene (the
   * behaviour of earlier versions). Off (the default): the background never blooms and the
   * glow goes over it (see the class description and docs/rendering.md). A layered renderer, which
   * clears nothing, has no background of its own either way.
   */
  vtkSetMacro(BloomBackground, bool);
  vtkGetMacro(BloomBackground, bool);
  vtkBooleanMacro(BloomBackground, bool);
  ///@}

  ///@{
  /**
   * Whether the annotations (the delegate's overlay step: 2D actors and 2D widget
   * representations) are part of the frame that blooms. Off (the default): they are drawn after
   * the composite, over the bloom. The result images (ReadResultImage) hold the frame without
   * them.
   */
  vtkSetMacro(BloomAnnotations, bool);
  vtkGetMacro(BloomAnnotations, bool);
  vtkBooleanMacro(BloomAnnotations, bool);
  ///@}

  ///@{
  /**
   * Tiled frames (vtkWindowToImageFilter with a scale, a ParaView screenshot larger than its
   * view: the window's TileScale above 1) bloom as one frame (on, the default): each tile
   * renders with a guard band, the samples of the frame its glow reads, and the bloom's sizes
   * follow the frame's height, so the tiled image is the frame's, with no seams
   * (vtkBloomPassTile). Off: each tile blooms alone, as a frame of its own. A delegate that does
   * not render the scene itself (IceT's composite in parallel) needs it off: every rank would
   * have to widen its camera alike.
   */
  vtkSetMacro(SeamlessTiles, bool);
  vtkGetMacro(SeamlessTiles, bool);
  vtkBooleanMacro(SeamlessTiles, bool);
  ///@}

  ///@{
  /// The shader replacement that writes the emission (vtkOpenGLRenderPass's API).
  bool PreReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;
  bool PostReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;
  bool SetShaderParameters(vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkProp* prop,
    vtkOpenGLVertexArrayObject* VAO = nullptr) override;
  ///@}

  ///@{
  /**
   * Keep the bloomed result in a float texture after each render (off by default; it costs
   * one extra full-screen copy). Needed by ReadResultImage().
   */
  vtkSetMacro(CaptureResult, bool);
  vtkGetMacro(CaptureResult, bool);
  vtkBooleanMacro(CaptureResult, bool);
  ///@}

  ///@{
  /**
   * Read back, as float RGBA, the un-bloomed scene of the last render (ReadSceneImage) or the
   * bloomed result (ReadResultImage, with CaptureResult on). The window's context must be
   * current (it is after Render). Return false, with an error, when there is nothing to read.
   */
  bool ReadSceneImage(vtkImageData* image);
  bool ReadResultImage(vtkImageData* image);

  /**
   * Read back, as float RGBA, the emission of the last render with EMISSION_EMITTERS: the
   * scene's colour times the weight its render wrote in the alpha (the alpha is the weight),
   * or the emitters' own render (where their occluded parts are masked later, in the bright
   * pass). ReadSceneImage returns the scene with its own alpha. Return false, with an error,
   * when the last render was not selective.
   */
  bool ReadEmissionImage(vtkImageData* image);
  ///@}

  /**
   * Bloom a float image on the GPU with the same chain, without rendering a scene: `input`
   * (float or double, 3 or 4 components, 2-D) is uploaded as the scene, and `output` receives
   * the float RGBA result (alpha 1 for 3-component input). `window` provides the context; it
   * is initialized if needed. Returns false, with an error, on bad input.
   */
  bool ApplyToImage(vtkOpenGLRenderWindow* window, vtkImageData* input, vtkImageData* output);

  /**
   * What the last render (or ApplyToImage) did: its passes, whether the chain was skipped, the
   * bright region and the chain's coverage, the PSF grid, the precision, the tile's guard band,
   * the GPU times (vtkBloomFrameReport). Never null; read-only, and rewritten by each render.
   */
  vtkBloomFrameReport* GetLastFrame();

protected:
  vtkBloomPass();
  ~vtkBloomPass() override;

  /**
   * Called once the delegate has rendered the scene into the pass's float target, before the
   * chain reads it. `sceneColor` is that target's colour texture (RGBA16F or RGBA32F, the
   * renderer's tiled size). The default does nothing; a subclass whose delegate delivers the
   * scene elsewhere writes it here: ParaView's bloom view uploads the float image that IceT
   * composited from every rank (vtkPVBloomPass).
   */
  virtual void SceneRendered(const vtkRenderState* s, vtkTextureObject* sceneColor);

  /**
   * For SceneRendered(): the scene just written has no background (premultiplied colour over
   * transparent black, as IceT composites it), and the composite puts it over the solid
   * background `rgba` (a colour and its alpha), as it does with the renderer's own.
   */
  void SetSceneBackground(const double rgba[4]);

  /**
   * For a subclass that serves every tile of a frame larger than the window from one bloomed
   * frame, where a tile cannot be rendered with a guard band: ParaView's vtkPVBloomPass under
   * IceT, which composites the window's size only, renders the frame whole first (at the
   * window resized to it), then the tiles. A subclass makes these public where it needs them.
   * - KEPT_FRAME_KEEP: a render also keeps the frame it writes: the renderer's pixels after
   *   the composite (before the FXAA and the annotations), what lay below included where the
   *   composite blends over it, read back as float RGBA (16 bytes a pixel on the CPU, so that
   *   it outlives the context: an OSMesa window's resize releases every GPU resource).
   * - KEPT_FRAME_SERVE: a render of a tile (the window's TileScale above 1) of a frame the kept
   *   one's size writes the kept frame's part instead of blooming: no chain runs, and no guard
   *   band is rendered, but the scene is (its delegate's render may be a collective one); the
   *   kept pixels replace the tile's, and the FXAA and the annotations follow as in any
   *   render. Where no frame of that size is kept, the tile blooms alone, said once.
   * - KEPT_FRAME_OFF (the default): neither. The kept frame stays until ReleaseKeptFrame().
   */
  enum KeptFrameModes
  {
    KEPT_FRAME_OFF = 0,
    KEPT_FRAME_KEEP = 1,
    KEPT_FRAME_SERVE = 2
  };
  ///@{
  /// See KeptFrameModes; other values are refused with an error.
  void SetKeptFrameMode(int mode);
  vtkGetMacro(KeptFrameMode, int);
  ///@}
  /// Free the kept frame; the window's context must be current.
  void ReleaseKeptFrame();
  /// The kept frame's size, 0 x 0 when none is kept.
  void GetKeptFrameSize(int size[2]);

  vtkSmartPointer<vtkBloomParameters> Parameters;
  vtkPropCollection* Emitters;
  int FloatPrecision;
  int EmissionSource;
  bool EmitInSceneRender = true;
  bool ThresholdEmitters = false;
  bool BloomBackground = false;
  bool BloomAnnotations = false;
  bool SeamlessTiles = true;
  int KeptFrameMode = KEPT_FRAME_OFF;
  bool UseComputeShaders;
  bool ThresholdSamples = true;
  bool CaptureResult;

private:
  vtkBloomPass(const vtkBloomPass&) = delete;
  void operator=(const vtkBloomPass&) = delete;

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
  friend class vtkBloomPassTesting; // the tests' switches (vtkBloomPassTesting.h)
};

#endif
