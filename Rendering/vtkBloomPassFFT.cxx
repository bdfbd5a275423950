// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// PSF bloom's convolution on the GPU (see vtkBloomPassFFT.h): the buffers, the twiddle tables,
// the kernels' spectra and the six dispatches of a convolution. The shaders are
// glsl/vtkBloomPassFFTCS.glsl.
#include "vtkBloomPassFFT.h"

#include "vtkBloomPassFFTCS.h"
#include "vtkBloomPassProfiler.h"
#include "vtkBloomPassPrograms.h"
#include "vtkBloomVTKCompat.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include <algorithm>
#include <cmath>

namespace
{
// Work groups of the point-wise stages (separate, multiply, fold): 16 x 16.
constexpr int Tile = 16;

int Groups(int n)
{
  return (n + Tile - 1) / Tile;
}
}

//------------------------------------------------------------------------------
vtkBloomPassFFT::vtkBloomPassFFT() = default;

//------------------------------------------------------------------------------
vtkBloomPassFFT::~vtkBloomPassFFT() = default;

//------------------------------------------------------------------------------
int vtkBloomPassFFT::GoodSize(int n)
{
  for (int m = std::max(n, 1);; ++m)
  {
    int r = m;
    for (int p : { 2, 3, 5 })
    {
      while (r % p == 0)
      {
        r /= p;
      }
    }
    if (r == 1)
    {
      return m;
    }
  }
}

//------------------------------------------------------------------------------
std::vector<int> vtkBloomPassFFT::Radices(int n)
{
  // Radix 4 first: fewer stages and a butterfly with no multiplication.
  std::vector<int> radices;
  for (int p : { 4, 2, 3, 5 })
  {
    while (n % p == 0)
    {
      radices.push_back(p);
      n /= p;
    }
  }
  return radices;
}

//------------------------------------------------------------------------------
bool vtkBloomPassFFT::Split(int n, int& n1, int& n2, int longest)
{
  n1 = n;
  n2 = 1;
  if (n <= longest)
  {
    return true;
  }
  // Factors close to sqrt(n): more, shorter work groups rather than a few long ones.
  for (int d = 1; d <= MaximumLength; ++d)
  {
    if (n % d == 0 && static_cast<long long>(d) * d >= n && n / d <= MaximumLength)
    {
      n1 = d;
      n2 = n / d;
      return true;
    }
  }
  return false;
}

//------------------------------------------------------------------------------
int vtkBloomPassFFT::LongestOnePass(int axis)
{
  // A column of more than 2048 samples fills shared memory alone, so its work group reads one
  // sample a row; in four steps, 32 columns a group, it read and wrote in runs: 0.45 against
  // 0.79 ms each way for 2304-sample columns on an NVIDIA H200 (docs/gpu.md).
  return axis == 0 ? MaximumLength : MaximumLength / 2;
}

//------------------------------------------------------------------------------
std::vector<vtkBloomPassFFT::Pass> vtkBloomPassFFT::Passes(int n, int axis, float direction)
{
  int n1 = n, n2 = 1;
  Split(n, n1, n2, LongestOnePass(axis));
  if (n2 == 1)
  {
    return { Pass{ n, 1, 0, 1, false } };
  }
  // The strided sub-sequences (n1 samples, stride n2, n2 of them) and the contiguous runs (n2
  // samples, n1 of them). The twiddle follows the first dispatch of either direction.
  const Pass strided{ n1, n2, 1, n2, direction < 0.0f };
  const Pass runs{ n2, n1, n2, 1, direction > 0.0f };
  if (direction < 0.0f)
  {
    return { strided, runs };
  }
  return { runs, strided };
}

