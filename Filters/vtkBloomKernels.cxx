// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkBloomKernels.h"

#include <algorithm>
#include <cmath>
#include <complex>

namespace
{
// Lindeberg's discrete Gaussian e^{-t} I_n(t) for n = 0..radius, t = sigma^2.
// The modified Bessel functions are computed by Miller's backward recurrence
// I_{n-1}(t) = (2n / t) I_n(t) + I_{n+1}(t), started far beyond the radius and normalized with
// the identity e^{-t} (I_0 + 2 sum_{n>0} I_n) = 1. That needs no exp(t), so it neither overflows
// for wide kernels nor underflows for narrow ones.
std::vector<double> DiscreteGaussian(double t, int radius)
{
  const int start = radius + 16 + static_cast<int>(std::ceil(12.0 * std::sqrt(t)));
  std::vector<double> values(static_cast<size_t>(start) + 2, 0.0);
  double next = 0.0;       // I_{n+1}
  double current = 1e-300; // I_n, arbitrary scale
  values[start] = current;
  for (int n = start; n > 0; --n)
  {
    const double previous = (2.0 * n / t) * current + next;
    next = current;
    current = previous;
    values[n - 1] = current;
    if (current > 1e250)
    {
      // Rescale everything computed so far; only ratios matter.
      for (int m = n - 1; m <= start; ++m)
      {
        values[m] *= 1e-250;
      }
      next *= 1e-250;
      current *= 1e-250;
    }
  }
  double total = values[0];
  for (int n = 1; n <= start; ++n)
  {
    total += 2.0 * values[n];
  }
  std::vector<double> half(static_cast<size_t>(radius) + 1);
  for (int n = 0; n <= radius; ++n)
  {
    half[n] = values[n] / total;
  }
  return half;
}

// Mass of N(0, sigma^2) over [i - 1/2, i + 1/2], using erfc on the far side to avoid
// cancellation in the tails.
double IntegratedGaussian(int i, double sigma)
{
  const double s = 1.0 / (sigma * std::sqrt(2.0));
  const int a = std::abs(i);
  if (a == 0)
  {
    return std::erf(0.5 * s);
  }
  return 0.5 * (std::erfc((a - 0.5) * s) - std::erfc((a + 0.5) * s));
}
}

//------------------------------------------------------------------------------
std::vector<double> vtkBloomKernels::NormalizeHalfKernel(const std::vector<double>& half)
{
  if (half.empty())
  {
    return { 1.0 };
  }
  double sum = half[0];
  for (size_t i = 1; i < half.size(); ++i)
  {
    sum += 2.0 * half[i];
  }
  if (!(sum > 0.0) || !std::isfinite(sum))
  {
    return { 1.0 };
  }
  std::vector<double> result(half.size());
  for (size_t i = 0; i < half.size(); ++i)
  {
    result[i] = half[i] / sum;
  }
  return result;
}

//------------------------------------------------------------------------------
int vtkBloomKernels::RadiusForSigma(double sigma, double factor)
{
  if (!(sigma > 0.0) || !(factor > 0.0))
  {
    return 0;
  }
  const double r = std::ceil(sigma * factor - 1e-9);
  return r > 1e6 ? 1000000 : static_cast<int>(r);
}

//------------------------------------------------------------------------------
std::vector<double> vtkBloomKernels::GaussianHalfKernel(double sigma, int radius, int kind)
{
  if (!(sigma > 0.0) || radius <= 0)
  {
    return { 1.0 };
  }
  std::vector<double> half(static_cast<size_t>(radius) + 1);
  switch (kind)
  {
    case GAUSSIAN_INTEGRATED:
      for (int i = 0; i <= radius; ++i)
      {
        half[i] = IntegratedGaussian(i, sigma);
      }
      break;
    case GAUSSIAN_DISCRETE:
      half = DiscreteGaussian(sigma * sigma, radius);
      break;
    case GAUSSIAN_SAMPLED:
    default:
      for (int i = 0; i <= radius; ++i)
      {
        half[i] = std::exp(-(static_cast<double>(i) * i) / (2.0 * sigma * sigma));
      }
      break;
  }
  return NormalizeHalfKernel(half);
}

//------------------------------------------------------------------------------
double vtkBloomKernels::HalfKernelVariance(const std::vector<double>& half)
{
  double variance = 0.0;
  for (size_t i = 1; i < half.size(); ++i)
  {
    variance += 2.0 * half[i] * static_cast<double>(i * i);
  }
  return variance;
}

