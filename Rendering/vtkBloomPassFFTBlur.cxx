// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// A wide blur operator through an FFT in compute shaders (see vtkBloomPassFFTBlur.h): the
// operator's tables from vtkBloomFFTConvolution, the cost model, the buffers and the two
// dispatches of one axis. The shaders are glsl/vtkBloomPassFFTBlurCS.glsl, the convolution
// appended to vtkBloomPassFFT's line transform (glsl/vtkBloomPassFFTCS.glsl).
#include "vtkBloomPassFFTBlur.h"

#include "vtkBloomFFTConvolution.h"
#include "vtkBloomLinearOperator.h"
#include "vtkBloomParameters.h"
#include "vtkBloomPassFFT.h"
#include "vtkBloomPassFFTBlurCS.h"
#include "vtkBloomPassFFTCS.h"
#include "vtkBloomPassPrograms.h"
#include "vtkBloomVTKCompat.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace
{
// Work groups of the finishing stage: 16 x 16 samples.
constexpr int Tile = 16;

int Groups(int n)
{
  return (n + Tile - 1) / Tile;
}

// The outputs that input sample i reaches through the operator's weights rounded to float (the
// direct pass's weights: a far tail that underflows there reaches nothing), [lo[i], hi[i]],
// made monotone so that a range's reach is its ends', as vtkBloomFFTConvolution's own reach.
void FloatReach(const vtkBloomLinearOperator& op, int* lo, int* hi)
{
  const int n = op.InputSize;
  std::fill(lo, lo + n, n);
  std::fill(hi, hi + n, -1);
  for (int j = 0; j < op.OutputSize; ++j)
  {
    for (int k = 0; k < op.Width && op.First[j] + k < n; ++k)
    {
      if (static_cast<float>(op.Weights[static_cast<size_t>(j) * op.Width + k]) != 0.0f)
      {
        lo[op.First[j] + k] = std::min(lo[op.First[j] + k], j);
        hi[op.First[j] + k] = std::max(hi[op.First[j] + k], j);
      }
    }
  }
  for (int i = n - 2; i >= 0; --i)
  {
    lo[i] = std::min(lo[i], lo[i + 1]);
  }
  for (int i = 1; i < n; ++i)
  {
    hi[i] = std::max(hi[i], hi[i - 1]);
  }
}

std::string FinishDefines(int axis, unsigned int format)
{
  return "#define FFT_AXIS " + std::to_string(axis) + "\n#define FFT_BLUR_FINISH 1\n" +
    "#define FFT_BLUR_FORMAT " + (format == GL_RGBA16F ? "rgba16f" : "rgba32f") + "\n";
}

// A shader storage buffer holding `values` (at least one element: an empty binding is an error).
template <typename T>
unsigned int MakeBuffer(std::vector<T> values)
{
  if (values.empty())
  {
    values.push_back(T(0));
  }
  GLuint buffer = 0;
  glGenBuffers(1, &buffer);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffer);
  glBufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(values.size() * sizeof(T)),
    values.data(), GL_STATIC_DRAW);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
  return buffer;
}
}

//------------------------------------------------------------------------------
// One operator's GPU form: its layout, its tables and its cost.
struct vtkBloomPassFFTBlur::Operator
{
  vtkBloomFFTConvolution Convolution;
  bool Usable = false;
  bool Cheaper = false; ///< the modeled cost is below the direct pass's
  int N = 0;
  int Size = 0;
  int PadLeft = 0;
  int Blocks[2][4] = { { 0, 0, 0, 0 }, { 0, 0, 0, 0 } }; ///< Row0, Rows, Col0, Cols
  int Rank[2] = { 0, 0 };
  int VAt[2] = { 0, 0 };
  int UAt[2] = { 0, 0 };
  unsigned int Spectrum = 0; ///< N vec2
  unsigned int Tables = 0;   ///< extension (N), reachLo (n), reachHi (n)
  unsigned int Factors = 0;  ///< each block's V, then its U
  unsigned int Twiddles = 0; ///< vtkBloomPassFFT::TwiddleTable(N)

