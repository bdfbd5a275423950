// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file    vtkBloomExactSum.h
 * @brief   Internal: the exact sum of doubles, rounded once to nearest.
 *
 * Not installed and not part of the public API. vtkImageBloom's energies are exact sums of
 * per-pixel luminances: nothing is rounded until Get(), so the result does not depend on the
 * order of the additions or the number of threads, and values that cancel lose nothing.
 *
 * The store is Neal's small superaccumulator (R. M. Neal, "Fast exact summation using small and
 * large superaccumulators", arXiv:1505.05571, 2015): 64-bit chunks, chunk k holding the bits of
 * weight 2^(32 k - 1074), so every finite double, m 2^(p - 1074) with an integer m < 2^53 and
 * 0 <= p < 2046, is added as three 32-bit pieces. Non-finite values are summed apart and make
 * the result non-finite.
 *
 * AddRow() adds a whole array faster, per block of at most 2048 values whose magnitudes are
 * below 2^top. First by extraction (Rump, Ogita and Oishi 2008): with sigma = 2^(top + 12),
 * q = (sigma + x) - sigma keeps the bits of x down to 2^(top - 41), exactly, and the q of a
 * block add up in double without rounding; the remainders x - q, also exact, go through the
 * same step 41 binades lower. Two such levels (four where a value lies below 2^(top - 30))
 * are a few double additions per value, in vector lanes; they need IEEE's
 * default arithmetic (round to nearest, no flush to zero), which AddRow checks. A block that
 * leaves a remainder, has a top too large or too small, or holds Inf or NaN is summed as
 * three 64-bit integers of a fixed-point window 64 binades below its largest exponent, the
 * rare values below the window one by one. Either way the result is the same bit for bit.
 */

#ifndef vtkBloomExactSum_h
#define vtkBloomExactSum_h

#include <cstdint>
#include <type_traits>

// Loops over rows of pixels that vectorize with AVX2 (per-lane variable shifts, double lanes)
// are compiled twice where GCC can clone a function per instruction set (ifunc, x86-64 ELF),
// the copy chosen at load time. Without FMA, both copies give the same bits: GCC contracts
// a * b + c into FMA in C++ whatever the dialect, so no clone may target FMA (x86-64-v3/v4 did,
// and changed the luminances' last bit: NumericsHardCases caught it).
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__ELF__)
#define VTKBLOOM_TARGET_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define VTKBLOOM_TARGET_CLONES
#endif

// Row kernels inlined into those cloned loops, so that each clone gets its own copy.
#if defined(__GNUC__)
#define VTKBLOOM_ALWAYS_INLINE inline __attribute__((always_inline))
#else
#define VTKBLOOM_ALWAYS_INLINE inline
#endif

/// Lane q of a GCC vector, or the scalar itself (q ignored): one loop body for both.
template <typename V>
VTKBLOOM_ALWAYS_INLINE auto& vtkBloomLane(V& v, int q)
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

class vtkBloomExactSum
{
public:
  /// Add one double.
  void Add(double x);

  /// Add n doubles (the same result as n calls of Add, faster).
  void AddRow(const double* values, int n);

  /**
   * AddRow for a caller that has already seen the values: no value's magnitude exceeds
   * `largestMagnitude` (NaN values aside, which this finds). A smaller bound gives a wrong sum.
   */
  void AddRow(const double* values, int n, double largestMagnitude);

  /// Add another sum.
  void Add(const vtkBloomExactSum& other);

  /// The sum, rounded to nearest (ties to even); Inf or NaN when a non-finite value was added.
  double Get() const;

  /// Carry every chunk into the next: chunks 0..n-2 in [0, 2^32), the last one signed.
  void Normalize();

private:
  /// Record `units` more additions of at most 2^44 to each chunk; normalize before they could
  /// overflow (a chunk then holds less than 2^62, so two sums still add).
  void Grow(std::int64_t units);

  /// Add v 2^(bit - 1074) for a signed 64-bit v and 0 <= bit < 2080.
  void AddInteger(std::int64_t v, int bit);
  /// One block of AddRow (n <= MaximumBlock) by extraction, its values below 2^top; false, and
  /// nothing added, when a remainder is left or top is out of range.
  bool AddExtracted(const double* values, int n, int top);
  /// One block through the fixed-point window, its largest biased exponent `largest`.
  void AddBlock(const double* values, int n, std::uint64_t largest, bool anyNegative);

  // Chunk k holds bits of weight 2^(32 k - 1074); the largest double reaches chunk 65, and the
  // rest is room for carries.
  static constexpr int NumberOfChunks = 68;
  std::int64_t Chunks[NumberOfChunks] = {};
  double Special = 0.0;
  // Additions since the last Normalize, in units of 2^44 per chunk: a row normalizes once in
  // about 2^17 of them, not once per row.
  std::int64_t Pending = 0;
};

#endif
// VTK-HeaderTest-Exclude: vtkBloomExactSum.h
