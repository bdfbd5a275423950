// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// The OpenGL resources of vtkBloomPass: saved state, float targets, the scene target and the
// chain's targets (see vtkBloomPassResources.h).
#include "vtkBloomPassResources.h"

#include <algorithm>

#include "vtkBloomParameters.h"
#include "vtkBloomVTKCompat.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPointData.h"
#include "vtkRenderbuffer.h"
#include "vtkTextureObject.h"

//------------------------------------------------------------------------------
vtkBloomPassSavedState::vtkBloomPassSavedState(vtkOpenGLState* state)
  : Blend(state, GL_BLEND)
  , Depth(state, GL_DEPTH_TEST)
  , Scissor(state, GL_SCISSOR_TEST)
  , BlendFunc(state)
  , Viewport(state)
  , ScissorBox(state)
  , ClearColor(state)
{
}

//------------------------------------------------------------------------------
void vtkBloomPassTarget::Allocate(
  vtkOpenGLRenderWindow* context, int width, int height, unsigned int format)
{
  if (this->Color && this->Size[0] == width && this->Size[1] == height &&
    this->Color->GetInternalFormat(VTK_FLOAT, 4, false) == format)
  {
    return;
  }
  this->Release(context);
  this->Color = vtkSmartPointer<vtkTextureObject>::New();
  this->Color->SetContext(context);
  this->Color->SetInternalFormat(format);
  this->Color->SetMinificationFilter(vtkTextureObject::Nearest);
  this->Color->SetMagnificationFilter(vtkTextureObject::Nearest);
  this->Color->SetWrapS(vtkTextureObject::ClampToEdge);
  this->Color->SetWrapT(vtkTextureObject::ClampToEdge);
  this->Color->Allocate2D(width, height, 4, VTK_FLOAT);
  this->FBO = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
  this->FBO->SetContext(context);
  context->GetState()->PushFramebufferBindings();
  this->FBO->Bind();
  this->FBO->AddColorAttachment(0, this->Color);
  this->FBO->ActivateDrawBuffer(0);
  context->GetState()->PopFramebufferBindings();
  this->Size[0] = width;
  this->Size[1] = height;
  // Undefined content: dirty everywhere until a pass or a clear says otherwise.
  this->Dirty[0] = this->Dirty[2] = 0;
  this->Dirty[1] = width;
  this->Dirty[3] = height;
}

//------------------------------------------------------------------------------
void vtkBloomPassTarget::Release(vtkWindow* window)
{
  if (this->FBO)
  {
    this->FBO->ReleaseGraphicsResources(window);
  }
  if (this->Color)
  {
    this->Color->ReleaseGraphicsResources(window);
  }
  this->FBO = nullptr;
  this->Color = nullptr;
  this->Size[0] = this->Size[1] = 0;
}

//------------------------------------------------------------------------------
bool vtkBloomPassTarget::Read(vtkOpenGLRenderWindow* context, vtkImageData* image)
{
  context->MakeCurrent();
  vtkOpenGLState* state = context->GetState();
  state->PushFramebufferBindings();
  this->FBO->Bind(GL_READ_FRAMEBUFFER);
  this->FBO->ActivateReadBuffer(0);
  image->Initialize();
  image->SetExtent(0, this->Size[0] - 1, 0, this->Size[1] - 1, 0, 0);
  image->SetOrigin(0.0, 0.0, 0.0);
  image->SetSpacing(1.0, 1.0, 1.0);
  image->AllocateScalars(VTK_FLOAT, 4);
  image->GetPointData()->GetScalars()->SetName("RGBA");
  state->vtkglPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, this->Size[0], this->Size[1], GL_RGBA, GL_FLOAT, image->GetScalarPointer());
  state->PopFramebufferBindings();
  return true;
}

//------------------------------------------------------------------------------
unsigned int vtkBloomPassDepthFormat(vtkOpenGLRenderWindow* context)
{
  // The window's own depth format, as VTK's translucent passes allocate theirs
  // (vtkOrderIndependentTranslucentPass blits the scene's depth into a texture of that format,
  // and a blit between depth formats that differ is an error).
  if (context->GetStencilCapable())
  {
    return GL_DEPTH24_STENCIL8;
  }
  return context->GetDepthBufferSize() == 32 ? GL_DEPTH_COMPONENT32 : GL_DEPTH_COMPONENT24;
}

