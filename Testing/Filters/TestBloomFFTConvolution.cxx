// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// vtkBloomFFTConvolution against independent float64 references: a Gaussian convolved directly
// over an explicitly extended line (clamp, reflect, zero), and the ping-pong preset's 32
// clamped passes of its 13-tap kernel iterated one pass at a time. Also: exact zeros where
// nothing reaches, power-of-two scale invariance (no overflow near FLT_MAX), and threaded
// application equal to line-by-line application.
#include <vtkBloomFFTConvolution.h>
#include <vtkBloomKernels.h>
#include <vtkBloomLinearOperator.h>

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <random>
#include <string>
#include <thread>
#include <vector>

namespace
{
const int Clamp = vtkBloomLinearOperator::BORDER_CLAMP;
const int Reflect = vtkBloomLinearOperator::BORDER_REFLECT;
const int Zero = vtkBloomLinearOperator::BORDER_ZERO;

// Sample i of x extended beyond [0, n) by `border`, written without FoldIndex.
double Extended(const std::vector<double>& x, long i, int border)
{
  const long n = static_cast<long>(x.size());
  if (border == Zero)
  {
    return i < 0 || i >= n ? 0.0 : x[i];
  }
  if (border == Clamp)
  {
    return x[std::min(std::max(i, 0L), n - 1)];
  }
  while (i < 0 || i >= n) // half-sample mirror, applied until inside
  {
    i = i < 0 ? -1 - i : 2 * n - 1 - i;
  }
  return x[i];
}

std::vector<double> Convolve(
  const std::vector<double>& x, const std::vector<double>& half, int border)
{
  const int r = static_cast<int>(half.size()) - 1;
  std::vector<double> y(x.size(), 0.0);
  for (long j = 0; j < static_cast<long>(x.size()); ++j)
  {
    for (int k = -r; k <= r; ++k)
    {
      y[j] += half[std::abs(k)] * Extended(x, j + k, border);
    }
  }
  return y;
}

std::vector<double> GaussianHalf(double sigma)
{
  const int r = static_cast<int>(std::ceil(4.0 * sigma));
  std::vector<double> h(r + 1);
  double sum = 0.0;
  for (int k = 0; k <= r; ++k)
  {
    h[k] = std::exp(-0.5 * k * k / (sigma * sigma));
    sum += k == 0 ? h[k] : 2.0 * h[k];
  }
  for (double& v : h)
  {
    v /= sum;
  }
  return h;
}

vtkBloomLinearOperator Operator(int n, const std::vector<double>& half, int border, int passes)
{
  const auto once =
    vtkBloomLinearOperator::Convolve(n, vtkBloomKernels::SymmetricTaps(half, 1.0), border);
  vtkBloomLinearOperator op = once;
  for (int p = 1; p < passes; ++p)
  {
    op = once.Compose(op);
  }
  return op;
}

std::vector<double> RandomLine(int n, unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> x(n);
  for (double& v : x)
  {
    v = u(rng) < 0.02 ? 100.0 * u(rng) : u(rng); // a few bright samples, as a bright pass leaves
  }
  return x;
}

double RelativeL2(const std::vector<double>& a, const std::vector<double>& b)
{
  double d = 0.0, s = 0.0;
  for (size_t i = 0; i < a.size(); ++i)
  {
    d += (a[i] - b[i]) * (a[i] - b[i]);
    s += b[i] * b[i];
  }
  return std::sqrt(d / s);
}

template <typename T>
std::vector<double> ApplyFFT(const vtkBloomFFTConvolution& fft, const std::vector<double>& x)
{
  std::vector<T> line(x.begin(), x.end());
  vtkBloomFFTConvolution::Workspace ws;
  fft.Apply(line.data(), 1, 0, 1, ws);
  return std::vector<double>(line.begin(), line.end());
}
}