//------------------------------------------------------------------------------
vtkBloomPassFFT::Layout vtkBloomPassFFT::LayoutOf(const Pass& pass, int axis)
{
  const int length = pass.Length;
  int widest = 1; // the most butterflies of a stage
  for (int r : Radices(length))
  {
    widest = std::max(widest, length / r);
  }
  Layout layout;
  // A short line gets an invocation per butterfly of its widest stage; a longer one enough
  // that each runs at most 4 butterflies of radix 2, keeping their results in registers.
  layout.Threads = widest <= 64 ? widest : (length <= 512 ? 64 : (length <= 2048 ? 256 : 512));
  layout.Butterflies = (widest + layout.Threads - 1) / layout.Threads;
  // Units adjacent in memory, several to a group: columns (lines adjacent) or the sub-sequences
  // of a row's four-step transform (adjacent, or runs one after another).
  layout.BlockSubs = axis == 0 && pass.Count > 1;
  layout.SamplesFastest = axis == 0 && pass.Spacing == 1;
  layout.Lines = 1;
  layout.Stride = length;
  if (axis == 1 || layout.BlockSubs)
  {
    // Up to 32 columns (runs of 256 bytes a row) or 8 of a row's sub-sequences, as many as
    // fit in shared memory and in 1024 invocations (every context allows that many): the
    // best of 4 to 32 on an NVIDIA H200 (docs/gpu.md).
    for (int lines = axis == 0 ? 8 : 32; lines > 1; lines /= 2)
    {
      // Units Stride apart in shared memory, Stride = max(1, 16 / lines) (mod 16): the 16
      // invocations of a half warp, which load a sample of each of `lines` units, hit
      // different banks.
      const int stride = length + ((std::max(1, 16 / lines) - length) % 16 + 16) % 16;
      if (lines * stride <= MaximumLength && lines * layout.Threads <= 1024)
      {
        layout.Lines = lines;
        layout.Stride = stride;
        break;
      }
    }
  }
  return layout;
}

//------------------------------------------------------------------------------
std::string vtkBloomPassFFT::TransformDefines(
  const Pass& pass, int n, bool fromTexture, const Layout& layout)
{
  const std::vector<int> radices = Radices(pass.Length);
  std::string calls;
  int ns = 1;
  for (int r : radices)
  {
    // The stages as calls with literal arguments, which the compiler specializes.
    calls += "Stage(" + std::to_string(r) + ", " + std::to_string(ns) + "); ";
    ns *= r;
  }
  const auto define = [](const char* name, int value)
  { return "#define " + std::string(name) + " " + std::to_string(value) + "\n"; };
  return "#define FFT_TRANSFORM 1\n" + define("FFT_N", pass.Length) +
    define("FFT_TWIDDLE_STRIDE", n / pass.Length) + define("FFT_THREADS", layout.Threads) +
    "#define FFT_STAGE_CALLS " + calls + "\n" + define("FFT_BUTTERFLIES", layout.Butterflies) +
    define("FFT_LINES", layout.Lines) + define("FFT_STRIDE", layout.Stride) +
    (layout.BlockSubs ? "#define FFT_BLOCK_SUBS 1\n" : "") +
    (layout.SamplesFastest ? "#define FFT_SAMPLES_FASTEST 1\n" : "") +
    (fromTexture ? "#define FFT_FROM_TEXTURE 1\n" : "") +
    (pass.Twiddle ? "#define FFT_FOUR_STEP_TWIDDLE 1\n" : "");
}

//------------------------------------------------------------------------------
std::string vtkBloomPassFFT::LineTransformDefines(int n)
{
  // One pass over a whole line in shared memory (vtkBloomPassFFTBlur: lines of at most
  // MaximumLength samples).
  const Pass whole{ n, 1, 0, 1, false };
  return TransformDefines(whole, n, false, LayoutOf(whole, 0)) + "#define FFT_LIBRARY 1\n";
}

//------------------------------------------------------------------------------
std::vector<float> vtkBloomPassFFT::TwiddleTable(int n)
{
  std::vector<float> table(2 * static_cast<size_t>(n));
  for (int m = 0; m < n; ++m)
  {
    const double angle = 2.0 * 3.14159265358979323846 * m / n;
    table[2 * m] = static_cast<float>(std::cos(angle));
    table[2 * m + 1] = static_cast<float>(std::sin(angle));
  }
  return table;
}

