// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// The delegate's steps the pass adjusts: its overlay and its translucency (see
// vtkBloomPassSteps.h).
#include "vtkBloomPassSteps.h"

#include "vtkBloomVTKCompat.h"
#include "vtkCameraPass.h"
#include "vtkDepthPeelingPass.h"
#include "vtkDualDepthPeelingPass.h"
#include "vtkHiddenLineRemovalPass.h"
#include "vtkImageProcessingPass.h"
#include "vtkOpaquePass.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOpenGLState.h"
#include "vtkOrderIndependentTranslucentPass.h"
#include "vtkOverlayPass.h"
#include "vtkProp.h"
#include "vtkRenderPassCollection.h"
#include "vtkRenderState.h"
#include "vtkRenderStepsPass.h"
#include "vtkSequencePass.h"
#include "vtkTranslucentPass.h"

#include <cstring>

//------------------------------------------------------------------------------
vtkBloomPassSteps::vtkBloomPassSteps()
  : Empty(vtkSmartPointer<vtkSequencePass>::New())
{
}

//------------------------------------------------------------------------------
vtkBloomPassSteps::~vtkBloomPassSteps()
{
  this->Restore();
}

//------------------------------------------------------------------------------
template <typename Visit>
void vtkBloomPassSteps::Walk(
  vtkRenderPass* pass, vtkSequencePass* sequence, int index, int depth, const Visit& visit)
{
  // Passes that wrap others, followed a few levels deep (a cycle would be a user's error).
  if (!pass || depth > 16)
  {
    return;
  }
  visit(pass, sequence, index);
  if (auto* camera = vtkCameraPass::SafeDownCast(pass))
  {
    Walk(camera->GetDelegatePass(), nullptr, -1, depth + 1, visit);
  }
  else if (auto* processing = vtkImageProcessingPass::SafeDownCast(pass))
  {
    Walk(processing->GetDelegatePass(), nullptr, -1, depth + 1, visit);
  }
  else if (auto* list = vtkSequencePass::SafeDownCast(pass))
  {
    vtkRenderPassCollection* passes = list->GetPasses();
    for (int i = 0; passes && i < passes->GetNumberOfItems(); ++i)
    {
      Walk(vtkRenderPass::SafeDownCast(passes->GetItemAsObject(i)), list, i, depth + 1, visit);
    }
  }
}

//------------------------------------------------------------------------------
vtkRenderStepsPass* vtkBloomPassSteps::FindPlainStep(
  vtkRenderPass* delegate, vtkRenderPass* (vtkRenderStepsPass::*get)(), const char* className)
{
  vtkRenderStepsPass* found = nullptr;
  Walk(delegate, nullptr, -1, 0,
    [&](vtkRenderPass* pass, vtkSequencePass*, int)
    {
      auto* steps = vtkRenderStepsPass::SafeDownCast(pass);
      vtkRenderPass* step = steps ? (steps->*get)() : nullptr;
      // Only VTK's plain step, by its exact class: a user's own step is theirs.
      if (!found && step && std::strcmp(step->GetClassName(), className) == 0)
      {
        found = steps;
      }
    });
  return found;
}

//------------------------------------------------------------------------------
int vtkBloomPassSteps::DetachOverlay(vtkRenderPass* delegate)
{
  Walk(delegate, nullptr, -1, 0,
    [this](vtkRenderPass* pass, vtkSequencePass* sequence, int index)
    {
      Slot slot;
      if (auto* steps = vtkRenderStepsPass::SafeDownCast(pass))
      {
        slot.Steps = steps;
        slot.Pass = steps->GetOverlayPass();
      }
      else if (sequence && vtkOverlayPass::SafeDownCast(pass))
      {
        slot.Sequence = sequence;
        slot.Index = index;
        slot.Pass = pass;
      }
      if (slot.Pass)
      {
        this->Overlays.push_back(slot);
      }
    });
  for (Slot& slot : this->Overlays)
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
  return static_cast<int>(this->Overlays.size());
}

//------------------------------------------------------------------------------
int vtkBloomPassSteps::RenderOverlay(const vtkRenderState* s, int x, int y, int width, int height)
{
  int rendered = 0;
  if (!this->Overlays.empty())
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
    for (Slot& slot : this->Overlays)
    {
      slot.Pass->Render(s);
      rendered += slot.Pass->GetNumberOfRenderedProps();
    }
  }
  this->Restore();
  return rendered;
}