//------------------------------------------------------------------------------
void vtkBloomPassSceneTarget::AllocateWithDepth(vtkOpenGLRenderWindow* context, int width,
  int height, unsigned int format, unsigned int depthFormat)
{
  if (this->Color && this->Size[0] == width && this->Size[1] == height &&
    this->DepthFormat == depthFormat)
  {
    return;
  }
  this->Allocate(context, width, height, format);
  this->Depth = vtkSmartPointer<vtkTextureObject>::New();
  this->Depth->SetContext(context);
  if (depthFormat == GL_DEPTH24_STENCIL8)
  {
    this->Depth->AllocateDepthStencil(width, height);
  }
  else
  {
    this->Depth->AllocateDepth(width, height,
      depthFormat == GL_DEPTH_COMPONENT32 ? vtkTextureObject::Fixed32 : vtkTextureObject::Fixed24);
  }
  this->DepthFormat = depthFormat;
  context->GetState()->PushFramebufferBindings();
  this->FBO->Bind();
  this->FBO->AddDepthAttachment(this->Depth);
  context->GetState()->PopFramebufferBindings();
}

//------------------------------------------------------------------------------
void vtkBloomPassSceneTarget::ReleaseAll(vtkWindow* window)
{
  this->Release(window);
  if (this->Depth)
  {
    this->Depth->ReleaseGraphicsResources(window);
  }
  this->Depth = nullptr;
}

//------------------------------------------------------------------------------
void vtkBloomPassMultisampleTarget::Allocate(vtkOpenGLRenderWindow* context, int width, int height,
  unsigned int format, unsigned int depthFormat, int samples)
{
  if (this->FBO && this->Size[0] == width && this->Size[1] == height && this->Samples == samples &&
    this->Format == format && this->DepthFormat == depthFormat)
  {
    return;
  }
  this->Release(context);
  this->Color = vtkSmartPointer<vtkTextureObject>::New();
  this->Color->SetContext(context);
  this->Color->SetSamples(static_cast<unsigned int>(samples));
  this->Color->SetInternalFormat(format);
  this->Color->Allocate2D(width, height, 4, VTK_FLOAT);
  // The depth's format is the scene target's, as a depth resolve requires.
  this->Depth = vtkSmartPointer<vtkRenderbuffer>::New();
  this->Depth->SetContext(context);
  this->Depth->Create(depthFormat, width, height, samples);
  this->FBO = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
  this->FBO->SetContext(context);
  context->GetState()->PushFramebufferBindings();
  this->FBO->Bind();
  this->FBO->AddColorAttachment(0, this->Color);
  this->FBO->AddDepthAttachment(this->Depth);
  this->FBO->ActivateDrawBuffer(0);
  context->GetState()->PopFramebufferBindings();
  this->Size[0] = width;
  this->Size[1] = height;
  this->Samples = samples;
  this->Format = format;
  this->DepthFormat = depthFormat;
}

//------------------------------------------------------------------------------
void vtkBloomPassMultisampleTarget::Release(vtkWindow* window)
{
  if (this->FBO)
  {
    this->FBO->ReleaseGraphicsResources(window);
  }
  if (this->Color)
  {
    this->Color->ReleaseGraphicsResources(window);
  }
  if (this->Depth)
  {
    this->Depth->ReleaseGraphicsResources(window);
  }
  this->FBO = nullptr;
  this->Color = nullptr;
  this->Depth = nullptr;
  this->Size[0] = this->Size[1] = this->Samples = 0;
}

//------------------------------------------------------------------------------
void vtkBloomPassMultisampleTarget::Resolve(
  vtkOpenGLRenderWindow* context, vtkBloomPassSceneTarget& target, bool depth)
{
  vtkOpenGLState* state = context->GetState();
  state->PushFramebufferBindings();
  this->FBO->Bind(GL_READ_FRAMEBUFFER);
  this->FBO->ActivateReadBuffer(0);
  target.FBO->Bind(GL_DRAW_FRAMEBUFFER);
  target.FBO->ActivateDrawBuffer(0);
  // A multisample resolve must cover the same rectangle; depth resolves by nearest.
  glBlitFramebuffer(0, 0, this->Size[0], this->Size[1], 0, 0, this->Size[0], this->Size[1],
    depth ? GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT : GL_COLOR_BUFFER_BIT, GL_NEAREST);
  state->PopFramebufferBindings();
}

