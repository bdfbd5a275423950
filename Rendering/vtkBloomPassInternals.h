// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkBloomPassInternals.h
 * @brief  (private to vtkBloomPass) the pass's internals, shared by the pass's own source files
 *         (docs/architecture.md lists them).
 */

#ifndef vtkBloomPassInternals_h
#define vtkBloomPassInternals_h

#include "vtkBloomFrameReport.h"
#include "vtkBloomPass.h"
#include "vtkBloomPassBackground.h"
#include "vtkBloomPassChainRunner.h"
#include "vtkBloomPassDepth.h"
#include "vtkBloomPassEmission.h"
#include "vtkBloomPassFFT.h"
#include "vtkBloomPassFFTBlur.h"
#include "vtkBloomPassPSFSplit.h"
#include "vtkBloomPassProfiler.h"
#include "vtkBloomPassResources.h"
#include "vtkBloomPassSteps.h"
#include "vtkBloomPassTile.h"
#include "vtkBloomVTKCompat.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkOpenGLFXAAFilter.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOpenGLState.h"
#include "vtkProp.h"
#include "vtkPropCollection.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"

#include <string>
#include <vector>

//------------------------------------------------------------------------------
// The render-pass side of the internals: the GL resources and the chain runner that draws into
// them, and the steps of Render() that need the pass's protected members.
class vtkBloomPass::vtkInternals
{
public:
  explicit vtkInternals(vtkBloomPass* owner)
    : Runner(owner, Resources, FFTBlur, Profiler)
    , Emission(vtkBloomPass::EMITTER_SOURCE(), vtkBloomPass::EMITTER_SCALAR_RANGE())
  {
  }

  vtkBloomPassResources Resources;
  vtkBloomPassFFTBlur FFTBlur;   ///< the chain's wide blurs, run by the runner's blur passes
  vtkBloomPassProfiler Profiler; ///< the frame's GPU profile (vtkBloomPassTesting), opt-in
  vtkBloomPassChainRunner Runner;
  vtkBloomPassChainRunner::Light Light;   ///< what the runner blooms
  vtkBloomPassChainRunner::Output Output; ///< how the runner writes the frame
  vtkBloomPassEmission Emission;
  vtkBloomPassSteps Steps;       ///< the delegate's overlay (over the bloom) and translucency
  std::string BackgroundWarning; ///< why the background blooms, said once

  // Where the delegate's frame cannot be put over the background afterwards, the background
  // stays in the frame (it is the renderer's frame still): said once per reason.
  void WarnBackgroundInScene(vtkBloomPass* self, bool oit, vtkRenderPass* processing)
  {
    std::string why;
    if (processing)
    {
      why = std::string("The delegate's ") + processing->GetClassName() +
        " processes the whole frame, background included";
    }
    else if (oit)
    {
      why = "Translucent geometry without depth peeling (order-independent transparency) "
            "leaves no coverage to put the background under";
    }
    if (!why.empty() && why != this->BackgroundWarning)
    {
      vtkWarningWithObjectMacro(self, << why << ": the background is part of the frame that "
                                      << "blooms (turn on the renderer's UseDepthPeeling, or "
                                      << "put the pass inside the other, to keep it out).");
    }
    this->BackgroundWarning = why;
  }
  vtkSmartPointer<vtkOpenGLFXAAFilter> FXAA; ///< the renderer's FXAA, made on first use

