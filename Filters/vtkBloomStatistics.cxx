#include "vtkBloomStatistics.h"

#include "vtkBloomBrightPass.h"
#include "vtkBloomKernels.h"
#include "vtkImageBloomThreshold.h"
#include "vtkImageData.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

namespace
{
// Rec. 709 luminance of the pixel at v: RGB for 3-4 components, the value for 1-2.
template <typename T>
double PixelLuminance(const T* v, int nc)
{
  return nc >= 3 ? vtkBloomKernels::LuminanceR * static_cast<double>(v[0]) +
      vtkBloomKernels::LuminanceG * static_cast<double>(v[1]) +
      vtkBloomKernels::LuminanceB * static_cast<double>(v[2])
                 : static_cast<double>(v[0]);
}

// The exact sum of doubles, rounded once to nearest (ties to even): Neal's small
// superaccumulator (R. M. Neal, "Fast exact summation using small and large superaccumulators",
// arXiv:1505.05571, 2015). Every finite double is m 2^(p - 1074) with an integer m < 2^53 and
// 0 <= p < 2046; it is added, with its sign, as three 32-bit pieces into 64-bit chunks that hold
// the bits of weight 2^(32 k - 1074). A chunk absorbs 2^31 additions before it could overflow,
// and Normalize() carries every chunk into the next, so nothing is ever rounded: cancellation
// loses nothing (an image whose values cancel sums to 0, and one changed pixel shows in the sum
// exactly) and the result does not depend on the order of additions. Non-finite values are
// summed apart and make the result non-finite.
class ExactSum
{
public:
  void Add(double x)
  {
    std::uint64_t bits;
    std::memcpy(&bits, &x, sizeof(bits));
    const int biased = static_cast<int>((bits >> 52) & 0x7FF);
    if (biased == 0x7FF)
    {
      this->Special += x;
      return;
    }
    std::uint64_t m = bits & ((std::uint64_t(1) << 52) - 1);
    int p = 0; // subnormals and zero: m 2^-1074
    if (biased != 0)
    {
      m |= std::uint64_t(1) << 52;
      p = biased - 1;
    }
    const int k = p >> 5, r = p & 31;
    // The bits of m 2^r (at most 84): 0-31, 32-63, 64 and above.
    const std::int64_t low = static_cast<std::int64_t>((m << r) & 0xFFFFFFFFu);
    const std::int64_t middle = static_cast<std::int64_t>((m >> (32 - r)) & 0xFFFFFFFFu);
    const std::int64_t high = static_cast<std::int64_t>((m >> 32) >> (32 - r));
    if (bits >> 63)
    {
      this->Chunks[k] -= low;
      this->Chunks[k + 1] -= middle;
      this->Chunks[k + 2] -= high;
    }
    else
    {
      this->Chunks[k] += low;
      this->Chunks[k + 1] += middle;
      this->Chunks[k + 2] += high;
    }
  }

  /// Add another sum; `other` must be normalized (Normalize()).
  void Add(const ExactSum& other)
  {
    for (int i = 0; i < NumberOfChunks; ++i)
    {
      this->Chunks[i] += other.Chunks[i];
    }
    this->Special += other.Special;
    this->Normalize();
  }

  /// Carry every chunk into the next: chunks 0..n-2 in [0, 2^32), the last one signed.
  void Normalize()
  {
    for (int i = 0; i + 1 < NumberOfChunks; ++i)
    {
      const std::int64_t low = this->Chunks[i] & 0xFFFFFFFF;
      this->Chunks[i + 1] += (this->Chunks[i] - low) / 4294967296LL; // exact
      this->Chunks[i] = low;
    }
  }