//------------------------------------------------------------------------------
unsigned int vtkBloomPassFFT::Program(const std::string& defines, std::string* log)
{
  auto found = this->Programs.find(defines);
  if (found != this->Programs.end())
  {
    return found->second;
  }
  std::string text = vtkBloomPassFFTCS;
  vtkShaderProgram::Substitute(text, "//VTK::System::Dec", "#version 430 core\n" + defines);
  const unsigned int id = vtkBloomPassPrograms::BuildComputeProgram(text.c_str(), log);
  this->Programs[defines] = id;
  return id;
}

//------------------------------------------------------------------------------
int vtkBloomPassFFT::CachedUniform(UniformCache& cache, unsigned int program, const char* name)
{
  const auto key = std::make_pair(program, std::string(name));
  auto found = cache.find(key);
  if (found == cache.end())
  {
    found = cache.emplace(key, glGetUniformLocation(program, name)).first;
  }
  return found->second;
}

//------------------------------------------------------------------------------
int vtkBloomPassFFT::Uniform(unsigned int program, const char* name)
{
  return vtkBloomPassFFT::CachedUniform(this->Locations, program, name);
}

//------------------------------------------------------------------------------
void vtkBloomPassFFT::SetKernels(const Kernel kernels[3], vtkMTimeType version)
{
  this->Radius = 0;
  for (int c = 0; c < 3; ++c)
  {
    this->Kernels[c] = kernels[c];
    this->Radius = std::max(this->Radius, kernels[c].Radius);
  }
  this->KernelsVersion = version;
}

