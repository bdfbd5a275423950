// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// vtkBloomPass's chain as compute shaders (OpenGL 4.3): the same vtkBloomPassFS.glsl compiled
// with COMPUTE, one invocation per output sample, written with imageStore. On a GPU whose
// fragment shading runs on part of the chip only (an NVIDIA H100: docs/gpu.md), a compute pass
// does the same work many times faster. The composite writes the framebuffer it was called
// with the same way, where that framebuffer's colour buffer is a texture (FramebufferImage).
// VTK 9.1's shader classes have no compute stage, so the programs are plain OpenGL; their
// uniforms go through vtkBloomPassChainRunner::Uniforms.
#include "vtkBloomPassChainRunner.h"

#include "vtkBloomPassFS.h"
#include "vtkBloomPassPrograms.h"
#include "vtkBloomPassResources.h"
#include "vtkBloomVTKCompat.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include <algorithm>
#include <string>

//------------------------------------------------------------------------------
int vtkBloomPassChainRunner::Uniforms::Location(const char* name)
{
  if (this->Program)
  {
    return this->Program->IsUniformUsed(name) ? 0 : -1;
  }
  LocationCache& cache = *this->Locations;
  for (const LocationCache::Seen& seen : cache.ByAddress)
  {
    if (seen.Address == name && seen.Name == name)
    {
      return seen.Location;
    }
  }
  auto found = cache.ByName.find(name);
  if (found == cache.ByName.end())
  {
    found = cache.ByName.emplace(name, glGetUniformLocation(this->Raw, name)).first;
  }
  if (cache.ByAddress.size() < LocationCache::MaximumSeen)
  {
    cache.ByAddress.push_back({ name, found->first, found->second });
  }
  return found->second;
}

//------------------------------------------------------------------------------
void vtkBloomPassChainRunner::Uniforms::Int(const char* name, int value)
{
  const int at = this->Location(name);
  if (at >= 0 && this->Program)
  {
    this->Program->SetUniformi(name, value);
  }
  else if (at >= 0)
  {
    glUniform1i(at, value);
  }
}

//------------------------------------------------------------------------------
void vtkBloomPassChainRunner::Uniforms::Float(const char* name, double value)
{
  const int at = this->Location(name);
  if (at >= 0 && this->Program)
  {
    this->Program->SetUniformf(name, static_cast<float>(value));
  }
  else if (at >= 0)
  {
    glUniform1f(at, static_cast<float>(value));
  }
}

//------------------------------------------------------------------------------
void vtkBloomPassChainRunner::Uniforms::Int2(const char* name, const int values[2])
{
  const int at = this->Location(name);
  if (at >= 0 && this->Program)
  {
    this->Program->SetUniform2i(name, values);
  }
  else if (at >= 0)
  {
    glUniform2i(at, values[0], values[1]);
  }
}

//------------------------------------------------------------------------------
void vtkBloomPassChainRunner::Uniforms::Float2(const char* name, const float values[2])
{
  const int at = this->Location(name);
  if (at >= 0 && this->Program)
  {
    this->Program->SetUniform2f(name, values);
  }
  else if (at >= 0)
  {
    glUniform2f(at, values[0], values[1]);
  }
}

//------------------------------------------------------------------------------
void vtkBloomPassChainRunner::Uniforms::Float3(const char* name, const double values[3])
{
  const float v[3] = { static_cast<float>(values[0]), static_cast<float>(values[1]),
    static_cast<float>(values[2]) };
  const int at = this->Location(name);
  if (at >= 0 && this->Program)
  {
    this->Program->SetUniform3f(name, v);
  }
  else if (at >= 0)
  {
    glUniform3f(at, v[0], v[1], v[2]);
  }
}

//------------------------------------------------------------------------------
void vtkBloomPassChainRunner::Uniforms::Float4(const char* name, const float values[4])
{
  const int at = this->Location(name);
  if (at >= 0 && this->Program)
  {
    this->Program->SetUniform4f(name, values);
  }
  else if (at >= 0)
  {
    glUniform4f(at, values[0], values[1], values[2], values[3]);
  }
}

