// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkBloomStatisticsRows.h"

#include "vtkBloomBrightPass.h"
#include "vtkBloomKernels.h"
#include "vtkImageBloomThreshold.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <type_traits>

namespace
{
#if defined(__GNUC__)
// Four pixels per step in vector lanes (elsewhere the one-pixel loop does every pixel).
typedef double Lanes __attribute__((vector_size(32)));
typedef std::int64_t Masks __attribute__((vector_size(32)));
typedef float Floats8 __attribute__((vector_size(32), aligned(4), may_alias));
typedef double Pairs __attribute__((vector_size(32))); // four pairs of floats, as 64-bit lanes
typedef double Doubles8 __attribute__((vector_size(64)));
constexpr int Width = 4;
#endif

// What decides "bright": vtkImageBloomThreshold's parameters.
struct BrightTest
{
  double Threshold, Knee, ClampLuminance;
};

// L (Rec. 709 for three colours or more, else the value) and the largest colour value b of the
// W pixels at v, as vtkBloomBrightPass computes them in double.
template <int NC, int W, typename V>
VTKBLOOM_ALWAYS_INLINE void LoadPixels(const float* v, V& l, V& b)
{
  V r{}, g{}, u{};
  for (int q = 0; q < W; ++q)
  {
    vtkBloomLane(r, q) = static_cast<double>(v[q * NC]);
    if constexpr (NC >= 3)
    {
      vtkBloomLane(g, q) = static_cast<double>(v[q * NC + 1]);
      vtkBloomLane(u, q) = static_cast<double>(v[q * NC + 2]);
    }
  }
  if constexpr (NC >= 3)
  {
    l = vtkBloomKernels::Luminance(r, g, u);
    b = vtkBloomMax(vtkBloomMax(r, g), u);
  }
  else
  {
    l = r;
    b = r;
  }
}

#if defined(__GNUC__)
// The same for four RGBA pixels, by two loads, two permutes within each pair of pixels, two
// interleaves of 64-bit pairs and one conversion per channel (GCC turns a conversion of four
// floats into two halves, of eight into whole AVX2 conversions).
template <>
VTKBLOOM_ALWAYS_INLINE void LoadPixels<4, Width, Lanes>(const float* v, Lanes& l, Lanes& b)
{
  const Floats8 p01 = *reinterpret_cast<const Floats8*>(v);
  const Floats8 p23 = *reinterpret_cast<const Floats8*>(v + 8);
  // r0 r1 g0 g1 b0 b1 a0 a1, and the same for pixels 2 and 3.
  const Pairs q01 = (Pairs)__builtin_shufflevector(p01, p01, 0, 4, 1, 5, 2, 6, 3, 7);
  const Pairs q23 = (Pairs)__builtin_shufflevector(p23, p23, 0, 4, 1, 5, 2, 6, 3, 7);
  // r0 r1 r2 r3 b0 b1 b2 b3, and the greens with the alphas.
  const Doubles8 rb =
    __builtin_convertvector((Floats8)__builtin_shufflevector(q01, q23, 0, 4, 2, 6), Doubles8);
  const Doubles8 ga =
    __builtin_convertvector((Floats8)__builtin_shufflevector(q01, q23, 1, 5, 3, 7), Doubles8);
  const Lanes r = __builtin_shufflevector(rb, rb, 0, 1, 2, 3);
  const Lanes u = __builtin_shufflevector(rb, rb, 4, 5, 6, 7);
  const Lanes g = __builtin_shufflevector(ga, ga, 0, 1, 2, 3);
  l = vtkBloomKernels::Luminance(r, g, u);
  b = vtkBloomMax(vtkBloomMax(r, g), u);
}
#endif

// What the bright pass keeps of the largest value b: > 0 exactly when it keeps a value > 0
// (for colours that are finite and within the clamp).
template <int Mode, typename V>
VTKBLOOM_ALWAYS_INLINE V Kept(V l, V b, double t0, double k)
{
  using M = vtkImageBloomThreshold;
  if constexpr (Mode == M::PER_CHANNEL)
  {
    return b - t0;
  }
  else if constexpr (Mode == M::NONE)
  {
    return b;
  }
  else
  {
    return b * vtkBloomBrightPassFactor<V, double>(l, b, Mode, t0, k);
  }
}

// What one pass over a row's luminances found (NaN ignored by the extremes).
struct RowExtremes
{
  double Peak = -std::numeric_limits<double>::infinity();      ///< the largest L
  double Lowest = std::numeric_limits<double>::infinity();     ///< the smallest L
  double Brightest = -std::numeric_limits<double>::infinity(); ///< the largest colour value
  bool Finite = true; ///< every L finite (a NaN or Inf colour value makes L non-finite)

