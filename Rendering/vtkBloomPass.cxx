// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// vtkBloomPass's render: Render() plans the frame (PlanFrame), then the internals' steps
// (vtkBloomPassInternals.h) render the scene, run the chain, composite and draw the overlay,
// and write what the frame did (vtkBloomFrameReport); also the kept frame of tiled screenshots
// (KeptFrameMode) and the parameter plumbing. docs/architecture.md maps the pass's other files.
#include "vtkBloomPassInternals.h"

#include "vtkDataArray.h"
#include "vtkImageBloom.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPointData.h"
#include "vtkTextureObject.h"

#include <algorithm>
#include <cmath>
#include <iterator>
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
}

//------------------------------------------------------------------------------
bool vtkBloomPass::vtkInternals::Prepare(vtkBloomPass* self, vtkOpenGLRenderWindow* window, int w,
  int h, int samples, bool emitters, int precision)
{
  vtkBloomPassResources& res = this->Resources;
  if (res.Context && res.Context != window)
  {
    // Moved to another window: what the pass and its delegate made in the first is freed in
    // the first's context.
    vtkOpenGLRenderWindow* first = res.Context;
    first->PushContext();
    self->ReleaseGraphicsResources(first);
    first->PopContext();
  }
  res.Context = window;
  this->Report->FloatPrecision = precision;
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
  settings.SimulateComputeFailure = this->Switches.SimulateComputeShaderFailure;
  settings.SingleDrawSamples = this->Switches.SingleDrawSamples;
  settings.FuseSeparablePasses = this->Switches.FuseSeparablePasses;
  this->Runner.BeginFrame(settings);
  this->Profiler.StartFrame(this->Switches.ProfilePasses);
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
      this->ReleaseOperators(window);
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
    this->ReleaseOperators(window);
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
  std::fill(this->Report->TileGuardBand, this->Report->TileGuardBand + 2, 0);
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
  this->Report->TileGuardBand[0] = tile.Size[0] - w;
  this->Report->TileGuardBand[1] = tile.Size[1] - h;
  this->PropsOfTile(r, props, count);
}

