#include "vtkImageSeparableGaussian.h"

#include "vtkBloomImageOps.h"
#include "vtkBloomKernels.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

vtkStandardNewMacro(vtkImageSeparableGaussian);

namespace
{
//------------------------------------------------------------------------------
// Non-finite bookkeeping: bit 0 = +Inf, bit 1 = -Inf, bit 2 = NaN.
enum : std::uint8_t
{
  KIND_POSITIVE_INFINITY = 1,
  KIND_NEGATIVE_INFINITY = 2,
  KIND_NAN = 4
};

std::uint8_t KindOf(double v)
{
  if (std::isnan(v))
  {
    return KIND_NAN;
  }
  if (std::isinf(v))
  {
    return v > 0 ? KIND_POSITIVE_INFINITY : KIND_NEGATIVE_INFINITY;
  }
  return 0;
}

// Kinds of the samples of a block (same indexing as vtkBloomBuffer).
struct KindBlock
{
  int Lo[3] = { 0, 0, 0 };
  int Size[3] = { 0, 0, 0 };
  int NumberOfComponents = 0;
  std::vector<std::uint8_t> Kinds;

  size_t Offset(int i, int j, int k) const
  {
    return ((static_cast<size_t>(k - this->Lo[2]) * this->Size[1] + (j - this->Lo[1])) *
               this->Size[0] +
             (i - this->Lo[0])) *
      this->NumberOfComponents;
  }
};

// out[o] = OR of in[m] over the non-zero taps m of op's row o, for o in [outLo, outLo + outSize).
KindBlock DilateKinds(
  const KindBlock& in, int axis, const vtkBloomLinearOperator& op, int outLo, int outSize)
{
  KindBlock out;
  std::copy(in.Lo, in.Lo + 3, out.Lo);
  std::copy(in.Size, in.Size + 3, out.Size);
  out.Lo[axis] = outLo;
  out.Size[axis] = outSize;
  out.NumberOfComponents = in.NumberOfComponents;
  const int nc = in.NumberOfComponents;
  out.Kinds.assign(
    static_cast<size_t>(out.Size[0]) * out.Size[1] * out.Size[2] * nc, std::uint8_t(0));
  int idx[3];
  for (idx[2] = out.Lo[2]; idx[2] < out.Lo[2] + out.Size[2]; ++idx[2])
  {
    for (idx[1] = out.Lo[1]; idx[1] < out.Lo[1] + out.Size[1]; ++idx[1])
    {
      for (idx[0] = out.Lo[0]; idx[0] < out.Lo[0] + out.Size[0]; ++idx[0])
      {
        std::uint8_t* dst = out.Kinds.data() + out.Offset(idx[0], idx[1], idx[2]);
        const int o = idx[axis];
        for (int t = 0; t < op.Width; ++t)
        {
          const int m = op.First[o] + t;
          if (op.Weights[static_cast<size_t>(o) * op.Width + t] == 0.0 || m < in.Lo[axis] ||
            m >= in.Lo[axis] + in.Size[axis])
          {
            continue;
          }
          int src[3] = { idx[0], idx[1], idx[2] };
          src[axis] = m;
          const std::uint8_t* s = in.Kinds.data() + in.Offset(src[0], src[1], src[2]);
          for (int c = 0; c < nc; ++c)
          {
            dst[c] |= s[c];
          }
        }
      }
    }
  }
  return out;
}

//------------------------------------------------------------------------------
// Replace the non-finite samples of `data` (n values) in place: with sanitize, NaN -> 0 and
// +/-Inf -> the finite extremes of T; otherwise all of them -> 0. Records kinds when asked.
template <typename T>
bool CleanValues(T* data, vtkIdType n, bool sanitize, std::vector<std::uint8_t>* kinds)
{
  bool found = false;
  for (vtkIdType e = 0; e < n; ++e)
  {
    const T v = data[e];
    if (std::isfinite(v))
    {
      continue;
    }
    found = true;
    if (kinds)
    {
      (*kinds)[e] = KindOf(static_cast<double>(v));
    }
    if (sanitize && std::isinf(v))
    {
      data[e] = v > 0 ? std::numeric_limits<T>::max() : std::numeric_limits<T>::lowest();
    }
    else
    {
      data[e] = T(0);
    }
  }
  return found;
}

template <typename T>
bool HasNonFinite(const T* data, vtkIdType n)
{
  for (vtkIdType e = 0; e < n; ++e)
  {
    if (!std::isfinite(data[e]))
    {
      return true;
    }
  }
  return false;
}

// Clamp to the finite range of T (NaN from an overflow becomes 0), over an extent.
template <typename T>
void ClampToFinite(vtkImageData* image, const int extent[6])
{
  const int nc = image->GetNumberOfScalarComponents();
  for (int k = extent[4]; k <= extent[5]; ++k)
  {
    for (int j = extent[2]; j <= extent[3]; ++j)
    {
      T* p = static_cast<T*>(image->GetScalarPointer(extent[0], j, k));
      const size_t count = static_cast<size_t>(extent[1] - extent[0] + 1) * nc;
      for (size_t e = 0; e < count; ++e)
      {
        if (!std::isfinite(p[e]))
        {
          p[e] = std::isnan(p[e])
            ? T(0)
            : (p[e] > 0 ? std::numeric_limits<T>::max() : std::numeric_limits<T>::lowest());
        }
      }
    }
  }
}

//------------------------------------------------------------------------------
// The fast one-dimensional filters. A line holds `n` samples of `lanes` independent values
// each, sample-major ([n][lanes]); lanes are components and neighbouring lines, so the inner
// loops run over contiguous memory and vectorize.

// Gwosdek's extended box applied `passes` times. The line is extended once by the total support
// with the border, then each pass shrinks it by r + 1 on each side, so the cascade is exactly
// the cascaded kernel applied to the extended signal for every border. Window sums come from
// per-block prefix and suffix sums (blocks of 2r + 1 samples), never from subtracting what
// leaves a running sum, so a huge sample leaves no residue outside its support.
void BoxCascadeLine(double* line, int n, int lanes, int border,
  const vtkBloomKernels::ExtendedBox& box, int passes, std::vector<double>& scratch)
{
  const int r = box.Radius;
  const int margin = passes * (r + 1);
  const int length = n + 2 * margin;
  const int window = 2 * r + 1;
  const size_t L = static_cast<size_t>(lanes);
  scratch.resize(3 * static_cast<size_t>(length) * L);
  double* ext = scratch.data();
  double* prefix = ext + static_cast<size_t>(length) * L;
  double* suffix = prefix + static_cast<size_t>(length) * L;
  for (int m = 0; m < length; ++m)
  {
    const int source = vtkBloomLinearOperator::FoldIndex(m - margin, n, border);
    double* dst = ext + m * L;
    if (source < 0)
    {
      std::fill(dst, dst + L, 0.0);
    }
    else
    {
      std::copy(line + source * L, line + (source + 1) * L, dst);
    }
  }
  const double alpha = box.Alpha;
  const double scale = 1.0 / (window + 2.0 * alpha);
  int current = length;
  for (int pass = 0; pass < passes; ++pass)
  {
    // Block sums over [b w, (b + 1) w): prefix[i] = sum of the block up to i, suffix[i] = from i.
    for (int start = 0; start < current; start += window)
    {
      const int end = std::min(start + window, current);
      std::copy(ext + start * L, ext + (start + 1) * L, prefix + start * L);
      for (int i = start + 1; i < end; ++i)
      {
        for (size_t l = 0; l < L; ++l)
        {
          prefix[i * L + l] = prefix[(i - 1) * L + l] + ext[i * L + l];
        }
      }
      std::copy(ext + (end - 1) * L, ext + end * L, suffix + (end - 1) * L);
      for (int i = end - 2; i >= start; --i)
      {
        for (size_t l = 0; l < L; ++l)
        {
          suffix[i * L + l] = suffix[(i + 1) * L + l] + ext[i * L + l];
        }
      }
    }
    // Output j is centred on input j + r + 1; its window is [j + 1, j + window].
    const int outLength = current - 2 * (r + 1);
    for (int j = 0; j < outLength; ++j)
    {
      const int s = j + 1;
      const int e = j + window;
      const double* a = ext + j * L;
      const double* b = ext + (e + 1) * L;
      double* out = ext + j * L;
      if (s % window == 0)
      {
        const double* full = prefix + e * L;
        for (size_t l = 0; l < L; ++l)
        {
          out[l] = (full[l] + alpha * (a[l] + b[l])) * scale;
        }
      }
      else
      {
        const double* left = suffix + s * L;
        const double* right = prefix + e * L;
        for (size_t l = 0; l < L; ++l)
        {
          out[l] = (left[l] + right[l] + alpha * (a[l] + b[l])) * scale;
        }
      }
    }
    current = outLength;
  }
  std::copy(ext, ext + static_cast<size_t>(n) * L, line);
}

// A direct convolution with a short symmetric half kernel (the recursive method below sigma
// 0.5, where a third-order recursion cannot reach the variance).
void DirectLine(double* line, int n, int lanes, int border, const std::vector<double>& half,
  std::vector<double>& scratch)
{
  const size_t L = static_cast<size_t>(lanes);
  const int radius = static_cast<int>(half.size()) - 1;
  scratch.assign(static_cast<size_t>(n) * L, 0.0);
  for (int m = 0; m < n; ++m)
  {
    for (int k = -radius; k <= radius; ++k)
    {
      const int source = vtkBloomLinearOperator::FoldIndex(m + k, n, border);
      if (source < 0)
      {
        continue;
      }
      const double w = half[static_cast<size_t>(std::abs(k))];
      for (size_t l = 0; l < L; ++l)
      {
        scratch[m * L + l] += w * line[source * L + l];
      }
    }
  }
  std::copy(scratch.begin(), scratch.end(), line);
}

// 3 x 3 helpers for the periodic steady state of the recursion.
using Matrix3 = std::array<std::array<double, 3>, 3>;

Matrix3 Multiply(const Matrix3& a, const Matrix3& b)
{
  Matrix3 c{};
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      for (int k = 0; k < 3; ++k)
      {
        c[i][j] += a[i][k] * b[k][j];
      }
    }
  }
  return c;
}

