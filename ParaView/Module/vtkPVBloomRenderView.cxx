#include "vtkPVBloomRenderView.h"

#include "vtkBloomPass.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkPVImageBloom.h"
#include "vtkPVSynchronizedRenderer.h"
#include "vtkRenderWindow.h"

vtkStandardNewMacro(vtkPVBloomRenderView);

//------------------------------------------------------------------------------
vtkPVBloomRenderView::vtkPVBloomRenderView()
{
  this->BloomPass->SetParameters(this->BloomParameters);
}

//------------------------------------------------------------------------------
vtkPVBloomRenderView::~vtkPVBloomRenderView()
{
  if (vtkRenderWindow* window = this->GetRenderWindow())
  {
    this->BloomPass->ReleaseGraphicsResources(window);
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
  this->BloomParameters->SetPreset(name);
}

//------------------------------------------------------------------------------
const char* vtkPVBloomRenderView::GetBloomPreset()
{
  return this->BloomParameters->GetPreset();
}

//------------------------------------------------------------------------------
void vtkPVBloomRenderView::SetBloomCustomParameters(vtkImageBloom* parameters)
{
  this->BloomParameters->SetCustomParameters(parameters);
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
void vtkPVBloomRenderView::AboutToRenderOnLocalProcess(bool interactive)
{
  this->Superclass::AboutToRenderOnLocalProcess(interactive);
  if (this->GetMakingSelection())
  {
    return; // ParaView emptied the slot for the selection render, and refills it afterwards.
  }
  vtkPVSynchronizedRenderer* sync = this->SynchronizedRenderers;
  vtkImageProcessingPass* slot = sync->GetImageProcessingPass();
  vtkBloomPass* bloom = this->BloomPass;
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
}

//------------------------------------------------------------------------------
void vtkPVBloomRenderView::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "UseBloom: " << this->UseBloom << "\n";
  os << indent << "BloomPass:\n";
  this->BloomPass->PrintSelf(os, indent.GetNextIndent());
}