//------------------------------------------------------------------------------
void vtkBloomPassChainRunner::Uniforms::Ints(const char* name, int count, const int* values)
{
  const int at = this->Location(name);
  if (at >= 0 && this->Program)
  {
    this->Program->SetUniform1iv(name, count, values);
  }
  else if (at >= 0)
  {
    glUniform1iv(at, count, values);
  }
}

//------------------------------------------------------------------------------
void vtkBloomPassChainRunner::Uniforms::Floats(const char* name, int count, const float* values)
{
  const int at = this->Location(name);
  if (at >= 0 && this->Program)
  {
    this->Program->SetUniform1fv(name, count, values);
  }
  else if (at >= 0)
  {
    glUniform1fv(at, count, values);
  }
}

//------------------------------------------------------------------------------
bool vtkBloomPassChainRunner::ComputeSupported()
{
  if (this->ComputeSupport == 0)
  {
    this->ComputeSupport = vtkBloomPassPrograms::ContextRunsCompute(&this->GLVersion) ? 1 : -1;
  }
  return this->ComputeSupport > 0;
}

//------------------------------------------------------------------------------
bool vtkBloomPassChainRunner::SampleShadingSupported()
{
  if (this->SampleShading == 0)
  {
    // The extension, also where OpenGL 4.0 has it in its core: VTK's shaders are GLSL 1.50,
    // which reach gl_SampleID through it.
    this->SampleShading = vtkBloomPassPrograms::HasExtension("GL_ARB_sample_shading") ? 1 : -1;
  }
  return this->SampleShading > 0;
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkBloomPassChainRunner::CompositeSamples()
{
  // Over the layers below (Output::Over) the first composite has blended already: a sample
  // cannot be composited again.
  if (!this->Out.SceneSamples || this->Out.SceneSampleCount < 2 || this->Out.Over)
  {
    return nullptr;
  }
  GLint samples = 0;
  glGetIntegerv(GL_SAMPLES, &samples);
  return samples == this->Out.SceneSampleCount && this->SampleShadingSupported()
    ? this->Out.SceneSamples
    : nullptr;
}

//------------------------------------------------------------------------------
bool vtkBloomPassChainRunner::SoftwareRasterizer()
{
  if (this->Software == 0)
  {
    const GLubyte* name = glGetString(GL_RENDERER);
    const std::string renderer = name ? reinterpret_cast<const char*>(name) : "";
    bool software = false;
    for (const char* cpu : { "llvmpipe", "softpipe", "SwiftShader" })
    {
      software = software || renderer.find(cpu) != std::string::npos;
    }
    this->Software = software ? 1 : -1;
  }
  return this->Software > 0;
}

//------------------------------------------------------------------------------
vtkBloomPassChainRunner::ImageTarget vtkBloomPassChainRunner::ComputeTarget(
  vtkBloomPassTarget* target, const int origin[2], const PassSpec& spec, int width, int height)
{
  // The bright pass under an occlusion query counts fragments: it stays a fragment pass.
  ImageTarget image;
  // A pass over the framebuffer's content blends: a fragment pass.
  if (!this->Frame.UseCompute || (spec.DiscardZero && this->CountingSamples) ||
    (!target && this->Out.Over) || !this->ComputeSupported())
  {
    return image;
  }
  if (target)
  {
    image.Texture = target->Color->GetHandle();
    image.Format = target->Color->GetInternalFormat(VTK_FLOAT, 4, false);
    image.Offset[0] = origin[0];
    image.Offset[1] = origin[1];
  }
  else
  {
    // The samples the pass writes into the framebuffer: the composite's window of the frame.
    const Box written = spec.Step == STEP_COMPOSITE ? Box::Window(this->Out.Window, width, height)
                                                    : Box::Whole(width, height);
    const int corner[2] = { origin[0] + written.X0, origin[1] + written.Y0 };
    if (!this->FramebufferImage(corner, written.X1 - written.X0, written.Y1 - written.Y0, image))
    {
      return ImageTarget();
    }
    image.Offset[0] = origin[0];
    image.Offset[1] = origin[1];
  }
  return image;
}

//------------------------------------------------------------------------------
bool vtkBloomPassChainRunner::FramebufferImage(
  const int origin[2], int width, int height, ImageTarget& image)
{
  // A fragment pass into the window's framebuffer runs on the GPU's graphics units, which on
  // an NVIDIA H100 are a few of its multiprocessors: there a full-screen copy takes 0.59 ms at
  // 3840x2160 as fragments (a blit too) and 0.06 ms as a compute pass (docs/gpu.md). The
  // compute pass must write what the fragments would: no blending (Pass() turns it off), no
  // scissor (vtkBloomPass::Render turns it off), and everything else checked here.
  if (this->GLVersion < 45 || !glGetTextureParameteriv || !glGetTextureLevelParameteriv)
  {
    return false;
  }
  GLint framebuffer = 0, samples = 0, buffer = GL_NONE;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &framebuffer);
  glGetIntegerv(GL_SAMPLES, &samples);
  glGetIntegerv(GL_DRAW_BUFFER0, &buffer);
  if (framebuffer == 0 || samples != 0 || buffer < GL_COLOR_ATTACHMENT0 ||
    buffer > GL_COLOR_ATTACHMENT15)
  {
    return false;
  }
  GLint type = GL_NONE, name = 0, level = 0, layered = GL_FALSE;
  const GLenum attachment = static_cast<GLenum>(buffer);
  glGetFramebufferAttachmentParameteriv(
    GL_DRAW_FRAMEBUFFER, attachment, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
  if (type != GL_TEXTURE)
  {
    return false;
  }
  glGetFramebufferAttachmentParameteriv(
    GL_DRAW_FRAMEBUFFER, attachment, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &name);
  glGetFramebufferAttachmentParameteriv(
    GL_DRAW_FRAMEBUFFER, attachment, GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL, &level);
  glGetFramebufferAttachmentParameteriv(
    GL_DRAW_FRAMEBUFFER, attachment, GL_FRAMEBUFFER_ATTACHMENT_LAYERED, &layered);
  GLint kind = GL_NONE, format = GL_NONE, size[2] = { 0, 0 };
  glGetTextureParameteriv(static_cast<GLuint>(name), GL_TEXTURE_TARGET, &kind);
  if (kind != GL_TEXTURE_2D || layered != GL_FALSE)
  {
    return false;
  }
  const GLuint texture = static_cast<GLuint>(name);
  glGetTextureLevelParameteriv(texture, level, GL_TEXTURE_INTERNAL_FORMAT, &format);
  glGetTextureLevelParameteriv(texture, level, GL_TEXTURE_WIDTH, &size[0]);
  glGetTextureLevelParameteriv(texture, level, GL_TEXTURE_HEIGHT, &size[1]);
  GLboolean mask[4] = { GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE };
  glGetBooleanv(GL_COLOR_WRITEMASK, mask);
  if ((format != GL_RGBA8 && format != GL_RGBA16F && format != GL_RGBA32F) || origin[0] < 0 ||
    origin[1] < 0 || origin[0] + width > size[0] || origin[1] + height > size[1] || !mask[0] ||
    !mask[1] || !mask[2] || !mask[3])
  {
    return false;
  }
  image.Texture = texture;
  image.Level = level;
  image.Format = static_cast<unsigned int>(format);
  image.Offset[0] = origin[0];
  image.Offset[1] = origin[1];
  return true;
}

//------------------------------------------------------------------------------
vtkBloomPassChainRunner::ComputeProgram* vtkBloomPassChainRunner::Compute(
  const std::string& variant, bool blend, unsigned int format)
{
  const char* layout = format == GL_RGBA8 ? "rgba8" : format == GL_RGBA16F ? "rgba16f" : "rgba32f";
  const std::string header = std::string("#version 430 core\n#define COMPUTE 1\n#define BLEND ") +
    (blend ? "1" : "0") + "\n#define IMAGE_FORMAT " + layout + "\n";
  const std::string key = header + variant;
  if (this->FailedCompute.count(key))
  {
    return nullptr;
  }
  ComputeProgram& program = this->ComputePrograms[key];
  if (program.Id)
  {
    return &program;
  }
  std::string text = vtkBloomPassFS;
  vtkShaderProgram::Substitute(text, "//VTK::System::Dec", header);
  vtkShaderProgram::Substitute(text, "//VTK::Output::Dec", "");
  vtkShaderProgram::Substitute(text, "//BLOOM::Constants", ShaderConstants());
  vtkShaderProgram::Substitute(text, "//BLOOM::Variant", variant);
  std::string log;
  const GLuint id = this->Frame.SimulateComputeFailure
    ? 0
    : vtkBloomPassPrograms::BuildComputeProgram(text.c_str(), &log);
  if (!id)
  {
    // Its passes run as fragments from now on; one warning says so, for the first variant.
    if (!this->WarnedComputeFallback)
    {
      vtkWarningWithObjectMacro(this->Owner,
        << "A bloom compute program did not build; its passes run as fragment passes instead. "
        << (this->Frame.SimulateComputeFailure ? "(simulated for a test)" : log));
      this->WarnedComputeFallback = true;
    }
    this->ComputePrograms.Erase(key);
    this->FailedCompute.insert(key);
    return nullptr;
  }
  program.Id = id;
  this->CompiledProgram = true;
  return &program;
}

//------------------------------------------------------------------------------
void vtkBloomPassChainRunner::Dispatch(const ImageTarget& image, bool blend, const Box& rect)
{
  glBindImageTexture(0, image.Texture, image.Level, GL_FALSE, 0,
    blend ? GL_READ_WRITE : GL_WRITE_ONLY, image.Format);
  glDispatchCompute((rect.X1 - rect.X0 + 15) / 16, (rect.Y1 - rect.Y0 + 15) / 16, 1);
}

//------------------------------------------------------------------------------
vtkBloomPassChainRunner::TextureNames vtkBloomPassChainRunner::NamesOf(const PassTextures& textures)
{
  TextureNames names = {};
  for (size_t t = 0; t < names.size(); ++t)
  {
    names[t] = textures.Textures[t] ? textures.Textures[t]->GetHandle() : 0;
  }
  return names;
}

//------------------------------------------------------------------------------
void vtkBloomPassChainRunner::BeforeComputePass(const TextureNames& reads, unsigned int written)
{
  auto pending = [](const std::vector<unsigned int>& names, unsigned int name)
  { return std::find(names.begin(), names.end(), name) != names.end(); };
  // Read after write, write after read, write after write: only these need the barrier.
  bool hazard = pending(this->PendingWrites, written) || pending(this->PendingReads, written);
  for (unsigned int name : reads)
  {
    hazard = hazard || (name && pending(this->PendingWrites, name));
  }
  if (hazard)
  {
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    this->PendingWrites.clear();
    this->PendingReads.clear();
  }
}

//------------------------------------------------------------------------------
void vtkBloomPassChainRunner::AfterComputePass(const TextureNames& reads, unsigned int written)
{
  this->PendingWrites.push_back(written);
  for (unsigned int name : reads)
  {
    if (name)
    {
      this->PendingReads.push_back(name);
    }
  }
  glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  this->Resources.Context->GetShaderCache()->ReleaseCurrentShader();
}

//------------------------------------------------------------------------------
void vtkBloomPassChainRunner::FlushComputeWrites()
{
  if (!this->PendingWrites.empty())
  {
    // What follows may clear, draw into, read back or sample any target.
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
      GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT | GL_PIXEL_BUFFER_BARRIER_BIT);
  }
  this->PendingWrites.clear();
  this->PendingReads.clear();
}

//------------------------------------------------------------------------------
void vtkBloomPassChainRunner::EndCompute()
{
  // The next pass reads the target by texelFetch or imageLoad, clears it or reads it back;
  // after the composite, VTK draws into the framebuffer, blits it or reads its pixels.
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
    GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT | GL_PIXEL_BUFFER_BARRIER_BIT);
  glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  // VTK's shader cache must know that its last program is no longer bound.
  this->Resources.Context->GetShaderCache()->ReleaseCurrentShader();
}