Matrix3 Inverse(const Matrix3& m)
{
  Matrix3 inv{};
  const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
    m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
    m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  inv[0][0] = (m[1][1] * m[2][2] - m[1][2] * m[2][1]) / det;
  inv[0][1] = (m[0][2] * m[2][1] - m[0][1] * m[2][2]) / det;
  inv[0][2] = (m[0][1] * m[1][2] - m[0][2] * m[1][1]) / det;
  inv[1][0] = (m[1][2] * m[2][0] - m[1][0] * m[2][2]) / det;
  inv[1][1] = (m[0][0] * m[2][2] - m[0][2] * m[2][0]) / det;
  inv[1][2] = (m[0][2] * m[1][0] - m[0][0] * m[1][2]) / det;
  inv[2][0] = (m[1][0] * m[2][1] - m[1][1] * m[2][0]) / det;
  inv[2][1] = (m[0][1] * m[2][0] - m[0][0] * m[2][1]) / det;
  inv[2][2] = (m[0][0] * m[1][1] - m[0][1] * m[1][0]) / det;
  return inv;
}

// (I - A^period)^-1, where A advances the recursion state (v1, v2, v3) by one sample with no
// input: the map from the state change over one period to the periodic steady state.
Matrix3 PeriodicSteadyState(const vtkBloomKernels::RecursiveGaussian& c, long long period)
{
  Matrix3 a{};
  a[0] = { -c.Feedback[0], -c.Feedback[1], -c.Feedback[2] };
  a[1] = { 1.0, 0.0, 0.0 };
  a[2] = { 0.0, 1.0, 0.0 };
  Matrix3 power{};
  power[0][0] = power[1][1] = power[2][2] = 1.0;
  for (long long e = period; e > 0; e >>= 1)
  {
    if (e & 1)
    {
      power = Multiply(power, a);
    }
    a = Multiply(a, a);
  }
  Matrix3 m{};
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      m[i][j] = (i == j ? 1.0 : 0.0) - power[i][j];
    }
  }
  return Inverse(m);
}

