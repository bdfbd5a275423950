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

vtkStandardNewMacro(vtkPVBloomRenderView);

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
  if (this->InTileDisplayMode())
  {
    return true;
  }
  auto* controller = vtkMultiProcessController::GetGlobalController();
  return !controller || controller->GetLocalProcessId() == 0;
}

//------------------------------------------------------------------------------
void vtkPVBloomRenderView::UpdateFloatComposite()
{
  vtkPVSynchronizedRenderer* sync = this->SynchronizedRenderers;
  auto* icet = vtkIceTSynchronizedRenderers::SafeDownCast(sync->GetParallelSynchronizer());
  vtkIceTCompositePass* composite = icet ? icet->GetIceTCompositePass() : nullptr;
  vtkRenderPass* current = sync->GetRenderPass();
  // Only where no other render pass (OSPRay, ANARI, value rendering) holds IceT's slot, and
  // only in pvbatch: a server must hand its client the 8-bit image that float mode omits.
  const bool use = composite && this->UseBloom && this->CompositeFloatColor &&
    !this->GetMakingSelection() && !this->InTileDisplayMode() &&
    composite->GetImageReductionFactor() <= 1 &&
    vtkProcessModule::GetProcessType() == vtkProcessModule::PROCESS_BATCH &&
    (current == nullptr || current == this->CompositeScenePass);
  if (use)
  {
    // The background as the view set it, before ParaView clears it to black for IceT.
    vtkRenderer* renderer = this->GetRenderer();
    double rgb[3];
    renderer->GetBackground(rgb);
    this->BloomPass->SetCompositeBackground(rgb, renderer->GetBackgroundAlpha());
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
void vtkPVBloomRenderView::AboutToRenderOnLocalProcess(bool interactive)
{
  this->Superclass::AboutToRenderOnLocalProcess(interactive);
  this->UpdateFloatComposite();
  if (this->GetMakingSelection())
  {
    return; // ParaView emptied the slot for the selection render, and refills it afterwards.
  }
  vtkPVSynchronizedRenderer* sync = this->SynchronizedRenderers;
  // A tiled screenshot blooms as one frame where this process renders the whole scene; under
  // IceT the other ranks render their geometry with the tile's camera, which the pass cannot
  // widen, so each tile blooms alone there.
  const bool seamless =
    vtkIceTSynchronizedRenderers::SafeDownCast(sync->GetParallelSynchronizer()) == nullptr;
  this->BloomPass->SetSeamlessTiles(seamless);
  this->CullWholeFrame(seamless && this->UseBloom);
  vtkImageProcessingPass* slot = sync->GetImageProcessingPass();
  vtkPVBloomPass* bloom = this->BloomPass;
  // ParaView's own pass in the slot (tone mapping), if any: bloom is never replaced by it
  // silently, it is spliced in as that pass's delegate.
  vtkImageProcessingPass* outer = (slot && slot != bloom) ? slot : nullptr;
  const bool want = this->UseBloom && this->LocalProcessDisplaysImage();

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
}

//------------------------------------------------------------------------------
void vtkPVBloomRenderView::CullWholeFrame(bool seamless)
{
  // A tile of a screenshot renders with a guard band (vtkBloomPass::SeamlessTiles), and
  // ParaView's delegate draws the props the renderer kept, which it culls against the tile's
  // frustum before the pass can widen it: while the window is tiled, the renderer culls
  // nothing (every prop is drawn, the GPU clips what lies outside the band).
  vtkRenderer* renderer = this->GetRenderer();
  int scale[2] = { 1, 1 };
  this->GetRenderWindow()->GetTileScale(scale);
  vtkCullerCollection* cullers = renderer->GetCullers();
  const bool tiled = seamless && (scale[0] > 1 || scale[1] > 1);
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
