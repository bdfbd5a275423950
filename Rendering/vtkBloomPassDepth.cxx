// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// The scene's depth written where the frame is composited (see vtkBloomPassDepth.h).
#include "vtkBloomPassDepth.h"

#include "vtkBloomVTKCompat.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderUtilities.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

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
void vtkBloomPassDepth::ReleaseGraphicsResources(vtkWindow* window)
{
  if (this->Quad)
  {
    this->Quad->ReleaseGraphicsResources(window);
  }
  this->Quad.reset();
}
