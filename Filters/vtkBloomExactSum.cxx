// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkBloomExactSum.h"

#include <algorithm>
#include <cfenv>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <type_traits>

#if defined(__SSE__) || defined(_M_X64)
#include <xmmintrin.h> // _mm_getcsr: flush to zero and denormals are zero
#endif

namespace
{
// Blocks of at most this many values: the high sum takes values below 2^52, so 2048 of them
// stay inside a signed 64-bit integer.
constexpr int MaximumBlock = 2048;
// Values whose exponent is within this many binades of the largest go to the fixed-point sum
// (53 mantissa bits shifted by up to 63 fill 116 bits: three pieces of 32, 32 and 52 bits).
constexpr int WindowBinades = 63;

std::uint64_t Bits(double x)
{
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof(bits));
  return bits;
}

// The largest biased exponent of n values (0x7FF when one is Inf or NaN), and whether one has
// its sign bit set.
VTKBLOOM_TARGET_CLONES
std::uint64_t LargestExponent(const double* values, int n, bool& anyNegative)
{
  std::uint64_t largest = 0, signs = 0;
  for (int i = 0; i < n; ++i)
  {
    std::uint64_t bits;
    std::memcpy(&bits, values + i, sizeof(bits));
    const std::uint64_t biased = (bits >> 52) & 0x7FF;
    largest = biased > largest ? biased : largest;
    signs |= bits;
  }
  anyNegative = (signs >> 63) != 0;
  return largest;
}

// The sum over the values whose exponent max(biased, 1) is at least `base`, as
// sums[0] + 2^32 sums[1] + 2^64 sums[2] units of 2^(base - 1075). Returns whether a non-zero
// value lies below the window (those are left out). Without `Signed`, no value is negative.
template <bool Signed>
VTKBLOOM_ALWAYS_INLINE bool WindowSumOf(
  const double* values, int n, std::int64_t base, std::int64_t sums[3])
{
  std::int64_t a0 = 0, a1 = 0, a2 = 0;
  std::uint64_t below = 0;
  for (int i = 0; i < n; ++i)
  {
    std::uint64_t bits;
    std::memcpy(&bits, values + i, sizeof(bits));
    const std::int64_t biased = static_cast<std::int64_t>((bits >> 52) & 0x7FF);
    std::uint64_t m =
      (bits & ((std::uint64_t(1) << 52) - 1)) | (static_cast<std::uint64_t>(biased != 0) << 52);
    const std::int64_t shift = std::max<std::int64_t>(biased, 1) - base; // < 64
    const std::uint64_t inside = shift >= 0 ? ~std::uint64_t(0) : 0;
    below |= m & ~inside;
    m &= inside;
    const std::uint64_t s = static_cast<std::uint64_t>(shift) & 63;
    const std::uint64_t low = m << s, high = (m >> 1) >> (63 - s); // m 2^s in 128 bits
    if constexpr (Signed)
    {
      const std::int64_t negative = static_cast<std::int64_t>(bits) < 0 ? -1 : 0;
      a0 += (static_cast<std::int64_t>(low & 0xFFFFFFFFu) ^ negative) - negative;
      a1 += (static_cast<std::int64_t>(low >> 32) ^ negative) - negative;
      a2 += (static_cast<std::int64_t>(high) ^ negative) - negative;
    }
    else
    {
      a0 += static_cast<std::int64_t>(low & 0xFFFFFFFFu);
      a1 += static_cast<std::int64_t>(low >> 32);
      a2 += static_cast<std::int64_t>(high);
    }
  }
  sums[0] = a0;
  sums[1] = a1;
  sums[2] = a2;
  return below != 0;
}

// The extraction path (Rump, Ogita and Oishi, "Accurate floating-point summation part I",
// SIAM J. Sci. Comput. 31(1), 2008, ExtractVector): for sigma = 2^s with |x| <= sigma / 2, the
// round-to-nearest q = (sigma + x) - sigma is a multiple of 2^(s - 53) and x - q is exact. Per
// level the q are summed in double, exactly, because a sum of n <= 2^11 multiples of 2^(s - 53)
// each at most 2^(s - 12) (1 + 2^-41) stays a multiple below 2^53 units; the remainders, at
// most 2^(s - 53), go to the next level, whose sigma is 41 binades lower. Four doubles per step in
// vector lanes, where the compiler has them.
#if defined(__GNUC__)
typedef double Doubles __attribute__((vector_size(32)));
typedef std::uint64_t Words __attribute__((vector_size(32)));
constexpr int ExtractWidth = 4;
#else
typedef double Doubles;
typedef std::uint64_t Words;
constexpr int ExtractWidth = 1;
#endif
// Binades from a level's values' bound 2^top to its sigma (n <= 2^11 values, one to spare),
// and from one level's sigma to the next level's bound (2^-53 sigma, and 2^-1 of rounding).
constexpr int SigmaAboveTop = 12;
constexpr int BinadesPerLevel = 41;
// The tops for which every level's sigma is a normal double far from overflow.
constexpr int LowestTop = -880, HighestTop = 1000;

