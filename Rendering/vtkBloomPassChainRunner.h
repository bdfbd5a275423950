// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkBloomPassChainRunner.h
 * @brief  (private to vtkBloomPass) runs a vtkBloomChain as full-screen GLSL passes on the
 *         targets of a vtkBloomPassResources, and composites the result.
 *
 * Every pass is step(Y X source) (see glsl/vtkBloomPassFS.glsl): up to two banded operators of
 * the chain, one along x and one along y, then one point-wise step. Each axis is drawn in
 * segments: the operator's translation-invariant interior from uniform weights (OP_PERIODIC),
 * its borders from the operator's rows uploaded as a small R32F texture (OP_TABLE). One
 * program per variant (evaluation modes, interior taps, step, flags) is made on first use,
 * from the one shader file and #defines: a fragment program, or for the passes into the
 * chain's own targets where the context has OpenGL 4.3 a compute program of the same file
 * (vtkBloomPassCompute.cxx). With Restrict each pass covers only the box its output can be
 * non-zero in (vtkBloomPassRegion.cxx). A separable pair of passes that is one draw runs as one
 * tiled compute pass (PassSpec::Tiled), and a second term of the same output may share it
 * (PassSpec::Second: a level's two downsample terms, a level's blur inside its upsample); the
 * compute passes into the chain's targets barrier only where a later pass needs it
 * (Deferring).
 */

#ifndef vtkBloomPassChainRunner_h
#define vtkBloomPassChainRunner_h

#include "vtkBloomPassFramePlan.h"    // For the frame's settings, light and output
#include "vtkBloomPassOperators.h"    // For the operators' textures and interiors
#include "vtkBloomPassProfiler.h"     // For the profile
#include "vtkBloomPassProgramCache.h" // For the programs
#include "vtkBloomPassTypes.h"        // For the boxes, the pass specs and the targets
#include "vtkSmartPointer.h"          // For the operator textures

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

class vtkBloomLinearOperator;
class vtkBloomPassFFTBlur;
class vtkBloomPassResources;
class vtkBloomParameters;
class vtkObject;
class vtkOpenGLQuadHelper;
class vtkShaderProgram;
class vtkTextureObject;
class vtkWindow;

// The values (OP_, STEP_) are the runner's own names until the chain's steps move out of it
// (docs/architecture.md, migration step 9), as are the aliases below.
class vtkBloomPassChainRunner : public vtkBloomPassShaderValues
{
public:
  using Settings = vtkBloomPassFramePlan::Settings;
  using Light = vtkBloomPassFramePlan::Light;
  using Output = vtkBloomPassFramePlan::Output;
  using Box = vtkBloomPassBox;
  using Segment = vtkBloomPassSegment;
  using PassSpec = vtkBloomPassSpec;
  using Interior = vtkBloomPassOperators::Interior;
  static constexpr int MaximumTileRows = vtkBloomPassOperators::MaximumTileRows;

  /// `owner` reports the errors; `resources` holds the chain, the context and the targets;
  /// `fftBlur` runs the wide blurs (FFTBlurPass); `profiler` lists the passes where the frame
  /// is profiled. The runner owns none of them.
  vtkBloomPassChainRunner(vtkObject* owner, vtkBloomPassResources& resources,
    vtkBloomPassFFTBlur& fftBlur, vtkBloomPassProfiler& profiler);
  ~vtkBloomPassChainRunner();
  vtkBloomPassChainRunner(const vtkBloomPassChainRunner&) = delete;
  vtkBloomPassChainRunner& operator=(const vtkBloomPassChainRunner&) = delete;

  /// Start a frame with `settings`: the pass counts start from nothing.
  void BeginFrame(const Settings& settings);

  /**
   * Bloom `light` into the chain's targets. Returns false when the bloom is skipped (no level,
   * a disabled effect or nothing bright): the composite then keeps the scene only.
   */
  bool Run(const Light& light);

  /**
   * PSF mode (vtkBloomParameters::BLOOM_PSF): the bright pass of `light` at full size, with no
   * resample, into `bright` (as vtkImageBloom's PSF mode thresholds its input). False when the
   * bloom is skipped (a disabled effect, or nothing bright with SkipEmptyBloom).
   */
  bool BrightPassPSF(const Light& light, vtkBloomPassTarget& bright);

