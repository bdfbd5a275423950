// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// vtkBloomPass's implementation: the render (scene, chain, composite, overlay) and its
// internals, the kept frame of tiled screenshots (KeptFrameMode), the image entry points
// (ApplyToImage, the read-backs) and the parameter plumbing.
// The steps with a seam of their own live beside it (vtkBloomPassResources, ...ChainRunner,
// ...Background, ...Steps, ...Emission, ...FFT, ...PSFSplit); what stays here (PSF mode's choice
// between the exact and the split convolution among it) shares the pass's protected
// state, which is why the file passes 800 lines.
#include "vtkBloomPass.h"

#include "vtkBloomPassBackground.h"
#include "vtkBloomPassChainRunner.h"
#include "vtkBloomPassDepth.h"
#include "vtkBloomPassEmission.h"
#include "vtkBloomPassFFT.h"
#include "vtkBloomPassPSFSplit.h"
#include "vtkBloomPassResources.h"
#include "vtkBloomPassSteps.h"
#include "vtkBloomPassTile.h"
#include "vtkBloomVTKCompat.h"
#include "vtkDataArray.h"
#include "vtkImageBloom.h"
#include "vtkImageData.h"
#include "vtkImageSeparableGaussian.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLFXAAFilter.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOpenGLState.h"
#include "vtkPointData.h"
#include "vtkProp.h"
#include "vtkPropCollection.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkTextureObject.h"

#include <algorithm>
#include <cmath>
#include <vector>

vtkStandardNewMacro(vtkBloomPass);

namespace
{
// The part of the framebuffer the pass was called with that it renders: the renderer's tile of
// the window, or, where a pass above it renders into a framebuffer of its own (vtkSSAAPass at a
// larger size), the whole of that framebuffer, as vtkCameraPass does.
void RenderedPart(const vtkRenderState* s, int& x, int& y, int& w, int& h)
{
  x = y = 0;
  if (s->GetFrameBuffer())
  {
    int size[2];
    s->GetWindowSize(size);
    w = size[0];
    h = size[1];
  }
  else
  {
    s->GetRenderer()->GetTiledSizeAndOrigin(&w, &h, &x, &y);
  }
}

// A scene read back from a render that wrote its emission in the alpha (an emitting fragment
// has alpha 1 + weight, vtkBloomPassEmission): the scene, with its alpha at most 1, or
// (`emission`) the emission, the colour times the weight.
void vtkBloomPassDecodeEmission(vtkImageData* image, bool emission)
{
  float* rgba = static_cast<float*>(image->GetScalarPointer());
  for (vtkIdType p = 0; p < image->GetNumberOfPoints(); ++p, rgba += 4)
  {
    const float weight = std::min(std::max(rgba[3] - 1.0f, 0.0f), 1.0f);
    for (int c = 0; emission && c < 3; ++c)
    {
      rgba[c] *= weight;
    }
    rgba[3] = emission ? weight : std::min(rgba[3], 1.0f);
  }
}
}

//------------------------------------------------------------------------------
// The render-pass side of the internals: the GL resources and the chain runner that draws into
// them, and the steps of Render() that need the pass's protected members.
class vtkBloomPass::vtkInternals
{
public:
  explicit vtkInternals(vtkBloomPass* owner)
    : Runner(owner, Resources)
  {
  }

  vtkBloomPassResources Resources;
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
    self->LastAnnotationsOverBloom =
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
  vtkBloomPassDepth Depth;       ///< the scene's depth, written where the frame is composited
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

  bool Prepare(vtkBloomPass* self, vtkOpenGLRenderWindow* window, int w, int h, int samples,
    bool emitters, int precision);

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

  // The last evaluation's content-aware figures.
  void Report(vtkBloomPass* self)
  {
    const int* region = this->Runner.GetBrightRegion();
    std::copy(region, region + 4, self->LastBrightRegion);
    self->LastChainCoverage = this->Runner.GetCoverage();
    self->LastComputePasses = this->Runner.GetComputePasses();
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
    this->Resources.ReleaseAll(w);
  }
};

