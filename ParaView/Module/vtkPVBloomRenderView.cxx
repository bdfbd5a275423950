// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkPVBloomRenderView.h"

#include "vtkCuller.h"
#include "vtkCullerCollection.h"
#include "vtkIceTCompositePass.h"
#include "vtkIceTSynchronizedRenderers.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLFXAAPass.h"
#include "vtkPVImageBloom.h"
#include "vtkPVSynchronizedRenderer.h"
#include "vtkProcessModule.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSynchronizedRenderers.h"

vtkStandardNewMacro(vtkPVBloomRenderView);

namespace
{
/**
 * The capture delegate a server's client-server synchronizer reads its client's image from
 * while IceT composites float colour. It passes the render's start and end on to IceT's
 * synchronizer (its own capture delegate: with no renderer of its own, vtkSynchronizedRenderers
 * forwards both), so IceT composites as before; but the image it hands over is the frame the
 * bloom composited into the root's framebuffer, read back as a one-rank server reads it, not
 * IceT's 8-bit composite, which float mode leaves empty.
 */
class vtkPVBloomFrameCapture : public vtkSynchronizedRenderers
{
public:
  static vtkPVBloomFrameCapture* New();
  vtkTypeMacro(vtkPVBloomFrameCapture, vtkSynchronizedRenderers);
  vtkRenderer* Frame = nullptr; ///< the view's renderer (not this synchronizer's)

protected:
  vtkPVBloomFrameCapture() { this->AutomaticEventHandling = false; }
  vtkRawImage& CaptureRenderedImage() override
  {
    this->Image.MarkInValid();
    if (this->Frame)
    {
      this->Image.Capture(this->Frame);
    }
    return this->Image;
  }
};
vtkStandardNewMacro(vtkPVBloomFrameCapture);
}

//------------------------------------------------------------------------------
vtkPVBloomRenderView::vtkPVBloomRenderView()
{
  // The pass renders the parameters the preset resolves to.
  this->BloomPass->SetParameters(this->BloomPresetResolver->GetParameters());
}

//------------------------------------------------------------------------------
vtkPVBloomRenderView::~vtkPVBloomRenderView()
{
  if (vtkRenderWindow* window = this->GetRenderWindow())
  {
    this->BloomPass->ReleaseGraphicsResources(window);
    this->CompositeScenePass->ReleaseGraphicsResources(window);
  }
}

