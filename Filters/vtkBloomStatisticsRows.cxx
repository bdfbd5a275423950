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
typedef std::uint64_t Bits __attribute__((vector_size(32)));
typedef float Floats __attribute__((vector_size(16), aligned(4), may_alias));
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

#if defined(__GNUC__)
// The same for four RGBA pixels, through four vector loads and a transpose.
template <>
VTKBLOOM_ALWAYS_INLINE void LoadPixels<4, Width, Lanes>(const float* v, Lanes& l, Lanes& b)
{
  const Floats p0 = *reinterpret_cast<const Floats*>(v);
  const Floats p1 = *reinterpret_cast<const Floats*>(v + 4);
  const Floats p2 = *reinterpret_cast<const Floats*>(v + 8);
  const Floats p3 = *reinterpret_cast<const Floats*>(v + 12);
  const Floats rg01 = __builtin_shufflevector(p0, p1, 0, 4, 1, 5);
  const Floats rg23 = __builtin_shufflevector(p2, p3, 0, 4, 1, 5);
  const Floats b01 = __builtin_shufflevector(p0, p1, 2, 6, 3, 7);
  const Floats b23 = __builtin_shufflevector(p2, p3, 2, 6, 3, 7);
  const Lanes r = __builtin_convertvector(__builtin_shufflevector(rg01, rg23, 0, 1, 4, 5), Lanes);
  const Lanes g = __builtin_convertvector(__builtin_shufflevector(rg01, rg23, 2, 3, 6, 7), Lanes);
  const Lanes u = __builtin_convertvector(__builtin_shufflevector(b01, b23, 0, 1, 4, 5), Lanes);
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

// What vtkBloomExactSum::AddRow's hint needs of a row's luminances.
struct RowBits
{
  std::uint64_t Largest = 0; ///< the largest bit pattern with the sign cleared
  std::uint64_t Signs = 0;   ///< the sign bits or'ed
};

// The luminances of a row into `lum`, `peak` raised to their maximum (NaN ignored), `bits`
// raised to theirs and, with a test, the number of bright pixels. A colour with a NaN or Inf
// value has a NaN or infinite luminance, so "finite and within the clamp" is one test on L.
template <int NC, int Mode>
VTKBLOOM_ALWAYS_INLINE vtkIdType MeasurePixels(
  const float* row, int n, double* lum, double& peak, RowBits& bits, const BrightTest* test)
{
  const double most = std::numeric_limits<double>::max();
  const double ceiling = test ? std::min(test->ClampLuminance, most) : most;
  const double t0 = test ? test->Threshold : 0.0, k = test ? test->Threshold * test->Knee : 0.0;
  const std::uint64_t magnitude = ~(std::uint64_t(1) << 63);
  vtkIdType count = 0;
  bool other = false;
  int i = 0;
#if defined(__GNUC__)
  Lanes top = Lanes{} - std::numeric_limits<double>::infinity();
  Masks counted{}, others{}, largest{};
  Bits signs{};
  for (; i + Width <= n; i += Width)
  {
    Lanes l, b;
    LoadPixels<NC, Width>(row + static_cast<size_t>(i) * NC, l, b);
    std::memcpy(lum + i, &l, sizeof(l));
    top = l > top ? l : top;
    Bits lb;
    std::memcpy(&lb, &l, sizeof(lb));
    signs |= lb;
    const Masks m = reinterpret_cast<Masks>(lb & magnitude);
    largest = m > largest ? m : largest;
    if (test)
    {
      const Masks regular = (l >= -most) & (l <= ceiling);
      others |= ~regular;
      // The formula only where the bright pass's own zero test cannot rule out all four
      // pixels (by their largest L and colour value; NaN lanes are others, counted apart).
      double lmax = l[0], bmax = b[0];
      for (int q = 1; q < Width; ++q)
      {
        lmax = l[q] > lmax ? l[q] : lmax;
        bmax = b[q] > bmax ? b[q] : bmax;
      }
      if (!vtkBloomBrightPassIsZeroBelow(
            lmax, bmax, Mode, test->Threshold, test->Knee, test->ClampLuminance))
      {
        counted -= regular & (Kept<Mode>(l, b, t0, k) > 0.0);
      }
    }
  }
  for (int q = 0; q < Width; ++q)
  {
    peak = top[q] > peak ? top[q] : peak;
    count += static_cast<vtkIdType>(counted[q]);
    other = other || others[q] != 0;
    bits.Largest = std::max(bits.Largest, static_cast<std::uint64_t>(largest[q]));
    bits.Signs |= signs[q];
  }
#endif
  for (; i < n; ++i)
  {
    double l, b;
    LoadPixels<NC, 1>(row + static_cast<size_t>(i) * NC, l, b);
    lum[i] = l;
    peak = l > peak ? l : peak;
    std::uint64_t lb;
    std::memcpy(&lb, &l, sizeof(lb));
    bits.Signs |= lb;
    bits.Largest = std::max(bits.Largest, lb & magnitude);
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
VTKBLOOM_ALWAYS_INLINE vtkIdType MeasurePixels(const float* row, int n, double* lum, double& peak,
  RowBits& bits, int mode, const BrightTest* test)
{
  using M = vtkImageBloomThreshold;
  switch (test ? mode : M::NONE)
  {
    case M::SMOOTHSTEP_KNEE:
      return MeasurePixels<NC, M::SMOOTHSTEP_KNEE>(row, n, lum, peak, bits, test);
    case M::QUADRATIC_KNEE:
      return MeasurePixels<NC, M::QUADRATIC_KNEE>(row, n, lum, peak, bits, test);
    case M::HARD_LUMINANCE:
      return MeasurePixels<NC, M::HARD_LUMINANCE>(row, n, lum, peak, bits, test);
    case M::PER_CHANNEL:
      return MeasurePixels<NC, M::PER_CHANNEL>(row, n, lum, peak, bits, test);
    case M::EXCESS_KNEE:
      return MeasurePixels<NC, M::EXCESS_KNEE>(row, n, lum, peak, bits, test);
    default:
      return MeasurePixels<NC, M::NONE>(row, n, lum, peak, bits, test);
  }
}

// One row: luminances, peak and (with a test) the bright count; compiled for AVX2 too.
VTKBLOOM_TARGET_CLONES
vtkIdType MeasureRow(const float* row, int n, int nc, double* lum, double& peak, RowBits& bits,
  int mode, const BrightTest* test)
{
  switch (nc)
  {
    case 1:
      return MeasurePixels<1>(row, n, lum, peak, bits, mode, test);
    case 2:
      return MeasurePixels<2>(row, n, lum, peak, bits, mode, test);
    case 3:
      return MeasurePixels<3>(row, n, lum, peak, bits, mode, test);
    default:
      return MeasurePixels<4>(row, n, lum, peak, bits, mode, test);
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
  std::vector<double>& l = this->Scratch;
  l.resize(static_cast<size_t>(n));
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
    RowBits bits;
    double* lum = l.data() + b;
    const size_t at = static_cast<size_t>(b) * nc;
    this->Bright += MeasureRow(
      input + at, e - b, nc, lum, k == 1 ? this->PeakIn : outsidePeak, bits, this->Mode, &test);
    (k == 1 ? this->EnergyIn : outside).AddRow(lum, e - b, bits.Largest, (bits.Signs >> 63) != 0);
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
    RowBits bits;
    const size_t at = static_cast<size_t>(begin) * nc;
    MeasureRow(
      output + at, end - begin, nc, l.data() + begin, this->PeakOut, bits, this->Mode, nullptr);
    this->EnergyOut.AddRow(l.data() + begin, end - begin, bits.Largest, (bits.Signs >> 63) != 0);
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