  /**
   * Only light blooms: the emitters whatever their colour (`selective`), not the background,
   * not the annotations (the delegate's overlay, drawn after the composite); translucency and
   * hidden lines as the frame without the pass has them. A layer blooms over the layers below
   * it.
   */
  void PlanWhatBlooms(vtkBloomPass* self, const vtkRenderState* s, bool selective)
  {
    vtkRenderer* r = s->GetRenderer();
    this->Output.GlowAlpha = true;
    this->Light.Threshold = !selective || self->ThresholdEmitters;
    this->Output.Over = r->Transparent();
    this->Report->AnnotationsOverBloom =
      !self->BloomAnnotations && this->Steps.DetachOverlay(self->DelegatePass) > 0;
    // The renderer removes hidden lines and draws translucency through depth peeling or OIT
    // only where it has no pass: where this pass is its own, the pass does it in its place.
    // Inside other passes (PyVista's SSAA, SSAO, ...) the frame without bloom draws them with
    // the plain steps, and so does the scene here.
    bool oit = false;
    if (r->GetPass() == self)
    {
      this->Steps.RemoveHiddenLines(s, self->DelegatePass);
      oit =
        this->Steps.WrapTranslucency(s, self->DelegatePass) == vtkBloomPassSteps::ORDER_INDEPENDENT;
    }
    vtkRenderPass* processing = vtkBloomPassSteps::FindImageProcessing(self->DelegatePass);
    if (!self->BloomBackground && !r->Transparent())
    {
      this->WarnBackgroundInScene(self, oit, processing);
    }
    vtkBloomPassBackground::Plan(this->Resources, r, self->BloomBackground || oit || processing);
  }

  void ApplyFXAA(vtkOpenGLRenderer* renderer)
  {
    if (!this->FXAA)
    {
      this->FXAA = vtkSmartPointer<vtkOpenGLFXAAFilter>::New();
    }
    if (renderer->GetFXAAOptions())
    {
      this->FXAA->UpdateConfiguration(renderer->GetFXAAOptions());
    }
    this->FXAA->Execute(renderer);
  }
  /// The switches that only tests and benchmarks set (vtkBloomPassTesting.h says what each
  /// does).
  struct
  {
    bool SimulateComputeShaderFailure = false;
    int SingleDrawSamples = -1; ///< automatic
    bool FuseSeparablePasses = true;
    bool ProfilePasses = false;
    bool ShareWindowDepth = true;
  } Switches;
  vtkBloomPassDepth Depth; ///< the scene's depth where the frame is composited
  /// The framebuffer the pass was called with (its GL name), whose depth buffer the scene's
  /// render may write (vtkBloomPassDepth::Share), and whether this frame's did: DepthShared
  /// says whether a Depth.Write() is still owed.
  unsigned int CalledFramebuffer = 0;
  bool ShareDepth = false; ///< this frame may share it
  bool DepthShared = false;
  vtkBloomPassFFT FFT;           ///< PSF mode's convolution
  vtkBloomPassPSFSplit PSFSplit; ///< a split PSF's (PSFTailScale > 1, a tail left)
  bool UsePSFSplit = false;      ///< the current PSFs are split

  /// The bloom term of `source` (masked by the emitters' depth with `mask`): the chain, or in
  /// PSF mode the bright pass and its convolution; false when the bloom is skipped.
  bool RunBloom(vtkBloomPass* self, vtkTextureObject* source, bool mask);
  bool RunPSF(vtkBloomPass* self);
  /// PSF mode: the PSFs of the parameters, made again only when they changed.
  bool UpdateKernels(vtkBloomParameters* parameters);
  std::vector<double> KernelsSignature; ///< what the current PSFs were made from
  bool KernelsFailed = false;           ///< they could not be made (the filter said why)
  int KernelsRadius = 0;                ///< the largest PSF's radius
  bool TileWarned = false;              ///< a guard band was cut, said once
  vtkMTimeType KernelsVersion = 0;
  std::string PSFError; ///< the last reason PSF mode could not run, said once

  /// The chain's operators are about to change: what the runner and the FFT blur made of them
  /// goes.
  void ReleaseOperators(vtkWindow* w)
  {
    this->Runner.ReleaseOperators(w);
    this->FFTBlur.ReleaseOperators();
  }

  bool Prepare(vtkBloomPass* self, vtkOpenGLRenderWindow* window, int w, int h, int samples,
    bool emitters, int precision);

