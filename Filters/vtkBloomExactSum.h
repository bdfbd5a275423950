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
 * fixed-point sum, which vectorizes), then adds those three integers to the chunks; the rare
 * values below the window take the one-by-one path. The result is the same bit for bit.
 */

#ifndef vtkBloomExactSum_h
#define vtkBloomExactSum_h

#include <cstdint>

// Loops over rows of pixels that vectorize with AVX2 (per-lane variable shifts, double lanes)
// are compiled twice where GCC can clone a function per instruction set (ifunc, x86-64 ELF),
// the copy chosen at load time. Without FMA, both copies give the same bits.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__ELF__)
#define VTKBLOOM_TARGET_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define VTKBLOOM_TARGET_CLONES
#endif

class vtkBloomExactSum
{
public:
  /// Add one double.
  void Add(double x);

  /// Add n doubles (the same result as n calls of Add, faster); normalizes.
  void AddRow(const double* values, int n);

  /// Add another sum; normalizes.
  void Add(const vtkBloomExactSum& other);

  /// The sum, rounded to nearest (ties to even); Inf or NaN when a non-finite value was added.
  double Get() const;

  /// Carry every chunk into the next: chunks 0..n-2 in [0, 2^32), the last one signed.
  void Normalize();

private:
  /// Add v 2^(bit - 1074) for a signed 64-bit v and 0 <= bit < 2080.
  void AddInteger(std::int64_t v, int bit);
  /// One block of AddRow (n <= MaximumBlock).
  void AddBlock(const double* values, int n);

  // Chunk k holds bits of weight 2^(32 k - 1074); the largest double reaches chunk 65, and the
  // rest is room for carries.
  static constexpr int NumberOfChunks = 68;
  std::int64_t Chunks[NumberOfChunks] = {};
  double Special = 0.0;
};

#endif
// VTK-HeaderTest-Exclude: vtkBloomExactSum.h