// One causal pass over buffer[3 .. 3 + count) (buffer[0..2] hold the three previous outputs,
// oldest first), writing in place.
void CausalPass(double* buffer, int count, size_t L, const vtkBloomKernels::RecursiveGaussian& c)
{
  const double g = c.Gain, f1 = c.Feedback[0], f2 = c.Feedback[1], f3 = c.Feedback[2];
  for (int m = 3; m < count + 3; ++m)
  {
    double* w = buffer + m * L;
    const double* w1 = w - L;
    const double* w2 = w - 2 * L;
    const double* w3 = w - 3 * L;
    for (size_t l = 0; l < L; ++l)
    {
      w[l] = g * w[l] - f1 * w1[l] - f2 * w2[l] - f3 * w3[l];
    }
  }
}

// One anti-causal pass over buffer[0 .. count) (buffer[count .. count + 3) hold the three next
// outputs, nearest first), writing in place.
void AntiCausalPass(
  double* buffer, int count, size_t L, const vtkBloomKernels::RecursiveGaussian& c)
{
  const double g = c.Gain, f1 = c.Feedback[0], f2 = c.Feedback[1], f3 = c.Feedback[2];
  for (int m = count - 1; m >= 0; --m)
  {
    double* y = buffer + m * L;
    const double* y1 = y + L;
    const double* y2 = y + 2 * L;
    const double* y3 = y + 3 * L;
    for (size_t l = 0; l < L; ++l)
    {
      y[l] = g * y[l] - f1 * y1[l] - f2 * y2[l] - f3 * y3[l];
    }
  }
}