//------------------------------------------------------------------------------
bool vtkBloomPassFFT::Prepare(
  vtkOpenGLRenderWindow* context, int width, int height, std::string& why)
{
  if (this->Context && this->Context != context)
  {
    this->ReleaseGraphicsResources(this->Context);
  }
  this->Context = context;
  int version = 0;
  if (!vtkBloomPassPrograms::ContextRunsCompute(&version))
  {
    why = "PSF bloom needs OpenGL 4.3 compute shaders; this context has OpenGL " +
      std::to_string(version / 10) + "." + std::to_string(version % 10) + ".";
    return false;
  }
  int grid[2];
  why = this->MakeGrid(width, height, grid);
  if (!why.empty())
  {
    return false;
  }
  if (grid[0] != this->Grid[0] || grid[1] != this->Grid[1])
  {
    this->Grid[0] = grid[0];
    this->Grid[1] = grid[1];
    this->SpectraVersion = 0;
    this->ProgramsBuilt = false;
    // A grid within the limits may still not fit the GPU's memory: a buffer that could not be
    // allocated has size 0 (and GL_OUT_OF_MEMORY is raised).
    this->AllocateBuffers();
    GLint64 allocated[2] = { 0, 0 };
    for (int b = 0; b < 2; ++b)
    {
      glBindBuffer(GL_SHADER_STORAGE_BUFFER, b ? this->SpectraBuffer : this->SignalBuffer);
      glGetBufferParameteri64v(GL_SHADER_STORAGE_BUFFER, GL_BUFFER_SIZE, &allocated[b]);
    }
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
    const long long needed = SignalBytes(grid) + SpectraBytes(grid);
    if (allocated[0] + allocated[1] < needed)
    {
      why = "PSF bloom's FFT grid " + std::to_string(grid[0]) + " x " + std::to_string(grid[1]) +
        " does not fit in the GPU's memory (" + std::to_string(needed) + " bytes of buffers).";
      this->Grid[0] = this->Grid[1] = 0;
      return false;
    }
  }
  this->Size[0] = width;
  this->Size[1] = height;
  if (!this->ProgramsBuilt && !this->BuildPrograms(grid, why))
  {
    return false;
  }
  if (this->SpectraVersion != this->KernelsVersion)
  {
    this->MakeSpectra();
    this->SpectraVersion = this->KernelsVersion;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkBloomPassFFT::BuildPrograms(const int grid[2], std::string& why)
{
  // The programs of the point-wise stages and of both axes' transforms (rows forward from a
  // texture, the rest from the buffer), made once per grid; each transform's dispatches are
  // planned here with their layouts and programs.
  std::string log;
  for (const char* defines : { "#define FFT_SEPARATE 1\n", "#define FFT_MULTIPLY 1\n",
         "#define FFT_FOLD 1\n", "#define FFT_FOLD 1\n#define FFT_REFLECT 1\n" })
  {
    if (!this->Program(defines, &log))
    {
      why = "A PSF bloom FFT program did not build: " + log;
      return false;
    }
  }
  for (int axis = 0; axis < 2; ++axis)
  {
    for (int inverse = 0; inverse < 2; ++inverse)
    {
      std::vector<PlannedPass>& planned = this->Planned[axis][inverse];
      planned.clear();
      for (const Pass& pass : Passes(grid[axis], axis, inverse ? 1.0f : -1.0f))
      {
        const bool fromTexture = axis == 0 && !inverse && planned.empty();
        const Layout layout = LayoutOf(pass, axis);
        const unsigned int program =
          this->Program(TransformDefines(pass, grid[axis], fromTexture, layout), &log);
        if (!program)
        {
          why = "A PSF bloom FFT program did not build: " + log;
          return false;
        }
        planned.push_back(PlannedPass{ pass, layout, program });
      }
    }
  }
  this->ProgramsBuilt = true;
  return true;
}

//------------------------------------------------------------------------------
std::string vtkBloomPassFFT::MakeGrid(int width, int height, int grid[2]) const
{
  const std::string image = "the image " + std::to_string(width) + " x " + std::to_string(height) +
    " padded by the PSF radius " + std::to_string(this->Radius);
  const long long padded[2] = { width + 2LL * this->Radius, height + 2LL * this->Radius };
  if (std::max(padded[0], padded[1]) > MaximumGridLength)
  {
    return "PSF bloom's FFT grid (" + image + ") has a line longer than " +
      std::to_string(MaximumGridLength) + " samples.";
  }
  grid[0] = GoodSize(static_cast<int>(padded[0]));
  grid[1] = GoodSize(static_cast<int>(padded[1]));
  const std::string name = "PSF bloom's FFT grid " + std::to_string(grid[0]) + " x " +
    std::to_string(grid[1]) + " (" + image + ")";
  // The shaders index the buffers with 32-bit ints.
  const long long bytes = std::max(SignalBytes(grid), SpectraBytes(grid));
  GLint64 block = 0;
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &block);
  const long long limit = std::min<long long>(MaximumBufferBytes, block);
  if (bytes > limit)
  {
    return name + " needs a buffer of " + std::to_string(bytes) + " bytes, more than the " +
      std::to_string(limit) + " allowed.";
  }
  GLint texture = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &texture);
  if (2 * this->Radius + 1 > texture)
  {
    return "PSF bloom's kernel window " + std::to_string(2 * this->Radius + 1) +
      " is wider than this context's largest texture, " + std::to_string(texture) + ".";
  }
  return std::string();
}

//------------------------------------------------------------------------------
long long vtkBloomPassFFT::SignalBytes(const int grid[2])
{
  return 2LL * grid[0] * grid[1] * 2 * sizeof(float);
}

//------------------------------------------------------------------------------
long long vtkBloomPassFFT::SpectraBytes(const int grid[2])
{
  // Hermitian spectra: the frequencies 0 to NY / 2 along y (glsl/vtkBloomPassFFTCS.glsl).
  return 3LL * grid[0] * (grid[1] / 2 + 1) * 2 * sizeof(float);
}