//------------------------------------------------------------------------------
bool vtkBloomPass::vtkInternals::Prepare(vtkBloomPass* self, vtkOpenGLRenderWindow* window, int w,
  int h, int samples, bool emitters, int precision)
{
  vtkBloomPassResources& res = this->Resources;
  if (res.Context && res.Context != window)
  {
    self->ReleaseGraphicsResources(res.Context);
  }
  res.Context = window;
  self->LastFloatPrecision = precision;
  const unsigned int format = precision == FLOAT32 ? GL_RGBA32F : GL_RGBA16F;
  if (format != res.Format)
  {
    this->ReleaseAll(window);
    res.Context = window;
    res.Format = format;
  }
  vtkBloomPassChainRunner::Settings settings;
  settings.Parameters = self->Parameters;
  settings.Restrict = self->Parameters->GetRestrictToBrightRegion();
  settings.UseCompute = self->UseComputeShaders;
  settings.SimulateComputeFailure = self->SimulateComputeShaderFailure;
  settings.SingleDrawSamples = self->SingleDrawSamples;
  settings.FuseSeparablePasses = self->FuseSeparablePasses;
  settings.Profiling = self->ProfilePasses;
  this->Runner.BeginFrame(settings);
  // An image (ApplyToImage): thresholded whole, its own background, into its own target.
  this->Light.InAlpha = false;
  this->Light.Threshold = true;
  this->Output.EmissionInAlpha = false;
  this->Output.Over = false;
  res.BackgroundMode = vtkBloomPassResources::BACKGROUND_IN_SCENE;
  res.AllocateScene(w, h, emitters, samples);
  this->Output.PSFBloom = nullptr;
  if (self->Parameters->GetBloomMode() == vtkBloomParameters::BLOOM_PSF)
  {
    // PSF mode builds no chain: its bright pass and bloom are full-size targets.
    if (res.ChainTime != 0)
    {
      this->Runner.ReleaseOperators(window);
      res.ReleaseChain(window);
    }
    res.PSFBright.Allocate(window, w, h, GL_RGBA32F);
    res.PSFBloom.Allocate(window, w, h, GL_RGBA32F);
    this->Output.PSFBloom = &res.PSFBloom;
    return true;
  }
  res.PSFBright.Release(window);
  res.PSFBloom.Release(window);
  // A tile of a tiled frame: the frame's chain cut to the part rendered.
  int part[4] = { 0, 0, 0, 0 };
  const bool tiled = this->Tile.Tiled;
  if (tiled)
  {
    this->Tile.GetPart(part);
  }
  if (res.ChainIsStale(self->Parameters, w, h, part))
  {
    // The runner's operator textures belong to the chain about to be rebuilt.
    this->Runner.ReleaseOperators(window);
    res.BuildChain(self->Parameters, w, h, tiled ? &this->TileFrame.Chain : nullptr, part);
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkBloomPass::vtkInternals::PlanTile(
  vtkBloomPass* self, vtkRenderer* r, int w, int h, vtkProp**& props, int& count)
{
  vtkBloomPassTile& tile = this->Tile;
  tile.Locate(r, w, h);
  std::fill(this->Output.Window, this->Output.Window + 4, 0);
  std::fill(self->LastTileGuardBand, self->LastTileGuardBand + 2, 0);
  this->Serving = tile.Tiled && self->KeptFrameMode == KEPT_FRAME_SERVE;
  if (this->Serving)
  {
    std::copy(tile.GetPosition(), tile.GetPosition() + 2, this->ServedAt);
    std::copy(tile.Frame, tile.Frame + 2, this->ServedFrame);
  }
  if (!tile.Tiled || !self->SeamlessTiles || this->Serving)
  {
    tile = vtkBloomPassTile();
    tile.TileSize[0] = tile.Size[0] = w;
    tile.TileSize[1] = tile.Size[1] = h;
    return;
  }
  // The frame's samples that the tile's bloom reads.
  const int* at = tile.GetPosition();
  int first[2], last[2];
  vtkBloomParameters* parameters = self->Parameters;
  const bool psf = parameters->GetBloomMode() == vtkBloomParameters::BLOOM_PSF;
  if (!psf)
  {
    this->TileFrame.Update(parameters, tile.Frame);
  }
  // In PSF mode, the PSF's radius (full resolution, no pyramid).
  const int radius = psf && this->UpdateKernels(parameters) ? this->KernelsRadius : 0;
  for (int a = 0; a < 2; ++a)
  {
    if (psf)
    {
      first[a] = at[a] - radius;
      last[a] = at[a] + tile.TileSize[a] + radius;
    }
    else
    {
      this->TileFrame.Chain.GetInputRange(
        a, at[a], at[a] + tile.TileSize[a] - 1, first[a], last[a]);
      ++last[a];
    }
  }
  GLint largest = 0, viewport[2] = { 0, 0 };
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &largest);
  glGetIntegerv(GL_MAX_VIEWPORT_DIMS, viewport);
  tile.Plan(first, last, std::min({ largest, viewport[0], viewport[1] }));
  if (tile.Capped && !this->TileWarned)
  {
    vtkWarningWithObjectMacro(self, << "A tile and the samples its glow reads ("
                                    << last[0] - first[0] << " x " << last[1] - first[1]
                                    << ") exceed the context's largest target (" << largest
                                    << "): the glow may show seams at tile edges.");
    this->TileWarned = true;
  }
  int* window = this->Output.Window;
  window[0] = tile.Inner[0];
  window[1] = tile.Inner[0] + tile.TileSize[0];
  window[2] = tile.Inner[1];
  window[3] = tile.Inner[1] + tile.TileSize[1];
  self->LastTileGuardBand[0] = tile.Size[0] - w;
  self->LastTileGuardBand[1] = tile.Size[1] - h;
  this->PropsOfTile(r, props, count);
}

//------------------------------------------------------------------------------
bool vtkBloomPass::vtkInternals::RunBloom(vtkBloomPass* self, vtkTextureObject* source, bool mask)
{
  self->LastPSFGrid[0] = self->LastPSFGrid[1] = 0;
  // A multisampled scene's samples, for a bright pass that thresholds each (the runner's bright
  // pass says where it applies: whole-scene bloom, with a threshold).
  const vtkBloomPassResources& res = this->Resources;
  this->Light.Emission = source;
  this->Light.Mask = mask;
  this->Light.Samples =
    self->ThresholdSamples && res.Samples > 1 ? res.Multisample.Color.Get() : nullptr;
  this->Light.SampleCount = res.Samples;
  if (self->Parameters->GetBloomMode() == vtkBloomParameters::BLOOM_PSF)
  {
    return this->RunPSF(self);
  }
  return this->Runner.Run(this->Light);
}

//------------------------------------------------------------------------------
bool vtkBloomPass::vtkInternals::UpdateKernels(vtkBloomParameters* parameters)
{
  // Only the parameters the PSFs depend on: a strength or threshold slider must not remake an
  // Airy pattern (seconds for a wide one) and its spectra every frame.
  vtkImageData* image = parameters->GetPSFImage();
  const double* wavelengths = parameters->GetWavelengths();
  std::vector<double> signature = { static_cast<double>(parameters->GetPSFType()),
    static_cast<double>(parameters->GetPSFRadius()), parameters->GetAiryRadius(), wavelengths[0],
    wavelengths[1], wavelengths[2], image ? static_cast<double>(image->GetMTime()) : -1.0,
    static_cast<double>(parameters->GetPSFTailScale()),
    static_cast<double>(parameters->GetEffectivePSFCoreRadius()) };
  for (const auto* values :
    { &parameters->GetPSFGaussianSigmas(), &parameters->GetPSFGaussianWeights() })
  {
    signature.push_back(static_cast<double>(values->size()));
    signature.insert(signature.end(), values->begin(), values->end());
  }
  if (signature == this->KernelsSignature && this->KernelsVersion != 0)
  {
    return !this->KernelsFailed;
  }
  this->KernelsSignature = signature;
  // The CPU filter's own PSFs (vtkImageBloom::ComputePSF), which report invalid parameters.
  vtkNew<vtkImageBloom> filter;
  filter->SetParameters(parameters);
  vtkBloomPassFFT::Kernel kernels[3];
  ++this->KernelsVersion;
  this->KernelsFailed = false;
  this->KernelsRadius = 0;
  for (int c = 0; c < 3; ++c)
  {
    kernels[c].Values = filter->ComputePSF(c, kernels[c].Radius);
    if (kernels[c].Values.empty())
    {
      this->KernelsFailed = true;
      return false;
    }
    this->KernelsRadius = std::max(this->KernelsRadius, kernels[c].Radius);
  }
  // Split (as the CPU filter splits them) where a tail is left; else the exact convolution.
  this->UsePSFSplit = false;
  if (parameters->GetPSFTailScale() > 1)
  {
    vtkBloomPSFSplit splits[3];
    for (int c = 0; c < 3; ++c)
    {
      splits[c] = vtkBloomPSFSplit::Make(
        kernels[c], parameters->GetPSFTailScale(), parameters->GetEffectivePSFCoreRadius());
      this->UsePSFSplit = this->UsePSFSplit || splits[c].HasTail();
    }
    if (this->UsePSFSplit)
    {
      this->PSFSplit.SetKernels(splits, this->KernelsVersion);
      return true;
    }
  }
  this->FFT.SetKernels(kernels, this->KernelsVersion);
  return true;
}

//------------------------------------------------------------------------------
bool vtkBloomPass::vtkInternals::RunPSF(vtkBloomPass* self)
{
  // Where PSF mode cannot run (no compute shaders, a grid too large, invalid PSFs) the scene
  // renders without bloom, and the reason is reported once.
  vtkBloomPassResources& res = this->Resources;
  if (!this->UpdateKernels(self->Parameters))
  {
    return false;
  }
  std::string why;
  if (self->SimulateComputeShaderFailure)
  {
    why = "PSF bloom's compute programs did not build (simulated for a test).";
  }
  // The other convolution's buffers go (a frame-wide PSF's exact grid holds 1.3 GB).
  if (this->UsePSFSplit && this->FFT.GetGridSize()[0] != 0)
  {
    this->FFT.ReleaseGraphicsResources(res.Context);
  }
  else if (!this->UsePSFSplit && this->PSFSplit.GetGridSize()[0] != 0)
  {
    this->PSFSplit.ReleaseGraphicsResources(res.Context);
  }
  const int* size = res.PSFBright.Size;
  if (!why.empty() ||
    !(this->UsePSFSplit ? this->PSFSplit.Prepare(res.Context, size[0], size[1], why)
                        : this->FFT.Prepare(res.Context, size[0], size[1], why)))
  {
    if (why != this->PSFError)
    {
      vtkErrorWithObjectMacro(self, << why << " The scene renders without bloom.");
      this->PSFError = why;
    }
    return false;
  }
  this->PSFError.clear();
  const int* grid = this->UsePSFSplit ? this->PSFSplit.GetGridSize() : this->FFT.GetGridSize();
  std::copy(grid, grid + 2, self->LastPSFGrid);
  if (!this->Runner.BrightPassPSF(this->Light, res.PSFBright))
  {
    return false;
  }
  // With ProfilePasses each stage of the convolution is a profiled span, sized as the grid.
  vtkBloomPassFFT::StageTimer timer;
  timer.Begin = [this] { this->Runner.BeginProfiledSpan(); };
  timer.End = [this, grid](const char* name, double bytes)
  { this->Runner.EndProfiledSpan(name, grid[0], grid[1], bytes); };
  const bool reflect = self->Parameters->GetPSFBorderMode() == vtkImageSeparableGaussian::REFLECT;
  vtkBloomPassFFT::StageTimer* stages = self->ProfilePasses ? &timer : nullptr;
  if (this->UsePSFSplit)
  {
    this->PSFSplit.Convolve(res.PSFBright.Color, res.PSFBloom.Color, reflect, stages);
  }
  else
  {
    this->FFT.Convolve(res.PSFBright.Color, res.PSFBloom.Color, reflect, stages);
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkBloomPass::vtkInternals::RenderDelegate(vtkBloomPass* self, const vtkRenderState* s,
  vtkBloomPassSceneTarget& target, vtkProp** props, int count, Content content)
{
  vtkRenderer* r = s->GetRenderer();
  vtkOpenGLState* state = this->Resources.Context->GetState();
  vtkRenderState s2(r);
  s2.SetPropArrayAndCount(props, count);
  // Multisampled, the delegate renders into the multisampled target, resolved once below.
  vtkBloomPassMultisampleTarget& multisample = this->Resources.Multisample;
  vtkOpenGLFramebufferObject* fbo = this->Resources.Samples ? multisample.FBO : target.FBO;
  s2.SetFrameBuffer(fbo);
  fbo->Bind();
  fbo->ActivateDrawBuffer(0);
  state->vtkglViewport(0, 0, target.Size[0], target.Size[1]);
  state->vtkglScissor(0, 0, target.Size[0], target.Size[1]);

  // Emitters shine on black, and the scene renders over transparent black unless its
  // background blooms: the composite puts it over the background (vtkBloomPassBackground).
  const vtkBloomPassHiddenBackground hidden(r,
    content == EMITTERS ||
      this->Resources.BackgroundMode != vtkBloomPassResources::BACKGROUND_IN_SCENE);
  if (r->Transparent() || content == EMITTERS)
  {
    // The camera pass does not clear layered renderers; an offscreen target must start empty.
    state->vtkglClearColor(0.0, 0.0, 0.0, 0.0);
    state->vtkglClearDepth(1.0);
    state->vtkglDepthMask(GL_TRUE);
    state->vtkglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  }
  state->vtkglEnable(GL_DEPTH_TEST);
  // The emission's shader replacement. In the scene's render it raises the alpha of an
  // emitting fragment above 1, which blending would mix into the colour: every prop is opaque
  // there (vtkBloomPassEmission::Plan), so blending changes nothing else and is off.
  const bool emission = content != SCENE;
  this->Emission.EmittersAlone = content == EMITTERS;
  if (emission)
  {
    self->PreRender(&s2);
  }
  if (content == SCENE_AND_EMISSION)
  {
    state->vtkglDisable(GL_BLEND);
  }
  {
    const vtkBloomPassSteps::RendererFXAAOff noFXAA(r);
    const vtkBloomPassTileCamera part(r, this->Tile);
    self->DelegatePass->Render(&s2);
  }
  if (emission)
  {
    self->PostRender(&s2);
  }
  if (this->Resources.Samples)
  {
    multisample.Resolve(this->Resources.Context, target);
  }
  if (content != EMITTERS)
  {
    self->NumberOfRenderedProps += self->DelegatePass->GetNumberOfRenderedProps();
  }
}

//------------------------------------------------------------------------------
vtkBloomPass::vtkBloomPass()
  : Parameters(vtkSmartPointer<vtkBloomParameters>::New())
  , Emitters(vtkPropCollection::New())
  , FloatPrecision(FLOAT_AUTOMATIC)
  , EmissionSource(EMISSION_SCENE)
  , UseComputeShaders(true)
  , LastComputePasses(0)
  , CaptureResult(false)
  , LastBrightRegion{ 0, 0, 0, 0 }
  , LastChainCoverage(1.0)
  , LastPSFGrid{ 0, 0 }
  , NumberOfPasses(0)
  , LastBloomSkipped(false)
  , ProfilePasses(false)
  , Internals(new vtkInternals(this))
{
}

//------------------------------------------------------------------------------
vtkBloomPass::~vtkBloomPass()
{
  this->Emitters->Delete();
}

//------------------------------------------------------------------------------
void vtkBloomPass::SetParameters(vtkImageBloom* filter)
{
  this->SetParameters(filter ? filter->GetParameters() : nullptr);
}

//------------------------------------------------------------------------------
void vtkBloomPass::SetParameters(vtkBloomParameters* parameters)
{
  if (!parameters)
  {
    vtkErrorMacro(<< "The bloom parameters cannot be null.");
    return;
  }
  if (this->Parameters != parameters)
  {
    this->Parameters = parameters;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkBloomPass::SetFloatPrecision(int bits)
{
  if (bits != FLOAT_AUTOMATIC && bits != FLOAT16 && bits != FLOAT32)
  {
    vtkErrorMacro(<< "FloatPrecision must be 0 (automatic), 16 or 32, not " << bits << ".");
    return;
  }
  if (bits != this->FloatPrecision)
  {
    this->FloatPrecision = bits;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
bool vtkBloomPass::SetPreset(const char* name)
{
  const std::string error = vtkBloomParameters::CheckPresetName(name);
  if (!error.empty())
  {
    vtkErrorMacro(<< error);
    return false;
  }
  return this->Parameters->SetPreset(name);
}

//------------------------------------------------------------------------------
void vtkBloomPass::Render(const vtkRenderState* s)
{
  vtkOpenGLClearErrorMacro();
  this->NumberOfRenderedProps = 0;
  this->NumberOfPasses = 0;
  if (!this->DelegatePass)
  {
    vtkWarningMacro(<< "No delegate in vtkBloomPass.");
    return;
  }
  vtkRenderer* r = s->GetRenderer();
  if (r->GetSelector())
  {
    // Hardware picking renders ids as colours, and only the renderer's own path tells the
    // selector which prop it draws (a pass, this one's delegate included, does not): the ids
    // reach the selector through that path, untouched.
    vtkSmartPointer<vtkRenderPass> keep(this); // the renderer may hold the only reference
    r->SetPass(nullptr);
    r->DeviceRender();
    r->SetPass(this);
    return;
  }
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(r->GetRenderWindow());
  if (!window)
  {
    vtkErrorMacro(<< "vtkBloomPass needs a vtkOpenGLRenderWindow.");
    return;
  }
  int x, y, w, h;
  RenderedPart(s, x, y, w, h);
  if (w <= 0 || h <= 0)
  {
    return;
  }
  vtkOpenGLState* state = window->GetState();
  const vtkBloomPassSavedState saved(state);
  vtkInternals& in = *this->Internals;
  vtkBloomPassResources& res = in.Resources;
  // Multisampling is kept: where the framebuffer the pass was called with has samples, the
  // scene renders with as many.
  GLint samples = 0;
  glGetIntegerv(GL_SAMPLES, &samples);
  // The part rendered: the renderer's tile, with its guard band where the frame is tiled, and
  // the props it shows.
  vtkProp** props = s->GetPropArray();
  int count = s->GetPropArrayCount();
  in.PlanTile(this, r, w, h, props, count);
  const vtkBloomPassTile& tile = in.Tile;
  // Selective bloom: in the scene's own render where it can be, else the emitters again.
  const bool selective = this->EmissionSource == EMISSION_EMITTERS;
  const bool inScene = selective &&
    in.Emission.Plan(this->Emitters, props, count, this->DelegatePass, this->EmitInSceneRender);
  this->LastEmissionInSceneRender = inScene;
  // The renderer's FXAA, applied here, or a pass around this one processes the frame further.
  const bool fxaa = r->GetUseFXAA() && r->GetPass() == this;
  const bool processed = fxaa || r->GetPass() != this;
  const int precision = this->FloatPrecision != FLOAT_AUTOMATIC ? this->FloatPrecision
    : processed                                                 ? FLOAT32
                                                                : FLOAT16;
  if (!in.Prepare(
        this, window, tile.Size[0], tile.Size[1], samples, selective && !inScene, precision))
  {
    return;
  }
  in.PlanWhatBlooms(this, s, selective);
  if (this->CaptureResult)
  {
    res.Result.Allocate(window, w, h, GL_RGBA32F);
  }

  // 1. The scene (and, in one render, its emission), then any emitters on their own, in float.
  state->PushFramebufferBindings();
  // The delegate writes the float colour and a 32-bit depth once (the profile's lower bound).
  const double sceneBytes = (res.Format == GL_RGBA32F ? 20.0 : 12.0) * w * h;
  if (this->ProfilePasses)
  {
    in.Runner.BeginProfiledSpan();
  }
  in.RenderDelegate(this, s, res.Scene, props, count,
    inScene ? vtkInternals::SCENE_AND_EMISSION : vtkInternals::SCENE);
  if (res.BackgroundMode == vtkBloomPassResources::BACKGROUND_TEXTURE)
  {
    vtkBloomPassBackground::Draw(res, r, x, y, w, h);
  }
  this->SceneRendered(s, res.Scene.Color);
  if (this->ProfilePasses)
  {
    in.Runner.EndProfiledSpan("scene", w, h, sceneBytes);
  }
  if (selective && !inScene)
  {
    std::vector<vtkProp*>& emitters = in.Emission.SecondRender;
    if (this->ProfilePasses)
    {
      in.Runner.BeginProfiledSpan();
    }
    in.RenderDelegate(this, s, res.Emitter, emitters.data(), static_cast<int>(emitters.size()),
      vtkInternals::EMITTERS);
    if (this->ProfilePasses)
    {
      in.Runner.EndProfiledSpan("emitters", w, h, sceneBytes);
    }
  }

  // 2. The chain into the pass's own targets; for a tile of a kept frame (KeptFrameMode), that
  // frame's part staged instead. 3. Then into the framebuffer the pass was called with.
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDisable(GL_SCISSOR_TEST);
  const bool twoRenders = selective && !inScene;
  this->LastTileFromKeptFrame = in.StageServedTile(this, w, h);
  const bool bloom = !this->LastTileFromKeptFrame && in.RunChain(this, inScene, twoRenders);
  state->PopFramebufferBindings();
  if (this->LastTileFromKeptFrame)
  {
    in.ServeTile(x, y);
  }
  else
  {
    in.Composite(this, x, y, bloom);
  }
  if (this->KeptFrameMode == KEPT_FRAME_KEEP)
  {
    in.KeepFramebuffer(state, x, y, w, h);
  }
  // The scene's depth under the composited frame, for what reads it next: the annotations (a
  // label mapper hides the labels of points the scene covers), a pass around this one.
  in.Depth.Write(window, res.Scene.Depth, x, y, w, h, tile.Inner);
  // The renderer's viewport again (the scene's render had the part's, a tile with its band),
  // for what follows and reads it: the FXAA, the annotations.
  state->vtkglViewport(x, y, w, h);
  state->vtkglScissor(x, y, w, h);
  // 4. The renderer's FXAA, which VTK applies only where a renderer has no pass: where this
  // pass is the renderer's, as the renderer applies it, to the frame without its annotations.
  // Inside other passes (ParaView's own FXAA pass, a tone mapping) FXAA is theirs to apply.
  if (fxaa)
  {
    in.ApplyFXAA(static_cast<vtkOpenGLRenderer*>(r));
  }
  // 5. The annotations, over the bloom; the delegate's steps as they were.
  this->NumberOfRenderedProps += in.Steps.RenderOverlay(s, x, y, w, h);
  in.Report(this);
  this->NumberOfPasses = in.Runner.GetPasses();
  if (this->ProfilePasses)
  {
    in.Runner.ResolveProfile();
  }
  vtkOpenGLCheckErrorMacro("failed after vtkBloomPass::Render");
}

//------------------------------------------------------------------------------
bool vtkBloomPass::vtkInternals::RunChain(vtkBloomPass* self, bool inScene, bool twoRenders)
{
  vtkBloomPassResources& res = this->Resources;
  // In one render the emission is the scene's colour where its alpha says so.
  this->Light.InAlpha = inScene;
  this->Output.EmissionInAlpha = inScene;
  const bool bloom =
    this->RunBloom(self, twoRenders ? res.Emitter.Color : res.Scene.Color, twoRenders);
  self->LastBloomSkipped = !bloom;
  // Into a multisampled framebuffer, the samples at anti-aliased edges are then composited from
  // the scene's own samples, as the renderer would have drawn them
  // (vtkBloomPassChainRunner::Output::SceneSamples). With two renders the multisampled target
  // last held the emitters: the resolved scene only.
  this->Output.SceneSamples =
    res.Samples > 1 && !twoRenders ? res.Multisample.Color.Get() : nullptr;
  this->Output.SceneSampleCount = res.Samples;
  if (self->CaptureResult)
  {
    // The result's first sample is the tile's.
    const int zero[2] = { -this->Tile.Inner[0], -this->Tile.Inner[1] };
    this->Runner.Composite(this->Output, &res.Result, zero, bloom);
  }
  return bloom;
}

//------------------------------------------------------------------------------
void vtkBloomPass::vtkInternals::Composite(vtkBloomPass* self, int x, int y, bool bloom)
{
  // The composite writes the tile only (Output.Window): its first sample lands at the
  // viewport's corner.
  const int shifted[2] = { x - this->Tile.Inner[0], y - this->Tile.Inner[1] };
  if (self->CaptureResult)
  {
    const int origin[2] = { x, y };
    this->Runner.Copy(this->Output, nullptr, origin, this->Resources.Result);
    this->Runner.CompositeEdges(this->Output, shifted, bloom);
  }
  else
  {
    this->Runner.Composite(this->Output, nullptr, shifted, bloom);
  }
}

//------------------------------------------------------------------------------
bool vtkBloomPass::vtkInternals::StageServedTile(vtkBloomPass* self, int w, int h)
{
  if (!this->Serving)
  {
    return false;
  }
  const int* at = this->ServedAt;
  const int* frame = this->ServedFrame;
  const int* kept = this->KeptImage ? this->KeptImage->GetDimensions() : nullptr;
  if (!kept || kept[0] != frame[0] || kept[1] != frame[1] || at[0] + w > frame[0] ||
    at[1] + h > frame[1])
  {
    if (!this->ServeWarned)
    {
      vtkWarningWithObjectMacro(self, << "KeptFrameMode is SERVE, but no frame of " << frame[0]
                                      << " x " << frame[1] << " is kept: the tile blooms alone.");
      this->ServeWarned = true;
    }
    return false;
  }
  // The tile's part of the kept frame, rows of the frame's width, into the staging target...
  vtkBloomPassTarget& staging = this->Resources.Kept;
  staging.Allocate(this->Resources.Context, w, h, GL_RGBA32F);
  const float* first = static_cast<const float*>(this->KeptImage->GetScalarPointer()) +
    4 * (static_cast<size_t>(at[1]) * frame[0] + at[0]);
  staging.Color->Activate(); // rows of RGBA floats are 16-byte aligned: any unpack alignment
  glPixelStorei(GL_UNPACK_ROW_LENGTH, frame[0]);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, w, h, GL_RGBA, GL_FLOAT, first);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  staging.Color->Deactivate();
  self->LastBloomSkipped = false;
  return true;
}

//------------------------------------------------------------------------------
void vtkBloomPass::vtkInternals::ServeTile(int x, int y)
{
  // ... then over the tile's pixels, replacing them (the kept pixels hold what lay below).
  vtkBloomPassChainRunner::Output replace = this->Output;
  replace.Over = false;
  const int origin[2] = { x, y };
  this->Runner.Copy(replace, nullptr, origin, this->Resources.Kept);
}

//------------------------------------------------------------------------------
void vtkBloomPass::SetKeptFrameMode(int mode)
{
  if (mode != KEPT_FRAME_OFF && mode != KEPT_FRAME_KEEP && mode != KEPT_FRAME_SERVE)
  {
    vtkErrorMacro(<< "KeptFrameMode must be 0 (off), 1 (keep) or 2 (serve), not " << mode << ".");
    return;
  }
  if (mode != this->KeptFrameMode)
  {
    this->KeptFrameMode = mode;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkBloomPass::ReleaseKeptFrame()
{
  vtkBloomPassResources& res = this->Internals->Resources;
  res.Kept.Release(res.Context); // the staging target
  this->Internals->KeptImage = nullptr;
}

//------------------------------------------------------------------------------
void vtkBloomPass::GetKeptFrameSize(int size[2])
{
  vtkImageData* kept = this->Internals->KeptImage;
  size[0] = kept ? kept->GetDimensions()[0] : 0;
  size[1] = kept ? kept->GetDimensions()[1] : 0;
}

//------------------------------------------------------------------------------
void vtkBloomPass::SceneRendered(const vtkRenderState*, vtkTextureObject*) {}

//------------------------------------------------------------------------------
bool vtkBloomPass::PreReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
  std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop)
{
  this->Superclass::PreReplaceShaderValues(
    vertexShader, geometryShader, fragmentShader, mapper, prop);
  vtkBloomPassEmission::PreReplace(fragmentShader, mapper);
  return true;
}

//------------------------------------------------------------------------------
bool vtkBloomPass::PostReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
  std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop)
{
  this->Superclass::PostReplaceShaderValues(
    vertexShader, geometryShader, fragmentShader, mapper, prop);
  vtkBloomPassEmission::PostReplace(fragmentShader, mapper);
  return true;
}

//------------------------------------------------------------------------------
bool vtkBloomPass::SetShaderParameters(vtkShaderProgram* program, vtkAbstractMapper* mapper,
  vtkProp* prop, vtkOpenGLVertexArrayObject* VAO)
{
  this->Superclass::SetShaderParameters(program, mapper, prop, VAO);
  this->Internals->Emission.SetUniforms(program, mapper, prop);
  return true;
}

//------------------------------------------------------------------------------
double vtkBloomPass::GetRegionCost() const
{
  return this->Internals->Runner.GetRegionCost();
}

//------------------------------------------------------------------------------
double vtkBloomPass::GetFullCost() const
{
  return this->Internals->Runner.GetFullCost();
}

//------------------------------------------------------------------------------
double vtkBloomPass::GetLastChainMilliseconds()
{
  vtkBloomPassResources& res = this->Internals->Resources;
  if (!res.Context)
  {
    return -1.0;
  }
  res.Context->MakeCurrent();
  return this->Internals->Runner.CollectLastChainMilliseconds();
}

//------------------------------------------------------------------------------
bool vtkBloomPass::ApplyToImage(
  vtkOpenGLRenderWindow* window, vtkImageData* input, vtkImageData* output)
{
  if (!window || !input || !output)
  {
    vtkErrorMacro(<< "ApplyToImage needs a window, an input and an output.");
    return false;
  }
  vtkDataArray* scalars = input->GetPointData()->GetScalars();
  int dims[3];
  input->GetDimensions(dims);
  const int nc = scalars ? scalars->GetNumberOfComponents() : 0;
  if (!scalars || (input->GetScalarType() != VTK_FLOAT && input->GetScalarType() != VTK_DOUBLE) ||
    nc < 3 || nc > 4)
  {
    vtkErrorMacro(<< "ApplyToImage needs float or double scalars with 3 or 4 components.");
    return false;
  }
  if (dims[0] < 1 || dims[1] < 1 || dims[2] != 1)
  {
    vtkErrorMacro(<< "ApplyToImage needs a non-empty two-dimensional image.");
    return false;
  }
  window->Initialize();
  window->MakeCurrent();
  const int w = dims[0], h = dims[1];
  vtkOpenGLState* state = window->GetState();
  const vtkBloomPassSavedState saved(state);
  vtkInternals& in = *this->Internals;
  vtkBloomPassResources& res = in.Resources;
  // An image is not processed further: automatic precision is the half floats'. It is its
  // own frame, whatever the window's tiling.
  in.Tile = vtkBloomPassTile();
  std::fill(in.Output.Window, in.Output.Window + 4, 0);
  if (!in.Prepare(this, window, w, h, 0, false,
        this->FloatPrecision == FLOAT_AUTOMATIC ? FLOAT16 : this->FloatPrecision))
  {
    return false;
  }
  in.Output.GlowAlpha = false; // an image keeps its alpha, as vtkImageBloom's output does
  res.Result.Allocate(window, w, h, GL_RGBA32F);

  // Upload the image as the scene, in float RGBA (alpha 1 when there is none).
  std::vector<float> pixels(static_cast<size_t>(w) * h * 4);
  for (vtkIdType p = 0; p < static_cast<vtkIdType>(w) * h; ++p)
  {
    for (int c = 0; c < 4; ++c)
    {
      pixels[p * 4 + c] = c < nc ? static_cast<float>(scalars->GetComponent(p, c)) : 1.0f;
    }
  }
  res.Scene.Color->Bind();
  state->vtkglPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, w, h, GL_RGBA, GL_FLOAT, pixels.data());
  res.Scene.Color->Deactivate();

  state->PushFramebufferBindings();
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDisable(GL_SCISSOR_TEST);
  const bool bloom = in.RunBloom(this, res.Scene.Color, false);
  this->LastBloomSkipped = !bloom;
  const int zero[2] = { 0, 0 };
  in.Runner.Composite(in.Output, &res.Result, zero, bloom);
  in.Report(this);
  state->PopFramebufferBindings();
  this->NumberOfPasses = in.Runner.GetPasses();
  if (this->ProfilePasses)
  {
    in.Runner.ResolveProfile();
  }

  const bool ok = this->ReadResultImage(output);
  if (ok)
  {
    int extent[6];
    input->GetExtent(extent);
    output->SetExtent(extent);
    output->SetOrigin(input->GetOrigin());
    output->SetSpacing(input->GetSpacing());
  }
  vtkOpenGLCheckErrorMacro("failed after vtkBloomPass::ApplyToImage");
  return ok;
}

//------------------------------------------------------------------------------
bool vtkBloomPass::ReadSceneImage(vtkImageData* image)
{
  vtkBloomPassResources& res = this->Internals->Resources;
  if (!image || !res.Context || !res.Scene.FBO)
  {
    vtkErrorMacro(<< "There is no rendered scene to read; render first.");
    return false;
  }
  if (!res.Scene.Read(res.Context, image))
  {
    return false;
  }
  if (this->Internals->Light.InAlpha)
  {
    // The emission rode on the alpha (1 + weight); the scene's own alpha is at most 1.
    vtkBloomPassDecodeEmission(image, false);
  }
  // The frame as the renderer would have drawn it: the scene over its background.
  vtkBloomPassBackground::PutOver(res, image);
  return true;
}

//------------------------------------------------------------------------------
void vtkBloomPass::SetSceneBackground(const double rgba[4])
{
  vtkBloomPassResources& res = this->Internals->Resources;
  res.BackgroundMode = vtkBloomPassResources::BACKGROUND_COLOR;
  std::copy(rgba, rgba + 4, res.BackgroundColor);
  res.Background.Release(res.Context);
}

//------------------------------------------------------------------------------
bool vtkBloomPass::ReadEmissionImage(vtkImageData* image)
{
  vtkBloomPassResources& res = this->Internals->Resources;
  const bool inScene = this->Internals->Light.InAlpha;
  if (!image || !res.Context || !(inScene || res.Emitter.FBO))
  {
    vtkErrorMacro(<< "There is no emission to read; render with EMISSION_EMITTERS first.");
    return false;
  }
  if (!inScene)
  {
    return res.Emitter.Read(res.Context, image);
  }
  if (!res.Scene.Read(res.Context, image))
  {
    return false;
  }
  vtkBloomPassDecodeEmission(image, true);
  return true;
}

//------------------------------------------------------------------------------
bool vtkBloomPass::ReadResultImage(vtkImageData* image)
{
  vtkBloomPassResources& res = this->Internals->Resources;
  if (!image || !res.Context || !res.Result.FBO)
  {
    vtkErrorMacro(<< "There is no bloomed result to read; turn CaptureResult on and render.");
    return false;
  }
  return res.Result.Read(res.Context, image);
}

//------------------------------------------------------------------------------
void vtkBloomPass::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Superclass::ReleaseGraphicsResources(w);
  this->Internals->ReleaseAll(w);
}

//------------------------------------------------------------------------------
int vtkBloomPass::GetNumberOfProfiledPasses()
{
  return static_cast<int>(this->Internals->Runner.GetProfile().size());
}

//------------------------------------------------------------------------------
std::string vtkBloomPass::GetProfiledPassName(int i)
{
  const auto& profile = this->Internals->Runner.GetProfile();
  return i >= 0 && i < static_cast<int>(profile.size()) ? profile[i].Name : std::string();
}

//------------------------------------------------------------------------------
void vtkBloomPass::GetProfiledPassSize(int i, int size[2])
{
  const auto& profile = this->Internals->Runner.GetProfile();
  const bool in = i >= 0 && i < static_cast<int>(profile.size());
  size[0] = in ? profile[i].Size[0] : 0;
  size[1] = in ? profile[i].Size[1] : 0;
}

//------------------------------------------------------------------------------
double vtkBloomPass::GetProfiledPassMilliseconds(int i)
{
  const auto& profile = this->Internals->Runner.GetProfile();
  return i >= 0 && i < static_cast<int>(profile.size()) ? profile[i].Milliseconds : 0.0;
}

//------------------------------------------------------------------------------
double vtkBloomPass::GetProfiledPassBytes(int i)
{
  const auto& profile = this->Internals->Runner.GetProfile();
  return i >= 0 && i < static_cast<int>(profile.size()) ? profile[i].Bytes : 0.0;
}

//------------------------------------------------------------------------------
void vtkBloomPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FloatPrecision: " << this->FloatPrecision << "\n";
  os << indent << "LastFloatPrecision: " << this->LastFloatPrecision << "\n";
  os << indent
     << "EmissionSource: " << (this->EmissionSource == EMISSION_EMITTERS ? "Emitters" : "Scene")
     << "\n";
  os << indent << "Emitters: " << this->Emitters->GetNumberOfItems() << "\n";
  os << indent << "EmitInSceneRender: " << (this->EmitInSceneRender ? "On" : "Off") << "\n";
  os << indent << "ThresholdEmitters: " << (this->ThresholdEmitters ? "On" : "Off") << "\n";
  os << indent << "BloomBackground: " << (this->BloomBackground ? "On" : "Off") << "\n";
  os << indent << "BloomAnnotations: " << (this->BloomAnnotations ? "On" : "Off") << "\n";
  os << indent << "SeamlessTiles: " << (this->SeamlessTiles ? "On" : "Off") << "\n";
  os << indent << "KeptFrameMode: " << this->KeptFrameMode << "\n";
  os << indent << "LastAnnotationsOverBloom: " << (this->LastAnnotationsOverBloom ? "On" : "Off")
     << "\n";
  os << indent << "LastEmissionInSceneRender: " << (this->LastEmissionInSceneRender ? "On" : "Off")
     << "\n";
  os << indent << "UseComputeShaders: " << (this->UseComputeShaders ? "On" : "Off") << "\n";
  os << indent
     << "SimulateComputeShaderFailure: " << (this->SimulateComputeShaderFailure ? "On" : "Off")
     << "\n";
  os << indent << "SingleDrawSamples: " << this->SingleDrawSamples << "\n";
  os << indent << "FuseSeparablePasses: " << (this->FuseSeparablePasses ? "On" : "Off") << "\n";
  os << indent << "ThresholdSamples: " << (this->ThresholdSamples ? "On" : "Off") << "\n";
  os << indent << "LastComputePasses: " << this->LastComputePasses << "\n";
  os << indent << "CaptureResult: " << (this->CaptureResult ? "On" : "Off") << "\n";
  os << indent << "LastPSFGrid: " << this->LastPSFGrid[0] << " " << this->LastPSFGrid[1] << "\n";
  os << indent << "NumberOfPasses: " << this->NumberOfPasses << "\n";
  os << indent << "LastBloomSkipped: " << (this->LastBloomSkipped ? "On" : "Off") << "\n";
  os << indent << "LastBrightRegion: " << this->LastBrightRegion[0] << " "
     << this->LastBrightRegion[1] << " " << this->LastBrightRegion[2] << " "
     << this->LastBrightRegion[3] << "\n";
  os << indent << "LastChainCoverage: " << this->LastChainCoverage << "\n";
  os << indent << "ProfilePasses: " << (this->ProfilePasses ? "On" : "Off") << "\n";
  os << indent << "Parameters:\n";
  this->Parameters->PrintSelf(os, indent.GetNextIndent());
}