// The recursive Gaussian on one line. Clamp and zero: Triggs-Sdika initialization (exact for
// the constant extension). Reflect: the half-sample mirror is periodic with period 2n, and the
// state after one period is an affine function of the state before it, so the exact steady
// state is (I - A^2n)^-1 times the state reached from zero.
void RecursiveLine(double* line, int n, int lanes, int border,
  const vtkBloomKernels::RecursiveGaussian& c, const Matrix3& periodic,
  std::vector<double>& scratch)
{
  const size_t L = static_cast<size_t>(lanes);
  if (border == vtkBloomLinearOperator::BORDER_REFLECT && c.Sigma >= 3.0 * n)
  {
    // Far wider than the mirrored period 2n, the Gaussian's periodic ripple is below
    // exp(-2 pi^2 1.5^2) ~ 1e-19: the answer is the mean. The recursion itself would only add
    // round-off there (its poles are within 1e-3 of 1).
    for (size_t l = 0; l < L; ++l)
    {
      double sum = 0.0;
      for (int m = 0; m < n; ++m)
      {
        sum += line[m * L + l];
      }
      for (int m = 0; m < n; ++m)
      {
        line[m * L + l] = sum / n;
      }
    }
    return;
  }
  if (border == vtkBloomLinearOperator::BORDER_REFLECT)
  {
    const int period = 2 * n;
    scratch.resize(static_cast<size_t>(period + 6) * L);
    double* b = scratch.data();
    auto load = [&]()
    {
      for (int m = 0; m < period; ++m)
      {
        const int source = m < n ? m : period - 1 - m;
        std::copy(line + source * L, line + (source + 1) * L, b + (m + 3) * L);
      }
    };
    // Causal: from a zero state, then from the steady state.
    load();
    std::fill(b, b + 3 * L, 0.0);
    CausalPass(b, period, L, c);
    std::vector<double> state(3 * L);
    for (size_t l = 0; l < L; ++l)
    {
      const double r[3] = { b[(period + 2) * L + l], b[(period + 1) * L + l], b[period * L + l] };
      for (int i = 0; i < 3; ++i)
      {
        state[i * L + l] = periodic[i][0] * r[0] + periodic[i][1] * r[1] + periodic[i][2] * r[2];
      }
    }
    load();
    for (size_t l = 0; l < L; ++l)
    {
      // buffer[0..2] are w[-3], w[-2], w[-1]; the state is (w[-1], w[-2], w[-3]).
      b[2 * L + l] = state[0 * L + l];
      b[1 * L + l] = state[1 * L + l];
      b[0 * L + l] = state[2 * L + l];
    }
    CausalPass(b, period, L, c);
    // Anti-causal over w[0 .. period) (now at b + 3L): zero state, then the steady state.
    double* w = b + 3 * L;
    std::vector<double> causal(w, w + static_cast<size_t>(period) * L);
    std::fill(w + static_cast<size_t>(period) * L, w + static_cast<size_t>(period + 3) * L, 0.0);
    AntiCausalPass(w, period, L, c);
    for (size_t l = 0; l < L; ++l)
    {
      const double r[3] = { w[0 * L + l], w[1 * L + l], w[2 * L + l] };
      for (int i = 0; i < 3; ++i)
      {
        state[i * L + l] = periodic[i][0] * r[0] + periodic[i][1] * r[1] + periodic[i][2] * r[2];
      }
    }
    std::copy(causal.begin(), causal.end(), w);
    for (int i = 0; i < 3; ++i)
    {
      std::copy(state.begin() + i * L, state.begin() + (i + 1) * L, w + (period + i) * L);
    }
    AntiCausalPass(w, period, L, c);
    std::copy(w, w + static_cast<size_t>(n) * L, line);
    return;
  }

  // Clamp or zero: buffer = [w[-3], w[-2], w[-1], w[0] .. w[n-1], y[n], y[n+1], y[n+2]].
  scratch.resize(static_cast<size_t>(n + 6) * L);
  double* b = scratch.data();
  const bool zero = border == vtkBloomLinearOperator::BORDER_ZERO;
  for (int i = 0; i < 3; ++i)
  {
    // The constant past of the clamp extension is its own steady state (unit DC gain).
    for (size_t l = 0; l < L; ++l)
    {
      b[i * L + l] = zero ? 0.0 : line[l];
    }
  }
  std::copy(line, line + static_cast<size_t>(n) * L, b + 3 * L);
  CausalPass(b, n, L, c);
  double* w = b + 3 * L;
  for (size_t l = 0; l < L; ++l)
  {
    const double u = zero ? 0.0 : line[(n - 1) * L + l];
    // With n < 3 the earlier states are the initial ones in b[0..2], just before w.
    const std::ptrdiff_t at =
      static_cast<std::ptrdiff_t>(n + 3) * lanes + static_cast<std::ptrdiff_t>(l);
    const double d[3] = { b[at - lanes] - u, b[at - 2 * lanes] - u, b[at - 3 * lanes] - u };
    for (int j = 0; j < 3; ++j)
    {
      w[(n + j) * L + l] =
        u + c.Boundary[j][0] * d[0] + c.Boundary[j][1] * d[1] + c.Boundary[j][2] * d[2];
    }
  }
  AntiCausalPass(w, n, L, c);
  std::copy(w, w + static_cast<size_t>(n) * L, line);
}
}