  /// What one Render() decides at its top, and its steps read.
  struct Frame
  {
    int X = 0, Y = 0, Width = 0, Height = 0; ///< the renderer's part of the framebuffer
    vtkProp** Props = nullptr;               ///< what the scene's render shows (a tile's own)
    int Count = 0;
    bool Selective = false;  ///< only the emitters bloom
    bool InScene = false;    ///< their emission written in the scene's own render
    bool TwoRenders = false; ///< the emitters rendered again, on their own
    bool FXAA = false;       ///< the renderer's FXAA, applied by this pass
  };
  /// The frame's plan, the targets made ready for it; false where it cannot bloom (said).
  bool PlanFrame(
    vtkBloomPass* self, const vtkRenderState* s, vtkOpenGLRenderWindow* window, Frame& frame);
  /// Render()'s steps, in their order.
  void RenderScene(vtkBloomPass* self, const vtkRenderState* s, const Frame& frame);
  bool BloomIntoTargets(vtkBloomPass* self, vtkOpenGLState* state, const Frame& frame);
  void CompositeIntoFramebuffer(
    vtkBloomPass* self, vtkOpenGLRenderWindow* window, const Frame& frame, bool bloom);
  void FinishFrame(vtkBloomPass* self, const vtkRenderState* s, const Frame& frame);

  /// The part of the frame the coming render renders: the renderer's tiled size, or, in a
  /// tiled frame (SeamlessTiles), the tile and its guard band.
  vtkBloomPassTile Tile;
  vtkBloomPassTileFrame TileFrame; ///< the chain of the whole tiled frame
  void PlanTile(vtkBloomPass* self, vtkRenderer* r, int w, int h, vtkProp**& props, int& count);

