// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// The scene's depth where the frame is composited: shared, or written (see vtkBloomPassDepth.h).
#include "vtkBloomPassDepth.h"

#include "vtkBloomVTKCompat.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderUtilities.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include <algorithm>

namespace
{
// The texel under each fragment: the viewport's pixel (i, j) is the texel (i, j) + first, with
// no interpolation and no flip.
const char* DepthFS = R"(//VTK::System::Dec
in vec2 texCoord;
uniform sampler2D sceneDepth;
uniform vec2 size;   // the viewport's, in pixels
uniform ivec2 first; // the texel of the viewport's pixel (0, 0)
//VTK::Output::Dec
void main()
{
  gl_FragDepth = texelFetch(sceneDepth, ivec2(texCoord * size) + first, 0).r;
}
)";
}

//------------------------------------------------------------------------------
vtkBloomPassDepth::vtkBloomPassDepth() = default;

//------------------------------------------------------------------------------
vtkBloomPassDepth::~vtkBloomPassDepth() = default;

//------------------------------------------------------------------------------
void vtkBloomPassDepth::Write(vtkOpenGLRenderWindow* window, vtkTextureObject* depth, int x, int y,
  int width, int height, const int offset[2])
{
  if (!depth || width <= 0 || height <= 0)
  {
    return;
  }
  if (!this->Quad)
  {
    this->Quad.reset(new vtkOpenGLQuadHelper(
      window, vtkOpenGLRenderUtilities::GetFullScreenQuadVertexShader().c_str(), DepthFS, ""));
  }
  else
  {
    window->GetShaderCache()->ReadyShaderProgram(this->Quad->Program);
  }
  if (!this->Quad->Program || !this->Quad->Program->GetCompiled())
  {
    return;
  }
  vtkOpenGLState* state = window->GetState();
  vtkOpenGLState::ScopedglColorMask colorMask(state);
  vtkOpenGLState::ScopedglDepthMask depthMask(state);
  vtkOpenGLState::ScopedglDepthFunc depthFunc(state);
  vtkOpenGLState::ScopedglEnableDisable depthTest(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable blend(state, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable scissor(state, GL_SCISSOR_TEST);
  vtkOpenGLState::ScopedglViewport viewport(state);
  vtkOpenGLState::ScopedglScissor scissorBox(state);
  state->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  state->vtkglDepthMask(GL_TRUE);
  state->vtkglDepthFunc(GL_ALWAYS);
  state->vtkglEnable(GL_DEPTH_TEST);
  state->vtkglDisable(GL_BLEND);
  state->vtkglEnable(GL_SCISSOR_TEST);
  state->vtkglViewport(x, y, width, height);
  state->vtkglScissor(x, y, width, height);
  depth->Activate();
  this->Quad->Program->SetUniformi("sceneDepth", depth->GetTextureUnit());
  const float size[2] = { static_cast<float>(width), static_cast<float>(height) };
  this->Quad->Program->SetUniform2f("size", size);
  this->Quad->Program->SetUniform2i("first", offset);
  this->Quad->Render();
  depth->Deactivate();
}

//------------------------------------------------------------------------------
bool vtkBloomPassDepth::Attachment::Describe(unsigned int framebuffer)
{
  // OpenGL 4.5's direct state access: the framebuffers are not bound, so that VTK's record of
  // the bindings (vtkOpenGLState) stays true.
  *this = Attachment();
  if (!glGetNamedFramebufferAttachmentParameteriv || !glGetNamedRenderbufferParameteriv ||
    !glGetTextureLevelParameteriv || !glGetTextureParameteriv || framebuffer == 0)
  {
    return false;
  }
  GLint type = GL_NONE, name = 0, layered = GL_FALSE;
  glGetNamedFramebufferAttachmentParameteriv(
    framebuffer, GL_DEPTH_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
  if (type != GL_RENDERBUFFER && type != GL_TEXTURE)
  {
    return false;
  }
  glGetNamedFramebufferAttachmentParameteriv(
    framebuffer, GL_DEPTH_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &name);
  this->Type = type;
  this->Name = static_cast<unsigned int>(name);
  if (type == GL_RENDERBUFFER)
  {
    glGetNamedRenderbufferParameteriv(this->Name, GL_RENDERBUFFER_WIDTH, &this->Size[0]);
    glGetNamedRenderbufferParameteriv(this->Name, GL_RENDERBUFFER_HEIGHT, &this->Size[1]);
    glGetNamedRenderbufferParameteriv(this->Name, GL_RENDERBUFFER_SAMPLES, &this->Size[2]);
    return true;
  }
  GLint kind = GL_NONE;
  glGetNamedFramebufferAttachmentParameteriv(
    framebuffer, GL_DEPTH_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL, &this->Level);
  glGetNamedFramebufferAttachmentParameteriv(
    framebuffer, GL_DEPTH_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_LAYERED, &layered);
  glGetTextureParameteriv(this->Name, GL_TEXTURE_TARGET, &kind);
  if (layered != GL_FALSE || (kind != GL_TEXTURE_2D && kind != GL_TEXTURE_2D_MULTISAMPLE))
  {
    return false;
  }
  glGetTextureLevelParameteriv(this->Name, this->Level, GL_TEXTURE_WIDTH, &this->Size[0]);
  glGetTextureLevelParameteriv(this->Name, this->Level, GL_TEXTURE_HEIGHT, &this->Size[1]);
  glGetTextureLevelParameteriv(this->Name, this->Level, GL_TEXTURE_SAMPLES, &this->Size[2]);
  return true;
}

//------------------------------------------------------------------------------
void vtkBloomPassDepth::Attachment::AttachTo(unsigned int framebuffer) const
{
  if (this->Type == GL_RENDERBUFFER)
  {
    glNamedFramebufferRenderbuffer(framebuffer, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, this->Name);
  }
  else
  {
    glNamedFramebufferTexture(framebuffer, GL_DEPTH_ATTACHMENT, this->Name, this->Level);
  }
}

//------------------------------------------------------------------------------
bool vtkBloomPassDepth::Share(unsigned int called, unsigned int target)
{
  this->EndShare();
  Attachment theirs;
  if (!glNamedFramebufferRenderbuffer || !glNamedFramebufferTexture ||
    !glCheckNamedFramebufferStatus || called == target || !theirs.Describe(called) ||
    !this->Own.Describe(target) ||
    !std::equal(theirs.Size, theirs.Size + 3, static_cast<const int*>(this->Own.Size)))
  {
    return false;
  }
  theirs.AttachTo(target);
  this->SharedTarget = target;
  if (glCheckNamedFramebufferStatus(target, GL_DRAW_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
  {
    this->EndShare(); // a combination of formats the driver refuses: Write() instead
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkBloomPassDepth::EndShare()
{
  if (this->SharedTarget)
  {
    this->Own.AttachTo(this->SharedTarget);
    this->SharedTarget = 0;
  }
}

//------------------------------------------------------------------------------
void vtkBloomPassDepth::ReleaseGraphicsResources(vtkWindow* window)
{
  if (this->Quad)
  {
    this->Quad->ReleaseGraphicsResources(window);
  }
  this->Quad.reset();
}
