// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// vtkBloomExactSum, the exact summation behind vtkImageBloom's energies: the fast row path
// (fixed point in a window below each block's largest exponent) against the one-by-one
// superaccumulator, and both against sums whose exact value is known.

#include "vtkBloomExactSum.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cfenv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#if defined(__SSE__) || defined(_M_X64)
#include <xmmintrin.h> // _mm_getcsr, _mm_setcsr
#endif

namespace
{
double OneByOne(const std::vector<double>& v)
{
  vtkBloomExactSum s;
  for (double x : v)
  {
    s.Add(x);
  }
  return s.Get();
}

double ByRow(const std::vector<double>& v)
{
  vtkBloomExactSum s;
  s.AddRow(v.data(), static_cast<int>(v.size()));
  return s.Get();
}

// Bit-for-bit equality (NaN equals NaN, -0 differs from +0).
bool Same(double a, double b)
{
  return std::memcmp(&a, &b, sizeof(a)) == 0 || (std::isnan(a) && std::isnan(b));
}

// Values of one kind: uniform [0, 1); signed over 200 binades; signed over the whole finite
// range, subnormals included; random finite bit patterns; small subnormals only; near the
// largest double; signed over 60 binades (the extraction's four levels); positive over 20
// binades, a frame's luminances (its two levels).
constexpr int NumberOfKinds = 8;
std::vector<double> Values(int kind, int n, std::mt19937_64& g)
{
  std::vector<double> v(n);
  for (double& x : v)
  {
    const double r = std::ldexp(static_cast<double>(g() >> 11), -53);
    const double sign = (g() & 1) ? -1.0 : 1.0;
    switch (kind)
    {
      case 0:
        x = r;
        break;
      case 1:
        x = sign * std::ldexp(r, static_cast<int>(g() % 200) - 100);
        break;
      case 2:
        x = sign * std::ldexp(r, static_cast<int>(g() % 2100) - 1074);
        break;
      case 3:
      {
        const std::uint64_t bits = g();
        std::memcpy(&x, &bits, sizeof(x));
        x = std::isfinite(x) ? x : 0.0;
        break;
      }
      case 4:
        x = sign * std::ldexp(static_cast<double>(g() % 1000), -1074);
        break;
      case 6:
        x = sign * std::ldexp(r, static_cast<int>(g() % 60) - 30);
        break;
      case 7:
        x = std::ldexp(r, static_cast<int>(g() % 20) - 10);
        break;
      default:
        x = sign * std::numeric_limits<double>::max() * r;
        break;
    }
  }
  return v;
}
}

// The row path gives the one-by-one sum to the last bit, for every kind of value and for
// lengths around the 2048-value blocks.
TEST(NumericsExactSum, RowsEqualOneByOne)
{
  std::mt19937_64 g(42);
  const int lengths[] = { 1, 2, 7, 2047, 2048, 2049, 4096, 4097, 6000 };
  for (int kind = 0; kind < NumberOfKinds; ++kind)
  {
    for (int n : lengths)
    {
      for (int trial = 0; trial < 4; ++trial)
      {
        const std::vector<double> v = Values(kind, n, g);
        const double a = OneByOne(v), b = ByRow(v);
        EXPECT_TRUE(Same(a, b)) << "kind " << kind << ", n " << n << ": " << a << " vs " << b;
      }
    }
  }
}

// Sums whose value is known exactly, where any rounding before the end shows.
TEST(NumericsExactSum, KnownSums)
{
  const double tiny = std::ldexp(1.0, -53), big = std::numeric_limits<double>::max();
  // 1 + 2^-53 + 2^-53 is 1 + 2^-52 (left to right in double gives 1).
  EXPECT_EQ(ByRow({ 1.0, tiny, tiny }), 1.0 + 2.0 * tiny);
  // 1 + 2^-53 is a tie: to even, 1; the least bit of anything below breaks it upwards.
  EXPECT_EQ(ByRow({ 1.0, tiny }), 1.0);
  EXPECT_EQ(ByRow({ 1.0, tiny, std::ldexp(1.0, -1074) }), 1.0 + 2.0 * tiny);
  // Cancellation across the whole range leaves the small term alone.
  EXPECT_EQ(ByRow({ big, 1e-300, -big, big, -big, 3.0 }), 3.0 + 1e-300);
  // 3000 of the smallest subnormal.
  EXPECT_EQ(ByRow(std::vector<double>(3000, std::ldexp(1.0, -1074))), std::ldexp(3000.0, -1074));
  // Overflow rounds to infinity; non-finite values make the sum non-finite.
  EXPECT_EQ(ByRow(std::vector<double>(5000, big)), std::numeric_limits<double>::infinity());
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(ByRow({ 1.0, inf, 2.0 }), inf);
  EXPECT_TRUE(std::isnan(ByRow({ inf, -inf })));
  EXPECT_TRUE(std::isnan(ByRow({ 1.0, std::nan("") })));
  // A shuffled row of x and -x pairs sums to +0 exactly.
  std::mt19937_64 g(5);
  std::vector<double> pairs = Values(2, 3001, g);
  const size_t half = pairs.size();
  for (size_t i = 0; i < half; ++i)
  {
    pairs.push_back(-pairs[i]);
  }
  std::shuffle(pairs.begin(), pairs.end(), g);
  EXPECT_TRUE(Same(ByRow(pairs), 0.0));
}

