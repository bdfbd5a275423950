// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// The split PSF's convolution on the GPU (see vtkBloomPassPSFSplit.h); its shaders are
// glsl/vtkBloomPassPSFSplitCS.glsl.
#include "vtkBloomPassPSFSplit.h"

#include "vtkBloomPassPSFSplitCS.h"
#include "vtkBloomPassProfiler.h"
#include "vtkBloomPassPrograms.h"
#include "vtkBloomVTKCompat.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include <algorithm>
#include <vector>

namespace
{
// The core's work group: CoreLanes x CoreRows invocations, CoreOutputs each along a row.
constexpr int CoreLanes = 32;
constexpr int CoreRows = 8;
// 8 outputs an invocation: 2.23 ms for a core of radius 16 at 3840x2160 on an NVIDIA H200,
// against 3.03 with 4 and 2.24 with 16; one output column an invocation (16 rows of it) took
// 11.1, and the weights in a uniform block instead of a storage buffer 3.23 with 8 and 2.15
// with 16 (docs/gpu.md).
constexpr int CoreOutputs = 8;
constexpr const char* DownDefines[2] = { "#define SPLIT_DOWN_X 1\n", "#define SPLIT_DOWN_Y 1\n" };

vtkSmartPointer<vtkTextureObject> GridTexture(vtkOpenGLRenderWindow* context, int w, int h)
{
  auto texture = vtkSmartPointer<vtkTextureObject>::New();
  texture->SetContext(context);
  texture->SetInternalFormat(GL_RGBA32F);
  texture->SetMinificationFilter(vtkTextureObject::Nearest);
  texture->SetMagnificationFilter(vtkTextureObject::Nearest);
  texture->Allocate2D(w, h, 4, VTK_FLOAT);
  return texture;
}
}

//------------------------------------------------------------------------------
vtkBloomPassPSFSplit::vtkBloomPassPSFSplit() = default;

//------------------------------------------------------------------------------
vtkBloomPassPSFSplit::~vtkBloomPassPSFSplit() = default;

//------------------------------------------------------------------------------
void vtkBloomPassPSFSplit::SetKernels(const vtkBloomPSFSplit splits[3], vtkMTimeType version)
{
  vtkBloomPassFFT::Kernel tails[3];
  this->CoreRadius = 0;
  for (int c = 0; c < 3; ++c)
  {
    this->Splits[c] = splits[c];
    this->CoreRadius = std::max(this->CoreRadius, splits[c].Core.Radius);
    tails[c] = splits[c].GridKernel();
  }
  this->Scale = splits[0].Scale;
  this->TailFFT.SetKernels(tails, version);
  this->KernelsVersion = version;
}

//------------------------------------------------------------------------------
bool vtkBloomPassPSFSplit::Prepare(
  vtkOpenGLRenderWindow* context, int width, int height, std::string& why)
{
  if (this->Context && this->Context != context)
  {
    this->ReleaseGraphicsResources(this->Context);
  }
  this->Context = context;
  if (this->CoreRadius > MaximumCoreRadius)
  {
    why = "PSF bloom's core radius " + std::to_string(this->CoreRadius) + " is above " +
      std::to_string(MaximumCoreRadius) + " (PSFCoreRadius).";
    return false;
  }
  const int cw = vtkBloomPSFSplit::CoarseSize(width, this->Scale);
  const int ch = vtkBloomPSFSplit::CoarseSize(height, this->Scale);
  if (!this->TailFFT.Prepare(context, cw, ch, why))
  {
    return false;
  }
  if (this->ProgramsRadius != this->CoreRadius)
  {
    // The four programs, found (or built) once per core radius.
    const std::string defines[4] = { DownDefines[0], DownDefines[1], this->CoreDefines(false),
      this->CoreDefines(true) };
    unsigned int* ids[4] = { &this->DownPrograms[0], &this->DownPrograms[1], &this->CorePrograms[0],
      &this->CorePrograms[1] };
    for (int p = 0; p < 4; ++p)
    {
      *ids[p] = this->Program(defines[p], &why);
      if (!*ids[p])
      {
        return false;
      }
    }
    this->ProgramsRadius = this->CoreRadius;
  }
  if (!this->CoarseBright || width != this->Size[0] || height != this->Size[1] ||
    this->Scale != this->TentsScale)
  {
    this->ReleaseTextures();
    this->CoarseRows = GridTexture(context, cw, height);
    this->CoarseBright = GridTexture(context, cw, ch);
    this->CoarseBloom = GridTexture(context, cw, ch);
    this->CoarseSize[0] = cw;
    this->CoarseSize[1] = ch;
    this->Size[0] = width;
    this->Size[1] = height;
    this->UploadTents();
  }
  if (this->CoresVersion != this->KernelsVersion)
  {
    this->UploadCores();
    this->CoresVersion = this->KernelsVersion;
  }
  return true;
}

