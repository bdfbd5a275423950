// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkBloomFFTConvolution.h"

#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>
#include <type_traits>

namespace
{
/**
 * Gram-Schmidt with column pivoting: B (rows x cols, row-major) ~ U V^T with U orthonormal
 * (rank x rows) and V^T (rank x cols), stopping once every remaining column's norm is at most
 * `tolerance`.
 */
int Factor(std::vector<double> b, int rows, int cols, double tolerance, std::vector<double>& u,
  std::vector<double>& vt)
{
  std::vector<double> norms(cols, 0.0);
  auto columnNorm = [&](int c)
  {
    double s = 0.0;
    for (int r = 0; r < rows; ++r)
    {
      s += b[r * cols + c] * b[r * cols + c];
    }
    return s;
  };
  for (int c = 0; c < cols; ++c)
  {
    norms[c] = columnNorm(c);
  }
  u.clear();
  vt.clear();
  int rank = 0;
  std::vector<double> q(rows);
  while (rank < std::min(rows, cols))
  {
    const int p = static_cast<int>(std::max_element(norms.begin(), norms.end()) - norms.begin());
    if (!(std::sqrt(norms[p]) > tolerance))
    {
      break;
    }
    // Two passes of orthogonalization against the previous directions keep q orthonormal.
    for (int r = 0; r < rows; ++r)
    {
      q[r] = b[r * cols + p];
    }
    for (int pass = 0; pass < 2; ++pass)
    {
      for (int k = 0; k < rank; ++k)
      {
        const double* uk = u.data() + static_cast<size_t>(k) * rows;
        double d = 0.0;
        for (int r = 0; r < rows; ++r)
        {
          d += uk[r] * q[r];
        }
        for (int r = 0; r < rows; ++r)
        {
          q[r] -= d * uk[r];
        }
      }
    }
    double length = 0.0;
    for (int r = 0; r < rows; ++r)
    {
      length += q[r] * q[r];
    }
    length = std::sqrt(length);
    if (!(length > 0.0))
    {
      break;
    }
    for (int r = 0; r < rows; ++r)
    {
      q[r] /= length;
    }
    u.insert(u.end(), q.begin(), q.end());
    // Row `rank` of V^T: q^T B; then remove q's part from every column.
    vt.resize(vt.size() + cols);
    double* v = vt.data() + static_cast<size_t>(rank) * cols;
    for (int c = 0; c < cols; ++c)
    {
      double d = 0.0;
      for (int r = 0; r < rows; ++r)
      {
        d += q[r] * b[r * cols + c];
      }
      v[c] = d;
      for (int r = 0; r < rows; ++r)
      {
        b[r * cols + c] -= d * q[r];
      }
      norms[c] = columnNorm(c);
    }
    ++rank;
  }
  return rank;
}

template <typename P>
struct Fftw;

template <>
struct Fftw<float>
{
  using Complex = fftwf_complex;
  static void* Malloc(size_t n) { return fftwf_malloc(n); }
  static void Free(void* p) { fftwf_free(p); }
  static void* PlanForward(int n, float* in, Complex* out)
  {
    return fftwf_plan_dft_r2c_1d(n, in, out, FFTW_ESTIMATE);
  }
  static void* PlanInverse(int n, Complex* in, float* out)
  {
    return fftwf_plan_dft_c2r_1d(n, in, out, FFTW_ESTIMATE);
  }
  static void Forward(void* plan, float* in, Complex* out)
  {
    fftwf_execute_dft_r2c(static_cast<fftwf_plan>(plan), in, out);
  }
  static void Inverse(void* plan, Complex* in, float* out)
  {
    fftwf_execute_dft_c2r(static_cast<fftwf_plan>(plan), in, out);
  }
  static void Destroy(void* plan) { fftwf_destroy_plan(static_cast<fftwf_plan>(plan)); }
};

template <>
struct Fftw<double>
{
  using Complex = fftw_complex;
  static void* Malloc(size_t n) { return fftw_malloc(n); }
  static void Free(void* p) { fftw_free(p); }
  static void* PlanForward(int n, double* in, Complex* out)
  {
    return fftw_plan_dft_r2c_1d(n, in, out, FFTW_ESTIMATE);
  }
  static void* PlanInverse(int n, Complex* in, double* out)
  {
    return fftw_plan_dft_c2r_1d(n, in, out, FFTW_ESTIMATE);
  }
  static void Forward(void* plan, double* in, Complex* out)
  {
    fftw_execute_dft_r2c(static_cast<fftw_plan>(plan), in, out);
  }
  static void Inverse(void* plan, Complex* in, double* out)
  {
    fftw_execute_dft_c2r(static_cast<fftw_plan>(plan), in, out);
  }
  static void Destroy(void* plan) { fftw_destroy_plan(static_cast<fftw_plan>(plan)); }
};

template <typename P>
void MakePlans(int n, void*& forward, void*& inverse)
{
  using F = Fftw<P>;
  P* real = static_cast<P*>(F::Malloc(sizeof(P) * n));
  auto* complex = static_cast<typename F::Complex*>(F::Malloc(sizeof(P) * 2 * (n / 2 + 1)));
  forward = F::PlanForward(n, real, complex);
  inverse = F::PlanInverse(n, complex, real);
  F::Free(real);
  F::Free(complex);
}

//------------------------------------------------------------------------------
// The kernel of the operator's invariant rows, without its zero ends, and where row j reads
// it: x[j + offset + k]. False when those rows are all zero.
bool InvariantKernel(const vtkBloomLinearOperator& op,
  const vtkBloomLinearOperator::InvariantRange& range, std::vector<double>& kernel, int& offset)
{
  const int mid = (range.Begin + range.End) / 2;
  const size_t width = static_cast<size_t>(op.Width);
  const double* row = op.Weights.data() + mid * width;
  int k0 = 0, k1 = op.Width - 1;
  while (k0 <= k1 && row[k0] == 0.0)
  {
    ++k0;
  }
  while (k1 >= k0 && row[k1] == 0.0)
  {
    --k1;
  }
  if (k0 > k1)
  {
    return false;
  }
  kernel.assign(row + k0, row + k1 + 1);
  offset = op.First[mid] - mid + k0;
  return true;
}

//------------------------------------------------------------------------------
// The kernel's spectrum for a circular convolution of length n whose output j sits at
// PadLeft + j, divided by n (FFTW's inverse does not), interleaved re, im, in double and
// single precision.
void KernelSpectrum(const std::vector<double>& kernel, int offset, int n,
  std::vector<double>& spectrumD, std::vector<float>& spectrumF)
{
  const int taps = static_cast<int>(kernel.size());
  std::vector<double> h(n, 0.0);
  for (int k = 0; k < taps; ++k)
  {
    const long long m = ((-(offset + k)) % n + n) % n;
    h[m] += kernel[k];
  }
  std::vector<fftw_complex> spectrum(n / 2 + 1);
  {
    std::lock_guard<std::mutex> lock(vtkBloomFFTConvolution::PlannerMutex());
    fftw_plan plan = fftw_plan_dft_r2c_1d(n, h.data(), spectrum.data(), FFTW_ESTIMATE);
    fftw_execute(plan);
    fftw_destroy_plan(plan);
  }
  spectrumD.resize(2 * spectrum.size());
  spectrumF.resize(2 * spectrum.size());
  for (size_t q = 0; q < spectrum.size(); ++q)
  {
    for (int part = 0; part < 2; ++part)
    {
      spectrumD[2 * q + part] = spectrum[q][part] / n;
      spectrumF[2 * q + part] = static_cast<float>(spectrumD[2 * q + part]);
    }
  }
}

//------------------------------------------------------------------------------
// Columns [c0, c1] of `rows` (which start at column w0) as a dense block, factored into
// block.U and block.V; block.Rank is 0 when nothing is left above the tolerance.
void FactorBlock(const std::vector<std::vector<double>>& rows, int w0, int c0, int c1,
  vtkBloomFFTConvolution::Block& block)
{
  block.Col0 = c0;
  block.Cols = c1 - c0 + 1;
  std::vector<double> dense(static_cast<size_t>(block.Rows) * block.Cols);
  for (int r = 0; r < block.Rows; ++r)
  {
    std::copy(rows[r].begin() + (c0 - w0), rows[r].begin() + (c1 - w0) + 1,
      dense.begin() + static_cast<size_t>(r) * block.Cols);
  }
  std::vector<double> vt;
  block.Rank = Factor(std::move(dense), block.Rows, block.Cols, 1e-12, block.U, vt);
  block.V.resize(vt.size());
  for (int k = 0; k < block.Rank; ++k)
  {
    for (int q = 0; q < block.Cols; ++q)
    {
      block.V[static_cast<size_t>(q) * block.Rank + k] =
        vt[static_cast<size_t>(k) * block.Cols + q];
    }
  }
}

//------------------------------------------------------------------------------
// D = M - T on rows [r0, r1) (rows outside the invariant range, at one end), factored into
// `block`. False when D is zero there, or of rank 0.
bool BorderCorrection(const vtkBloomLinearOperator& op, const std::vector<double>& kernel,
  int offset, int border, int r0, int r1, vtkBloomFFTConvolution::Block& block)
{
  const int n = op.InputSize;
  const size_t width = static_cast<size_t>(op.Width);
  const int taps = static_cast<int>(kernel.size());
  // The columns the rows touch (M's support and T's folded taps) bound the block.
  int w0 = n, w1 = -1;
  for (int j = r0; j < r1; ++j)
  {
    w0 = std::min(w0, op.First[j]);
    w1 = std::max(w1, std::min(n - 1, op.First[j] + op.Width - 1));
    for (int k = 0; k < taps; ++k)
    {
      const int i = vtkBloomLinearOperator::FoldIndex(j + offset + k, n, border);
      if (i >= 0)
      {
        w0 = std::min(w0, i);
        w1 = std::max(w1, i);
      }
    }
  }
  const int span = w1 - w0 + 1;
  std::vector<std::vector<double>> rows(r1 - r0, std::vector<double>(span, 0.0));
  int c0 = n, c1 = -1;
  for (int j = r0; j < r1; ++j)
  {
    std::vector<double>& d = rows[j - r0];
    for (size_t k = 0; k < width && op.First[j] + static_cast<int>(k) < n; ++k)
    {
      d[op.First[j] + k - w0] += op.Weights[j * width + k];
    }
    for (int k = 0; k < taps; ++k)
    {
      const int i = vtkBloomLinearOperator::FoldIndex(j + offset + k, n, border);
      if (i >= 0)
      {
        d[i - w0] -= kernel[k];
      }
    }
    for (int i = 0; i < span; ++i)
    {
      if (d[i] != 0.0)
      {
        c0 = std::min(c0, i + w0);
        c1 = std::max(c1, i + w0);
      }
    }
  }
  if (c1 < c0)
  {
    return false;
  }
  block.Row0 = r0;
  block.Rows = r1 - r0;
  FactorBlock(rows, w0, c0, c1, block);
  return block.Rank > 0;
}

//------------------------------------------------------------------------------
// The outputs each input sample reaches, [lo[i], hi[i]], made monotone so that a range's
// reach is its ends'.
void OutputReach(const vtkBloomLinearOperator& op, std::vector<int>& lo, std::vector<int>& hi)
{
  const int n = op.InputSize;
  lo.assign(n, n);
  hi.assign(n, -1);
  for (int j = 0; j < n; ++j)
  {
    for (int i = op.First[j]; i < std::min(n, op.First[j] + op.Width); ++i)
    {
      lo[i] = std::min(lo[i], j);
      hi[i] = std::max(hi[i], j);
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
}

//------------------------------------------------------------------------------
vtkBloomFFTConvolution::Workspace::~Workspace()
{
  if (this->Single)
  {
    Fftw<float>::Free(this->Real);
    Fftw<float>::Free(this->Complex);
  }
  else
  {
    Fftw<double>::Free(this->Real);
    Fftw<double>::Free(this->Complex);
  }
}

//------------------------------------------------------------------------------
void vtkBloomFFTConvolution::Workspace::Reserve(int n, bool single)
{
  if (this->Capacity >= n && this->Single == single && this->Real)
  {
    return;
  }
  this->~Workspace();
  this->Single = single;
  this->Capacity = n;
  const size_t bytes = single ? sizeof(float) : sizeof(double);
  this->Real = single ? Fftw<float>::Malloc(bytes * n) : Fftw<double>::Malloc(bytes * n);
  this->Complex = single ? Fftw<float>::Malloc(bytes * 2 * (n / 2 + 1))
                         : Fftw<double>::Malloc(bytes * 2 * (n / 2 + 1));
}

//------------------------------------------------------------------------------
std::mutex& vtkBloomFFTConvolution::PlannerMutex()
{
  static std::mutex mutex;
  return mutex;
}

//------------------------------------------------------------------------------
int vtkBloomFFTConvolution::GoodTransformSize(int n)
{
  // 1536 takes two thirds of the time of 1500 here: sizes with a factor 5 are left out.
  for (int m = std::max(n, 2);; ++m)
  {
    int r = m;
    for (int p : { 2, 3 })
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
vtkBloomFFTConvolution::vtkBloomFFTConvolution() = default;

//------------------------------------------------------------------------------
vtkBloomFFTConvolution::~vtkBloomFFTConvolution()
{
  this->Release();
}

//------------------------------------------------------------------------------
void vtkBloomFFTConvolution::Release()
{
  std::lock_guard<std::mutex> lock(vtkBloomFFTConvolution::PlannerMutex());
  for (void** plan : { &this->Forward, &this->Inverse })
  {
    if (*plan)
    {
      this->Single ? Fftw<float>::Destroy(*plan) : Fftw<double>::Destroy(*plan);
      *plan = nullptr;
    }
  }
  this->Ready = false;
}

//------------------------------------------------------------------------------
double vtkBloomFFTConvolution::DirectCost(const vtkBloomLinearOperator& op)
{
  double nonzero = 0.0;
  for (double w : op.Weights)
  {
    nonzero += w != 0.0 ? 1.0 : 0.0;
  }
  return nonzero;
}

//------------------------------------------------------------------------------
double vtkBloomFFTConvolution::Cost() const
{
  return this->Cost(this->N, FFTCostFactor);
}

//------------------------------------------------------------------------------
double vtkBloomFFTConvolution::Cost(int n, double factor) const
{
  if (!this->Ready)
  {
    return std::numeric_limits<double>::infinity();
  }
  double cost = factor * n * std::log2(static_cast<double>(n)) + 8.0 * n;
  for (const Block& b : this->Corrections)
  {
    cost += static_cast<double>(b.Rank) * (b.Rows + b.Cols);
  }
  return cost;
}

//------------------------------------------------------------------------------
void vtkBloomFFTConvolution::ComputeKernelSpectrum(int n, std::vector<double>& spectrum) const
{
  std::vector<float> single;
  KernelSpectrum(this->Kernel, this->Offset, n, spectrum, single);
}

//------------------------------------------------------------------------------
int vtkBloomFFTConvolution::GetCorrectionRank(int side) const
{
  for (const Block& b : this->Corrections)
  {
    if ((side == 0) == (b.Row0 == 0))
    {
      return b.Rank;
    }
  }
  return 0;
}

//------------------------------------------------------------------------------
bool vtkBloomFFTConvolution::Build(const vtkBloomLinearOperator& op, int border, bool single)
{
  this->Release();
  this->Corrections.clear();
  const int n = op.InputSize;
  if (n != op.OutputSize || n < 2 || op.Width < 1)
  {
    return false;
  }
  const vtkBloomLinearOperator::InvariantRange range = op.FindInvariantRange(1, 1);
  if (range.Begin >= range.End || range.Stride != 1)
  {
    return false;
  }
  // The kernel of the invariant rows, without its zero ends: row j reads x[j + offset + k].
  std::vector<double> kernel;
  int offset = 0;
  if (!InvariantKernel(op, range, kernel, offset))
  {
    return false;
  }
  const int taps = static_cast<int>(kernel.size());
  this->Size = n;
  this->Border = border;
  this->Single = single;
  this->PadLeft = std::max(0, -offset);
  this->PadRight = std::max(0, offset + taps - 1);
  this->N = vtkBloomFFTConvolution::GoodTransformSize(n + this->PadLeft + this->PadRight);
  KernelSpectrum(kernel, offset, this->N, this->SpectrumD, this->SpectrumF);
  this->Kernel = kernel;
  this->Offset = offset;

  // D = M - T on the rows outside the invariant range, one block per end.
  for (int side = 0; side < 2; ++side)
  {
    const int r0 = side == 0 ? 0 : range.End;
    const int r1 = side == 0 ? range.Begin : n;
    if (r0 >= r1)
    {
      continue;
    }
    Block block;
    if (BorderCorrection(op, kernel, offset, border, r0, r1, block))
    {
      this->Corrections.push_back(std::move(block));
    }
  }

  OutputReach(op, this->ReachLo, this->ReachHi);

  std::lock_guard<std::mutex> lock(vtkBloomFFTConvolution::PlannerMutex());
  if (single)
  {
    MakePlans<float>(this->N, this->Forward, this->Inverse);
  }
  else
  {
    MakePlans<double>(this->N, this->Forward, this->Inverse);
  }
  this->Ready = this->Forward && this->Inverse;
  return this->Ready;
}

//------------------------------------------------------------------------------
template <typename T, typename P>
void vtkBloomFFTConvolution::ApplyLine(T* x, std::ptrdiff_t stride, Workspace& ws) const
{
  using F = Fftw<P>;
  const int n = this->Size;
  const int left = this->PadLeft;
  P* r = static_cast<P*>(ws.Real);
  P* line = r + left;
  // Read the line, then find its non-zero range [a, b] and its largest magnitude.
  for (int m = 0; m < n; ++m)
  {
    line[m] = static_cast<P>(x[m * stride]);
  }
  int a = 0, b = n - 1;
  while (a < n && line[a] == P(0))
  {
    ++a;
  }
  if (a == n)
  {
    return; // an all-zero line stays zero
  }
  while (line[b] == P(0))
  {
    --b;
  }
  // Eight independent maxima (one serial chain of maxima would cost its latency per sample).
  P lanes[8] = { 0, 0, 0, 0, 0, 0, 0, 0 };
  int m = a;
  for (; m + 8 <= b + 1; m += 8)
  {
    for (int k = 0; k < 8; ++k)
    {
      const P v = std::abs(line[m + k]);
      lanes[k] = v > lanes[k] ? v : lanes[k];
    }
  }
  for (; m <= b; ++m)
  {
    const P v = std::abs(line[m]);
    lanes[0] = v > lanes[0] ? v : lanes[0];
  }
  const P largest = *std::max_element(lanes, lanes + 8);
  // Scale by a power of two (exact) so that the largest magnitude is below 1, and extend.
  int exponent = 0;
  std::frexp(static_cast<double>(largest), &exponent);
  const P scale = static_cast<P>(std::ldexp(1.0, -exponent));
  for (int m = a; m <= b; ++m)
  {
    line[m] *= scale;
  }
  for (int q = 1; q <= left; ++q)
  {
    const int i = vtkBloomLinearOperator::FoldIndex(-q, n, this->Border);
    r[left - q] = i < 0 ? P(0) : line[i];
  }
  for (int q = 0; q < this->PadRight; ++q)
  {
    const int i = vtkBloomLinearOperator::FoldIndex(n + q, n, this->Border);
    line[n + q] = i < 0 ? P(0) : line[i];
  }
  std::fill(line + n + this->PadRight, r + this->N, P(0));
  // The corrections' coefficients V^T x, from the (scaled) line before it is overwritten.
  ws.Coefficients.clear();
  for (const Block& block : this->Corrections)
  {
    const size_t first = ws.Coefficients.size();
    ws.Coefficients.resize(first + block.Rank, 0.0);
    double* t = ws.Coefficients.data() + first;
    for (int q = 0; q < block.Cols; ++q)
    {
      const double xq = static_cast<double>(line[block.Col0 + q]);
      const double* v = block.V.data() + static_cast<size_t>(q) * block.Rank;
      for (int k = 0; k < block.Rank; ++k)
      {
        t[k] += v[k] * xq;
      }
    }
  }
  auto* c = static_cast<typename F::Complex*>(ws.Complex);
  F::Forward(this->Forward, r, c);
  const P* s = std::is_same<P, float>::value ? reinterpret_cast<const P*>(this->SpectrumF.data())
                                             : reinterpret_cast<const P*>(this->SpectrumD.data());
  for (int q = 0; q <= this->N / 2; ++q)
  {
    const P re = c[q][0] * s[2 * q] - c[q][1] * s[2 * q + 1];
    const P im = c[q][0] * s[2 * q + 1] + c[q][1] * s[2 * q];
    c[q][0] = re;
    c[q][1] = im;
  }
  F::Inverse(this->Inverse, c, r);

  // Back to the line's scale, plus the corrections, exact zeros where nothing reaches. The
  // scale is a power of two, so the product in P is exact unless it leaves P's range.
  const int lo = this->ReachLo[a], hi = this->ReachHi[b];
  const double unscale = std::ldexp(1.0, exponent);
  const double largestT = static_cast<double>(std::numeric_limits<T>::max());
  auto store = [&](int j, double v)
  { x[j * stride] = static_cast<T>(std::min(std::max(v * unscale, -largestT), largestT)); };
  for (int j = 0; j < lo; ++j)
  {
    x[j * stride] = T(0);
  }
  for (int j = hi + 1; j < n; ++j)
  {
    x[j * stride] = T(0);
  }
  if (std::abs(exponent) < 64 && sizeof(T) <= sizeof(P))
  {
    const P unscaleP = static_cast<P>(unscale);
    const P largestP = static_cast<P>(std::numeric_limits<T>::max());
    for (int j = lo; j <= hi; ++j)
    {
      const P v = line[j] * unscaleP;
      x[j * stride] = static_cast<T>(v > largestP ? largestP : (v < -largestP ? -largestP : v));
    }
  }
  else
  {
    for (int j = lo; j <= hi; ++j)
    {
      store(j, static_cast<double>(line[j]));
    }
  }
  // The border rows once more, with their correction U t.
  std::vector<double>& fix = ws.Line;
  size_t coefficient = 0;
  for (const Block& block : this->Corrections)
  {
    const int j0 = std::max(lo, block.Row0), j1 = std::min(hi + 1, block.Row0 + block.Rows);
    fix.assign(std::max(j1 - j0, 0), 0.0);
    for (int k = 0; k < block.Rank; ++k)
    {
      const double t = ws.Coefficients[coefficient++];
      const double* u = block.U.data() + static_cast<size_t>(k) * block.Rows;
      for (int j = j0; j < j1; ++j)
      {
        fix[j - j0] += t * u[j - block.Row0];
      }
    }
    for (int j = j0; j < j1; ++j)
    {
      store(j, static_cast<double>(line[j]) + fix[j - j0]);
    }
  }
}

//------------------------------------------------------------------------------
template <typename T>
void vtkBloomFFTConvolution::ApplyLines(
  T* data, std::ptrdiff_t sampleStride, std::ptrdiff_t lineStride, int count, Workspace& ws) const
{
  if (!this->Ready)
  {
    return;
  }
  ws.Reserve(this->N, this->Single);
  for (int l = 0; l < count; ++l)
  {
    if (this->Single)
    {
      this->ApplyLine<T, float>(data + l * lineStride, sampleStride, ws);
    }
    else
    {
      this->ApplyLine<T, double>(data + l * lineStride, sampleStride, ws);
    }
  }
}

//------------------------------------------------------------------------------
void vtkBloomFFTConvolution::Apply(float* data, std::ptrdiff_t sampleStride,
  std::ptrdiff_t lineStride, int count, Workspace& ws) const
{
  this->ApplyLines(data, sampleStride, lineStride, count, ws);
}

//------------------------------------------------------------------------------
void vtkBloomFFTConvolution::Apply(double* data, std::ptrdiff_t sampleStride,
  std::ptrdiff_t lineStride, int count, Workspace& ws) const
{
  this->ApplyLines(data, sampleStride, lineStride, count, ws);
}

//------------------------------------------------------------------------------
template <typename T>
void vtkBloomFFTConvolution::ApplyAxis(
  T* data, const int size[3], int lanes, int activeLanes, int axis) const
{
  if (!this->Ready || size[axis] != this->Size)
  {
    return;
  }
  // Lines are numbered so that neighbours in the numbering are neighbours in memory.
  const int u = axis == 0 ? 1 : 0; // the faster of the other two axes
  const int v = axis == 2 ? 1 : 2; // the slower one
  std::ptrdiff_t stride[3] = { lanes, 0, 0 };
  stride[1] = stride[0] * size[0];
  stride[2] = stride[1] * size[1];
  const int n = size[axis];
  vtkSMPThreadLocal<Workspace> workspaces;
  if (axis == 0)
  {
    // Rows are contiguous: one line per row and lane.
    const vtkIdType lines = static_cast<vtkIdType>(size[u]) * size[v] * activeLanes;
    vtkSMPTools::For(0, lines,
      [&](vtkIdType begin, vtkIdType end)
      {
        Workspace& ws = workspaces.Local();
        for (vtkIdType id = begin; id < end; ++id)
        {
          const vtkIdType lane = id % activeLanes;
          const vtkIdType rest = id / activeLanes;
          T* line = data + (rest % size[u]) * stride[u] + (rest / size[u]) * stride[v] + lane;
          this->ApplyLines(line, stride[0], 0, 1, ws);
        }
      });
    return;
  }
  // Columns: a strided line touches a cache line (and often a page) per sample, so copy a tile
  // of Tile neighbouring columns (whole rows of them, contiguous) and filter it there.
  constexpr int Tile = 16;
  const int tiles = (size[u] + Tile - 1) / Tile;
  vtkSMPThreadLocal<std::vector<T>> tileBuffers;
  vtkSMPTools::For(0, static_cast<vtkIdType>(tiles) * size[v],
    [&](vtkIdType begin, vtkIdType end)
    {
      Workspace& ws = workspaces.Local();
      std::vector<T>& tile = tileBuffers.Local();
      for (vtkIdType id = begin; id < end; ++id)
      {
        const int first = static_cast<int>(id % tiles) * Tile;
        const int columns = std::min(Tile, size[u] - first);
        const std::ptrdiff_t row = static_cast<std::ptrdiff_t>(columns) * lanes;
        T* base = data + first * stride[u] + (id / tiles) * stride[v];
        tile.resize(static_cast<size_t>(n) * row);
        for (int m = 0; m < n; ++m)
        {
          std::copy(base + m * stride[axis], base + m * stride[axis] + row, tile.data() + m * row);
        }
        for (int c = 0; c < columns; ++c)
        {
          for (int lane = 0; lane < activeLanes; ++lane)
          {
            this->ApplyLines(tile.data() + c * lanes + lane, row, 0, 1, ws);
          }
        }
        for (int m = 0; m < n; ++m)
        {
          std::copy(tile.data() + m * row, tile.data() + (m + 1) * row, base + m * stride[axis]);
        }
      }
    });
}

template void vtkBloomFFTConvolution::ApplyAxis<float>(float*, const int[3], int, int, int) const;
template void vtkBloomFFTConvolution::ApplyAxis<double>(double*, const int[3], int, int, int) const;