//------------------------------------------------------------------------------
vtkImageSeparableGaussian::vtkImageSeparableGaussian()
{
  this->StandardDeviations[0] = 2.0;
  this->StandardDeviations[1] = 2.0;
  this->StandardDeviations[2] = 0.0;
  this->Radius[0] = this->Radius[1] = this->Radius[2] = -1;
  this->RadiusFactor = 4.0;
  this->KernelType = SAMPLED;
  this->BorderMode = CLAMP;
  this->Method = EXACT;
  this->SanitizeNonFinite = true;
  this->CleanInput = nullptr;
}

//------------------------------------------------------------------------------
vtkImageSeparableGaussian::~vtkImageSeparableGaussian() = default;

//------------------------------------------------------------------------------
std::vector<double> vtkImageSeparableGaussian::GetHalfKernel(int axis)
{
  if (axis < 0 || axis > 2)
  {
    return { 1.0 };
  }
  const double sigma = this->StandardDeviations[axis];
  const int radius = this->Radius[axis] >= 0
    ? this->Radius[axis]
    : vtkBloomKernels::RadiusForSigma(sigma, this->RadiusFactor);
  return vtkBloomKernels::GaussianHalfKernel(sigma, radius, this->KernelType);
}

//------------------------------------------------------------------------------
bool vtkImageSeparableGaussian::BuildTerms(
  const int inWhole[6], const int*, std::vector<Term>& terms)
{
  Term term;
  for (int a = 0; a < 3; ++a)
  {
    const double sigma = this->StandardDeviations[a];
    if (!(sigma >= 0.0) || !std::isfinite(sigma))
    {
      vtkErrorMacro(<< "StandardDeviations must be finite and >= 0; axis " << a << " has " << sigma
                    << ".");
      return false;
    }
    const std::vector<double> half = this->GetHalfKernel(a);
    const int n = inWhole[2 * a + 1] - inWhole[2 * a] + 1;
    if (half.size() > 1 && n > 0)
    {
      term.Operators[a] = vtkBloomLinearOperator::Convolve(
        n, vtkBloomKernels::SymmetricTaps(half, 1.0), this->BorderMode);
      term.Use[a] = !term.Operators[a].IsIdentity();
    }
  }
  terms.push_back(std::move(term));
  return true;
}

//------------------------------------------------------------------------------
const char* vtkImageSeparableGaussian::GetMethodName(int method)
{
  switch (method)
  {
    case BOX_CASCADE_3:
      return "BoxCascade3";
    case BOX_CASCADE_5:
      return "BoxCascade5";
    case RECURSIVE:
      return "Recursive";
    default:
      return "Exact";
  }
}

//------------------------------------------------------------------------------
vtkBloomLinearOperator vtkImageSeparableGaussian::SupportOperator(int axis, int n)
{
  const double sigma = this->StandardDeviations[axis];
  int radius = 0;
  switch (this->Method)
  {
    case BOX_CASCADE_3:
    case BOX_CASCADE_5:
    {
      const int passes = this->Method == BOX_CASCADE_3 ? 3 : 5;
      const auto box = vtkBloomKernels::ExtendedBoxForVariance(sigma * sigma / passes);
      radius = passes * (box.Radius + (box.Alpha > 0.0 ? 1 : 0));
      break;
    }
    case RECURSIVE:
      radius = vtkBloomKernels::RadiusForSigma(sigma, this->RadiusFactor);
      break;
    default:
    {
      const std::vector<double> half = this->GetHalfKernel(axis);
      return vtkBloomLinearOperator::Convolve(
        n, vtkBloomKernels::SymmetricTaps(half, 1.0), this->BorderMode);
    }
  }
  std::vector<double> ones(static_cast<size_t>(std::max(radius, 0)) + 1, 1.0);
  return vtkBloomLinearOperator::Convolve(
    n, vtkBloomKernels::SymmetricTaps(ones, 1.0), this->BorderMode);
}

