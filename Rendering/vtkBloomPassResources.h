// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkBloomPassResources.h
 * @brief  (private to vtkBloomPass) the pass's OpenGL resources: the float targets, the scene
 *         and emitter targets with their depth, the chain's intermediate targets, and the GL
 *         state the pass saves while it runs.
 *
 * vtkBloomPass makes these on first use and remakes them when the size, the precision or the
 * parameters change; vtkBloomPassChainRunner draws into them. Every target is a float RGBA
 * texture with nearest filtering and clamped borders: the passes read it with exact texel
 * fetches, never through hardware filtering.
 */

#ifndef vtkBloomPassResources_h
#define vtkBloomPassResources_h

#include "vtkBloomChain.h"     // For the chain the targets are sized for
#include "vtkBloomPassTypes.h" // For the targets
#include "vtkOpenGLState.h"    // For the scoped savers
#include "vtkSmartPointer.h"   // For the targets' textures and framebuffers
#include "vtkType.h"           // For vtkMTimeType
#include "vtkWeakPointer.h"    // For the context

#include <vector>

class vtkBloomParameters;
class vtkImageData;
class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkRenderbuffer;
class vtkTextureObject;
class vtkWindow;

//------------------------------------------------------------------------------
// The OpenGL state the pass changes, restored when it returns.
struct vtkBloomPassSavedState
{
  vtkOpenGLState::ScopedglEnableDisable Blend, Depth, Scissor;
  vtkOpenGLState::ScopedglBlendFuncSeparate BlendFunc;
  vtkOpenGLState::ScopedglViewport Viewport;
  vtkOpenGLState::ScopedglScissor ScissorBox;
  vtkOpenGLState::ScopedglClearColor ClearColor;

  explicit vtkBloomPassSavedState(vtkOpenGLState* state);
};

//------------------------------------------------------------------------------
/// The depth format of the scene's targets: the window's (vtkBloomPassDepthFormat).
unsigned int vtkBloomPassDepthFormat(vtkOpenGLRenderWindow* context);

//------------------------------------------------------------------------------
// A float colour target with a depth texture, for the delegate's render.
struct vtkBloomPassSceneTarget : vtkBloomPassTarget
{
  vtkSmartPointer<vtkTextureObject> Depth;
  unsigned int DepthFormat = 0;

  void AllocateWithDepth(vtkOpenGLRenderWindow* context, int width, int height, unsigned int format,
    unsigned int depthFormat);
  void ReleaseAll(vtkWindow* window);
};

//------------------------------------------------------------------------------
// A multisampled float colour and depth, where the delegate renders when the framebuffer the
// pass was called with is multisampled; resolved once into a single-sample scene target. The
// colour is a multisample texture, which the bright pass may read sample by sample
// (vtkBloomPass::ThresholdSamples).
struct vtkBloomPassMultisampleTarget
{
  vtkSmartPointer<vtkOpenGLFramebufferObject> FBO;
  vtkSmartPointer<vtkTextureObject> Color;
  vtkSmartPointer<vtkRenderbuffer> Depth;
  int Size[2] = { 0, 0 };
  int Samples = 0;
  unsigned int Format = 0;
  unsigned int DepthFormat = 0;

  /// Make it at width x height with `samples` samples of `format` and `depthFormat`, unless
  /// it already is.
  void Allocate(vtkOpenGLRenderWindow* context, int width, int height, unsigned int format,
    unsigned int depthFormat, int samples);
  void Release(vtkWindow* window);

  /**
   * Resolve the colour (the average of the samples, in float) and, with `depth`, the depth (one
   * sample) into `target`, of the same size and format. The framebuffer bindings are restored
   * afterwards.
   */
  void Resolve(vtkOpenGLRenderWindow* context, vtkBloomPassSceneTarget& target, bool depth);
};