  bool NonNegative = false; ///< every weight is >= 0
  void Upload(const vtkBloomLinearOperator& op, int border);
  void Release()
  {
    for (unsigned int* b : { &this->Spectrum, &this->Tables, &this->Factors, &this->Twiddles })
    {
      if (*b)
      {
        glDeleteBuffers(1, b);
        *b = 0;
      }
    }
  }
};

//------------------------------------------------------------------------------
void vtkBloomPassFFTBlur::Operator::Upload(const vtkBloomLinearOperator& op, int border)
{
  const vtkBloomFFTConvolution& c = this->Convolution;
  const int n = this->Size, padded = n + c.GetPadLeft() + c.GetPadRight();
  // The kernel's spectrum for N, in double, completed by Hermitian symmetry (the kernel is
  // real): the shader multiplies a complex signal, whose spectrum has no symmetry.
  std::vector<double> half;
  c.ComputeKernelSpectrum(this->N, half);
  std::vector<float> spectrum(2 * static_cast<size_t>(this->N));
  for (int q = 0; q < this->N; ++q)
  {
    const int h = q <= this->N / 2 ? q : this->N - q;
    spectrum[2 * q] = static_cast<float>(half[2 * h]);
    spectrum[2 * q + 1] = static_cast<float>(q <= this->N / 2 ? half[2 * h + 1] : -half[2 * h + 1]);
  }
  // E: sample m of the buffer is x[FoldIndex(m - PadLeft)] up to the padding, then zero.
  std::vector<int> tables(static_cast<size_t>(this->N) + 2 * n, -1);
  for (int m = 0; m < padded; ++m)
  {
    tables[m] = vtkBloomLinearOperator::FoldIndex(m - this->PadLeft, n, border);
  }
  FloatReach(op, tables.data() + this->N, tables.data() + this->N + n);
  std::vector<float> factors;
  const std::vector<vtkBloomFFTConvolution::Block>& blocks = c.GetCorrections();
  for (size_t b = 0; b < blocks.size() && b < 2; ++b)
  {
    const vtkBloomFFTConvolution::Block& block = blocks[b];
    const int at[4] = { block.Row0, block.Rows, block.Col0, block.Cols };
    std::copy(at, at + 4, this->Blocks[b]);
    this->Rank[b] = block.Rank;
    this->VAt[b] = static_cast<int>(factors.size());
    factors.insert(factors.end(), block.V.begin(), block.V.end());
    this->UAt[b] = static_cast<int>(factors.size());
    factors.insert(factors.end(), block.U.begin(), block.U.end());
  }
  this->Spectrum = MakeBuffer(spectrum);
  this->Tables = MakeBuffer(tables);
  this->Factors = MakeBuffer(factors);
  this->Twiddles = MakeBuffer(vtkBloomPassFFT::TwiddleTable(this->N));
}

//------------------------------------------------------------------------------
vtkBloomPassFFTBlur::vtkBloomPassFFTBlur() = default;

//------------------------------------------------------------------------------
vtkBloomPassFFTBlur::~vtkBloomPassFFTBlur() = default;

//------------------------------------------------------------------------------
vtkBloomPassFFTBlur::Operator* vtkBloomPassFFTBlur::Prepare(
  vtkOpenGLRenderWindow* context, const vtkBloomLinearOperator& op)
{
  if (this->Context && this->Context != context)
  {
    this->ReleaseGraphicsResources(this->Context);
  }
  this->Context = context;
  auto found = this->Operators.find(&op);
  if (found != this->Operators.end())
  {
    return found->second.get();
  }
  if (!this->MaximumLength)
  {
    // One line of vec2 in shared memory, less the two shared integers of the line's range.
    GLint bytes = 0;
    glGetIntegerv(GL_MAX_COMPUTE_SHARED_MEMORY_SIZE, &bytes);
    this->MaximumLength = std::max(1, (bytes - 16) / 8);
  }
  auto entry = std::make_unique<Operator>();
  Operator& o = *entry;
  this->Operators[&op] = std::move(entry);
  // The level blurs clamp (vtkBloomChain), as vtkBloomFastChain's FFT path assumes.
  const int border = vtkBloomLinearOperator::BORDER_CLAMP;
  if (!o.Convolution.Build(op, border, true) || o.Convolution.GetCorrections().size() > 2)
  {
    return &o;
  }
  const vtkBloomFFTConvolution& c = o.Convolution;
  o.Size = op.InputSize;
  o.PadLeft = c.GetPadLeft();
  o.N = vtkBloomPassFFT::GoodSize(o.Size + c.GetPadLeft() + c.GetPadRight());
  if (o.N > this->MaximumLength)
  {
    return &o;
  }
  // The CPU's model at the GPU's length; both transforms of a line count.
  o.Cheaper = c.Cost(o.N, 2.0 * FFTCostFactor) < vtkBloomFFTConvolution::DirectCost(op);
  o.NonNegative =
    std::all_of(op.Weights.begin(), op.Weights.end(), [](double w) { return w >= 0.0; });
  o.Upload(op, border);
  o.Usable = true;
  return &o;
}

