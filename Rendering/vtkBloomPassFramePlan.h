// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkBloomPassFramePlan.h
 * @brief  (private to vtkBloomPass) what a frame gives the chain: how it runs (Settings), the
 *         light it blooms (Light) and how the composite writes the frame (Output).
 *
 * vtkBloomPass fills them for each frame and vtkBloomPassChainRunner reads them. They are
 * values: they own nothing they point to. docs/architecture.md plans them as one plan, built
 * once at the top of a frame, with the tally of what the frame did.
 */

#ifndef vtkBloomPassFramePlan_h
#define vtkBloomPassFramePlan_h

class vtkBloomParameters;
class vtkTextureObject;
struct vtkBloomPassTarget;

struct vtkBloomPassFramePlan
{
  /// How the chain runs, fixed for a frame: given to vtkBloomPassChainRunner::BeginFrame().
  struct Settings
  {
    /// The chain and the point-wise values (threshold, composite); not owned.
    vtkBloomParameters* Parameters = nullptr;
    /// Every pass after the bright pass covers only the box its output can be non-zero in
    /// (vtkBloomParameters::RestrictToBrightRegion, vtkBloomPassRegion.cxx).
    bool Restrict = false;
    /**
     * The chain's passes into its targets as compute shaders where the context runs them
     * (vtkBloomPassCompute.cxx; vtkBloomPass::UseComputeShaders), the bright region's reduction
     * as one dispatch, and the composite too where the framebuffer's colour buffer can be
     * written as an image (FramebufferImage); else fragment passes.
     */
    bool UseCompute = true;
    /// For tests: every compute variant fails to build (the fallback to fragments then runs).
    bool SimulateComputeFailure = false;
    /// A pass of at most this many output samples is one draw (vtkBloomPass::SingleDrawSamples;
    /// negative: automatic, by the rasterizer).
    int SingleDrawSamples = -1;
    /**
     * A separable pair of passes (x into a scratch target, then y) that is one draw is one
     * compute dispatch instead (vtkBloomPass::FuseSeparablePasses): a 2D pass whose work groups
     * sum the source rows they read once, in shared memory (TILE in vtkBloomPassFS.glsl).
     */
    bool FuseSeparablePasses = true;
  };

  /// The light that vtkBloomPassChainRunner::Run() (or BrightPassPSF()) blooms.
  struct Light
  {
    /// The scene's or the emitters' colour.
    vtkTextureObject* Emission = nullptr;
    /// Only where the emitters are the visible surface (their depth against the scene's).
    bool Mask = false;
    /**
     * The scene's render wrote selective bloom's emission in its alpha (vtkBloomPassEmission):
     * the bright pass reads the colour times min(1, max(0, alpha - 1)).
     */
    bool InAlpha = false;
    /// The parameters' threshold applies (true), or the emission is taken whole (false:
    /// selective bloom's emitters are light whatever their colour).
    bool Threshold = true;
    /**
     * The multisampled scene (its colour before the resolve) and its samples: the bright pass
     * thresholds each sample and takes their mean (SAMPLE_THRESHOLD in vtkBloomPassFS.glsl;
     * vtkBloomPass::ThresholdSamples). Null: Emission, as it is.
     */
    vtkTextureObject* Samples = nullptr;
    int SampleCount = 0;
  };

  /// How vtkBloomPassChainRunner::Composite(), Copy() and CompositeEdges() write the frame.
  struct Output
  {
    /// A transparent scene's alpha is raised by the glow (a rendered frame), or kept (an
    /// image, as vtkImageBloom keeps it).
    bool GlowAlpha = true;
    /// The scene's alpha holds the emission (Light::InAlpha): the composite reads it as
    /// min(alpha, 1).
    bool EmissionInAlpha = false;
    /**
     * The pass into the framebuffer goes over what it holds, premultiplied (GL_ONE,
     * GL_ONE_MINUS_SRC_ALPHA), instead of replacing it: a renderer on a higher layer, which
     * clears nothing, blooms over the layers below. Such a pass is always a fragment pass.
     */
    bool Over = false;
    /**
     * The multisampled scene: where the composite writes a framebuffer of as many samples, each
     * sample is the composite of the scene's own sample (COMPOSITE_SAMPLES in
     * vtkBloomPassFS.glsl), so that the window resolves the samples the renderer would have
     * drawn, as it resolves them (VTK presents a multisampled window through a gamma 2.2
     * average). Null, or no per-sample shading (GL_ARB_sample_shading): the resolved scene, the
     * same value in every sample.
     */
    vtkTextureObject* SceneSamples = nullptr;
    int SceneSampleCount = 0;
    /**
     * The samples of the chain's frame written, x0 x1 y0 y1 (x1, y1 past the end); all 0: the
     * whole frame. A tile rendered with its guard band (vtkBloomPassTile) writes the tile only.
     */
    int Window[4] = { 0, 0, 0, 0 };
    /// PSF mode: the full-size bloom term the composite adds, and its size (null: the chain's).
    vtkBloomPassTarget* PSFBloom = nullptr;
  };
};

#endif
// VTK-HeaderTest-Exclude: vtkBloomPassFramePlan.h