//------------------------------------------------------------------------------
std::vector<vtkBloomKernels::Tap> vtkBloomKernels::SymmetricTaps(
  const std::vector<double>& half, double spacing)
{
  std::vector<Tap> taps;
  const int radius = static_cast<int>(half.size()) - 1;
  for (int k = -radius; k <= radius; ++k)
  {
    taps.push_back({ k * spacing, half[std::abs(k)] });
  }
  return taps;
}

//------------------------------------------------------------------------------
std::vector<vtkBloomKernels::Tap> vtkBloomKernels::BilinearTaps()
{
  return { { 0.0, 1.0 } };
}

//------------------------------------------------------------------------------
std::vector<vtkBloomKernels::Tap> vtkBloomKernels::TentTaps()
{
  return { { -1.0, 0.25 }, { 0.0, 0.5 }, { 1.0, 0.25 } };
}

//------------------------------------------------------------------------------
std::vector<vtkBloomKernels::Tap> vtkBloomKernels::HalfTexelPairTaps()
{
  return { { -0.5, 0.5 }, { 0.5, 0.5 } };
}

//------------------------------------------------------------------------------
std::vector<vtkBloomKernels::Tap> vtkBloomKernels::Binomial5Taps()
{
  return { { -2.0, 1.0 / 16 }, { -1.0, 4.0 / 16 }, { 0.0, 6.0 / 16 }, { 1.0, 4.0 / 16 },
    { 2.0, 1.0 / 16 } };
}

//------------------------------------------------------------------------------
std::vector<vtkBloomKernels::Tap> vtkBloomKernels::LeftPairTaps()
{
  return { { -1.0, 0.5 }, { 0.0, 0.5 } };
}

//------------------------------------------------------------------------------
std::vector<vtkBloomKernels::Tap> vtkBloomKernels::RightPairTaps()
{
  return { { 0.0, 0.5 }, { 1.0, 0.5 } };
}

//------------------------------------------------------------------------------
std::vector<double> vtkBloomKernels::Binomial7HalfKernel()
{
  return { 20.0 / 64, 15.0 / 64, 6.0 / 64, 1.0 / 64 };
}

//------------------------------------------------------------------------------
std::vector<double> vtkBloomKernels::WebGPUMarketBlurHalfKernel()
{
  // Seed 000, fs_blur. These already sum to 1 to 1e-10, so they are used as given.
  return { 0.2270270270, 0.1945945946, 0.1216216216, 0.0540540541, 0.0162162162 };
}

//------------------------------------------------------------------------------
std::vector<double> vtkBloomKernels::PingPongBlurHalfKernel()
{
  // Seed 002 sums to 1.0179994; 64 passes would compound that to a gain of about 3.
  return NormalizeHalfKernel({ 0.227027, 0.1945946, 0.1216216, 0.054054, 0.016216, 0.007, 0.002 });
}

//------------------------------------------------------------------------------
vtkBloomKernels::ExtendedBox vtkBloomKernels::ExtendedBoxForVariance(double variance)
{
  ExtendedBox box;
  if (!(variance > 0.0) || !std::isfinite(variance))
  {
    return box;
  }
  // Largest r with r (r + 1) / 3 <= v (the variance of the plain box of radius r).
  int r = static_cast<int>(std::floor(0.5 * (std::sqrt(1.0 + 12.0 * variance) - 1.0)));
  while (r > 0 && r * (r + 1.0) / 3.0 > variance)
  {
    --r;
  }
  while ((r + 1.0) * (r + 2.0) / 3.0 <= variance)
  {
    ++r;
  }
  // Solve v c = r (r + 1) (2r + 1) / 3 + 2 alpha (r + 1)^2 with c = 2r + 1 + 2 alpha for alpha.
  const double plain = r * (r + 1.0) / 3.0;
  const double alpha =
    (2.0 * r + 1.0) * (plain - variance) / (2.0 * (variance - (r + 1.0) * (r + 1.0)));
  box.Radius = r;
  box.Alpha = std::min(std::max(alpha, 0.0), 1.0);
  return box;
}

