// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkBloomLineFilters.h"

#include "vtkBloomLinearOperator.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace vtkBloomLineFilters
{
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