//------------------------------------------------------------------------------
vtkBloomPassSteps::Translucency vtkBloomPassSteps::WrapTranslucency(
  const vtkRenderState* s, vtkRenderPass* delegate)
{
  // As vtkOpenGLRenderer::UpdateGeometry: only where some prop has translucent geometry.
  bool translucent = false;
  for (int i = 0; i < s->GetPropArrayCount() && !translucent; ++i)
  {
    translucent = s->GetPropArray()[i]->HasTranslucentPolygonalGeometry() != 0;
  }
  vtkRenderStepsPass* found =
    FindPlainStep(delegate, &vtkRenderStepsPass::GetTranslucentPass, "vtkTranslucentPass");
  if (!translucent || !found)
  {
    return NO_TRANSLUCENCY;
  }
  auto* renderer = static_cast<vtkOpenGLRenderer*>(s->GetRenderer());
  const bool peeling = renderer->GetUseDepthPeeling() != 0;
  vtkRenderPass* step = found->GetTranslucentPass();
  if (!this->Wrapper || this->Peeling != peeling || this->Wrapped != step)
  {
    if (!peeling)
    {
      auto oit = vtkSmartPointer<vtkOrderIndependentTranslucentPass>::New();
      oit->SetTranslucentPass(step);
      this->Wrapper = oit;
    }
    else if (renderer->IsDualDepthPeelingSupported())
    {
      auto dual = vtkSmartPointer<vtkDualDepthPeelingPass>::New();
      dual->SetTranslucentPass(step);
      this->Wrapper = dual;
    }
    else
    {
      auto single = vtkSmartPointer<vtkDepthPeelingPass>::New();
      single->SetTranslucentPass(step);
      this->Wrapper = single;
    }
    this->Peeling = peeling;
    this->Wrapped = step;
  }
  if (auto* dual = vtkDualDepthPeelingPass::SafeDownCast(this->Wrapper))
  {
    dual->SetMaximumNumberOfPeels(renderer->GetMaximumNumberOfPeels());
    dual->SetOcclusionRatio(renderer->GetOcclusionRatio());
  }
  else if (auto* single = vtkDepthPeelingPass::SafeDownCast(this->Wrapper))
  {
    single->SetMaximumNumberOfPeels(renderer->GetMaximumNumberOfPeels());
    single->SetOcclusionRatio(renderer->GetOcclusionRatio());
  }
  Slot slot;
  slot.Steps = found;
  slot.Pass = step;
  this->Translucents.push_back(slot);
  found->SetTranslucentPass(this->Wrapper);
  return peeling ? DEPTH_PEELING : ORDER_INDEPENDENT;
}

//------------------------------------------------------------------------------
bool vtkBloomPassSteps::RemoveHiddenLines(const vtkRenderState* s, vtkRenderPass* delegate)
{
  // As vtkOpenGLRenderer::DeviceRenderOpaqueGeometry: only where some actor is a wireframe.
  if (!s->GetRenderer()->GetUseHiddenLineRemoval() ||
    !vtkHiddenLineRemovalPass::WireframePropsExist(s->GetPropArray(), s->GetPropArrayCount()))
  {
    return false;
  }
  vtkRenderStepsPass* found =
    FindPlainStep(delegate, &vtkRenderStepsPass::GetOpaquePass, "vtkOpaquePass");
  if (!found)
  {
    return false;
  }
  if (!this->HiddenLines)
  {
    this->HiddenLines = vtkSmartPointer<vtkHiddenLineRemovalPass>::New();
  }
  Slot slot;
  slot.Steps = found;
  slot.Pass = found->GetOpaquePass();
  this->Opaques.push_back(slot);
  found->SetOpaquePass(this->HiddenLines);
  return true;
}

//------------------------------------------------------------------------------
vtkRenderPass* vtkBloomPassSteps::FindImageProcessing(vtkRenderPass* delegate)
{
  vtkRenderPass* found = nullptr;
  Walk(delegate, nullptr, -1, 0,
    [&found](vtkRenderPass* pass, vtkSequencePass*, int)
    {
      if (!found && vtkImageProcessingPass::SafeDownCast(pass))
      {
        found = pass;
      }
    });
  return found;
}

//------------------------------------------------------------------------------
void vtkBloomPassSteps::Restore()
{
  for (Slot& slot : this->Overlays)
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
  this->Overlays.clear();
  for (Slot& slot : this->Translucents)
  {
    slot.Steps->SetTranslucentPass(slot.Pass);
  }
  this->Translucents.clear();
  for (Slot& slot : this->Opaques)
  {
    slot.Steps->SetOpaquePass(slot.Pass);
  }
  this->Opaques.clear();
}

//------------------------------------------------------------------------------
void vtkBloomPassSteps::ReleaseGraphicsResources(vtkWindow* window)
{
  if (this->Wrapper)
  {
    this->Wrapper->ReleaseGraphicsResources(window);
  }
}

//------------------------------------------------------------------------------
vtkBloomPassSteps::RendererFXAAOff::RendererFXAAOff(vtkRenderer* renderer)
  : Renderer(renderer)
  , UseFXAA(renderer->GetUseFXAA())
{
  renderer->SetUseFXAA(false);
}

//------------------------------------------------------------------------------
vtkBloomPassSteps::RendererFXAAOff::~RendererFXAAOff()
{
  this->Renderer->SetUseFXAA(this->UseFXAA);
}