  /**
   * out = keep * scene + Strength * Tint * bloom into `target`, or into the bound framebuffer
   * at `origin` when `target` is null: the frame's sample (i, j) lands at origin + (i, j), for
   * the samples of output.Window.
   */
  void Composite(const Output& output, vtkBloomPassTarget* target, const int origin[2], bool bloom);

  /// Copy `source` into `target`, or into the bound framebuffer at `origin` when it is null.
  void Copy(const Output& output, vtkBloomPassTarget* target, const int origin[2],
    vtkBloomPassTarget& source);

  /**
   * After the composite or the copy into the bound framebuffer at `origin`, where that
   * framebuffer is multisampled: its samples at anti-aliased edges become the composites of the
   * scene's own samples (COMPOSITE_SAMPLES in vtkBloomPassFS.glsl), as the renderer would have
   * drawn them. Nothing where it does not apply (CompositeSamples).
   */
  void CompositeEdges(const Output& output, const int origin[2], bool bloom);

  ///@{
  /// What the frame did: passes drawn (the composite included) and how many of them as compute.
  int GetPasses() const { return this->Passes; }
  int GetComputePasses() const { return this->ComputePasses; }
  ///@}

  /**
   * The last Run()'s bright region (the bounding box of the bright pass's non-zero samples, in
   * level-0 samples, x0 x1 y0 y1 with x1, y1 past the end; all 0 when empty or not measured)
   * and the samples its passes computed over those a full evaluation computes (1 when not
   * restricted), the composite included.
   */
  const int* GetBrightRegion() const { return this->BrightRegion; }
  double GetCoverage() const { return this->Coverage; }

  /// Average GPU milliseconds of a content-aware evaluation with and without the region
  /// measured; negative until timed (RegionPays).
  double GetRegionCost() const { return this->RegionCost; }
  double GetFullCost() const { return this->FullCost; }

  /**
   * GPU milliseconds of the latest evaluation whose timestamps have arrived (from the bright
   * pass to the end of the composite); negative until one has. CollectCostTimings() takes what
   * has arrived, without waiting (the context must be current); every evaluation is timed while
   * TimeEveryChain is on, else only those RegionPays learns from.
   */
  double GetLastChainMilliseconds() const { return this->LastChainMilliseconds; }
  void CollectCostTimings();
  void SetTimeEveryChain(bool time) { this->TimeEveryChain = time; }
  bool GetTimeEveryChain() const { return this->TimeEveryChain; }

  /// Free the operator textures; call it before the chain is rebuilt.
  void ReleaseOperators(vtkWindow* w);

  /// Free the operator textures, the programs and the query.
  void ReleaseGraphicsResources(vtkWindow* w);

private:
  // What BeginFrame(), Run() and the composite's calls were given, for the passes they draw.
  Settings Frame;
  Light In;
  Output Out;

  // What the frame did (the getters').
  int Passes = 0;        ///< passes drawn since BeginFrame, the composite included
  int ComputePasses = 0; ///< of them, compute passes
  int BrightRegion[4] = { 0, 0, 0, 0 };
  double Coverage = 1.0;
  double RegionCost = -1.0;
  double FullCost = -1.0;
  double LastChainMilliseconds = -1.0;
  /// Every evaluation is timed (vtkBloomPassTesting::SetTimeChains); else only those
  /// RegionPays learns from.
  bool TimeEveryChain = false;

  /// Whether the context renders on the CPU (Mesa's llvmpipe or softpipe, SwiftShader), asked
  /// once per context.
  bool SoftwareRasterizer();
  int Software = 0; ///< 0 not asked, 1 yes, -1 no
  static std::string ShaderConstants();

  /// The most samples a pass may have to be one draw (SingleDrawSamples, or its automatic value).
  int SingleDrawLimit();
  /**
   * Whether the separable pair x then y (x's output rows are y's input) runs as one tiled
   * compute pass (PassSpec::Tiled): FuseSeparablePasses, compute shaders, a pass of one draw, and
   * at most MaximumTileRows rows read by any 16 consecutive outputs of y.
   */
  bool Fuses(const vtkBloomLinearOperator& x, const vtkBloomLinearOperator& y);
  /// Fuses both terms, of one output size, into one tiled pass (their rows shared memory).
  bool FusesTwo(const vtkBloomLinearOperator& x, const vtkBloomLinearOperator& y,
    const vtkBloomLinearOperator& x2, const vtkBloomLinearOperator& y2);
  /**
   * CASCADE: level i's blur runs inside its upsample-and-accumulate pass (the pass's addend,
   * TILE2) rather than as a pass into Work: a blurred level below the last, with a weight, and
   * both terms fused (FusesTwo).
   */
  bool BlurInUpsample(size_t i);
  /// Whether a blur's operator runs through the FFT (FFTBlurPass would take it).
  bool UsesFFT(const vtkBloomLinearOperator& op);