//------------------------------------------------------------------------------
int vtkImageSeparableGaussian::RequestUpdateExtent(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  if (this->Method == EXACT)
  {
    return this->Superclass::RequestUpdateExtent(request, inputVector, outputVector);
  }
  // The fast methods read whole lines on every filtered axis.
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  int inWhole[6], outExt[6];
  inInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), inWhole);
  outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), outExt);
  int inExt[6];
  for (int a = 0; a < 3; ++a)
  {
    const bool filtered = this->StandardDeviations[a] > 0.0;
    inExt[2 * a] = filtered ? inWhole[2 * a] : std::max(outExt[2 * a], inWhole[2 * a]);
    inExt[2 * a + 1] =
      filtered ? inWhole[2 * a + 1] : std::min(outExt[2 * a + 1], inWhole[2 * a + 1]);
    if (inExt[2 * a] > inExt[2 * a + 1])
    {
      std::copy(inWhole, inWhole + 6, inExt);
      break;
    }
  }
  inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), inExt, 6);
  return 1;
}

//------------------------------------------------------------------------------
int vtkImageSeparableGaussian::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkImageData* input = vtkImageData::GetData(inInfo);
  vtkImageData* output = vtkImageData::GetData(outInfo);
  if (!input || !input->GetPointData()->GetScalars() ||
    !vtkImageSeparableAlgorithm::IsSupportedInput(
      input->GetScalarType(), input->GetNumberOfScalarComponents()))
  {
    // The superclass reports the error and empties the output.
    return this->Superclass::RequestData(request, inputVector, outputVector);
  }
  for (int a = 0; a < 3; ++a)
  {
    const double sigma = this->StandardDeviations[a];
    if (!(sigma >= 0.0) || !std::isfinite(sigma))
    {
      vtkErrorMacro(<< "StandardDeviations must be finite and >= 0; axis " << a << " has " << sigma
                    << ".");
      output->Initialize();
      return 0;
    }
  }

  // Non-finite input: work on a cleaned copy (see the class description).
  vtkDataArray* scalars = input->GetPointData()->GetScalars();
  const vtkIdType count = scalars->GetNumberOfValues();
  const bool isFloat = input->GetScalarType() == VTK_FLOAT;
  void* raw = scalars->GetVoidPointer(0);
  const bool nonFinite = isFloat ? HasNonFinite(static_cast<const float*>(raw), count)
                                 : HasNonFinite(static_cast<const double*>(raw), count);
  vtkSmartPointer<vtkImageData> clean;
  KindBlock kinds;
  if (nonFinite)
  {
    clean = vtkSmartPointer<vtkImageData>::New();
    clean->DeepCopy(input);
    void* data = clean->GetPointData()->GetScalars()->GetVoidPointer(0);
    std::vector<std::uint8_t>* record = nullptr;
    if (!this->SanitizeNonFinite)
    {
      int ext[6];
      input->GetExtent(ext);
      const int* whole = inInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT());
      for (int a = 0; a < 3; ++a)
      {
        kinds.Lo[a] = ext[2 * a] - whole[2 * a];
        kinds.Size[a] = ext[2 * a + 1] - ext[2 * a] + 1;
      }
      kinds.NumberOfComponents = input->GetNumberOfScalarComponents();
      kinds.Kinds.assign(static_cast<size_t>(count), std::uint8_t(0));
      record = &kinds.Kinds;
    }
    if (isFloat)
    {
      CleanValues(static_cast<float*>(data), count, this->SanitizeNonFinite, record);
    }
    else
    {
      CleanValues(static_cast<double*>(data), count, this->SanitizeNonFinite, record);
    }
    this->CleanInput = clean;
  }

  int result = 1;
  if (this->Method == EXACT)
  {
    // Every piece repeats the x pass over the rows its y support needs, so the default pieces of
    // 64 KiB (a few rows) would redo it about 2R / rows times: cut slabs, about four per thread.
    int updateExtent[6];
    outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), updateExtent);
    vtkIdType bytes =
      static_cast<vtkIdType>(input->GetNumberOfScalarComponents()) * input->GetScalarSize();
    for (int a = 0; a < 3; ++a)
    {
      bytes *= std::max(updateExtent[2 * a + 1] - updateExtent[2 * a] + 1, 1);
    }
    const int threads = std::max(1, vtkSMPTools::GetEstimatedNumberOfThreads());
    this->SplitMode = SLAB;
    this->DesiredBytesPerPiece = std::max<vtkIdType>(65536, bytes / (4 * threads));
    result = this->Superclass::RequestData(request, inputVector, outputVector);
  }
  else
  {
    inInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), this->InputWholeExtent);
    outInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), this->OutputWholeExtent);
    int outExt[6];
    outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), outExt);
    this->AllocateOutputData(output, outInfo, outExt);
    this->CopyAttributeData(input, output, inputVector);
    this->ExecuteFast(clean ? clean.Get() : input, output, outExt);
  }
  this->CleanInput = nullptr;
  if (!result || !output->GetPointData()->GetScalars())
  {
    return result;
  }

  int outExt[6];
  output->GetExtent(outExt);
  if (this->SanitizeNonFinite)
  {
    if (isFloat)
    {
      ClampToFinite<float>(output, outExt);
    }
    else
    {
      ClampToFinite<double>(output, outExt);
    }
  }
  else if (nonFinite)
  {
    // Mark the outputs whose support holds a non-finite input sample.
    const int* whole = inInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT());
    for (int a = 0; a < 3; ++a)
    {
      if (!(this->StandardDeviations[a] > 0.0))
      {
        continue;
      }
      const int n = whole[2 * a + 1] - whole[2 * a] + 1;
      const vtkBloomLinearOperator op = this->SupportOperator(a, n);
      kinds = DilateKinds(
        kinds, a, op, outExt[2 * a] - whole[2 * a], outExt[2 * a + 1] - outExt[2 * a] + 1);
    }
    const int nc = output->GetNumberOfScalarComponents();
    for (int k = outExt[4]; k <= outExt[5]; ++k)
    {
      for (int j = outExt[2]; j <= outExt[3]; ++j)
      {
        for (int i = outExt[0]; i <= outExt[1]; ++i)
        {
          const std::uint8_t* kind =
            kinds.Kinds.data() + kinds.Offset(i - whole[0], j - whole[2], k - whole[4]);
          for (int c = 0; c < nc; ++c)
          {
            if (!kind[c])
            {
              continue;
            }
            const double value = kind[c] == KIND_POSITIVE_INFINITY
              ? std::numeric_limits<double>::infinity()
              : (kind[c] == KIND_NEGATIVE_INFINITY ? -std::numeric_limits<double>::infinity()
                                                   : std::numeric_limits<double>::quiet_NaN());
            output->SetScalarComponentFromDouble(i, j, k, c, value);
          }
        }
      }
    }
  }
  return result;
}