  double Get() const
  {
    if (this->Special != 0.0) // Inf, -Inf or NaN
    {
      return this->Special;
    }
    ExactSum n = *this;
    n.Normalize();
    const bool negative = n.Chunks[NumberOfChunks - 1] < 0;
    if (negative)
    {
      for (std::int64_t& c : n.Chunks)
      {
        c = -c;
      }
      n.Normalize();
    }
    // N = sum of Chunks[i] 2^(32 i), now non-negative with every chunk in [0, 2^32).
    int t = NumberOfChunks - 1;
    while (t >= 0 && n.Chunks[t] == 0)
    {
      --t;
    }
    if (t < 0)
    {
      return 0.0;
    }
    auto chunk = [&n](int i) { return i >= 0 ? static_cast<std::uint64_t>(n.Chunks[i]) : 0u; };
    double result;
    if (t <= 1 && chunk(1) < (std::uint64_t(1) << 21))
    {
      // N < 2^53: N 2^-1074 is a double (subnormal or small normal), exactly.
      result = std::ldexp(static_cast<double>((chunk(1) << 32) | chunk(0)), -1074);
    }
    else
    {
      // The window of chunks t, t-1, t-2 holds 64 + b bits, b the bit length of chunk t;
      // keep the top 53, round to nearest even with the bits below and every lower chunk.
      const std::uint64_t top = (chunk(t) << 32) | chunk(t - 1), bottom = chunk(t - 2);
      int b = 0;
      while ((chunk(t) >> b) != 0)
      {
        ++b;
      }
      bool sticky = false;
      for (int i = 0; i < t - 2; ++i)
      {
        sticky = sticky || n.Chunks[i] != 0;
      }
      const int drop = b + 11; // 12..43 bits of the window below the 53 kept
      std::uint64_t mantissa, rest, half;
      if (drop >= 32)
      {
        mantissa = top >> (drop - 32);
        rest = ((top & ((std::uint64_t(1) << (drop - 32)) - 1)) << 32) | bottom;
      }
      else
      {
        mantissa = (top << (32 - drop)) | (bottom >> drop);
        rest = bottom & ((std::uint64_t(1) << drop) - 1);
      }
      half = std::uint64_t(1) << (drop - 1);
      if (rest > half || (rest == half && (sticky || (mantissa & 1))))
      {
        ++mantissa; // 2^53 is still exact in a double
      }
      result = std::ldexp(static_cast<double>(mantissa), drop + 32 * (t - 2) - 1074);
    }
    return negative ? -result : result;
  }

private:
  // Chunk k holds bits of weight 2^(32 k - 1074); the largest double reaches chunk 65, and the
  // rest is room for carries.
  static constexpr int NumberOfChunks = 68;
  std::int64_t Chunks[NumberOfChunks] = {};
  double Special = 0.0;
};

// Add a row's luminances to `energy` (normalized after each row, so that a chunk never takes
// more than one row of additions) and raise `peak` to their maximum. Even and odd pixels go to
// two sums, added at the end of the row, so that consecutive additions, which often touch the
// same chunks, do not wait on each other; the sum is exact either way.
template <typename T>
void MeasureRow(const T* row, int n, int nc, ExactSum& energy, double& peak)
{
  ExactSum odd;
  double peakOdd = peak;
  int i = 0;
  for (; i + 1 < n; i += 2)
  {
    const double a = PixelLuminance(row + static_cast<size_t>(i) * nc, nc);
    const double b = PixelLuminance(row + static_cast<size_t>(i + 1) * nc, nc);
    energy.Add(a);
    odd.Add(b);
    peak = a > peak ? a : peak; // NaN is ignored
    peakOdd = b > peakOdd ? b : peakOdd;
  }
  if (i < n)
  {
    const double a = PixelLuminance(row + static_cast<size_t>(i) * nc, nc);
    energy.Add(a);
    peak = a > peak ? a : peak;
  }
  peak = peakOdd > peak ? peakOdd : peak;
  odd.Normalize();
  energy.Add(odd); // normalizes
}

template <int Colours, int Mode, typename T>
vtkIdType CountRow(
  const T* row, int n, int nc, double threshold, double knee, double clampLuminance)
{
  vtkIdType count = 0;
  for (int i = 0; i < n; ++i)
  {
    double colour[Colours];
    for (int c = 0; c < Colours; ++c)
    {
      colour[c] = static_cast<double>(row[static_cast<size_t>(i) * nc + c]);
    }
    // Most pixels of an image are below the threshold's zero edge, which is decided without
    // the formula (vtkBloomBrightPassIsZero answers true only where the formula gives zero;
    // with the mode a constant, it is a few comparisons).
    if (vtkBloomBrightPassIsZero<Colours>(colour, Mode, threshold, knee, clampLuminance))
    {
      continue;
    }
    vtkBloomBrightPass<Colours>(colour, Mode, threshold, knee, clampLuminance);
    bool bright = false;
    for (int c = 0; c < Colours; ++c)
    {
      bright = bright || colour[c] > 0.0;
    }
    count += bright ? 1 : 0;
  }
  return count;
}

template <int Colours, typename T>
vtkIdType CountRow(
  const T* row, int n, int nc, int mode, double threshold, double knee, double clampLuminance)
{
  return vtkBloomWithThresholdMode(mode,
    [&](auto m)
    { return CountRow<Colours, decltype(m)::value>(row, n, nc, threshold, knee, clampLuminance); });
}

template <typename T>
vtkIdType CountRow(
  const T* row, int n, int nc, int mode, double threshold, double knee, double clampLuminance)
{
  return nc >= 3 ? CountRow<3>(row, n, nc, mode, threshold, knee, clampLuminance)
                 : CountRow<1>(row, n, nc, mode, threshold, knee, clampLuminance);
}

// Call f(row index, pointer to the first pixel of row (j, k)) for every row of the extent, in
// parallel; f must only write to its own row's slot.
template <typename F>
void ForEachRow(vtkImageData* image, const int extent[6], F&& f)
{
  const int rowsPerSlice = extent[3] - extent[2] + 1;
  const vtkIdType rows = static_cast<vtkIdType>(rowsPerSlice) * (extent[5] - extent[4] + 1);
  vtkSMPTools::For(0, rows,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType r = begin; r < end; ++r)
      {
        const int j = extent[2] + static_cast<int>(r % rowsPerSlice);
        const int k = extent[4] + static_cast<int>(r / rowsPerSlice);
        f(r, image->GetScalarPointer(extent[0], j, k));
      }
    });
}