  /**
   * The steps of Run() and what they pass on: with Restrict, the box each target can be
   * non-zero in (Level: the pyramid's levels, Blur: after their blur, Accum: CASCADE's
   * accumulations); without, every box is the whole target. Blurred is each level's blurred
   * target (the level itself where it is not blurred); LastAccumulated, whether the last
   * level's blur already wrote its CASCADE accumulation.
   */
  struct ChainRegions
  {
    bool Restrict = false;
    std::vector<Box> Level;
    std::vector<Box> Blur;
    std::vector<Box> Accum;
    std::vector<vtkBloomPassTarget*> Blurred;
    bool LastAccumulated = false;
    /// The region a pass computes: `box` when restricted, else null (the whole target).
    const Box* Of(const Box& box) const;
  };
  /// Run()'s steps; Run() makes their last writes visible (FlushComputeWrites).
  bool RunSteps();
  /// Whether this Run() measures the bright region (Restrict, probed and explored over frames).
  bool ChooseRestrict();
  /// 1. The bright pass into level 0; false when nothing is bright (the bloom is skipped).
  bool BrightPass(ChainRegions& regions);
  /**
   * 2. and 3. The pyramid, each level from the unblurred level above it (DownsampleLevel), and
   * the blur of each contributing level (BlurLevel), interleaved: level i - 1's blur after level
   * i's downsample, which read the same level, so that the two run side by side on the GPU
   * (see Deferring).
   */
  void DownsampleAndBlurLevels(ChainRegions& regions);
  void DownsampleLevel(ChainRegions& regions, size_t i);
  void BlurLevel(ChainRegions& regions, size_t i);
  /// 4. The accumulation into Full (DIRECT) or the Accum targets (CASCADE).
  void AccumulateDirect(ChainRegions& regions);
  void AccumulateCascade(ChainRegions& regions);

  /**
   * One axis (0: x, 1: y) of a level's blur, `spec` into `target`: through the FFT
   * (FFTBlurPass) where the parameters' ConvolutionMode chooses it, else as a direct Pass().
   */
  void BlurPass(vtkBloomPassTarget& target, const PassSpec& spec, int axis);
  /**
   * The blur's operator along `axis` through the FFT in two compute dispatches
   * (vtkBloomPassFFTBlur, profiled as "<name>-fft" and "<name>-fft-finish"), over the whole
   * level; false, having drawn nothing, when the direct pass must run instead: no compute
   * shaders, ConvolutionMode DIRECT, AUTOMATIC with the direct pass cheaper by
   * vtkBloomPassFFTBlur's cost model, an operator with no convolution interior or too long a
   * line, or a program that does not build.
   */
  bool FFTBlurPass(vtkBloomPassTarget& target, const PassSpec& spec, int axis);
  vtkBloomPassFFTBlur* FFTBlur; ///< its owner's (vtkBloomPass::vtkInternals)

  // Content-aware evaluation (vtkBloomPassRegion.cxx).

  /**
   * The output samples of `x` (along x) and `y` (along y) that read any input sample of `in`:
   * outside it the pass reads only zeros. A null operator is the identity.
   */
  static Box Reach(const vtkBloomLinearOperator* x, const vtkBloomLinearOperator* y, const Box& in,
    int width, int height);

  /**
   * Reduce the bright level to the box of its non-zero samples: one compute dispatch where the
   * context has OpenGL 4.3 (MeasureBrightRegionByCompute), else two or three small fragment
   * passes; then a read-back of a few bytes (or kilobytes).
   */
  Box MeasureBrightRegion();
  bool MeasureBrightRegionByCompute(Box& box);
  void ReleaseCompute();
  unsigned int ReduceProgram = 0; ///< the compute program; 0: not made yet
  unsigned int ReduceBuffer = 0;  ///< its four integers
  int ComputeState = 0;           ///< 0 not made, 1 made, -1 it failed

  /**
   * Before a pass that replaces `target`'s samples in `region` (null: all of width x height):
   * clear what the target holds outside it, so that it is zero there, and record what it holds.
   */
  void PrepareTarget(vtkBloomPassTarget& target, const Box* region, int width, int height);