  // KEPT_FRAME_SERVE: this render is a tile of the frame that starts at ServedAt in a frame of
  // ServedFrame's size (no guard band: its part of the kept frame is written instead).
  bool Serving = false;
  int ServedAt[2] = { 0, 0 };
  int ServedFrame[2] = { 0, 0 };
  bool ServeWarned = false; ///< no frame of the tiles' size was kept, said once
  /**
   * The kept frame (KEPT_FRAME_KEEP): the renderer's pixels after the composite, read back to
   * float RGBA, so that it outlives the context (an OSMesa window's resize makes a new one and
   * releases every resource first). Staging (Resources.Kept) takes a tile's part of it back to
   * the GPU, or the framebuffer's pixels on their way here (a multisampled one is resolved).
   */
  vtkSmartPointer<vtkImageData> KeptImage;
  void KeepFramebuffer(vtkOpenGLState* state, int x, int y, int w, int h)
  {
    vtkBloomPassResources& res = this->Resources;
    vtkBloomPassTarget& staging = res.Kept;
    staging.Allocate(res.Context, w, h, GL_RGBA32F);
    GLint framebuffer = 0, buffer = GL_BACK;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &framebuffer);
    glGetIntegerv(GL_DRAW_BUFFER0, &buffer);
    state->PushFramebufferBindings();
    state->vtkglBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<unsigned int>(framebuffer));
    state->vtkglReadBuffer(static_cast<unsigned int>(buffer));
    staging.FBO->Bind(GL_DRAW_FRAMEBUFFER);
    staging.FBO->ActivateDrawBuffer(0);
    glBlitFramebuffer(x, y, x + w, y + h, 0, 0, w, h, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    state->PopFramebufferBindings();
    this->KeptImage = vtkSmartPointer<vtkImageData>::New();
    staging.Read(res.Context, this->KeptImage);
  }

  /**
   * Step 2 of Render(), while the pass's own targets are bound: the chain (or PSF mode's
   * convolution), and with CaptureResult the composite into the result target. Returns whether
   * it bloomed (false where the bloom was skipped).
   */
  bool RunChain(vtkBloomPass* self, bool inScene, bool twoRenders);
  /**
   * Step 3, into the framebuffer the pass was called with (at x, y): the composite of the scene
   * and `bloom`, or with CaptureResult the result's copy; then the edge samples.
   */
  void Composite(vtkBloomPass* self, int x, int y, bool bloom);
  /// KEPT_FRAME_SERVE: the tile's part of the kept frame uploaded to the staging target, and
  /// true; false, with nothing done, where it cannot. ServeTile() then copies it to (x, y).
  bool StageServedTile(vtkBloomPass* self, int w, int h);
  void ServeTile(int x, int y);

  /**
   * The renderer culled its props against the tile's frustum, before the pass could widen it:
   * a tile with a guard band shows every visible prop instead (the camera pass's delegate
   * draws what lies outside the band as any render does, clipped).
   */
  std::vector<vtkProp*> TileProps;
  std::vector<vtkProp*> Volumes; ///< the volumes of the scene's render (RenderDelegate)
  void PropsOfTile(vtkRenderer* r, vtkProp**& props, int& count)
  {
    if (this->Tile.Size[0] == this->Tile.TileSize[0] &&
      this->Tile.Size[1] == this->Tile.TileSize[1])
    {
      return;
    }
    this->TileProps.clear();
    vtkPropCollection* all = r->GetViewProps();
    vtkCollectionSimpleIterator it;
    all->InitTraversal(it);
    while (vtkProp* prop = all->GetNextProp(it))
    {
      if (prop->GetVisibility())
      {
        this->TileProps.push_back(prop);
      }
    }
    props = this->TileProps.data();
    count = static_cast<int>(this->TileProps.size());
  }

  /// What the delegate renders: the scene, the scene and its emission, or the emitters alone.
  enum Content
  {
    SCENE,
    SCENE_AND_EMISSION,
    EMITTERS
  };
  void RenderDelegate(vtkBloomPass* self, const vtkRenderState* s, vtkBloomPassSceneTarget& target,
    vtkProp** props, int count, Content content);

  /// What the frame did (GetLastFrame), the pass's only record of it.
  vtkNew<vtkBloomFrameReport> Report;
  /// The chain's figures, into the report, after the composite.
  void ReportChain()
  {
    vtkBloomFrameReport* report = this->Report;
    const int* region = this->Runner.GetBrightRegion();
    std::copy(region, region + 4, report->BrightRegion);
    report->ChainCoverage = this->Runner.GetCoverage();
    report->ComputePasses = this->Runner.GetComputePasses();
    report->NumberOfPasses = this->Runner.GetPasses();
    this->ReportTimes();
  }
  void ReportTimes()
  {
    vtkBloomFrameReport* report = this->Report;
    report->ChainMilliseconds = this->Runner.GetLastChainMilliseconds();
    report->RegionCost = this->Runner.GetRegionCost();
    report->FullCost = this->Runner.GetFullCost();
  }

  /// Release everything in the context of the window that holds it, if it is still alive,
  /// and make current again the context that was (vtkOpenGLRenderWindow::PushContext).
  void ReleaseInContext()
  {
    vtkOpenGLRenderWindow* window = this->Resources.Context;
    if (window)
    {
      window->PushContext();
      this->ReleaseAll(window);
      window->PopContext();
    }
  }

  void ReleaseAll(vtkWindow* w)
  {
    if (this->FXAA)
    {
      this->FXAA->ReleaseGraphicsResources();
    }
    this->Steps.ReleaseGraphicsResources(w);
    this->Depth.ReleaseGraphicsResources(w);
    this->FFT.ReleaseGraphicsResources(w);
    this->PSFSplit.ReleaseGraphicsResources(w);
    this->Runner.ReleaseGraphicsResources(w);
    this->Profiler.ReleaseGraphicsResources();
    this->FFTBlur.ReleaseGraphicsResources(w);
    this->Resources.ReleaseAll(w);
  }
};

#endif
// VTK-HeaderTest-Exclude: vtkBloomPassInternals.h