//------------------------------------------------------------------------------
std::string vtkBloomPassPSFSplit::CoreDefines(bool reflect) const
{
  return "#define SPLIT_CORE 1\n#define CORE_RADIUS " + std::to_string(this->CoreRadius) +
    "\n#define CORE_OUTPUTS " + std::to_string(CoreOutputs) + "\n#define CORE_LANES " +
    std::to_string(CoreLanes) + "\n#define CORE_ROWS " + std::to_string(CoreRows) + "\n" +
    (reflect ? "#define REFLECT 1\n" : "");
}

//------------------------------------------------------------------------------
unsigned int vtkBloomPassPSFSplit::Program(const std::string& defines, std::string* why)
{
  // A program that did not build is remembered (id 0, with its log) and not built again.
  auto found = this->Programs.find(defines);
  if (found == this->Programs.end())
  {
    std::string text = vtkBloomPassPSFSplitCS;
    vtkShaderProgram::Substitute(text, "//VTK::System::Dec", "#version 430 core\n" + defines);
    std::string log;
    const unsigned int id = vtkBloomPassPrograms::BuildComputeProgram(text.c_str(), &log);
    if (!id)
    {
      this->BuildLog = log;
    }
    found = this->Programs.emplace(defines, id).first;
  }
  if (!found->second && why)
  {
    *why = "PSF bloom's split program did not build: " + this->BuildLog;
  }
  return found->second;
}

//------------------------------------------------------------------------------
int vtkBloomPassPSFSplit::Uniform(unsigned int program, const char* name)
{
  return vtkBloomPassFFT::CachedUniform(this->Locations, program, name);
}

//------------------------------------------------------------------------------
void vtkBloomPassPSFSplit::UploadCores()
{
  // Each channel's core centred in the widest one's window, as vec4 (r, g, b, 0) per offset.
  const int r = this->CoreRadius, n = 2 * r + 1;
  std::vector<float> weights(static_cast<size_t>(n) * n * 4, 0.0f);
  for (int c = 0; c < 3; ++c)
  {
    const vtkBloomPSFSplit::Kernel& core = this->Splits[c].Core;
    const int kn = 2 * core.Radius + 1, offset = r - core.Radius;
    for (int y = 0; y < kn; ++y)
    {
      for (int x = 0; x < kn; ++x)
      {
        weights[(static_cast<size_t>(y + offset) * n + x + offset) * 4 + c] =
          static_cast<float>(core.Values[static_cast<size_t>(y) * kn + x]);
      }
    }
  }
  if (!this->CoreBuffer)
  {
    glGenBuffers(1, &this->CoreBuffer);
  }
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->CoreBuffer);
  glBufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(weights.size() * sizeof(float)),
    weights.data(), GL_STATIC_DRAW);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
}

//------------------------------------------------------------------------------
void vtkBloomPassPSFSplit::UploadTents()
{
  // Every column's, then every row's, tent weights (j0, j1, t, 0): the CPU's own.
  std::vector<float> tents;
  for (int axis = 0; axis < 2; ++axis)
  {
    for (int i = 0; i < this->Size[axis]; ++i)
    {
      int j0, j1;
      double t;
      vtkBloomPSFSplit::TentWeights(i, this->Scale, this->CoarseSize[axis], j0, j1, t);
      tents.insert(tents.end(),
        { static_cast<float>(j0), static_cast<float>(j1), static_cast<float>(t), 0.0f });
    }
  }
  if (!this->TentBuffer)
  {
    glGenBuffers(1, &this->TentBuffer);
  }
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->TentBuffer);
  glBufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(tents.size() * sizeof(float)),
    tents.data(), GL_STATIC_DRAW);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
  this->TentsScale = this->Scale;
}

//------------------------------------------------------------------------------
void vtkBloomPassPSFSplit::SetGrid(unsigned int program)
{
  glUniform2i(this->Uniform(program, "imageSize"), this->Size[0], this->Size[1]);
  glUniform2i(this->Uniform(program, "coarseSize"), this->CoarseSize[0], this->CoarseSize[1]);
  glUniform1i(this->Uniform(program, "scale"), this->Scale);
}