  /**
   * Coverage of the last evaluation; when it was measured, and it is at least DenseCoverage or
   * the region does not pay (RegionPays), the next ProbeInterval - 1 evaluations run the full
   * chain without measuring the region.
   */
  void EndCoverage(bool measured);
  static constexpr double DenseCoverage = 0.25;
  static constexpr int ProbeInterval = 8;
  int FramesUntilProbe = 0;

  /**
   * What the region costs against the full chain. Its read-back makes the CPU wait for the GPU
   * and leaves the GPU idle while the rest of the chain is submitted; a GPU that runs the whole
   * chain faster than that (an NVIDIA H100: docs/gpu.md) is better off with the full chain,
   * while on Mesa's llvmpipe, whose passes cost in proportion to their samples, the region is
   * the saving. Each content-aware evaluation is timed by two GPU timestamps, from the start of
   * the chain to the end of the composite, read back frames later without waiting, and
   * averaged per kind (RegionCost with the region measured, FullCost without); an evaluation
   * that compiled a program is not timed. While the region pays, the 4th evaluation and then
   * one in ExploreInterval run the full chain to learn FullCost. Once it does not pay, it is not
   * measured again on this context (ChooseRestrict): a measured frame would wait for the GPU
   * and stutter among the others. The output is the same bits either way.
   */
  bool RegionPays() const;
  void BeginCostTiming(bool measured);
  void EndCostTiming();
  bool CostTimingSupported();
  void ReleaseCostTiming();
  struct CostSlot
  {
    unsigned int Queries[2] = { 0, 0 };
    bool Measured = false;     ///< the evaluation measured the region
    bool ContentAware = false; ///< Restrict was on: the time counts for RegionPays
    bool Pending = false;      ///< both timestamps issued, not read yet
  };
  static constexpr int CostSlots = 4;
  static constexpr int ExploreInterval = 32;
  CostSlot CostTimings[CostSlots];
  int NextCostSlot = 0;
  bool CostTimingOpen = false;
  int CostTimingSupport = 0; ///< 0 not asked, 1 yes, -1 no
  static constexpr int FirstExplore = 4;
  int FramesUntilExplore = FirstExplore;
  bool RegionDeclined = false;  ///< the region did not pay: not measured again on this context
  bool CompiledProgram = false; ///< a program was made since BeginCostTiming

  /// The region of the bloom term within the composite's output; outside it the bloom is zero.
  Box CompositeRegion;
  bool CompositeRestricted = false;
  int CompositeSize[2] = { 0, 0 }; ///< the composite's size (CompositeSpec points at it)
  double ComputedSamples = 0.0;
  double FullSamples = 0.0;

  /// The program of one variant, made on first use; null (with an error) if it fails.
  vtkOpenGLQuadHelper* Program(const std::string& variant);
  std::string Variant(const PassSpec& spec, int xMode, int yMode);

  /**
   * One pass into `target` (or the bound framebuffer when null, at `origin`): one draw per
   * combination of x and y segments, each with the program of its evaluation modes.
   */
  void Pass(vtkBloomPassTarget* target, const int origin[2], const PassSpec& spec);
  /**
   * Sets one program's uniforms by name (unused ones are skipped): a VTK program (the fragment
   * passes) or a compute program of plain OpenGL (VTK 9.1's shader classes have no compute
   * stage), whose locations it caches.
   */
  struct LocationCache;
  struct Uniforms
  {
    vtkShaderProgram* Program = nullptr;
    unsigned int Raw = 0;
    LocationCache* Locations = nullptr;

    int Location(const char* name);
    void Int(const char* name, int value);
    void Float(const char* name, double value);
    void Int2(const char* name, const int values[2]);
    void Float2(const char* name, const float values[2]);
    void Float3(const char* name, const double values[3]);
    void Float4(const char* name, const float values[4]);
    void Ints(const char* name, int count, const int* values);
    void Floats(const char* name, int count, const float* values);
  };
  void SetStepUniforms(Uniforms& uniforms, int step);

  /**
   * A compute program's uniform locations: by name, asked of OpenGL once, and by the address
   * of the name (the callers pass literals; a hit is checked against the name it was made
   * for), so that a frame's lookups compare a few pointers rather than search strings.
   */
  struct LocationCache
  {
    struct Seen
    {
      const char* Address;
      std::string Name;
      int Location;
    };
    std::map<std::string, int> ByName;
    std::vector<Seen> ByAddress; ///< at most MaximumSeen
    static constexpr size_t MaximumSeen = 64;
  };