//------------------------------------------------------------------------------
class vtkBloomPassResources
{
public:
  /// The window whose context holds every resource below; weak, so that a pass that outlives
  /// its window does not free names of a context that is gone (the window freed them).
  vtkWeakPointer<vtkOpenGLRenderWindow> Context;
  unsigned int Format = 0; ///< the scene's internal format: GL_RGBA16F or GL_RGBA32F

  vtkBloomPassSceneTarget Scene;
  vtkBloomPassSceneTarget Emitter;
  /// Where the delegate renders when Samples > 1 (the framebuffer the pass was called with
  /// is multisampled), resolved into Scene and Emitter.
  vtkBloomPassMultisampleTarget Multisample;
  int Samples = 0;
  vtkBloomPassTarget Result;
  /// vtkBloomPass::KeptFrameMode's staging: the framebuffer's pixels on their way to the CPU,
  /// or a tile's part of the kept frame on its way back.
  vtkBloomPassTarget Kept;

  /**
   * Where the composite finds the renderer's background (vtkBloomPassBackground.h): in the
   * scene (BACKGROUND_IN_SCENE: it was rendered with it), a solid BackgroundColor (RGBA), or
   * the Background target, drawn as the renderer draws a gradient or textured background.
   */
  enum BackgroundModes
  {
    BACKGROUND_IN_SCENE = 0,
    BACKGROUND_COLOR = 1,
    BACKGROUND_TEXTURE = 2
  };
  int BackgroundMode = BACKGROUND_IN_SCENE;
  float BackgroundColor[4] = { 0.0f, 0.0f, 0.0f, 0.0f };
  /// Where the renderer's pixel (0, 0) lies in the Background target (its window position).
  int BackgroundOrigin[2] = { 0, 0 };
  vtkBloomPassTarget Background;

  // The chain and its resources, rebuilt when the size or the parameters change.
  vtkBloomChain Chain;
  vtkMTimeType ChainTime = 0;
  const vtkBloomParameters* ChainParameters = nullptr; // compared only, never dereferenced
  std::vector<vtkBloomPassTarget> Levels;              // L_i
  std::vector<vtkBloomPassTarget> Work;                // blurred levels and Karis sums
  std::vector<vtkBloomPassTarget> Accum;               // CASCADE accumulation A_i
  vtkBloomPassTarget Temp;                // the output of every x pass, at most the size of level 0
  vtkBloomPassTarget Full;                // DIRECT: the full-size bloom
  std::vector<vtkBloomPassTarget> Reduce; // the bright region's reduction (RGBA32F boxes)

  /// PSF mode (vtkBloomParameters::BLOOM_PSF): the full-size bright pass and its convolution
  /// with the PSFs (vtkBloomPassFFT), RGBA32F; no chain is built then.
  vtkBloomPassTarget PSFBright;
  vtkBloomPassTarget PSFBloom;

  /**
   * Make the scene target at width x height in Format, and the emitters' when `emitters`
   * (else release it); and the multisampled target with `samples` samples when `samples` > 1
   * (else release it).
   */
  void AllocateScene(int width, int height, bool emitters, int samples);

  /// Whether the chain was built for other or older parameters, or another size or part.
  bool ChainIsStale(vtkBloomParameters* parameters, int width, int height, const int part[4]) const;

  /**
   * Build the chain for `parameters` at width x height, or cut it from `frame`'s chain to
   * `part` (x0 x1 y0 y1 of a tiled frame; vtkBloomChain::Cut), and make its RGBA32F targets.
   */
  void BuildChain(vtkBloomParameters* parameters, int width, int height, const vtkBloomChain* frame,
    const int part[4]);
  int ChainPart[4] = { 0, 0, 0, 0 }; ///< the part of a tiled frame; all 0 untiled

  void ReleaseChain(vtkWindow* w);
  void ReleaseAll(vtkWindow* w);
};

#endif
// VTK-HeaderTest-Exclude: vtkBloomPassResources.h