//------------------------------------------------------------------------------
void vtkBloomPassPSFSplit::Down(vtkTextureObject* source)
{
  // Along x into CoarseRows (nodes x pixel rows), then along y into CoarseBright.
  vtkTextureObject* from[2] = { source, this->CoarseRows };
  vtkTextureObject* to[2] = { this->CoarseRows, this->CoarseBright };
  const int rows[2] = { this->Size[1], this->CoarseSize[1] };
  for (int axis = 0; axis < 2; ++axis)
  {
    const unsigned int program = this->DownPrograms[axis];
    glUseProgram(program);
    this->SetGrid(program);
    from[axis]->Activate();
    glUniform1i(this->Uniform(program, "source"), from[axis]->GetTextureUnit());
    glBindImageTexture(0, to[axis]->GetHandle(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, this->TentBuffer);
    glDispatchCompute((this->CoarseSize[0] + 15) / 16, (rows[axis] + 15) / 16, 1);
    // The next stage (or the tail's row transforms) reads it as a texture.
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    from[axis]->Deactivate();
  }
  glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, 0);
}

//------------------------------------------------------------------------------
void vtkBloomPassPSFSplit::Core(vtkTextureObject* source, vtkTextureObject* target, bool reflect)
{
  const unsigned int program = this->CorePrograms[reflect ? 1 : 0];
  glUseProgram(program);
  this->SetGrid(program);
  source->Activate();
  glUniform1i(this->Uniform(program, "source"), source->GetTextureUnit());
  this->CoarseBloom->Activate();
  glUniform1i(this->Uniform(program, "tail"), this->CoarseBloom->GetTextureUnit());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, this->CoreBuffer);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, this->TentBuffer);
  glBindImageTexture(0, target->GetHandle(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  const int width = CoreOutputs * CoreLanes;
  glDispatchCompute(
    (this->Size[0] + width - 1) / width, (this->Size[1] + CoreRows - 1) / CoreRows, 1);
  // The composite reads the target by texelFetch or imageLoad next.
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
    GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
  glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, 0);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, 0);
  this->CoarseBloom->Deactivate();
  source->Deactivate();
  // VTK's shader cache must know that its last program is no longer bound.
  this->Context->GetShaderCache()->ReleaseCurrentShader();
}

//------------------------------------------------------------------------------
void vtkBloomPassPSFSplit::Convolve(
  vtkTextureObject* source, vtkTextureObject* target, bool reflect, vtkBloomPassProfiler& profiler)
{
  const double pixels = static_cast<double>(this->Size[0]) * this->Size[1];
  const double nodes = static_cast<double>(this->CoarseSize[0]) * this->CoarseSize[1];
  const int* grid = this->GetGridSize();
  profiler.Begin();
  this->Down(source);
  profiler.End("psf split down", grid[0], grid[1], 16.0 * (pixels + nodes));
  this->TailFFT.Convolve(this->CoarseBright, this->CoarseBloom, reflect, profiler);
  profiler.Begin();
  this->Core(source, target, reflect);
  profiler.End("psf split core", grid[0], grid[1], 32.0 * pixels);
}

//------------------------------------------------------------------------------
void vtkBloomPassPSFSplit::ReleaseTextures()
{
  for (vtkTextureObject* texture :
    { this->CoarseRows.Get(), this->CoarseBright.Get(), this->CoarseBloom.Get() })
  {
    if (texture && this->Context)
    {
      texture->ReleaseGraphicsResources(this->Context);
    }
  }
  this->CoarseRows = this->CoarseBright = this->CoarseBloom = nullptr;
  this->CoarseSize[0] = this->CoarseSize[1] = 0;
}

//------------------------------------------------------------------------------
void vtkBloomPassPSFSplit::ReleaseGraphicsResources(vtkWindow* w)
{
  this->TailFFT.ReleaseGraphicsResources(w);
  if (this->Context)
  {
    for (const auto& program : this->Programs)
    {
      if (program.second)
      {
        glDeleteProgram(program.second);
      }
    }
    for (unsigned int* buffer : { &this->CoreBuffer, &this->TentBuffer })
    {
      if (*buffer)
      {
        glDeleteBuffers(1, buffer);
      }
    }
  }
  this->ReleaseTextures();
  this->Programs.clear();
  this->Locations.clear();
  this->CoreBuffer = this->TentBuffer = 0;
  this->CoresVersion = 0;
  this->ProgramsRadius = -1;
  this->TentsScale = 0;
  this->Size[0] = this->Size[1] = 0;
  this->Context = nullptr;
}