template <int Levels>
struct Extracted
{
  Doubles Sums[Levels] = {};
  Words Rest = {}; ///< non-zero where a last remainder is: the levels missed a bit, or a NaN
};

// Levels of extraction of the values at v (n of them, n a multiple of ExtractWidth), the first
// level's sigma 2^s. Every step: q = (sigma + x) - sigma, sum += q, x -= q.
template <int Levels, typename V, typename W>
VTKBLOOM_ALWAYS_INLINE void ExtractInto(
  const double* v, int n, const double sigma[Levels], V sums[Levels], W& rest)
{
  for (int i = 0; i < n; i += static_cast<int>(sizeof(V) / sizeof(double)))
  {
    V x;
    std::memcpy(&x, v + i, sizeof(V));
    for (int k = 0; k < Levels; ++k)
    {
      const V q = (sigma[k] + x) - sigma[k];
      sums[k] += q;
      x -= q;
    }
    if constexpr (std::is_arithmetic<V>::value)
    {
      rest |= x != 0.0 ? 1u : 0u; // NaN included
    }
    else
    {
      rest |= (W)(x != 0.0); // lane masks; NaN included, -0 (a -0 value's remainder) not
    }
  }
}

template <int Levels>
VTKBLOOM_TARGET_CLONES Extracted<Levels> Extract(const double* values, int n, int top)
{
  double sigma[Levels];
  for (int k = 0; k < Levels; ++k)
  {
    sigma[k] = std::ldexp(1.0, top + SigmaAboveTop - k * BinadesPerLevel);
  }
  Extracted<Levels> e;
  const int body = n - n % ExtractWidth;
  ExtractInto<Levels>(values, body, sigma, e.Sums, e.Rest);
  double tail[Levels] = {};
  std::uint64_t tailRest = 0;
  ExtractInto<Levels>(values + body, n - body, sigma, tail, tailRest);
  for (int k = 0; k < Levels; ++k)
  {
    // The block's own q: the bound holds for any of their sums.
    vtkBloomLane(e.Sums[k], 0) += tail[k];
  }
  vtkBloomLane(e.Rest, 0) |= tailRest;
  return e;
}

// Whether the arithmetic is IEEE's default (round to nearest, subnormals kept, no excess
// precision), which the extraction's exactness needs. Otherwise the integer path sums.
bool ExtractionIsExact()
{
#if defined(__SSE__) || defined(_M_X64)
  // Flush to zero (bit 15) or denormals are zero (bit 6) would drop subnormal remainders.
  if ((_mm_getcsr() & 0x8040u) != 0)
  {
    return false;
  }
#endif
  return FLT_EVAL_METHOD == 0 && std::fegetround() == FE_TONEAREST;
}

VTKBLOOM_TARGET_CLONES
bool WindowSum(
  const double* values, int n, std::int64_t base, bool anyNegative, std::int64_t sums[3])
{
  return anyNegative ? WindowSumOf<true>(values, n, base, sums)
                     : WindowSumOf<false>(values, n, base, sums);
}

}

//------------------------------------------------------------------------------
void vtkBloomExactSum::Add(double x)
{
  const std::uint64_t bits = Bits(x);
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
  this->Grow(1);
}

//------------------------------------------------------------------------------
void vtkBloomExactSum::Grow(std::int64_t units)
{
  this->Pending += units;
  if (this->Pending >= (std::int64_t(1) << 17))
  {
    this->Normalize();
  }
}

//------------------------------------------------------------------------------
void vtkBloomExactSum::AddInteger(std::int64_t v, int bit)
{
  const int k = bit >> 5, r = bit & 31;
  // v = high 2^32 + low with low in [0, 2^32): low 2^r < 2^63 and |high 2^r| < 2^62.
  const std::uint64_t low = (static_cast<std::uint64_t>(v) & 0xFFFFFFFFu) << r;
  this->Chunks[k] += static_cast<std::int64_t>(low & 0xFFFFFFFFu);
  this->Chunks[k + 1] += static_cast<std::int64_t>(low >> 32);
  const std::int64_t high = (v >> 32) * (std::int64_t(1) << r);
  const std::int64_t rest = high & 0xFFFFFFFF;
  this->Chunks[k + 1] += rest;
  this->Chunks[k + 2] += (high - rest) / 4294967296LL; // exact
}

