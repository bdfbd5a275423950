// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkBloomPassPrograms.h"

#include "vtkBloomVTKCompat.h"

#include <cstring>
#include <string>

//------------------------------------------------------------------------------
bool vtkBloomPassPrograms::HasExtension(const char* wanted)
{
  GLint count = 0;
  glGetIntegerv(GL_NUM_EXTENSIONS, &count);
  for (GLint i = 0; i < count; ++i)
  {
    const GLubyte* name = glGetStringi(GL_EXTENSIONS, static_cast<GLuint>(i));
    if (name && std::strcmp(reinterpret_cast<const char*>(name), wanted) == 0)
    {
      return true;
    }
  }
  return false;
}

//------------------------------------------------------------------------------
bool vtkBloomPassPrograms::ContextRunsCompute(int* version)
{
  GLint major = 0, minor = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  if (version)
  {
    *version = major * 10 + minor;
  }
  // An older context may list what OpenGL 4.3 made core: VTK 9.6's EGL window asks for 3.2,
  // and NVIDIA's driver gives exactly 3.2, with every extension of the card.
  const bool extensions = major * 10 + minor >= 43 ||
    (HasExtension("GL_ARB_compute_shader") && HasExtension("GL_ARB_shader_image_load_store") &&
      HasExtension("GL_ARB_shader_storage_buffer_object"));
  return extensions && glDispatchCompute && glBindImageTexture && glMemoryBarrier &&
    glBindBufferBase;
}

//------------------------------------------------------------------------------
unsigned int vtkBloomPassPrograms::BuildComputeProgram(const char* source, std::string* log)
{
  const GLuint shader = glCreateShader(GL_COMPUTE_SHADER);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint compiled = 0, linked = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &compiled);
  GLuint program = glCreateProgram();
  glAttachShader(program, shader);
  glLinkProgram(program);
  glGetProgramiv(program, GL_LINK_STATUS, &linked);
  if (!compiled || !linked)
  {
    if (log)
    {
      char text[4096] = { 0 };
      glGetShaderInfoLog(shader, sizeof(text), nullptr, text);
      *log = text;
    }
    glDeleteProgram(program);
    program = 0;
  }
  glDeleteShader(shader);
  return program;
}
