#include "vtkBloomStatisticsRows.h"

#include "vtkBloomBrightPass.h"
#include "vtkBloomKernels.h"
#include "vtkImageBloomThreshold.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <type_traits>

#if defined(__GNUC__)
#define VTKBLOOM_ALWAYS_INLINE inline __attribute__((always_inline))
#else
#define VTKBLOOM_ALWAYS_INLINE inline
#endif

namespace
{
#if defined(__GNUC__)
// Four pixels per step in vector lanes (elsewhere the one-pixel loop does every pixel).
typedef double Lanes __attribute__((vector_size(32)));
typedef std::int64_t Masks __attribute__((vector_size(32)));
constexpr int Width = 4;
#endif

// What decides "bright": vtkImageBloomThreshold's parameters.
struct BrightTest
{
  double Threshold, Knee, ClampLuminance;
};

template <typename V>
VTKBLOOM_ALWAYS_INLINE auto& Lane(V& v, int q)
{
  if constexpr (std::is_arithmetic<V>::value)
  {
    (void)q;
    return v;
  }
  else
  {
    return v[q];
  }
}

// L (Rec. 709 for three colours or more, else the value) and the largest colour value b of the
// W pixels at v, as vtkBloomBrightPass computes them in double.
template <int NC, int W, typename V>
VTKBLOOM_ALWAYS_INLINE void LoadPixels(const float* v, V& l, V& b)
{
  V r{}, g{}, u{};
  for (int q = 0; q < W; ++q)
  {
    Lane(r, q) = static_cast<double>(v[q * NC]);
    if constexpr (NC >= 3)
    {
      Lane(g, q) = static_cast<double>(v[q * NC + 1]);
      Lane(u, q) = static_cast<double>(v[q * NC + 2]);
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

// The bright pixels among those the fast test left out: the bright pass itself.
template <int NC, int Mode>
vtkIdType CountOthers(
  const float* row, const double* lum, int n, double ceiling, const BrightTest& test)
{
  constexpr int C = NC >= 3 ? 3 : 1;
  vtkIdType count = 0;
  for (int i = 0; i < n; ++i)
  {
    if (lum[i] >= -std::numeric_limits<double>::max() && lum[i] <= ceiling)
    {
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

// The luminances of a row into `lum`, `peak` raised to their maximum (NaN ignored) and, with
// a test, the number of bright pixels. A colour with a NaN or Inf value has a NaN or infinite
// luminance, so "finite and within the clamp" is one test on L.
template <int NC, int Mode>
VTKBLOOM_ALWAYS_INLINE vtkIdType MeasurePixels(
  const float* row, int n, double* lum, double& peak, const BrightTest* test)
{
  const double most = std::numeric_limits<double>::max();
  const double ceiling = test ? std::min(test->ClampLuminance, most) : most;
  const double t0 = test ? test->Threshold : 0.0, k = test ? test->Threshold * test->Knee : 0.0;
  vtkIdType count = 0;
  bool other = false;
  int i = 0;
#if defined(__GNUC__)
  Lanes top = Lanes{} - std::numeric_limits<double>::infinity();
  Masks counted{}, others{};
  for (; i + Width <= n; i += Width)
  {
    Lanes l, b;
    LoadPixels<NC, Width>(row + static_cast<size_t>(i) * NC, l, b);
    std::memcpy(lum + i, &l, sizeof(l));
    top = l > top ? l : top;
    if (test)
    {
      const Masks regular = (l >= -most) & (l <= ceiling);
      counted -= regular & (Kept<Mode>(l, b, t0, k) > 0.0);
      others |= ~regular;
    }
  }
  for (int q = 0; q < Width; ++q)
  {
    peak = top[q] > peak ? top[q] : peak;
    count += static_cast<vtkIdType>(counted[q]);
    other = other || others[q] != 0;
  }
#endif
  for (; i < n; ++i)
  {
    double l, b;
    LoadPixels<NC, 1>(row + static_cast<size_t>(i) * NC, l, b);
    lum[i] = l;
    peak = l > peak ? l : peak;
    if (test)
    {
      const bool regular = l >= -most && l <= ceiling;
      count += regular && Kept<Mode>(l, b, t0, k) > 0.0 ? 1 : 0;
      other = other || !regular;
    }
  }
  return other ? count + CountOthers<NC, Mode>(row, lum, n, ceiling, *test) : count;
}

template <int NC>
VTKBLOOM_ALWAYS_INLINE vtkIdType MeasurePixels(
  const float* row, int n, double* lum, double& peak, int mode, const BrightTest* test)
{
  using M = vtkImageBloomThreshold;
  switch (test ? mode : M::NONE)
  {
    case M::SMOOTHSTEP_KNEE:
      return MeasurePixels<NC, M::SMOOTHSTEP_KNEE>(row, n, lum, peak, test);
    case M::QUADRATIC_KNEE:
      return MeasurePixels<NC, M::QUADRATIC_KNEE>(row, n, lum, peak, test);
    case M::HARD_LUMINANCE:
      return MeasurePixels<NC, M::HARD_LUMINANCE>(row, n, lum, peak, test);
    case M::PER_CHANNEL:
      return MeasurePixels<NC, M::PER_CHANNEL>(row, n, lum, peak, test);
    case M::EXCESS_KNEE:
      return MeasurePixels<NC, M::EXCESS_KNEE>(row, n, lum, peak, test);
    default:
      return MeasurePixels<NC, M::NONE>(row, n, lum, peak, test);
  }
}

// One row: luminances, peak and (with a test) the bright count; compiled for AVX2 too.
VTKBLOOM_TARGET_CLONES
vtkIdType MeasureRow(
  const float* row, int n, int nc, double* lum, double& peak, int mode, const BrightTest* test)
{
  switch (nc)
  {
    case 1:
      return MeasurePixels<1>(row, n, lum, peak, mode, test);
    case 2:
      return MeasurePixels<2>(row, n, lum, peak, mode, test);
    case 3:
      return MeasurePixels<3>(row, n, lum, peak, mode, test);
    default:
      return MeasurePixels<4>(row, n, lum, peak, mode, test);
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
void vtkBloomStatisticsRows::AddRow(const float* input, const float* output, int n, int nc)
{
  std::vector<double>& l = this->Scratch;
  l.resize(static_cast<size_t>(n));
  const BrightTest test{ this->Threshold, this->Knee, this->ClampLuminance };
  double rowPeak = -std::numeric_limits<double>::infinity();
  this->Bright += MeasureRow(input, n, nc, l.data(), rowPeak, this->Mode, &test);
  vtkBloomExactSum row;
  row.AddRow(l.data(), n);
  this->EnergyIn.Add(row);
  this->PeakIn = std::max(this->PeakIn, rowPeak);
  if (output)
  {
    MeasureRow(output, n, nc, l.data(), this->PeakOut, this->Mode, nullptr);
    this->EnergyOut.AddRow(l.data(), n);
  }
  else
  {
    // The output row is the input row: the same sum, the same peak.
    this->EnergyOut.Add(row);
    this->PeakOut = std::max(this->PeakOut, rowPeak);
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