//------------------------------------------------------------------------------
bool vtkBloomPassFFTBlur::Choose(
  vtkOpenGLRenderWindow* context, const vtkBloomLinearOperator& op, int mode)
{
  if (mode == vtkBloomParameters::CONVOLUTION_DIRECT)
  {
    return false;
  }
  const Operator* o = this->Prepare(context, op);
  return o->Usable && (mode == vtkBloomParameters::CONVOLUTION_FFT || o->Cheaper);
}

//------------------------------------------------------------------------------
int vtkBloomPassFFTBlur::GetTransformSize(const vtkBloomLinearOperator& op) const
{
  auto found = this->Operators.find(&op);
  return found != this->Operators.end() && found->second->Usable ? found->second->N : 0;
}

//------------------------------------------------------------------------------
unsigned int vtkBloomPassFFTBlur::Program(const std::string& defines, bool convolve)
{
  const std::string key = defines + (convolve ? "convolve" : "finish");
  auto found = this->Programs.find(key);
  if (found != this->Programs.end())
  {
    return found->second;
  }
  const std::string version = "#version 430 core\n";
  std::string text;
  std::string blur = vtkBloomPassFFTBlurCS;
  if (convolve)
  {
    // The line transform first (FFT_LIBRARY: without its main), then the convolution's main.
    text = vtkBloomPassFFTCS;
    vtkShaderProgram::Substitute(text, "//VTK::System::Dec", version + defines);
    vtkShaderProgram::Substitute(blur, "//VTK::System::Dec", "");
    text += blur;
  }
  else
  {
    text = blur;
    vtkShaderProgram::Substitute(text, "//VTK::System::Dec", version + defines);
  }
  std::string log;
  const unsigned int id = vtkBloomPassPrograms::BuildComputeProgram(text.c_str(), &log);
  this->Programs[key] = id;
  return id;
}

//------------------------------------------------------------------------------
int vtkBloomPassFFTBlur::Uniform(unsigned int program, const char* name)
{
  return vtkBloomPassFFT::CachedUniform(this->Locations, program, name);
}

//------------------------------------------------------------------------------
void vtkBloomPassFFTBlur::Reserve(size_t signal, size_t coefficients, size_t ranges)
{
  const size_t bytes[3] = { signal, coefficients, ranges };
  for (int b = 0; b < 3; ++b)
  {
    if (!this->Buffers[b])
    {
      glGenBuffers(1, &this->Buffers[b]);
    }
    if (this->Capacity[b] < bytes[b])
    {
      glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->Buffers[b]);
      glBufferData(
        GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(bytes[b]), nullptr, GL_DYNAMIC_COPY);
      this->Capacity[b] = bytes[b];
    }
  }
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
}