  // The compute passes (vtkBloomPassCompute.cxx).
  struct ComputeProgram
  {
    unsigned int Id = 0; ///< 0: it did not build
    LocationCache Locations;
  };
  vtkBloomPassProgramCache<ComputeProgram> ComputePrograms;
  /// Compute variants that did not build: not tried again, their passes run as fragments.
  std::set<std::string> FailedCompute;
  bool WarnedComputeFallback = false;

  /// Whether the context runs compute shaders (OpenGL 4.3), asked once.
  bool ComputeSupported();
  int ComputeSupport = 0; ///< 0 not asked, 1 yes, -1 no

  int GLVersion = 0; ///< major * 10 + minor, asked with ComputeSupport

  /// Whether a fragment shader can run per sample (gl_SampleID, GL_ARB_sample_shading), asked
  /// once.
  bool SampleShadingSupported();
  int SampleShading = 0; ///< 0 not asked, 1 yes, -1 no
  /**
   * The multisampled scene (Output::SceneSamples) where the bound framebuffer has as many samples,
   * a fragment shader can run per sample and the composite replaces what the framebuffer holds (not
   * Output::Over); else null.
   */
  vtkTextureObject* CompositeSamples();
  /// The composite's pass (Composite, CompositeEdges).
  PassSpec CompositeSpec(bool bloom);

  /**
   * Where a compute pass writes: level `Level` of the texture `Texture`, bound as image unit 0
   * in `Format` (GL_RGBA8, GL_RGBA16F or GL_RGBA32F), the pass's output sample (0, 0) at
   * `Offset`. A zero `Texture`: the pass draws fragments.
   */
  struct ImageTarget
  {
    unsigned int Texture = 0;
    int Level = 0;
    unsigned int Format = 0;
    int Offset[2] = { 0, 0 };
  };

  /**
   * Where `spec`, `width` x `height` samples into `target` (or into the bound framebuffer at
   * `origin` when null), runs as a compute pass: `target`'s texture, or the bound framebuffer's
   * colour texture (FramebufferImage); none when compute is off or unsupported.
   */
  ImageTarget ComputeTarget(
    vtkBloomPassTarget* target, const int origin[2], const PassSpec& spec, int width, int height);

  /**
   * The bound draw framebuffer's colour buffer as an image, when a compute pass writes it as a
   * fragment pass would: a single-sample 2D texture level in GL_RGBA8, GL_RGBA16F or
   * GL_RGBA32F that holds `origin` + `width` x `height`, every channel writable (VTK's render
   * framebuffer, and the float targets of vtkToneMappingPass and vtkFramebufferPass). Needs
   * OpenGL 4.5 to ask a texture's target and format.
   */
  bool FramebufferImage(const int origin[2], int width, int height, ImageTarget& image);

  /**
   * The compute program of one variant (vtkBloomPassFS.glsl with COMPUTE) that writes an
   * image of `format`, made on first use.
   */
  ComputeProgram* Compute(const std::string& variant, bool blend, unsigned int format);

  /// Bind `image` as image unit 0 and dispatch one invocation per sample of `rect`.
  void Dispatch(const ImageTarget& image, bool blend, const Box& rect);

  /// After a pass's dispatches: their writes visible to what reads the target next.
  void EndCompute();

  // The pieces of Pass().

  /// One draw of a pass: a rectangle of its output and the evaluation mode of each axis;
  /// Zero: a composite rectangle where the bloom is known zero.
  struct Draw
  {
    Box Rect;
    int XMode;
    int YMode;
    bool Zero;
  };

  /// The textures a pass reads, in a fixed order, and their samplers' names.
  struct PassTextures
  {
    std::array<vtkTextureObject*, 13> Textures;
    static constexpr const char* Samplers[13] = { "source", "xRows", "yRows", "addend", "scene",
      "emitterDepth", "sceneDepth", "background", "source2", "x2Rows", "y2Rows", "sourceSamples",
      "sceneSamples" };
  };