//------------------------------------------------------------------------------
void vtkPVBloomRenderView::SetUseBloom(bool use)
{
  if (use != this->UseBloom)
  {
    this->UseBloom = use;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkPVBloomRenderView::SetBloomPreset(const char* name)
{
  this->BloomPresetResolver->SetPreset(name);
}

//------------------------------------------------------------------------------
const char* vtkPVBloomRenderView::GetBloomPreset()
{
  return this->BloomPresetResolver->GetPreset();
}

//------------------------------------------------------------------------------
void vtkPVBloomRenderView::SetBloomCustomParameters(vtkBloomParameters* parameters)
{
  this->BloomPresetResolver->SetCustomParameters(parameters);
}

//------------------------------------------------------------------------------
void vtkPVBloomRenderView::SetBloomFloatPrecision(int bits)
{
  this->BloomPass->SetFloatPrecision(bits);
}

//------------------------------------------------------------------------------
int vtkPVBloomRenderView::GetBloomFloatPrecision()
{
  return this->BloomPass->GetFloatPrecision();
}

//------------------------------------------------------------------------------
void vtkPVBloomRenderView::SetBloomBackground(bool bloom)
{
  this->BloomPass->SetBloomBackground(bloom);
}

//------------------------------------------------------------------------------
bool vtkPVBloomRenderView::GetBloomBackground()
{
  return this->BloomPass->GetBloomBackground();
}

//------------------------------------------------------------------------------
bool vtkPVBloomRenderView::GetBloomLastSceneWasComposited()
{
  return this->BloomPass->GetLastSceneWasComposited();
}

//------------------------------------------------------------------------------
bool vtkPVBloomRenderView::LocalProcessDisplaysImage()
{
  auto* controller = vtkMultiProcessController::GetGlobalController();
  return !controller || controller->GetLocalProcessId() == 0;
}

//------------------------------------------------------------------------------
bool vtkPVBloomRenderView::TiledInParallel()
{
  int scale[2] = { 1, 1 };
  this->GetRenderWindow()->GetTileScale(scale);
  return (scale[0] > 1 || scale[1] > 1) &&
    vtkIceTSynchronizedRenderers::SafeDownCast(
      this->SynchronizedRenderers->GetParallelSynchronizer()) != nullptr;
}

//------------------------------------------------------------------------------
void vtkPVBloomRenderView::UpdateFloatComposite()
{
  vtkPVSynchronizedRenderer* sync = this->SynchronizedRenderers;
  auto* icet = vtkIceTSynchronizedRenderers::SafeDownCast(sync->GetParallelSynchronizer());
  vtkIceTCompositePass* composite = icet ? icet->GetIceTCompositePass() : nullptr;
  vtkRenderPass* current = sync->GetRenderPass();
  // Only where no other render pass (OSPRay, ANARI, value rendering) holds IceT's slot, in
  // pvbatch and in a server (whose client gets the frame the bloom wrote, below). The tiles
  // served from a whole frame (Render) composite float too: what follows the bloom is then
  // what follows it in the whole frame's render (no 8-bit image pasted over it).
  const int process = vtkProcessModule::GetProcessType();
  const bool batchOrServer = process == vtkProcessModule::PROCESS_BATCH ||
    process == vtkProcessModule::PROCESS_SERVER ||
    process == vtkProcessModule::PROCESS_RENDER_SERVER;
  const bool use = composite && this->UseBloom && this->CompositeFloatColor &&
    !this->GetMakingSelection() && !this->InTileDisplayMode() &&
    (!this->TiledInParallel() || this->TilesFromWholeFrame()) && batchOrServer &&
    (current == nullptr || current == this->CompositeScenePass);
  this->SendBloomedFrame(use ? icet : nullptr);
  if (use)
  {
    // The background as the view set it, before ParaView clears it to black for IceT; none
    // where a client draws it (a server's client-server synchronizer fixes the background:
    // the server renders over transparent black, and the client blends the premultiplied
    // frame, glow and its alpha included, over its own background).
    vtkRenderer* renderer = this->GetRenderer();
    vtkSynchronizedRenderers* cs = sync->GetCSSynchronizer();
    double rgb[3] = { 0.0, 0.0, 0.0 };
    const bool clientDraws = cs && cs->GetFixBackground();
    if (!clientDraws)
    {
      renderer->GetBackground(rgb);
    }
    this->BloomPass->SetCompositeBackground(
      rgb, clientDraws ? 0.0 : renderer->GetBackgroundAlpha());
    sync->SetRenderPass(this->CompositeScenePass);
    composite->SetEnableFloatValuePass(true);
  }
  else if (current == this->CompositeScenePass)
  {
    sync->SetRenderPass(nullptr);
    composite->SetEnableFloatValuePass(false);
  }
  this->BloomPass->SetCompositePass(use ? composite : nullptr);
}

//------------------------------------------------------------------------------
void vtkPVBloomRenderView::SendBloomedFrame(vtkSynchronizedRenderers* icet)
{
  // A server's root hands its client what its client-server synchronizer captures, through
  // IceT's synchronizer (its capture delegate), which also drives IceT's render. With the float
  // composite, a relay takes the delegate's place: IceT still renders through it, and the image
  // sent is the frame the bloom wrote (vtkPVBloomFrameCapture). Batch processes and satellites
  // have no client-server synchronizer.
  vtkSynchronizedRenderers* cs = this->SynchronizedRenderers->GetCSSynchronizer();
  if (!cs)
  {
    return;
  }
  vtkSynchronizedRenderers* current = cs->GetCaptureDelegate();
  if (icet && current == icet)
  {
    if (!this->FrameCapture)
    {
      auto capture = vtkSmartPointer<vtkPVBloomFrameCapture>::New();
      capture->Frame = this->GetRenderer();
      this->FrameCapture = capture;
    }
    this->FrameCapture->SetCaptureDelegate(icet);
    cs->SetCaptureDelegate(this->FrameCapture);
  }
  else if (!icet && this->FrameCapture && current == this->FrameCapture)
  {
    cs->SetCaptureDelegate(this->FrameCapture->GetCaptureDelegate());
  }
}

//------------------------------------------------------------------------------
void vtkPVBloomRenderView::AboutToRenderOnLocalProcess(bool interactive)
{
  this->Superclass::AboutToRenderOnLocalProcess(interactive);
  this->UpdateFloatComposite();
  if (this->GetMakingSelection())
  {
    return; // ParaView emptied the slot for the selection render, and refills it afterwards.
  }
  vtkPVSynchronizedRenderer* sync = this->SynchronizedRenderers;
  // A screenshot larger than the view renders in tiles, and blooms as one frame where this
  // process renders the whole scene (vtkBloomPass::SeamlessTiles). Under IceT the ranks render
  // the tile with its own camera and IceT composites the window's size only: each tile is
  // served from the whole frame (Render), where the renderer fills the window; elsewhere a tile
  // would bloom alone, and is refused (rendered without bloom, said once).
  const bool parallel =
    vtkIceTSynchronizedRenderers::SafeDownCast(sync->GetParallelSynchronizer()) != nullptr;
  const bool tiledInParallel = this->TiledInParallel() && !this->TilesFromWholeFrame();
  if (tiledInParallel && this->UseBloom && !this->TiledScreenshotRefused &&
    this->LocalProcessDisplaysImage())
  {
    vtkWarningMacro(<< "Bloom is off for a screenshot larger than the view: under MPI its "
                    << "tiles bloom as one frame only where the view's renderer fills its "
                    << "window. Resize the view to the screenshot's size instead.");
    this->TiledScreenshotRefused = true;
  }
  this->CullWholeFrame(!parallel && this->UseBloom);
  vtkImageProcessingPass* slot = sync->GetImageProcessingPass();
  vtkPVBloomPass* bloom = this->BloomPass;
  // ParaView's own pass in the slot (tone mapping), if any: bloom is never replaced by it
  // silently, it is spliced in as that pass's delegate.
  vtkImageProcessingPass* outer = (slot && slot != bloom) ? slot : nullptr;
  // A tile display shows each rank's tile of the composited frame, and a tile blooming alone
  // would cut every glow at the tiles' borders: the view refuses, once, rather than show that.
  const bool tileDisplay = this->InTileDisplayMode();
  if (tileDisplay && this->UseBloom && !this->TileDisplayRefused)
  {
    auto* controller = vtkMultiProcessController::GetGlobalController();
    if (!controller || controller->GetLocalProcessId() == 0)
    {
      vtkWarningMacro(<< "Bloom is off on tile displays: each display would bloom its own "
                      << "tile alone, cutting the glow at the tiles' borders.");
    }
    this->TileDisplayRefused = true;
  }
  const bool want =
    this->UseBloom && !tileDisplay && !tiledInParallel && this->LocalProcessDisplaysImage();

  if (outer)
  {
    const bool spliced = outer->GetDelegatePass() == bloom;
    if (want && !spliced)
    {
      bloom->SetDelegatePass(outer->GetDelegatePass());
      outer->SetDelegatePass(bloom);
    }
    else if (!want && spliced)
    {
      outer->SetDelegatePass(bloom->GetDelegatePass());
    }
  }
  else if (want && slot != bloom)
  {
    sync->SetImageProcessingPass(bloom); // also makes the camera pass its delegate
  }
  else if (!want && slot == bloom)
  {
    sync->SetImageProcessingPass(nullptr);
  }
  this->AvoidSecondFXAA();
  // vtkPVRenderView::Render turns the synchronizers on before this; the next render's turns
  // them on again.
  vtkSynchronizedRenderers* client = sync->GetCSSynchronizer();
  if (this->WithoutClient && client)
  {
    client->SetParallelRendering(false);
  }
}

//------------------------------------------------------------------------------
void vtkPVBloomRenderView::CullWholeFrame(bool bloom)
{
  // A tile of a screenshot renders with a guard band (vtkBloomPass::SeamlessTiles), and
  // ParaView's delegate draws the props the renderer kept, which it culls against the tile's
  // frustum before the pass can widen it: while the window is tiled, the renderer culls
  // nothing (every prop is drawn, the GPU clips what lies outside the band).
  vtkRenderer* renderer = this->GetRenderer();
  int scale[2] = { 1, 1 };
  this->GetRenderWindow()->GetTileScale(scale);
  vtkCullerCollection* cullers = renderer->GetCullers();
  const bool tiled = bloom && (scale[0] > 1 || scale[1] > 1);
  vtkCullerCollection* from = tiled ? cullers : this->TileCullers.GetPointer();
  vtkCullerCollection* to = tiled ? this->TileCullers.GetPointer() : cullers;
  vtkCollectionSimpleIterator it;
  from->InitTraversal(it);
  while (vtkCuller* culler = from->GetNextCuller(it))
  {
    to->AddItem(culler);
  }
  from->RemoveAllItems();
}

//------------------------------------------------------------------------------
void vtkPVBloomRenderView::AvoidSecondFXAA()
{
  // With FXAA on, vtkPVSynchronizedRenderer::SetupPasses wraps a pass in the image-processing
  // slot in a vtkOpenGLFXAAPass, and vtkSynchronizedRenderers applies FXAA again after the
  // render (from the renderer's UseFXAA). Without a pass in the slot only the second runs. The
  // bloom alone in the slot would make the frame anti-aliased twice where the view without it
  // is anti-aliased once: the renderer renders the bloom directly instead.
  vtkRenderer* renderer = this->GetRenderer();
  auto* fxaa = vtkOpenGLFXAAPass::SafeDownCast(renderer->GetPass());
  if (fxaa && fxaa->GetDelegatePass() == this->BloomPass.GetPointer())
  {
    renderer->SetPass(this->BloomPass);
  }
}

//------------------------------------------------------------------------------
void vtkPVBloomRenderView::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "UseBloom: " << this->UseBloom << "\n";
  os << indent << "CompositeFloatColor: " << this->CompositeFloatColor << "\n";
  os << indent << "BloomPass:\n";
  this->BloomPass->PrintSelf(os, indent.GetNextIndent());
}