//------------------------------------------------------------------------------
std::vector<double> vtkBloomKernels::ExtendedBoxHalfKernel(const ExtendedBox& box)
{
  std::vector<double> half(static_cast<size_t>(box.Radius) + 1, 1.0);
  if (box.Alpha > 0.0)
  {
    half.push_back(box.Alpha);
  }
  return NormalizeHalfKernel(half);
}

namespace
{
// van Vliet, Young and Verbeek (1998), third order, L-infinity optimized, for sigma 2:
// d = 1.86543 and 1.41650 +/- 1.00829 i. The causal part has poles p = d^(-1/q).
void RecursivePoles(double q, double& real, std::complex<double>& pair)
{
  const std::complex<double> d2(1.41650, 1.00829);
  real = std::exp(-std::log(1.86543) / q);
  pair = std::exp(-std::log(d2) / q);
}
}

//------------------------------------------------------------------------------
double vtkBloomKernels::RecursiveGaussianVariance(double q)
{
  // A causal first-order section (1 - p) / (1 - p z^-1) has variance p / (1 - p)^2; variances
  // of cascaded sections add, and the anti-causal pass doubles the sum.
  double real;
  std::complex<double> pair;
  RecursivePoles(q, real, pair);
  const double v =
    real / ((1.0 - real) * (1.0 - real)) + 2.0 * std::real(pair / ((1.0 - pair) * (1.0 - pair)));
  return 2.0 * v;
}

//------------------------------------------------------------------------------
vtkBloomKernels::RecursiveGaussian vtkBloomKernels::RecursiveGaussianCoefficients(double sigma)
{
  RecursiveGaussian c;
  if (!(sigma > 0.0) || !std::isfinite(sigma))
  {
    return c;
  }
  c.Sigma = sigma;
  // The variance grows monotonically with q: bisect on log q.
  const double target = sigma * sigma;
  double lo = std::log(1e-4), hi = std::log(1e8);
  for (int iteration = 0; iteration < 200; ++iteration)
  {
    const double mid = 0.5 * (lo + hi);
    if (RecursiveGaussianVariance(std::exp(mid)) < target)
    {
      lo = mid;
    }
    else
    {
      hi = mid;
    }
  }
  c.Q = std::exp(0.5 * (lo + hi));
  double real;
  std::complex<double> pair;
  RecursivePoles(c.Q, real, pair);
  // (1 - p1 z^-1)(1 - p2 z^-1)(1 - p3 z^-1) = 1 + F1 z^-1 + F2 z^-2 + F3 z^-3.
  const double sumPair = 2.0 * pair.real();
  const double productPair = std::norm(pair);
  c.Feedback[0] = -(real + sumPair);
  c.Feedback[1] = real * sumPair + productPair;
  c.Feedback[2] = -real * productPair;
  c.Gain = 1.0 + c.Feedback[0] + c.Feedback[1] + c.Feedback[2];

  // Decay length: the slowest pole falls below 1e-20.
  const double slowest = std::max(real, std::abs(pair));
  const double length = slowest > 0.0 ? std::log(1e-20) / std::log(slowest) : 1.0;
  c.DecayLength = static_cast<int>(std::min(std::ceil(length) + 8.0, 1.0e8));

  // Triggs-Sdika boundary matrix, column k: the response (y[N], y[N+1], y[N+2]) of the
  // extended signal (input 0 beyond the end) to the causal state w[N-1-k] = 1.
  const int n = c.DecayLength;
  std::vector<double> w(static_cast<size_t>(n) + 3), y(static_cast<size_t>(n) + 3);
  for (int k = 0; k < 3; ++k)
  {
    // w[0..2] hold w[N-3], w[N-2], w[N-1]; w[3 + m] is w[N + m].
    std::fill(w.begin(), w.end(), 0.0);
    w[2 - k] = 1.0;
    for (int m = 3; m < n + 3; ++m)
    {
      w[m] = -c.Feedback[0] * w[m - 1] - c.Feedback[1] * w[m - 2] - c.Feedback[2] * w[m - 3];
    }
    std::fill(y.begin(), y.end(), 0.0);
    for (int m = n - 1; m >= 0; --m)
    {
      const double next1 = y[m + 1], next2 = y[m + 2], next3 = y[m + 3];
      y[m] =
        c.Gain * w[m + 3] - c.Feedback[0] * next1 - c.Feedback[1] * next2 - c.Feedback[2] * next3;
    }
    for (int j = 0; j < 3; ++j)
    {
      c.Boundary[j][k] = y[j];
    }
  }
  return c;
}