vtkIdType NumberOfRows(const int extent[6])
{
  if (extent[1] < extent[0] || extent[3] < extent[2] || extent[5] < extent[4])
  {
    return 0;
  }
  return static_cast<vtkIdType>(extent[3] - extent[2] + 1) * (extent[5] - extent[4] + 1);
}
}

//------------------------------------------------------------------------------
vtkBloomLuminanceStatistics vtkBloomMeasureLuminance(vtkImageData* image, const int extent[6])
{
  vtkBloomLuminanceStatistics result;
  const vtkIdType rows = NumberOfRows(extent);
  if (rows == 0)
  {
    return result;
  }
  const int n = extent[1] - extent[0] + 1;
  const int nc = image->GetNumberOfScalarComponents();
  const bool isFloat = image->GetScalarType() == VTK_FLOAT;
  // One exact sum per thread: exact sums do not depend on how the rows are shared out.
  vtkSMPThreadLocal<ExactSum> energies;
  vtkSMPThreadLocal<double> peaks(-std::numeric_limits<double>::infinity());
  ForEachRow(image, extent,
    [&](vtkIdType, void* row)
    {
      if (isFloat)
      {
        MeasureRow(static_cast<const float*>(row), n, nc, energies.Local(), peaks.Local());
      }
      else
      {
        MeasureRow(static_cast<const double*>(row), n, nc, energies.Local(), peaks.Local());
      }
    });
  ExactSum total;
  for (const ExactSum& energy : energies)
  {
    total.Add(energy);
  }
  result.Energy = total.Get();
  result.Peak = -std::numeric_limits<double>::infinity();
  for (double peak : peaks)
  {
    result.Peak = std::max(result.Peak, peak);
  }
  return result;
}

//------------------------------------------------------------------------------
vtkIdType vtkBloomCountBrightPixels(vtkImageData* image, const int extent[6], int mode,
  double threshold, double knee, double clampLuminance)
{
  const vtkIdType rows = NumberOfRows(extent);
  if (rows == 0)
  {
    return 0;
  }
  const int n = extent[1] - extent[0] + 1;
  const int nc = image->GetNumberOfScalarComponents();
  const bool isFloat = image->GetScalarType() == VTK_FLOAT;
  std::vector<vtkIdType> counts(rows, 0);
  ForEachRow(image, extent,
    [&](vtkIdType r, void* row)
    {
      counts[r] = isFloat
        ? CountRow(static_cast<const float*>(row), n, nc, mode, threshold, knee, clampLuminance)
        : CountRow(static_cast<const double*>(row), n, nc, mode, threshold, knee, clampLuminance);
    });
  vtkIdType total = 0;
  for (vtkIdType c : counts)
  {
    total += c;
  }
  return total;
}