TEST(FiltersFFTConvolution, GaussianMatchesDirectConvolutionForEveryBorder)
{
  for (double sigma : { 8.0, 16.0, 32.0, 64.0 })
  {
    const auto half = GaussianHalf(sigma);
    for (int border : { Clamp, Reflect, Zero })
    {
      for (int n : { 1080, 1920 })
      {
        const std::string what = "sigma " + std::to_string(sigma) + " border " +
          std::to_string(border) + " n " + std::to_string(n);
        const vtkBloomLinearOperator op = Operator(n, half, border, 1);
        const auto x = RandomLine(n, static_cast<unsigned>(n + border));
        const auto reference = Convolve(x, half, border);
        vtkBloomFFTConvolution single, twice;
        ASSERT_TRUE(single.Build(op, border, true)) << what;
        ASSERT_TRUE(twice.Build(op, border, false)) << what;
        // Padding by the border is how a single convolution folds its borders: no correction.
        EXPECT_EQ(single.GetCorrectionRank(0) + single.GetCorrectionRank(1), 0) << what;
        EXPECT_LE(RelativeL2(ApplyFFT<float>(single, x), reference), 1e-6) << what;
        EXPECT_LE(RelativeL2(ApplyFFT<double>(twice, x), reference), 1e-13) << what;
      }
    }
  }
}

TEST(FiltersFFTConvolution, RepeatedClampedPassesMatchIteratedPasses)
{
  const auto half = vtkBloomKernels::PingPongBlurHalfKernel();
  for (int n : { 1080, 1920, 777 })
  {
    const vtkBloomLinearOperator op = Operator(n, half, Clamp, 32);
    const auto x = RandomLine(n, 7u + n);
    std::vector<double> reference = x;
    for (int p = 0; p < 32; ++p)
    {
      reference = Convolve(reference, half, Clamp);
    }
    vtkBloomFFTConvolution single, twice;
    ASSERT_TRUE(single.Build(op, Clamp, true));
    ASSERT_TRUE(twice.Build(op, Clamp, false));
    // The border correction of 32 clamped passes has a low numerical rank at each end.
    for (int side : { 0, 1 })
    {
      EXPECT_GT(twice.GetCorrectionRank(side), 0) << n;
      EXPECT_LE(twice.GetCorrectionRank(side), 24) << n;
    }
    EXPECT_LE(RelativeL2(ApplyFFT<float>(single, x), reference), 1e-6) << n;
    EXPECT_LE(RelativeL2(ApplyFFT<double>(twice, x), reference), 1e-11) << n;
    // The border rows are where the correction works: compare them alone too.
    const std::vector<double> fft = ApplyFFT<double>(twice, x);
    std::vector<double> edgeRef(reference.begin(), reference.begin() + 200);
    std::vector<double> edgeFFT(fft.begin(), fft.begin() + 200);
    EXPECT_LE(RelativeL2(edgeFFT, edgeRef), 1e-11) << n;
  }
}

TEST(FiltersFFTConvolution, ExactZerosWhereNothingReaches)
{
  const int n = 1500;
  const auto half = GaussianHalf(20.0); // radius 80
  const vtkBloomLinearOperator op = Operator(n, half, Reflect, 1);
  vtkBloomFFTConvolution fft;
  ASSERT_TRUE(fft.Build(op, Reflect, true));
  std::vector<double> x(n, 0.0);
  const std::vector<double> zero = ApplyFFT<float>(fft, x);
  for (double v : zero)
  {
    ASSERT_EQ(v, 0.0);
  }
  x[700] = 3.0;
  x[760] = 1e-3;
  const std::vector<double> y = ApplyFFT<float>(fft, x);
  for (int j = 0; j < n; ++j)
  {
    if (j < 700 - 80 || j > 760 + 80)
    {
      ASSERT_EQ(y[j], 0.0) << j;
    }
  }
  EXPECT_NEAR(y[700], 3.0 * half[0] + 1e-3 * half[60], 1e-6);
  // Sparse lines (a bright run, the rest zero) against the direct convolution, at the ends too.
  for (int start : { 0, 37, 700, 1400 })
  {
    std::vector<double> sparse(n, 0.0);
    for (int i = start; i < std::min(n, start + 60); ++i)
    {
      sparse[i] = 5.0 + std::sin(0.3 * i);
    }
    EXPECT_LE(RelativeL2(ApplyFFT<float>(fft, sparse), Convolve(sparse, half, Reflect)), 1e-6)
      << start;
  }
}