//------------------------------------------------------------------------------
void vtkBloomPassFFT::AllocateBuffers()
{
  if (!this->SignalBuffer)
  {
    glGenBuffers(1, &this->SignalBuffer);
    glGenBuffers(1, &this->SpectraBuffer);
    glGenBuffers(2, this->TwiddleBuffers);
  }
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->SignalBuffer);
  glBufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(SignalBytes(this->Grid)), nullptr,
    GL_DYNAMIC_COPY);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->SpectraBuffer);
  glBufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(SpectraBytes(this->Grid)), nullptr,
    GL_DYNAMIC_COPY);
  for (int axis = 0; axis < 2; ++axis)
  {
    const std::vector<float> table = vtkBloomPassFFT::TwiddleTable(this->Grid[axis]);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->TwiddleBuffers[axis]);
    glBufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(table.size() * sizeof(float)),
      table.data(), GL_STATIC_DRAW);
  }
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
}

//------------------------------------------------------------------------------
void vtkBloomPassFFT::SetSplit(unsigned int program)
{
  int n1[2], n2[2];
  for (int axis = 0; axis < 2; ++axis)
  {
    Split(this->Grid[axis], n1[axis], n2[axis], LongestOnePass(axis));
  }
  glUniform2i(this->Uniform(program, "split"), n2[0], n2[1]);
}

//------------------------------------------------------------------------------
void vtkBloomPassFFT::MakeSpectra()
{
  // The kernels as one RGBA32F texture of the largest kernel's window, each centred in it.
  const int r = this->Radius, n = 2 * r + 1;
  std::vector<float> texels(static_cast<size_t>(n) * n * 4, 0.0f);
  for (int c = 0; c < 3; ++c)
  {
    const Kernel& kernel = this->Kernels[c];
    const int kn = 2 * kernel.Radius + 1, offset = r - kernel.Radius;
    for (int y = 0; y < kn; ++y)
    {
      for (int x = 0; x < kn; ++x)
      {
        texels[(static_cast<size_t>(y + offset) * n + x + offset) * 4 + c] =
          static_cast<float>(kernel.Values[static_cast<size_t>(y) * kn + x]);
      }
    }
  }
  if (this->KernelTexture)
  {
    this->KernelTexture->ReleaseGraphicsResources(this->Context);
  }
  this->KernelTexture = vtkSmartPointer<vtkTextureObject>::New();
  this->KernelTexture->SetContext(this->Context);
  this->KernelTexture->SetInternalFormat(GL_RGBA32F);
  this->KernelTexture->Create2DFromRaw(n, n, 4, VTK_FLOAT, texels.data());
  const int size[2] = { n, n };
  this->Forward(this->KernelTexture, size);
  // Separate the red and green spectra, scaled by the inverse transform's 1 / (NX NY).
  const unsigned int program = this->Program("#define FFT_SEPARATE 1\n");
  glUseProgram(program);
  glUniform2i(this->Uniform(program, "size"), this->Grid[0], this->Grid[1]);
  this->SetSplit(program);
  glUniform1f(this->Uniform(program, "scale"),
    static_cast<float>(1.0 / (static_cast<double>(this->Grid[0]) * this->Grid[1])));
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, this->SignalBuffer);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, this->SpectraBuffer);
  glDispatchCompute(Groups(this->Grid[0]), Groups(this->Grid[1]), 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  this->KernelTexture->ReleaseGraphicsResources(this->Context);
  this->KernelTexture = nullptr;
}

//------------------------------------------------------------------------------
void vtkBloomPassFFT::Transform(int axis, float direction, const Lines& lines)
{
  // Only the first dispatch reads the texture or meets the zero padding; the second (four
  // steps) reads its output.
  Lines first = lines;
  for (const PlannedPass& planned : this->Planned[axis][direction > 0.0f ? 1 : 0])
  {
    this->RunPass(planned, axis, direction, first);
    first.Source = nullptr;
    first.SampleLimit = this->Grid[axis];
  }
}

//------------------------------------------------------------------------------
void vtkBloomPassFFT::ForwardRows(vtkTextureObject* source, const int sourceSize[2])
{
  // Rows past the source's are zero: left alone, ForwardColumns does not read them.
  this->Transform(0, -1.0f, Lines{ 0, sourceSize[1], this->Grid[0], source, sourceSize });
}