//------------------------------------------------------------------------------
bool vtkBloomPass::vtkInternals::RunBloom(vtkBloomPass* self, vtkTextureObject* source, bool mask)
{
  this->Report->PSFGrid[0] = this->Report->PSFGrid[1] = 0;
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
  // The scene's render writes the called framebuffer's depth where it can: nothing to copy.
  if (content != EMITTERS)
  {
    this->DepthShared =
      this->ShareDepth && this->Depth.Share(this->CalledFramebuffer, fbo->GetFBOIndex());
  }
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
  // The props the pass is attached to while they render (vtkOpenGLRenderPass::PreRender): with
  // emission, every prop, for its shader replacement; else the volumes, for their viewport.
  // A GPU volume mapper with no render pass attached places its rays and reads the scene's
  // depth at the renderer's origin in the window, where the pass's target has its first pixel
  // at (0, 0): the volume of a renderer that is not at the window's lower left was lost.
  // Attached, it keeps the viewport the delegate's camera pass set.
  vtkRenderState attached(r);
  if (emission)
  {
    attached.SetPropArrayAndCount(props, count);
  }
  else
  {
    this->Volumes.clear();
    std::copy_if(props, props + count, std::back_inserter(this->Volumes),
      [](vtkProp* prop) { return prop->IsA("vtkVolume"); });
    attached.SetPropArrayAndCount(this->Volumes.data(), static_cast<int>(this->Volumes.size()));
  }
  self->PreRender(&attached);
  if (content == SCENE_AND_EMISSION)
  {
    state->vtkglDisable(GL_BLEND);
  }
  {
    const vtkBloomPassSteps::RendererFXAAOff noFXAA(r);
    const vtkBloomPassTileCamera part(r, this->Tile);
    self->DelegatePass->Render(&s2);
  }
  self->PostRender(&attached);
  this->Depth.EndShare();
  if (this->Resources.Samples)
  {
    multisample.Resolve(this->Resources.Context, target, content == EMITTERS || !this->DepthShared);
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
  , CaptureResult(false)
  , Internals(new vtkInternals(this))
{
}

//------------------------------------------------------------------------------
vtkBloomPass::~vtkBloomPass()
{
  // VTK's textures, framebuffers and buffers free their GL names only when released, not when
  // deleted: a pass dropped without ReleaseGraphicsResources (switched off in an application)
  // would leave its targets in the window's context for as long as the window lives.
  this->Internals->ReleaseInContext();
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
  this->Internals->Report->NumberOfPasses = 0;
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
  vtkInternals::Frame frame;
  RenderedPart(s, frame.X, frame.Y, frame.Width, frame.Height);
  if (frame.Width <= 0 || frame.Height <= 0)
  {
    return;
  }
  const vtkBloomPassSavedState saved(window->GetState());
  vtkInternals& in = *this->Internals;
  if (!in.PlanFrame(this, s, window, frame))
  {
    return;
  }
  vtkOpenGLState* state = window->GetState();
  state->PushFramebufferBindings();
  in.RenderScene(this, s, frame);
  const bool bloom = in.BloomIntoTargets(this, state, frame);
  state->PopFramebufferBindings();
  in.CompositeIntoFramebuffer(this, window, frame, bloom);
  in.FinishFrame(this, s, frame);
  vtkOpenGLCheckErrorMacro("failed after vtkBloomPass::Render");
}

//------------------------------------------------------------------------------
bool vtkBloomPass::vtkInternals::PlanFrame(
  vtkBloomPass* self, const vtkRenderState* s, vtkOpenGLRenderWindow* window, Frame& frame)
{
  vtkRenderer* r = s->GetRenderer();
  GLint called = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &called);
  this->CalledFramebuffer = static_cast<unsigned int>(called);
  // Multisampling is kept: where the framebuffer the pass was called with has samples, the
  // scene renders with as many.
  GLint samples = 0;
  glGetIntegerv(GL_SAMPLES, &samples);
  // The part rendered: the renderer's tile, with its guard band where the frame is tiled, and
  // the props it shows.
  frame.Props = s->GetPropArray();
  frame.Count = s->GetPropArrayCount();
  this->PlanTile(self, r, frame.Width, frame.Height, frame.Props, frame.Count);
  // Selective bloom: in the scene's own render where it can be, else the emitters again.
  frame.Selective = self->EmissionSource == EMISSION_EMITTERS;
  frame.InScene = frame.Selective &&
    this->Emission.Plan(
      self->Emitters, frame.Props, frame.Count, self->DelegatePass, self->EmitInSceneRender);
  frame.TwoRenders = frame.Selective && !frame.InScene;
  this->Report->EmissionInSceneRender = frame.InScene;
  // The renderer's FXAA, applied here, or a pass around this one processes the frame further.
  frame.FXAA = r->GetUseFXAA() && r->GetPass() == self;
  const bool processed = frame.FXAA || r->GetPass() != self;
  const int precision = self->FloatPrecision != FLOAT_AUTOMATIC ? self->FloatPrecision
    : processed                                                 ? FLOAT32
                                                                : FLOAT16;
  if (!this->Prepare(
        self, window, this->Tile.Size[0], this->Tile.Size[1], samples, frame.TwoRenders, precision))
  {
    return false;
  }
  this->PlanWhatBlooms(self, s, frame.Selective);
  // The called framebuffer's depth buffer, shared with the scene's render, must cover the
  // same pixels; the emitters' second render needs the scene's depth as the pass's own texture.
  this->ShareDepth =
    this->Switches.ShareWindowDepth && frame.X == 0 && frame.Y == 0 && !frame.TwoRenders;
  if (self->CaptureResult)
  {
    this->Resources.Result.Allocate(window, frame.Width, frame.Height, GL_RGBA32F);
  }
  return true;
}

//------------------------------------------------------------------------------
// 1. The scene (and, in one render, its emission), then any emitters on their own, in float.
void vtkBloomPass::vtkInternals::RenderScene(
  vtkBloomPass* self, const vtkRenderState* s, const Frame& frame)
{
  vtkBloomPassResources& res = this->Resources;
  const int w = frame.Width, h = frame.Height;
  // The delegate writes the float colour and a 32-bit depth once (the profile's lower bound).
  const double sceneBytes = (res.Format == GL_RGBA32F ? 20.0 : 12.0) * w * h;
  this->Profiler.Begin();
  this->RenderDelegate(
    self, s, res.Scene, frame.Props, frame.Count, frame.InScene ? SCENE_AND_EMISSION : SCENE);
  if (res.BackgroundMode == vtkBloomPassResources::BACKGROUND_TEXTURE)
  {
    vtkBloomPassBackground::Draw(res, s->GetRenderer(), frame.X, frame.Y, w, h);
  }
  self->SceneRendered(s, res.Scene.Color);
  this->Profiler.End("scene", w, h, sceneBytes);
  if (frame.TwoRenders)
  {
    std::vector<vtkProp*>& emitters = this->Emission.SecondRender;
    this->Profiler.Begin();
    this->RenderDelegate(
      self, s, res.Emitter, emitters.data(), static_cast<int>(emitters.size()), EMITTERS);
    this->Profiler.End("emitters", w, h, sceneBytes);
  }
}

//------------------------------------------------------------------------------
// 2. The chain into the pass's own targets; for a tile of a kept frame (KeptFrameMode), that
// frame's part staged instead.
bool vtkBloomPass::vtkInternals::BloomIntoTargets(
  vtkBloomPass* self, vtkOpenGLState* state, const Frame& frame)
{
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDisable(GL_SCISSOR_TEST);
  this->Report->TileFromKeptFrame = this->StageServedTile(self, frame.Width, frame.Height);
  return !this->Report->TileFromKeptFrame && this->RunChain(self, frame.InScene, frame.TwoRenders);
}

//------------------------------------------------------------------------------
// 3. Into the framebuffer the pass was called with, and the scene's depth under it where the
// scene's render did not write that framebuffer's own.
void vtkBloomPass::vtkInternals::CompositeIntoFramebuffer(
  vtkBloomPass* self, vtkOpenGLRenderWindow* window, const Frame& frame, bool bloom)
{
  vtkOpenGLState* state = window->GetState();
  const int x = frame.X, y = frame.Y, w = frame.Width, h = frame.Height;
  if (this->Report->TileFromKeptFrame)
  {
    this->ServeTile(x, y);
  }
  else
  {
    this->Composite(self, x, y, bloom);
  }
  if (self->KeptFrameMode == KEPT_FRAME_KEEP)
  {
    this->KeepFramebuffer(state, x, y, w, h);
  }
  // The scene's depth under the composited frame, for what reads it next: the annotations (a
  // label mapper hides the labels of points the scene covers), a pass around this one.
  if (!this->DepthShared)
  {
    this->Profiler.Begin();
    this->Depth.Write(window, this->Resources.Scene.Depth, x, y, w, h, this->Tile.Inner);
    this->Profiler.End("depth", w, h, 8.0 * w * h);
  }
  // The renderer's viewport again (the scene's render had the part's, a tile with its band),
  // for what follows and reads it: the FXAA, the annotations.
  state->vtkglViewport(x, y, w, h);
  state->vtkglScissor(x, y, w, h);
}

//------------------------------------------------------------------------------
// 4. The renderer's FXAA, which VTK applies only where a renderer has no pass: where this pass
// is the renderer's, as the renderer applies it, to the frame without its annotations. Inside
// other passes (ParaView's own FXAA pass, a tone mapping) FXAA is theirs to apply. 5. The
// annotations, over the bloom; the delegate's steps as they were. Then what the frame did.
void vtkBloomPass::vtkInternals::FinishFrame(
  vtkBloomPass* self, const vtkRenderState* s, const Frame& frame)
{
  if (frame.FXAA)
  {
    this->Profiler.Begin();
    this->ApplyFXAA(static_cast<vtkOpenGLRenderer*>(s->GetRenderer()));
    this->Profiler.End("fxaa", frame.Width, frame.Height, 8.0 * frame.Width * frame.Height);
  }
  self->NumberOfRenderedProps +=
    this->Steps.RenderOverlay(s, frame.X, frame.Y, frame.Width, frame.Height);
  this->ReportChain();
  this->Profiler.Resolve();
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
  this->Report->BloomSkipped = !bloom;
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
  this->Report->BloomSkipped = false;
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
vtkBloomFrameReport* vtkBloomPass::GetLastFrame()
{
  vtkInternals& in = *this->Internals;
  vtkOpenGLRenderWindow* context = in.Resources.Context;
  if (context && in.Runner.GetTimeEveryChain())
  {
    // The timestamps that have arrived since the frame, never waited for.
    context->MakeCurrent();
    in.Runner.CollectCostTimings();
    in.ReportTimes();
  }
  return in.Report;
}

//------------------------------------------------------------------------------
void vtkBloomPass::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Superclass::ReleaseGraphicsResources(w);
  this->Internals->ReleaseAll(w);
}

//------------------------------------------------------------------------------
void vtkBloomPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FloatPrecision: " << this->FloatPrecision << "\n";
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
  os << indent << "UseComputeShaders: " << (this->UseComputeShaders ? "On" : "Off") << "\n";
  os << indent << "ThresholdSamples: " << (this->ThresholdSamples ? "On" : "Off") << "\n";
  os << indent << "CaptureResult: " << (this->CaptureResult ? "On" : "Off") << "\n";
  os << indent << "Parameters:\n";
  this->Parameters->PrintSelf(os, indent.GetNextIndent());
  os << indent << "LastFrame:\n";
  this->Internals->Report->PrintSelf(os, indent.GetNextIndent());
}