  /**
   * Within Run() (Deferring), a compute pass into one of the chain's targets makes no barrier of
   * its own: the next pass that reads a texture written since the last barrier, or writes one read
   * or written since, issues it first (BeforeComputePass). Independent passes (a level's blur
   * and the next level's downsample) then overlap on the GPU instead of each waiting for the
   * one before. Anything else that touches the targets (a clear, a fragment pass, the FFT, the
   * region's reduction, the composite) flushes first (FlushComputeWrites). Profiling keeps a
   * barrier after every pass, so that each pass's timestamps hold its own work.
   */
  bool Deferring = false;                            ///< within Run(), not Profiling
  using TextureNames = std::array<unsigned int, 13>; ///< PassTextures' names, 0 where absent
  static TextureNames NamesOf(const PassTextures& textures);
  void BeforeComputePass(const TextureNames& reads, unsigned int written);
  void AfterComputePass(const TextureNames& reads, unsigned int written);
  void FlushComputeWrites();
  std::vector<unsigned int> PendingWrites; ///< texture names written since the last barrier
  std::vector<unsigned int> PendingReads;  ///< and read since

  /**
   * One draw's program variant (its #defines) and compute program, found once: the key holds
   * everything Variant() writes into the #defines (the operators by address, the evaluation
   * modes, the step, the flags) and the image format and blending of the compute program, so
   * that a frame names each draw's program without writing its #defines again. Dropped with
   * the operators (ReleaseOperators) and the compute programs (ReleaseCompute).
   */
  struct VariantEntry
  {
    std::string Variant;
    ComputeProgram* Program = nullptr; ///< null: not made, or it did not build
    bool Asked = false;                ///< Compute() was asked for Program
  };
  using VariantKey = std::array<std::uintptr_t, 13>;
  std::map<VariantKey, VariantEntry> Variants;
  VariantEntry& VariantOf(const PassSpec& spec, const Draw& draw, unsigned int format);
  /**
   * Prepare `target` (clear outside the region), pick where the pass writes (a compute image,
   * or `target`'s framebuffer bound for fragments) and set the blending.
   */
  ImageTarget BeginPass(
    vtkBloomPassTarget* target, const int origin[2], const PassSpec& spec, int width, int height);
  /**
   * The compute program of every draw's variant (Compute, made now where it is new) into
   * `programs`; false when one does not build.
   */
  bool ComputeProgramsOf(const std::vector<VariantEntry*>& variants, bool blend,
    unsigned int format, std::vector<ComputeProgram*>& programs);
  /// The draws of a width x height pass, cut to its region; counts the samples it computes.
  std::vector<Draw> Draws(const PassSpec& spec, int width, int height);
  PassTextures PassTexturesOf(const PassSpec& spec);
  /// Every uniform of one draw: samplers, its rectangle, the operators' interiors, the step's.
  void SetDrawUniforms(
    Uniforms& u, const PassSpec& spec, const Draw& draw, const PassTextures& textures);

  bool CountingSamples = false; ///< the occlusion query is open: fragment passes only
  void Clear(vtkBloomPassTarget& target);

  vtkObject* Owner;
  vtkBloomPassResources& Resources;
  /// The chain's operators on the GPU, dropped when the chain is rebuilt (ReleaseOperators).
  vtkBloomPassOperators Operators;

  // One program per variant (operator modes, interior weights, step, flags), made on first use.
  // The program itself is the window's shader cache's (by its source), shared with the other
  // passes of the window: Handle says which compilation the quad's vertex array was bound to.
  struct FragmentProgram
  {
    std::unique_ptr<vtkOpenGLQuadHelper> Quad;
    int Handle = 0;
  };
  vtkBloomPassProgramCache<FragmentProgram> Programs;
  /// Free a fragment program's quad and its compiled program (the cache keeps its source).
  static void Release(FragmentProgram& program, vtkWindow* w);
  /// Free the programs that the last chains did not use; a chain is about to be built.
  void EndProgramGeneration(vtkWindow* w);

  /**
   * The profile's entry of one pass: its name, the size it wrote and its compulsory memory
   * traffic (every texture it reads read once, its target written once, and read once more
   * when it blends).
   */
  void EndProfiledPass(const PassSpec& spec);
  vtkBloomPassProfiler& Profiler; ///< its owner's (vtkBloomPass::vtkInternals)

  // Occlusion query that counts the non-zero samples of the bright pass (SkipEmptyBloom).
  unsigned int Query = 0;

  // Values of the current evaluation that the programs read as uniforms.
  bool SanitizeSource = false;
  bool SanitizeOutput = false;
};

#endif
// VTK-HeaderTest-Exclude: vtkBloomPassChainRunner.h