  double LargestMagnitude() const { return std::max(this->Peak, -this->Lowest); }
};

// The luminances of n pixels into `lum` and, with Bright, their largest colour values into
// `bright`, and the extremes of both. Per vector: the pixels' load, L and b, and their extremes;
// whether every L is finite rides on a plain sum of them, which only a NaN, an Inf or an
// overflow (then conservatively) makes non-finite.
template <int NC, bool Bright>
VTKBLOOM_ALWAYS_INLINE RowExtremes Luminances(const float* row, int n, double* lum, double* bright)
{
  RowExtremes e;
  double check = 0.0;
  int i = 0;
#if defined(__GNUC__)
  Lanes top = Lanes{} + e.Peak, low = Lanes{} + e.Lowest, most = Lanes{} + e.Brightest;
  Lanes sum{};
  for (; i + Width <= n; i += Width)
  {
    Lanes l, b;
    LoadPixels<NC, Width>(row + static_cast<size_t>(i) * NC, l, b);
    std::memcpy(lum + i, &l, sizeof(l));
    top = l > top ? l : top;
    low = l < low ? l : low;
    sum += l;
    if constexpr (Bright)
    {
      std::memcpy(bright + i, &b, sizeof(b));
      most = b > most ? b : most;
    }
  }
  for (int q = 0; q < Width; ++q)
  {
    e.Peak = top[q] > e.Peak ? top[q] : e.Peak;
    e.Lowest = low[q] < e.Lowest ? low[q] : e.Lowest;
    e.Brightest = most[q] > e.Brightest ? most[q] : e.Brightest;
    check += sum[q];
  }
#endif
  for (; i < n; ++i)
  {
    double l, b;
    LoadPixels<NC, 1>(row + static_cast<size_t>(i) * NC, l, b);
    lum[i] = l;
    e.Peak = l > e.Peak ? l : e.Peak;
    e.Lowest = l < e.Lowest ? l : e.Lowest;
    check += l;
    if constexpr (Bright)
    {
      bright[i] = b;
      e.Brightest = b > e.Brightest ? b : e.Brightest;
    }
  }
  e.Finite = check - check == 0.0;
  return e;
}

// The pixels the bright pass keeps, from their L and b, for a row whose every L is finite and
// within the clamp: the formula only on groups of vectors that the bright pass's own zero test
// cannot rule out lane by lane (most pixels of a frame are below the threshold's edge).
template <int Mode>
VTKBLOOM_ALWAYS_INLINE vtkIdType CountKept(
  const double* lum, const double* bright, int n, const BrightTest& test)
{
  const double t0 = test.Threshold, k = test.Threshold * test.Knee;
  vtkIdType count = 0;
  int i = 0;
#if defined(__GNUC__)
  constexpr int Group = 4;
  Masks counted{};
  for (; i + Group * Width <= n; i += Group * Width)
  {
    Masks open[Group], any{};
    for (int v = 0; v < Group; ++v)
    {
      Lanes l, b;
      std::memcpy(&l, lum + i + v * Width, sizeof(l));
      std::memcpy(&b, bright + i + v * Width, sizeof(b));
      open[v] =
        ~vtkBloomBrightPassIsZeroBelow(l, b, Mode, test.Threshold, test.Knee, test.ClampLuminance);
      any |= open[v];
    }
    if (((any[0] | any[1]) | (any[2] | any[3])) == 0)
    {
      continue;
    }
    for (int v = 0; v < Group; ++v)
    {
      Lanes l, b;
      std::memcpy(&l, lum + i + v * Width, sizeof(l));
      std::memcpy(&b, bright + i + v * Width, sizeof(b));
      counted -= open[v] & (Kept<Mode>(l, b, t0, k) > 0.0);
    }
  }
  for (int q = 0; q < Width; ++q)
  {
    count += static_cast<vtkIdType>(counted[q]);
  }
#endif
  for (; i < n; ++i)
  {
    count += Kept<Mode>(lum[i], bright[i], t0, k) > 0.0 ? 1 : 0;
  }
  return count;
}

// The same for a row that holds a non-finite colour value or a firefly: the bright pass itself
// on those pixels (it maps them first), the formula on the others.
template <int NC, int Mode>
vtkIdType CountKeptEach(
  const float* row, const double* lum, const double* bright, int n, const BrightTest& test)
{
  constexpr int C = NC >= 3 ? 3 : 1;
  const double ceiling = std::min(test.ClampLuminance, std::numeric_limits<double>::max());
  const double t0 = test.Threshold, k = test.Threshold * test.Knee;
  vtkIdType count = 0;
  for (int i = 0; i < n; ++i)
  {
    if (lum[i] >= -std::numeric_limits<double>::max() && lum[i] <= ceiling)
    {
      count += Kept<Mode>(lum[i], bright[i], t0, k) > 0.0 ? 1 : 0;
      continue;
    }
    double colour[C];
    for (int c = 0; c < C; ++c)
    {
      colour[c] = static_cast<double>(row[static_cast<size_t>(i) * NC + c]);
    }
    count +=
      vtkBloomBrightPassKeepsAny<C>(colour, Mode, test.Threshold, test.Knee, test.ClampLuminance)
      ? 1
      : 0;
  }
  return count;
}

// One row: the luminances into `lum` and their extremes and, with a test, the number of bright
// pixels (`bright` holds the largest colour values meanwhile).
template <int NC, int Mode>
VTKBLOOM_ALWAYS_INLINE vtkIdType MeasurePixels(const float* row, int n, double* lum, double* bright,
  RowExtremes& extremes, const BrightTest* test)
{
  extremes =
    test ? Luminances<NC, true>(row, n, lum, bright) : Luminances<NC, false>(row, n, lum, bright);
  if (!test ||
    (extremes.Finite &&
      vtkBloomBrightPassIsZeroBelow(extremes.Peak, extremes.Brightest, Mode, test->Threshold,
        test->Knee, test->ClampLuminance)))
  {
    return 0;
  }
  const bool regular = extremes.Finite && extremes.Peak <= test->ClampLuminance;
  return regular ? CountKept<Mode>(lum, bright, n, *test)
                 : CountKeptEach<NC, Mode>(row, lum, bright, n, *test);
}

// The mode as a template argument. Not through vtkBloomWithThresholdMode: its lambda's body
// would be compiled for the default target only, outside MeasureRow's AVX2 clone.
template <int NC>
VTKBLOOM_ALWAYS_INLINE vtkIdType MeasurePixels(const float* row, int n, double* lum, double* bright,
  RowExtremes& extremes, int mode, const BrightTest* test)
{
  using M = vtkImageBloomThreshold;
  switch (test ? mode : M::NONE)
  {
    case M::SMOOTHSTEP_KNEE:
      return MeasurePixels<NC, M::SMOOTHSTEP_KNEE>(row, n, lum, bright, extremes, test);
    case M::QUADRATIC_KNEE:
      return MeasurePixels<NC, M::QUADRATIC_KNEE>(row, n, lum, bright, extremes, test);
    case M::HARD_LUMINANCE:
      return MeasurePixels<NC, M::HARD_LUMINANCE>(row, n, lum, bright, extremes, test);
    case M::PER_CHANNEL:
      return MeasurePixels<NC, M::PER_CHANNEL>(row, n, lum, bright, extremes, test);
    case M::EXCESS_KNEE:
      return MeasurePixels<NC, M::EXCESS_KNEE>(row, n, lum, bright, extremes, test);
    default:
      return MeasurePixels<NC, M::NONE>(row, n, lum, bright, extremes, test);
  }
}

// One row for every component count and mode; compiled for AVX2 too.
VTKBLOOM_TARGET_CLONES
vtkIdType MeasureRow(const float* row, int n, int nc, double* lum, double* bright,
  RowExtremes& extremes, int mode, const BrightTest* test)
{
  switch (nc)
  {
    case 1:
      return MeasurePixels<1>(row, n, lum, bright, extremes, mode, test);
    case 2:
      return MeasurePixels<2>(row, n, lum, bright, extremes, mode, test);
    case 3:
      return MeasurePixels<3>(row, n, lum, bright, extremes, mode, test);
    default:
      return MeasurePixels<4>(row, n, lum, bright, extremes, mode, test);
  }
}
}