// Sums of parts added in any grouping (threads each summing some rows) give the same bits.
TEST(NumericsExactSum, MergingIsExact)
{
  std::mt19937_64 g(9);
  const std::vector<double> v = Values(1, 10000, g);
  vtkBloomExactSum parts[3], total;
  for (size_t i = 0; i < v.size(); i += 700)
  {
    const int n = static_cast<int>(std::min<size_t>(700, v.size() - i));
    parts[(i / 700) % 3].AddRow(v.data() + i, n);
  }
  for (const vtkBloomExactSum& p : parts)
  {
    total.Add(p);
  }
  EXPECT_TRUE(Same(total.Get(), OneByOne(v)));
}

// AddRow with the caller's hint (the largest magnitude, as the composite's statistics find it)
// gives the same bits as without; a larger bound than the row holds only moves the levels up,
// and a NaN the bound leaves out still makes the sum NaN.
TEST(NumericsExactSum, HintedRowsEqualOneByOne)
{
  std::mt19937_64 g(17);
  for (int kind = 0; kind < NumberOfKinds; ++kind)
  {
    for (int n : { 1, 5, 2048, 4097 })
    {
      const std::vector<double> v = Values(kind, n, g);
      double largest = 0.0;
      for (double x : v)
      {
        largest = std::max(largest, std::fabs(x));
      }
      vtkBloomExactSum exact, wider;
      exact.AddRow(v.data(), n, largest);
      wider.AddRow(
        v.data(), n, std::min(std::ldexp(largest, 40), std::numeric_limits<double>::max()));
      const double a = OneByOne(v);
      EXPECT_TRUE(Same(a, exact.Get())) << "kind " << kind << ", n " << n;
      EXPECT_TRUE(Same(a, wider.Get())) << "kind " << kind << ", n " << n << " (larger bound)";
    }
  }
  std::vector<double> v(100, 0.5);
  v[37] = std::nan("");
  vtkBloomExactSum s;
  s.AddRow(v.data(), static_cast<int>(v.size()), 0.5);
  EXPECT_TRUE(std::isnan(s.Get()));
}

// The extraction needs IEEE's default arithmetic; under another rounding direction, or with
// subnormals flushed (x86's FTZ and DAZ, which some applications set for speed), AddRow takes
// the integer path and still gives the sum to the last bit. Rows of values and their negatives
// with subnormals among them: the sum is the subnormals' alone, so a lost one shows.
TEST(NumericsExactSum, RowsAreExactInAnyFloatingPointEnvironment)
{
  std::mt19937_64 g(23);
  std::vector<std::vector<double>> rows;
  for (int kind : { 0, 6, 7 })
  {
    std::vector<double> v = Values(kind, 1500, g);
    const size_t half = v.size();
    for (size_t i = 0; i < half; ++i)
    {
      v.push_back(-v[i]);
    }
    for (int i = 0; i < 40; ++i)
    {
      v.push_back(std::ldexp(static_cast<double>(g() % 1000 + 1), -1074));
    }
    std::shuffle(v.begin(), v.end(), g);
    rows.push_back(v);
  }
  std::vector<double> expected;
  for (const std::vector<double>& v : rows)
  {
    expected.push_back(OneByOne(v));
  }
  auto check = [&](const char* environment)
  {
    for (size_t r = 0; r < rows.size(); ++r)
    {
      const std::vector<double>& v = rows[r];
      double largest = 0.0;
      for (double x : v)
      {
        largest = std::max(largest, std::fabs(x));
      }
      vtkBloomExactSum hinted;
      hinted.AddRow(v.data(), static_cast<int>(v.size()), largest);
      EXPECT_TRUE(Same(expected[r], ByRow(v))) << environment << ", row " << r;
      EXPECT_TRUE(Same(expected[r], hinted.Get())) << environment << ", row " << r << " (hinted)";
    }
  };
  check("round to nearest");
  for (int direction : { FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO })
  {
    const int saved = std::fegetround();
    ASSERT_EQ(std::fesetround(direction), 0);
    check("directed rounding");
    std::fesetround(saved);
  }
#if defined(__SSE__) || defined(_M_X64)
  const unsigned int saved = _mm_getcsr();
  _mm_setcsr(saved | 0x8040u); // flush to zero, denormals are zero
  check("FTZ and DAZ");
  _mm_setcsr(saved);
#endif
}

// Chunks are carried once in many additions, not after each (vtkBloomExactSum::Grow): a sum
// added to itself 200 times doubles every chunk each time, so it would wrap past 2^63 within
// about 31 doublings if a carry came too late.
TEST(NumericsExactSum, RepeatedMergesCarryBeforeOverflow)
{
  std::mt19937_64 g(3);
  const std::vector<double> v = Values(0, 3000, g);
  vtkBloomExactSum s;
  s.AddRow(v.data(), static_cast<int>(v.size()));
  const double first = s.Get();
  for (int i = 1; i <= 200; ++i)
  {
    s.Add(s);
    ASSERT_EQ(s.Get(), std::ldexp(first, i)) << "after " << i << " doublings";
  }
}