TEST(FiltersFFTConvolution, ScalingByPowersOfTwoIsExactAndNeverOverflows)
{
  const int n = 1920;
  const vtkBloomLinearOperator op =
    Operator(n, vtkBloomKernels::PingPongBlurHalfKernel(), Clamp, 32);
  vtkBloomFFTConvolution fft;
  ASSERT_TRUE(fft.Build(op, Clamp, true));
  const auto x = RandomLine(n, 11u);
  const std::vector<double> y = ApplyFFT<float>(fft, x);
  for (int e : { -60, 20, 120 })
  {
    std::vector<double> scaled(x);
    for (double& v : scaled)
    {
      v = std::ldexp(v, e);
    }
    const std::vector<double> ys = ApplyFFT<float>(fft, scaled);
    for (int j = 0; j < n; ++j)
    {
      ASSERT_EQ(ys[j], std::ldexp(y[j], e)) << "2^" << e << " at " << j;
    }
  }
  // A line of FLT_MAX samples: its blur is FLT_MAX everywhere, finite.
  std::vector<double> huge(n, static_cast<double>(FLT_MAX));
  for (double v : ApplyFFT<float>(fft, huge))
  {
    ASSERT_TRUE(std::isfinite(v));
    ASSERT_GE(v, 0.999 * FLT_MAX);
  }
}

TEST(FiltersFFTConvolution, ThreadedAxesEqualSingleLines)
{
  const int size[3] = { 300, 257, 1 };
  const int lanes = 4, active = 3;
  const auto half = GaussianHalf(12.0);
  const vtkBloomLinearOperator op = Operator(size[1], half, Clamp, 1);
  vtkBloomFFTConvolution fft;
  ASSERT_TRUE(fft.Build(op, Clamp, true));
  std::vector<float> image(static_cast<size_t>(size[0]) * size[1] * lanes);
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(0.0f, 2.0f);
  for (size_t i = 0; i < image.size(); ++i)
  {
    image[i] = i % lanes == 3 ? 0.0f : u(rng);
  }
  std::vector<float> lines = image;
  fft.ApplyAxis(image.data(), size, lanes, active, 1);
  vtkBloomFFTConvolution::Workspace ws;
  for (int i = 0; i < size[0]; ++i)
  {
    for (int l = 0; l < active; ++l)
    {
      fft.Apply(lines.data() + i * lanes + l, size[0] * lanes, 0, 1, ws);
    }
  }
  ASSERT_EQ(image, lines);
  for (size_t i = 3; i < image.size(); i += lanes)
  {
    ASSERT_EQ(image[i], 0.0f); // inactive lanes are untouched
  }
}

TEST(FiltersFFTConvolution, OperatorsWithoutAnInvariantInteriorAreRefused)
{
  // A kernel wider than the line: every row folds its border, so no row repeats another.
  const vtkBloomLinearOperator op = Operator(40, GaussianHalf(30.0), Reflect, 1);
  vtkBloomFFTConvolution fft;
  EXPECT_FALSE(fft.Build(op, Reflect, true));
  EXPECT_FALSE(fft.IsReady());
  EXPECT_EQ(fft.Cost(), HUGE_VAL);
}

TEST(FiltersFFTConvolution, PlansFromManyThreadsAtOnce)
{
  // FFTW's planner is global and not thread-safe; every plan is made under one lock, so
  // convolutions built, applied and destroyed on four threads at once give the serial bits.
  const auto half = GaussianHalf(9.0);
  std::vector<vtkBloomLinearOperator> ops;
  std::vector<std::vector<double>> expected;
  for (int n : { 300, 301, 500, 777 })
  {
    ops.push_back(Operator(n, half, Reflect, 1));
    vtkBloomFFTConvolution fft;
    EXPECT_TRUE(fft.Build(ops.back(), Reflect, true));
    expected.push_back(ApplyFFT<float>(fft, RandomLine(n, 3u)));
  }
  std::vector<int> mismatches(4, 0);
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t)
  {
    threads.emplace_back(
      [&, t]()
      {
        for (int round = 0; round < 25; ++round)
        {
          const size_t k = static_cast<size_t>(t + round) % ops.size();
          vtkBloomFFTConvolution fft;
          fft.Build(ops[k], Reflect, true);
          mismatches[t] += ApplyFFT<float>(fft, RandomLine(ops[k].InputSize, 3u)) != expected[k];
        }
      });
  }
  for (auto& thread : threads)
  {
    thread.join();
  }
  for (int t = 0; t < 4; ++t)
  {
    EXPECT_EQ(mismatches[t], 0) << "thread " << t;
  }
}
