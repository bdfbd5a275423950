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
  // it as the renderer left it.
  const bool blending = state->GetEnumState(GL_BLEND);
  this->BeginPass(renderer); // binds the RGBA32F framebuffer, clears colour to NaN, depth to 1
  state->SetEnumState(GL_BLEND, blending);
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