//------------------------------------------------------------------------------
void vtkBloomPassFFT::ForwardColumns(int rows)
{
  this->Transform(1, -1.0f, Lines{ 0, this->Grid[0], rows, nullptr, nullptr });
}

//------------------------------------------------------------------------------
void vtkBloomPassFFT::Forward(vtkTextureObject* source, const int sourceSize[2])
{
  this->ForwardRows(source, sourceSize);
  this->ForwardColumns(sourceSize[1]);
}

//------------------------------------------------------------------------------
void vtkBloomPassFFT::RunPass(
  const PlannedPass& planned, int axis, float direction, const Lines& lines)
{
  const Pass& pass = planned.Run;
  const Layout& layout = planned.Shape;
  const unsigned int program = planned.Program;
  vtkTextureObject* source = lines.Source; // only the first pass of the forward rows
  glUseProgram(program);
  // Rows: samples adjacent, lines NX apart; columns: samples NX apart, lines adjacent.
  glUniform1i(this->Uniform(program, "sampleStride"), axis == 0 ? 1 : this->Grid[0]);
  glUniform1i(this->Uniform(program, "lineStride"), axis == 0 ? this->Grid[0] : 1);
  glUniform1i(this->Uniform(program, "signalStride"), this->Grid[0] * this->Grid[1]);
  glUniform1i(this->Uniform(program, "lineFirst"), lines.First);
  glUniform1i(this->Uniform(program, "lineCount"), lines.Count);
  glUniform1i(this->Uniform(program, "sampleLimit"), lines.SampleLimit);
  glUniform1i(this->Uniform(program, "subCount"), pass.Count);
  glUniform1i(this->Uniform(program, "subOffset"), pass.Offset);
  glUniform1i(this->Uniform(program, "subSpacing"), pass.Spacing);
  glUniform1f(this->Uniform(program, "direction"), direction);
  if (source)
  {
    source->Activate();
    glUniform1i(this->Uniform(program, "source"), source->GetTextureUnit());
    glUniform2i(this->Uniform(program, "sourceSize"), lines.SourceSize[0], lines.SourceSize[1]);
  }
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, this->SignalBuffer);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, this->TwiddleBuffers[axis]);
  // One work group per block of units and signal, in rows of at most 65535 (every context
  // allows that many a dimension).
  const long long units = static_cast<long long>(lines.Count) * pass.Count;
  const long long blocks = layout.BlockSubs
    ? lines.Count * ((pass.Count + layout.Lines - 1) / layout.Lines)
    : pass.Count * ((lines.Count + layout.Lines - 1) / layout.Lines);
  const long long groups = units > 0 ? 2LL * blocks : 0;
  if (groups > 0)
  {
    const long long across = std::min<long long>(groups, 65535);
    glDispatchCompute(
      static_cast<GLuint>(across), static_cast<GLuint>((groups + across - 1) / across), 1);
  }
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  if (source)
  {
    source->Deactivate();
  }
}

