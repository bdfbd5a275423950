#include "vtkBloomExactSum.h"

#include <algorithm>
#include <cmath>
#include <cstring>

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
void vtkBloomExactSum::AddRow(const double* values, int n)
{
  for (int i = 0; i < n; i += MaximumBlock)
  {
    const int m = std::min(MaximumBlock, n - i);
    bool anyNegative = false;
    const std::uint64_t largest = LargestExponent(values + i, m, anyNegative);
    this->AddBlock(values + i, m, largest, anyNegative);
  }
}

//------------------------------------------------------------------------------
void vtkBloomExactSum::AddRow(
  const double* values, int n, std::uint64_t largestBits, bool anyNegative)
{
  // The row's largest exponent bounds every block's: a block whose own is lower sums the same
  // values, its window merely reaching higher than it needs.
  const std::uint64_t largest = (largestBits >> 52) & 0x7FF;
  for (int i = 0; i < n; i += MaximumBlock)
  {
    this->AddBlock(values + i, std::min(MaximumBlock, n - i), largest, anyNegative);
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