//------------------------------------------------------------------------------
void vtkImageSeparableGaussian::ThreadedRequestData(vtkInformation* request,
  vtkInformationVector** inputVector, vtkInformationVector* outputVector, vtkImageData*** inData,
  vtkImageData** outData, int outExt[6], int threadId)
{
  if (!this->CleanInput)
  {
    this->Superclass::ThreadedRequestData(
      request, inputVector, outputVector, inData, outData, outExt, threadId);
    return;
  }
  vtkImageData* clean[1] = { this->CleanInput };
  vtkImageData** cleanPorts[1] = { clean };
  this->Superclass::ThreadedRequestData(
    request, inputVector, outputVector, cleanPorts, outData, outExt, threadId);
}

//------------------------------------------------------------------------------
void vtkImageSeparableGaussian::ExecuteFast(
  vtkImageData* input, vtkImageData* output, const int outExt[6])
{
  if (outExt[0] > outExt[1] || outExt[2] > outExt[3] || outExt[4] > outExt[5])
  {
    return;
  }
  const int* whole = this->InputWholeExtent;
  const int wholeLo[3] = { whole[0], whole[2], whole[4] };
  int available[6], ext[6];
  input->GetExtent(available);
  for (int a = 0; a < 3; ++a)
  {
    const bool filtered = this->StandardDeviations[a] > 0.0;
    ext[2 * a] = filtered ? whole[2 * a] : outExt[2 * a];
    ext[2 * a + 1] = filtered ? whole[2 * a + 1] : outExt[2 * a + 1];
    if (ext[2 * a] < available[2 * a] || ext[2 * a + 1] > available[2 * a + 1])
    {
      vtkErrorMacro(<< "The input does not hold the extent the filter needs.");
      return;
    }
  }
  const int nc = input->GetNumberOfScalarComponents();
  vtkBloomBuffer buffer;
  vtkBloomImport(input, ext, wholeLo, 0, nc, buffer);

  int done = 0, total = 0;
  for (int a = 0; a < 3; ++a)
  {
    total += this->StandardDeviations[a] > 0.0 ? 1 : 0;
  }
  for (int axis = 0; axis < 3; ++axis)
  {
    const double sigma = this->StandardDeviations[axis];
    if (!(sigma > 0.0) || this->AbortExecute)
    {
      continue;
    }
    const int n = buffer.Size[axis];
    // Lines along `axis`: every faster axis and the components are lanes, sample-major.
    size_t stride = static_cast<size_t>(nc);
    for (int b = 0; b < axis; ++b)
    {
      stride *= static_cast<size_t>(buffer.Size[b]);
    }
    size_t groups = 1;
    for (int b = axis + 1; b < 3; ++b)
    {
      groups *= static_cast<size_t>(buffer.Size[b]);
    }
    const size_t chunk = axis == 0 ? stride : std::min<size_t>(stride, 64);
    const size_t chunksPerGroup = (stride + chunk - 1) / chunk;
    const int method = this->Method;
    const int border = this->BorderMode;
    const int passes = method == BOX_CASCADE_5 ? 5 : 3;
    const vtkBloomKernels::ExtendedBox box =
      vtkBloomKernels::ExtendedBoxForVariance(sigma * sigma / passes);
    vtkBloomKernels::RecursiveGaussian recursive;
    Matrix3 periodic{};
    // Below sigma 0.5 the third-order recursion cannot reach the variance: use Lindeberg's
    // discrete kernel (exact variance) directly there.
    const bool direct = method == RECURSIVE && sigma < 0.5;
    const std::vector<double> half = direct
      ? vtkBloomKernels::GaussianHalfKernel(
          sigma, vtkBloomKernels::RadiusForSigma(sigma, 6.0), vtkBloomKernels::GAUSSIAN_DISCRETE)
      : std::vector<double>();
    if (method == RECURSIVE && !direct)
    {
      recursive = vtkBloomKernels::RecursiveGaussianCoefficients(sigma);
      periodic = PeriodicSteadyState(recursive, 2LL * n);
    }
    double* data = buffer.Data.data();
    vtkSMPTools::For(0, static_cast<vtkIdType>(groups * chunksPerGroup),
      [&](vtkIdType begin, vtkIdType end)
      {
        std::vector<double> line, scratch;
        for (vtkIdType u = begin; u < end; ++u)
        {
          const size_t g = static_cast<size_t>(u) / chunksPerGroup;
          const size_t first = (static_cast<size_t>(u) % chunksPerGroup) * chunk;
          const size_t lanes = std::min(chunk, stride - first);
          double* base = data + g * n * stride + first;
          line.resize(static_cast<size_t>(n) * lanes);
          for (int m = 0; m < n; ++m)
          {
            std::copy(base + m * stride, base + m * stride + lanes, line.data() + m * lanes);
          }
          if (direct)
          {
            DirectLine(line.data(), n, static_cast<int>(lanes), border, half, scratch);
          }
          else if (method == RECURSIVE)
          {
            RecursiveLine(
              line.data(), n, static_cast<int>(lanes), border, recursive, periodic, scratch);
          }
          else
          {
            BoxCascadeLine(line.data(), n, static_cast<int>(lanes), border, box, passes, scratch);
          }
          for (int m = 0; m < n; ++m)
          {
            std::copy(line.data() + m * lanes, line.data() + (m + 1) * lanes, base + m * stride);
          }
        }
      });
    this->UpdateProgress(0.95 * (++done) / std::max(total, 1));
  }
  vtkBloomExport(buffer, wholeLo, output, outExt, 0);
  this->UpdateProgress(1.0);
}