//------------------------------------------------------------------------------
void vtkBloomPassFFT::Convolve(
  vtkTextureObject* source, vtkTextureObject* target, bool reflect, vtkBloomPassProfiler& profiler)
{
  // A transform reads and writes both signals (2 x 8 bytes a sample, each way) on the lines it
  // runs on; the multiply also reads the three spectra, half of them (Hermitian); the fold
  // reads both signals over the image.
  const double grid = static_cast<double>(this->Grid[0]) * this->Grid[1];
  const auto stage = [this, &profiler](const char* name, double bytes, auto&& run)
  {
    profiler.Begin();
    run();
    profiler.End(name, this->Grid[0], this->Grid[1], bytes);
  };
  // The forward rows only where the image is (the other rows are zero), the inverse rows only
  // where the fold reads: the full convolution's rows for REFLECT, the image's for ZERO.
  const int rows[2] = { reflect ? 0 : this->Radius,
    reflect ? std::min(this->Grid[1], this->Size[1] + 2 * this->Radius) : this->Size[1] };
  const double row = 32.0 * this->Grid[0]; // a row's traffic
  stage("psf rows", row * this->Size[1], [&] { this->ForwardRows(source, this->Size); });
  stage("psf columns", 32.0 * grid, [&] { this->ForwardColumns(this->Size[1]); });
  stage("psf multiply", 44.0 * grid, [&] { this->Multiply(); });
  stage("psf inverse columns", 32.0 * grid,
    [&] {
      this->Transform(1, 1.0f, Lines{ 0, this->Grid[0], this->Grid[1], nullptr, nullptr });
    });
  stage("psf inverse rows", row * rows[1],
    [&] {
      this->Transform(0, 1.0f, Lines{ rows[0], rows[1], this->Grid[0], nullptr, nullptr });
    });
  stage("psf fold", 32.0 * this->Size[0] * this->Size[1], [&] { this->Fold(target, reflect); });
}

//------------------------------------------------------------------------------
void vtkBloomPassFFT::Multiply()
{
  const unsigned int multiply = this->Program("#define FFT_MULTIPLY 1\n");
  glUseProgram(multiply);
  glUniform2i(this->Uniform(multiply, "size"), this->Grid[0], this->Grid[1]);
  this->SetSplit(multiply);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, this->SignalBuffer);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, this->SpectraBuffer);
  glDispatchCompute(Groups(this->Grid[0]), Groups(this->Grid[1]), 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

//------------------------------------------------------------------------------
void vtkBloomPassFFT::Fold(vtkTextureObject* target, bool reflect)
{
  const unsigned int fold =
    this->Program(reflect ? "#define FFT_FOLD 1\n#define FFT_REFLECT 1\n" : "#define FFT_FOLD 1\n");
  glUseProgram(fold);
  glUniform2i(this->Uniform(fold, "imageSize"), this->Size[0], this->Size[1]);
  glUniform1i(this->Uniform(fold, "radius"), this->Radius);
  glUniform1i(this->Uniform(fold, "rowStride"), this->Grid[0]);
  glUniform1i(this->Uniform(fold, "signalStride"), this->Grid[0] * this->Grid[1]);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, this->SignalBuffer);
  glBindImageTexture(0, target->GetHandle(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  glDispatchCompute(Groups(this->Size[0]), Groups(this->Size[1]), 1);
  // The composite reads the target by texelFetch or imageLoad next.
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
    GL_SHADER_STORAGE_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
  glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  for (GLuint binding : { 0u, 1u })
  {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, 0);
  }
  // VTK's shader cache must know that its last program is no longer bound.
  this->Context->GetShaderCache()->ReleaseCurrentShader();
}

//------------------------------------------------------------------------------
void vtkBloomPassFFT::ReleaseGraphicsResources(vtkWindow* w)
{
  if (this->Context)
  {
    for (const auto& program : this->Programs)
    {
      if (program.second)
      {
        glDeleteProgram(program.second);
      }
    }
    if (this->SignalBuffer)
    {
      glDeleteBuffers(1, &this->SignalBuffer);
      glDeleteBuffers(1, &this->SpectraBuffer);
      glDeleteBuffers(2, this->TwiddleBuffers);
    }
  }
  if (this->KernelTexture)
  {
    this->KernelTexture->ReleaseGraphicsResources(w);
    this->KernelTexture = nullptr;
  }
  this->Programs.clear();
  for (auto& axis : this->Planned)
  {
    for (std::vector<PlannedPass>& planned : axis)
    {
      planned.clear();
    }
  }
  this->Locations.clear();
  this->SignalBuffer = this->SpectraBuffer = 0;
  this->TwiddleBuffers[0] = this->TwiddleBuffers[1] = 0;
  this->Grid[0] = this->Grid[1] = 0;
  this->SpectraVersion = 0;
  this->Context = nullptr;
}