//------------------------------------------------------------------------------
void vtkBloomExactSum::AddBlock(
  const double* values, int n, std::uint64_t largest, bool anyNegative)
{
  if (largest == 0x7FF) // Inf or NaN: the one-by-one path sums them apart
  {
    for (int i = 0; i < n; ++i)
    {
      this->Add(values[i]);
    }
    return;
  }
  const std::int64_t base =
    std::max<std::int64_t>(static_cast<std::int64_t>(largest) - WindowBinades, 1);
  std::int64_t sums[3];
  const bool below = WindowSum(values, n, base, anyNegative, sums);
  const int bit = static_cast<int>(base) - 1; // 2^(base - 1075) = 2^(bit - 1074)
  this->AddInteger(sums[0], bit);
  this->AddInteger(sums[1], bit + 32);
  this->AddInteger(sums[2], bit + 64);
  if (below)
  {
    for (int i = 0; i < n; ++i)
    {
      const std::int64_t biased = static_cast<std::int64_t>((Bits(values[i]) >> 52) & 0x7FF);
      if (std::max<std::int64_t>(biased, 1) < base)
      {
        this->Add(values[i]);
      }
    }
  }
  this->Grow(1); // the three integers: less than 2^35 a chunk
}

//------------------------------------------------------------------------------
bool vtkBloomExactSum::AddExtracted(const double* values, int n, int top)
{
  if (top < LowestTop || top > HighestTop)
  {
    return false;
  }
  auto add = [this](const auto& e)
  {
    for (int q = 0; q < ExtractWidth; ++q)
    {
      if (vtkBloomLane(e.Rest, q) != 0)
      {
        return false;
      }
    }
    for (const Doubles& sum : e.Sums)
    {
      for (int q = 0; q < ExtractWidth; ++q)
      {
        this->Add(vtkBloomLane(sum, q));
      }
    }
    return true;
  };
  // Two levels catch every bit of values from 2^(top - 30) up, four from 2^(top - 112) up.
  return add(Extract<2>(values, n, top)) || add(Extract<4>(values, n, top));
}

//------------------------------------------------------------------------------
void vtkBloomExactSum::AddRow(const double* values, int n)
{
  const bool extract = ExtractionIsExact();
  for (int i = 0; i < n; i += MaximumBlock)
  {
    const int m = std::min(MaximumBlock, n - i);
    bool anyNegative = false;
    const std::uint64_t largest = LargestExponent(values + i, m, anyNegative);
    // Every value is below 2^(max(largest, 1) - 1022).
    const int top = std::max(static_cast<int>(largest), 1) - 1022;
    if (!(extract && largest != 0x7FF && this->AddExtracted(values + i, m, top)))
    {
      this->AddBlock(values + i, m, largest, anyNegative);
    }
  }
}

//------------------------------------------------------------------------------
void vtkBloomExactSum::AddRow(const double* values, int n, double largestMagnitude)
{
  int top = 0; // largestMagnitude < 2^top
  std::frexp(largestMagnitude, &top);
  const bool extract = ExtractionIsExact() && std::isfinite(largestMagnitude);
  for (int i = 0; i < n; i += MaximumBlock)
  {
    const int m = std::min(MaximumBlock, n - i);
    if (!(extract && this->AddExtracted(values + i, m, top)))
    {
      bool anyNegative = false; // the values themselves: a NaN the hint left out included
      const std::uint64_t largest = LargestExponent(values + i, m, anyNegative);
      this->AddBlock(values + i, m, largest, anyNegative);
    }
  }
}

//------------------------------------------------------------------------------
void vtkBloomExactSum::Add(const vtkBloomExactSum& other)
{
  for (int i = 0; i < NumberOfChunks; ++i)
  {
    this->Chunks[i] += other.Chunks[i];
  }
  this->Special += other.Special;
  this->Grow(other.Pending + 1);
}

//------------------------------------------------------------------------------
void vtkBloomExactSum::Normalize()
{
  for (int i = 0; i + 1 < NumberOfChunks; ++i)
  {
    const std::int64_t low = this->Chunks[i] & 0xFFFFFFFF;
    this->Chunks[i + 1] += (this->Chunks[i] - low) / 4294967296LL; // exact
    this->Chunks[i] = low;
  }
  this->Pending = 0;
}

//------------------------------------------------------------------------------
double vtkBloomExactSum::Get() const
{
  if (this->Special != 0.0) // Inf, -Inf or NaN
  {
    return this->Special;
  }
  vtkBloomExactSum n = *this;
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
    // N < 2^53: N 2^-1074 is a double (subnormal or the smallest binade), exactly, and N is
    // its bit pattern; written as bits, not computed, so that a flush to zero cannot drop it.
    const std::uint64_t bits = (chunk(1) << 32) | chunk(0);
    std::memcpy(&result, &bits, sizeof(result));
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
    std::uint64_t mantissa, rest;
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
    const std::uint64_t half = std::uint64_t(1) << (drop - 1);
    if (rest > half || (rest == half && (sticky || (mantissa & 1))))
    {
      ++mantissa; // 2^53 is still exact in a double
    }
    result = std::ldexp(static_cast<double>(mantissa), drop + 32 * (t - 2) - 1074);
  }
  return negative ? -result : result;
}