//------------------------------------------------------------------------------
bool vtkBloomPassFFTBlur::Convolve(const vtkBloomLinearOperator& op, int axis, int lines,
  vtkTextureObject* source, unsigned int format)
{
  const Operator& o = *this->Operators.at(&op);
  const unsigned int program = this->Program(vtkBloomPassFFT::LineTransformDefines(o.N) +
      "#define FFT_AXIS " + std::to_string(axis) + "\n#define FFT_BLUR_CONVOLVE 1\n",
    true);
  if (!program || !this->Program(FinishDefines(axis, format), false))
  {
    return false;
  }
  const int ranks = o.Rank[0] + o.Rank[1];
  this->Reserve(2 * static_cast<size_t>(lines) * o.Size * 2 * sizeof(float),
    2 * static_cast<size_t>(lines) * std::max(ranks, 1) * 2 * sizeof(float),
    2 * static_cast<size_t>(lines) * 4 * sizeof(int));
  glUseProgram(program);
  glUniform1f(this->Uniform(program, "direction"), -1.0f);
  glUniform1i(this->Uniform(program, "lineLength"), o.Size);
  glUniform1i(this->Uniform(program, "lines"), lines);
  glUniform1i(this->Uniform(program, "padLeft"), o.PadLeft);
  glUniform4iv(this->Uniform(program, "blocks"), 2, &o.Blocks[0][0]);
  glUniform2i(this->Uniform(program, "blockRank"), o.Rank[0], o.Rank[1]);
  glUniform2i(this->Uniform(program, "blockV"), o.VAt[0], o.VAt[1]);
  source->Activate();
  glUniform1i(this->Uniform(program, "source"), source->GetTextureUnit());
  const unsigned int bindings[7] = { this->Buffers[0], o.Twiddles, o.Spectrum, o.Tables, o.Factors,
    this->Buffers[1], this->Buffers[2] };
  for (GLuint b = 0; b < 7; ++b)
  {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, b, bindings[b]);
  }
  glDispatchCompute(lines, 2, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  source->Deactivate();
  return true;
}

//------------------------------------------------------------------------------
void vtkBloomPassFFTBlur::Finish(const vtkBloomLinearOperator& op, int axis, int lines,
  unsigned int target, unsigned int format, double weight)
{
  const Operator& o = *this->Operators.at(&op);
  const unsigned int program = this->Program(FinishDefines(axis, format), false);
  glUseProgram(program);
  glUniform1i(this->Uniform(program, "lineLength"), o.Size);
  glUniform1i(this->Uniform(program, "lines"), lines);
  glUniform1i(this->Uniform(program, "transformLength"), o.N);
  glUniform4iv(this->Uniform(program, "blocks"), 2, &o.Blocks[0][0]);
  glUniform2i(this->Uniform(program, "blockRank"), o.Rank[0], o.Rank[1]);
  glUniform2i(this->Uniform(program, "blockU"), o.UAt[0], o.UAt[1]);
  glUniform1i(this->Uniform(program, "nonNegative"), o.NonNegative ? 1 : 0);
  glUniform1f(this->Uniform(program, "weight"), static_cast<float>(weight));
  const unsigned int bindings[7] = { this->Buffers[0], 0, 0, o.Tables, o.Factors, this->Buffers[1],
    this->Buffers[2] };
  for (GLuint b = 0; b < 7; ++b)
  {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, b, bindings[b]);
  }
  glBindImageTexture(0, target, 0, GL_FALSE, 0, GL_WRITE_ONLY, format);
  const int width = axis == 0 ? o.Size : lines;
  const int height = axis == 0 ? lines : o.Size;
  glDispatchCompute(Groups(width), Groups(height), 1);
  for (GLuint b = 0; b < 7; ++b)
  {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, b, 0);
  }
}

//------------------------------------------------------------------------------
void vtkBloomPassFFTBlur::ReleaseOperators()
{
  if (this->Context)
  {
    for (auto& o : this->Operators)
    {
      o.second->Release();
    }
  }
  this->Operators.clear();
}

//------------------------------------------------------------------------------
void vtkBloomPassFFTBlur::ReleaseGraphicsResources(vtkWindow*)
{
  this->ReleaseOperators();
  if (this->Context)
  {
    for (const auto& program : this->Programs)
    {
      if (program.second)
      {
        glDeleteProgram(program.second);
      }
    }
    for (unsigned int& b : this->Buffers)
    {
      if (b)
      {
        glDeleteBuffers(1, &b);
      }
    }
  }
  this->Programs.clear();
  this->Locations.clear();
  std::fill(this->Buffers, this->Buffers + 3, 0u);
  std::fill(this->Capacity, this->Capacity + 3, size_t(0));
  this->MaximumLength = 0;
  this->Context = nullptr;
}
