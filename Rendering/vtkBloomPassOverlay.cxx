// The delegate's annotations drawn over the bloom (see vtkBloomPassOverlay.h).
#include "vtkBloomPassOverlay.h"

#include "vtkBloomVTKCompat.h"
#include "vtkCameraPass.h"
#include "vtkImageProcessingPass.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkOverlayPass.h"
#include "vtkRenderPassCollection.h"
#include "vtkRenderState.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderer.h"
#include "vtkSequencePass.h"

//------------------------------------------------------------------------------
vtkBloomPassOverlay::vtkBloomPassOverlay()
  : Empty(vtkSmartPointer<vtkSequencePass>::New())
{
}

//------------------------------------------------------------------------------
vtkBloomPassOverlay::~vtkBloomPassOverlay()
{
  this->Restore();
}

//------------------------------------------------------------------------------
void vtkBloomPassOverlay::Collect(vtkRenderPass* pass, int depth)
{
  // Passes that wrap others, followed a few levels deep (a cycle would be a user's error).
  if (!pass || depth > 16)
  {
    return;
  }
  if (auto* steps = vtkRenderStepsPass::SafeDownCast(pass))
  {
    if (steps->GetOverlayPass())
    {
      Slot slot;
      slot.Steps = steps;
      slot.Pass = steps->GetOverlayPass();
      this->Slots.push_back(slot);
    }
  }
  else if (auto* camera = vtkCameraPass::SafeDownCast(pass))
  {
    this->Collect(camera->GetDelegatePass(), depth + 1);
  }
  else if (auto* processing = vtkImageProcessingPass::SafeDownCast(pass))
  {
    this->Collect(processing->GetDelegatePass(), depth + 1);
  }
  else if (auto* sequence = vtkSequencePass::SafeDownCast(pass))
  {
    vtkRenderPassCollection* passes = sequence->GetPasses();
    for (int i = 0; passes && i < passes->GetNumberOfItems(); ++i)
    {
      auto* item = vtkRenderPass::SafeDownCast(passes->GetItemAsObject(i));
      if (vtkOverlayPass::SafeDownCast(item))
      {
        Slot slot;
        slot.Sequence = sequence;
        slot.Index = i;
        slot.Pass = item;
        this->Slots.push_back(slot);
      }
      else
      {
        this->Collect(item, depth + 1);
      }
    }
  }
}

//------------------------------------------------------------------------------
int vtkBloomPassOverlay::Detach(vtkRenderPass* delegate)
{
  this->Restore();
  this->Collect(delegate, 0);
  for (Slot& slot : this->Slots)
  {
    if (slot.Steps)
    {
      slot.Steps->SetOverlayPass(nullptr);
    }
    else
    {
      slot.Sequence->GetPasses()->ReplaceItem(slot.Index, this->Empty);
    }
  }
  return static_cast<int>(this->Slots.size());
}

//------------------------------------------------------------------------------
void vtkBloomPassOverlay::Restore()
{
  for (Slot& slot : this->Slots)
  {
    if (slot.Steps)
    {
      slot.Steps->SetOverlayPass(slot.Pass);
    }
    else
    {
      slot.Sequence->GetPasses()->ReplaceItem(slot.Index, slot.Pass);
    }
  }
  this->Slots.clear();
}

//------------------------------------------------------------------------------
int vtkBloomPassOverlay::Render(const vtkRenderState* s, int x, int y, int width, int height)
{
  int rendered = 0;
  if (!this->Slots.empty())
  {
    auto* window = static_cast<vtkOpenGLRenderWindow*>(s->GetRenderer()->GetRenderWindow());
    vtkOpenGLState* state = window->GetState();
    // As the camera pass sets it up for the delegate's steps, over the composited frame: the
    // frame's depth is not the scene's, so annotations are drawn in order, untested.
    state->vtkglViewport(x, y, width, height);
    state->vtkglScissor(x, y, width, height);
    state->vtkglEnable(GL_SCISSOR_TEST);
    state->vtkglDisable(GL_DEPTH_TEST);
    state->vtkglEnable(GL_BLEND);
    state->vtkglBlendFuncSeparate(
      GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    for (Slot& slot : this->Slots)
    {
      slot.Pass->Render(s);
      rendered += slot.Pass->GetNumberOfRenderedProps();
    }
  }
  this->Restore();
  return rendered;
}