//------------------------------------------------------------------------------
vtkBloomStatisticsRows::vtkBloomStatisticsRows(
  int mode, double threshold, double knee, double clampLuminance)
  : Mode(mode)
  , Threshold(threshold)
  , Knee(knee)
  , ClampLuminance(clampLuminance)
{
}

//------------------------------------------------------------------------------
void vtkBloomStatisticsRows::AddRow(
  const float* input, const float* output, int n, int nc, int begin, int end)
{
  begin = std::min(std::max(begin, 0), n);
  end = output ? std::min(std::max(end, begin), n) : begin;
  this->Luminance.resize(static_cast<size_t>(n));
  this->Brightness.resize(static_cast<size_t>(n));
  double* lum = this->Luminance.data();
  const BrightTest test{ this->Threshold, this->Knee, this->ClampLuminance };
  // The input in three spans: before, within and after the output's own [begin, end). The
  // pixels outside are summed apart, once, for the input and the output.
  vtkBloomExactSum outside;
  bool anyOutside = false;
  double outsidePeak = -std::numeric_limits<double>::infinity();
  const int spans[4] = { 0, begin, end, n };
  for (int k = 0; k < 3; ++k)
  {
    const int b = spans[k], e = spans[k + 1];
    if (b >= e)
    {
      continue;
    }
    RowExtremes x;
    this->Bright += MeasureRow(input + static_cast<size_t>(b) * nc, e - b, nc, lum + b,
      this->Brightness.data() + b, x, this->Mode, &test);
    double& peak = k == 1 ? this->PeakIn : outsidePeak;
    peak = std::max(peak, x.Peak);
    (k == 1 ? this->EnergyIn : outside).AddRow(lum + b, e - b, x.LargestMagnitude());
    anyOutside = anyOutside || k != 1;
  }
  if (anyOutside)
  {
    this->EnergyIn.Add(outside);
    this->EnergyOut.Add(outside);
  }
  this->PeakIn = std::max(this->PeakIn, outsidePeak);
  // The output: the input's own values outside the span (added above), its own within.
  this->PeakOut = std::max(this->PeakOut, outsidePeak);
  if (begin < end)
  {
    RowExtremes x;
    MeasureRow(output + static_cast<size_t>(begin) * nc, end - begin, nc, lum + begin, nullptr, x,
      this->Mode, nullptr);
    this->PeakOut = std::max(this->PeakOut, x.Peak);
    this->EnergyOut.AddRow(lum + begin, end - begin, x.LargestMagnitude());
  }
}

//------------------------------------------------------------------------------
void vtkBloomStatisticsRows::Merge(const vtkBloomStatisticsRows& other)
{
  this->EnergyIn.Add(other.EnergyIn);
  this->EnergyOut.Add(other.EnergyOut);
  this->PeakIn = std::max(this->PeakIn, other.PeakIn);
  this->PeakOut = std::max(this->PeakOut, other.PeakOut);
  this->Bright += other.Bright;
}

//------------------------------------------------------------------------------
vtkBloomLuminanceStatistics vtkBloomStatisticsRows::In() const
{
  return { this->EnergyIn.Get(), this->PeakIn };
}

//------------------------------------------------------------------------------
vtkBloomLuminanceStatistics vtkBloomStatisticsRows::Out() const
{
  return { this->EnergyOut.Get(), this->PeakOut };
}
