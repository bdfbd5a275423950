// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkPVBloomCompositeScenePass.h"

#include "vtkBloomVTKCompat.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOpenGLState.h"
#include "vtkPVDefaultPass.h"
#include "vtkRenderState.h"

vtkStandardNewMacro(vtkPVBloomCompositeScenePass);

//------------------------------------------------------------------------------
vtkPVBloomCompositeScenePass::vtkPVBloomCompositeScenePass()
  : Delegate(vtkPVDefaultPass::New())
{
  this->RenderingMode = vtkValuePass::FLOATING_POINT;
}

//------------------------------------------------------------------------------
vtkPVBloomCompositeScenePass::~vtkPVBloomCompositeScenePass()
{
  this->Delegate->Delete();
}

//------------------------------------------------------------------------------
void vtkPVBloomCompositeScenePass::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  vtkRenderer* renderer = s->GetRenderer();
  vtkOpenGLState* state = static_cast<vtkOpenGLRenderer*>(renderer)->GetState();
  // BeginPass turns blending off for its value rendering; the scene's translucent steps need
  // it as the renderer left it. Where it makes its framebuffer (the first render, and the
  // first after the window's size changed), vtkOpenGLFramebufferObject::InitializeViewport
  // also turns the depth and scissor tests off, and nothing in IceT's render turns the depth
  // test back on: the scene would be drawn without depth, all at IceT's background depth, and
  // IceT's composite would come out empty (measured: a view resized and rendered once).
  const bool blending = state->GetEnumState(GL_BLEND);
  const bool depthTest = state->GetEnumState(GL_DEPTH_TEST);
  const bool scissorTest = state->GetEnumState(GL_SCISSOR_TEST);
  this->BeginPass(renderer); // binds the RGBA32F framebuffer, clears colour to NaN, depth to 1
  state->SetEnumState(GL_BLEND, blending);
  state->SetEnumState(GL_DEPTH_TEST, depthTest);
  state->SetEnumState(GL_SCISSOR_TEST, scissorTest);
  state->vtkglClearColor(0.0, 0.0, 0.0, 0.0);
  state->vtkglClear(GL_COLOR_BUFFER_BIT);
  this->Delegate->Render(s);
  this->NumberOfRenderedProps = this->Delegate->GetNumberOfRenderedProps();
  this->EndPass();
}

//------------------------------------------------------------------------------
void vtkPVBloomCompositeScenePass::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Superclass::ReleaseGraphicsResources(window);
  this->Delegate->ReleaseGraphicsResources(window);
}

//------------------------------------------------------------------------------
void vtkPVBloomCompositeScenePass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Delegate: " << this->Delegate->GetClassName() << "\n";
}