//------------------------------------------------------------------------------
const char* vtkImageSeparableGaussian::GetKernelTypeAsString()
{
  switch (this->KernelType)
  {
    case INTEGRATED:
      return "Integrated";
    case DISCRETE:
      return "Discrete";
    default:
      return "Sampled";
  }
}

//------------------------------------------------------------------------------
const char* vtkImageSeparableGaussian::GetBorderModeAsString()
{
  switch (this->BorderMode)
  {
    case REFLECT:
      return "Reflect";
    case ZERO:
      return "Zero";
    default:
      return "Clamp";
  }
}

//------------------------------------------------------------------------------
void vtkImageSeparableGaussian::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "StandardDeviations: (" << this->StandardDeviations[0] << ", "
     << this->StandardDeviations[1] << ", " << this->StandardDeviations[2] << ")\n";
  os << indent << "Radius: (" << this->Radius[0] << ", " << this->Radius[1] << ", "
     << this->Radius[2] << ")\n";
  os << indent << "RadiusFactor: " << this->RadiusFactor << "\n";
  os << indent << "KernelType: " << this->GetKernelTypeAsString() << "\n";
  os << indent << "BorderMode: " << this->GetBorderModeAsString() << "\n";
  os << indent << "Method: " << this->GetMethodAsString() << "\n";
  os << indent << "SanitizeNonFinite: " << (this->SanitizeNonFinite ? "On" : "Off") << "\n";
}