//------------------------------------------------------------------------------
void vtkBloomPassResources::AllocateScene(int width, int height, bool emitters, int samples)
{
  const unsigned int depthFormat = vtkBloomPassDepthFormat(this->Context);
  this->Samples = samples > 1 ? samples : 0;
  if (this->Samples)
  {
    this->Multisample.Allocate(
      this->Context, width, height, this->Format, depthFormat, this->Samples);
  }
  else
  {
    this->Multisample.Release(this->Context);
  }
  this->Scene.AllocateWithDepth(this->Context, width, height, this->Format, depthFormat);
  if (emitters)
  {
    this->Emitter.AllocateWithDepth(this->Context, width, height, this->Format, depthFormat);
  }
  else
  {
    this->Emitter.ReleaseAll(this->Context);
  }
}

//------------------------------------------------------------------------------
bool vtkBloomPassResources::ChainIsStale(
  vtkBloomParameters* parameters, int width, int height, const int part[4]) const
{
  // The chain depends on the size, the part of a frame and the parameters only.
  return this->ChainTime == 0 || this->ChainParameters != parameters ||
    this->ChainTime < parameters->GetMTime() || this->Chain.Width != width ||
    this->Chain.Height != height || !std::equal(part, part + 4, this->ChainPart);
}

//------------------------------------------------------------------------------
void vtkBloomPassResources::BuildChain(vtkBloomParameters* parameters, int width, int height,
  const vtkBloomChain* frame, const int part[4])
{
  vtkOpenGLRenderWindow* window = this->Context;
  const vtkMTimeType parametersTime = parameters->GetMTime();
  this->ReleaseChain(window);
  if (frame)
  {
    const int begin[2] = { part[0], part[2] };
    const int end[2] = { part[1], part[3] };
    this->Chain.Cut(*frame, begin, end);
  }
  else
  {
    this->Chain.Build(parameters, width, height);
  }
  std::copy(part, part + 4, this->ChainPart);
  this->ChainTime = parametersTime;
  this->ChainParameters = parameters;
  const size_t n = this->Chain.Levels.size();
  // The scene is stored at the requested precision; the chain always runs on 32-bit floats, so
  // that half-float rounding does not compound over its dozen passes.
  const unsigned int chainFormat = GL_RGBA32F;
  this->Levels.resize(n);
  this->Work.resize(n);
  this->Accum.resize(this->Chain.AccumulateMode == vtkBloomParameters::CASCADE ? n : 0);
  for (size_t i = 0; i < n; ++i)
  {
    const int* size = this->Chain.Levels[i].Size;
    this->Levels[i].Allocate(window, size[0], size[1], chainFormat);
    this->Work[i].Allocate(window, size[0], size[1], chainFormat);
    if (!this->Accum.empty())
    {
      this->Accum[i].Allocate(window, size[0], size[1], chainFormat);
    }
  }
  if (n > 0)
  {
    // The x passes run on the levels only (the source fetch and the final resample are
    // two-dimensional passes), so level 0 is the largest intermediate.
    this->Temp.Allocate(
      window, this->Chain.Levels[0].Size[0], this->Chain.Levels[0].Size[1], chainFormat);
    if (this->Chain.AccumulateMode == vtkBloomParameters::DIRECT)
    {
      this->Full.Allocate(window, width, height, chainFormat);
    }
  }
}

//------------------------------------------------------------------------------
void vtkBloomPassResources::ReleaseChain(vtkWindow* w)
{
  for (auto* list : { &this->Levels, &this->Work, &this->Accum, &this->Reduce })
  {
    for (auto& t : *list)
    {
      t.Release(w);
    }
    list->clear();
  }
  this->Temp.Release(w);
  this->Full.Release(w);
  this->ChainTime = 0;
}

//------------------------------------------------------------------------------
void vtkBloomPassResources::ReleaseAll(vtkWindow* w)
{
  this->ReleaseChain(w);
  this->PSFBright.Release(w);
  this->PSFBloom.Release(w);
  this->Scene.ReleaseAll(w);
  this->Emitter.ReleaseAll(w);
  this->Multisample.Release(w);
  this->Result.Release(w);
  this->Kept.Release(w);
  this->Background.Release(w);
  this->Context = nullptr;
}
