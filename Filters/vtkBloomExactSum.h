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
 * AddRow() adds a whole array faster: per block of at most 2048 values it sums, in three 64-bit
 * integers, every value in a 64-binade window below the block's largest exponent, exactly (a
 * fixed-point sum, which vectorizes; without the sign handling when no value is negative), then
 * adds those three integers to the chunks; the rare values below the window take the one-by-one
 * path. The result is the same bit for bit.
 */

#ifndef vtkBloomExactSum_h
#define vtkBloomExactSum_h

#include <cstdint>

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

class vtkBloomExactSum
{
public:
  /// Add one double.
  void Add(double x);

  /// Add n doubles (the same result as n calls of Add, faster).
  void AddRow(const double* values, int n);

  /**
   * AddRow for a caller that has already seen the values: `largestBits` is the largest of their
   * bit patterns with the sign cleared (its exponent field bounds every value; 0x7FF there means
   * Inf or NaN) and `anyNegative` whether a sign bit is set. A wrong hint gives a wrong sum.
   */
  void AddRow(const double* values, int n, std::uint64_t largestBits, bool anyNegative);

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
  /// One block of AddRow (n <= MaximumBlock) whose largest biased exponent is `largest`.
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
