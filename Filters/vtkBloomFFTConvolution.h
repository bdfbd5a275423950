// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkBloomFFTConvolution
 * @brief   Applies a wide one-dimensional vtkBloomLinearOperator through FFTW.
 *
 * A same-size operator M (n samples to n) that is
 * a convolution away from the borders (a Gaussian with its border folded into the weights, or
 * many clamped passes of a small kernel folded into one, as the ping-pong preset does) is
 * applied to a line x as
 *
 *   M x = T x + D x,   T x = (K * E x) restricted to [0, n),
 *
 * where K is the kernel of M's translation-invariant rows (vtkBloomLinearOperator's
 * FindInvariantRange), E extends x beyond its ends by the operator's border mode (clamp,
 * reflect or zero) and D = M - T is what is left near the ends:
 * - T runs through one real FFT of the extended line, a product with the kernel's spectrum and
 *   one inverse FFT (FFTW, sizes 2^a 3^b, zero padded so that nothing wraps).
 * - D is zero for a single convolution (padding the line is how its borders were folded). For
 *   repeated clamped passes it is not, but it lives in two corner blocks (rows near each end
 *   reading samples near that end) of very low numerical rank: the 32 clamped passes of the
 *   ping-pong preset leave blocks of 192 x 384 whose singular values fall below 1e-9 of the
 *   first by the tenth. Each block is factored once, by Gram-Schmidt with column pivoting, to
 *   an absolute residual below 1e-12 per column, and applied as U (V^T x) in double.
 * So the path applies the same weights as the direct path, up to the rounding of the FFT.
 *
 * Error model (docs/numerics.md has the measurements): the FFT's rounding is about
 * eps sqrt(log2 N) relative to the line's L2 norm (eps = 6e-8 in single precision, 1.1e-16 in
 * double); D's truncation adds at most 1e-12 sqrt(cols) |x|. Each line is scaled by a power of
 * two so that its largest magnitude is below 1 before the transform (which cannot overflow)
 * and scaled back after, saturating at the largest finite value.
 *
 * Outputs that no non-zero input sample of the line can reach are exactly zero (the direct
 * path's zeros), and an all-zero line is left untouched with no transform. Every line is
 * computed the same way whatever the other lines and the threads, so results are
 * deterministic (FFTW_ESTIMATE plans, which do not depend on timing).
 *
 * Cost model: per line, the direct path costs nnz(M) multiply-adds; this path costs
 * FFTCostFactor N log2 N (forward and inverse real transforms) plus 8 N (extension, product,
 * copy) plus rank x (block rows + block columns) for D. Cost() and DirectCost() return these in
 * multiply-add units; callers pick the cheaper one (vtkImageSeparableGaussian and
 * vtkImageBloom do, unless told otherwise).
 *
 * FFTW's planner is not thread-safe: Build and the destructor take a process-wide lock. Apply
 * is const and may run from many threads at once, each with its own Workspace.
 */

#ifndef vtkBloomFFTConvolution_h
#define vtkBloomFFTConvolution_h

#include "vtkBloomLinearOperator.h" // For the operator
#include "vtkFiltersBloomModule.h"  // For export macro

#include <cstddef>
#include <mutex> // For the planner lock
#include <vector>

class VTKFILTERSBLOOM_EXPORT vtkBloomFFTConvolution
{
public:
  /**
   * Multiply-adds one N log2 N unit of the forward and inverse transforms costs, measured with
   * BloomAccuracyStudy against the direct path (docs/numerics.md).
   */
  static constexpr double FFTCostFactor = 2.0;

  vtkBloomFFTConvolution();
  ~vtkBloomFFTConvolution();
  vtkBloomFFTConvolution(const vtkBloomFFTConvolution&) = delete;
  vtkBloomFFTConvolution& operator=(const vtkBloomFFTConvolution&) = delete;

  /**
   * Prepare to apply `op` (same input and output size) with extension `border`
   * (vtkBloomLinearOperator::BorderMode), in single or double precision. Returns false, and
   * stays unusable, when the operator has no translation-invariant interior.
   */
  bool Build(const vtkBloomLinearOperator& op, int border, bool singlePrecision);

  /**
   * The one lock around FFTW's planner, which is global and not thread-safe: every plan made or
   * destroyed in this module (vtkBloomPSF's too) is made under it.
   */
  static std::mutex& PlannerMutex();

  /// The smallest m >= n whose only prime factors are 2 and 3 (of FFTW's sizes, the fastest).
  static int GoodTransformSize(int n);

  /// Whether Build succeeded.
  bool IsReady() const { return this->Ready; }

  /// Multiply-adds per line of the direct path: the operator's non-zero weights.
  static double DirectCost(const vtkBloomLinearOperator& op);

  /// Modeled multiply-adds per line of this path (see the class description).
  double Cost() const;

  /**
   * The same model for a transform of n samples whose N log2 N unit costs `factor`
   * multiply-adds (the render pass's GPU transform has its own length and factor).
   */
  double Cost(int n, double factor) const;

  /// FFT length and the ranks of the two border corrections (for tests and reports).
  int GetTransformSize() const { return this->N; }
  int GetCorrectionRank(int side) const;

  /// Per-thread scratch memory for Apply (allocated on first use; a copy starts empty).
  struct VTKFILTERSBLOOM_EXPORT Workspace
  {
    Workspace() = default;
    Workspace(const Workspace&) {}
    Workspace& operator=(const Workspace&) { return *this; }
    ~Workspace();
    void Reserve(int n, bool single);
    void* Real = nullptr;    ///< fftw(f)_malloc'd, N values
    void* Complex = nullptr; ///< fftw(f)_malloc'd, N / 2 + 1 complex values
    int Capacity = 0;
    bool Single = true;
    std::vector<double> Line; ///< the line as read, for the corrections
    std::vector<double> Coefficients;
  };

  /**
   * Apply to `count` lines in place: sample m of line l is at
   * data[l * lineStride + m * sampleStride].
   */
  void Apply(float* data, std::ptrdiff_t sampleStride, std::ptrdiff_t lineStride, int count,
    Workspace& ws) const;
  void Apply(double* data, std::ptrdiff_t sampleStride, std::ptrdiff_t lineStride, int count,
    Workspace& ws) const;

  /**
   * Apply along every line of `axis` of a sample-major buffer of size[0] x size[1] x size[2]
   * samples with `lanes` values each (lane l of sample (i, j, k) at
   * ((k size[1] + j) size[0] + i) lanes + l), threaded with vtkSMPTools. Only lanes
   * [0, activeLanes) are filtered.
   */
  template <typename T>
  void ApplyAxis(T* data, const int size[3], int lanes, int activeLanes, int axis) const;

  /**
   * One factored border correction: rows [Row0, Row0 + Rows) of D read input samples
   * [Col0, Col0 + Cols) as D_block = U^T V^T, i.e. (D x)[Row0 + r] = sum_k U[k Rows + r] t_k
   * with t_k = sum_q V[q Rank + k] x[Col0 + q].
   */
  struct Block
  {
    int Row0 = 0;
    int Rows = 0;
    int Col0 = 0;
    int Cols = 0;
    int Rank = 0;
    std::vector<double> U; ///< Rank x Rows
    std::vector<double> V; ///< Cols x Rank (V^T transposed, so that V^T x runs over rows of V)
  };

  ///@{
  /**
   * Read-only access for another implementation of the same M x = T x + D x (vtkBloomPass runs
   * it in compute shaders): the line length n; the extension E, PadLeft samples before the line
   * and PadRight after it, sample m of the extended line (-PadLeft <= m < n + PadRight) being
   * x[FoldIndex(m, n, Border)] (zero for -1); the outputs [ReachLo[a], ReachHi[b]] that input
   * samples [a, b] can reach; and D's blocks.
   */
  int GetSize() const { return this->Size; }
  int GetPadLeft() const { return this->PadLeft; }
  int GetPadRight() const { return this->PadRight; }
  int GetBorder() const { return this->Border; }
  const std::vector<int>& GetReachLo() const { return this->ReachLo; }
  const std::vector<int>& GetReachHi() const { return this->ReachHi; }
  const std::vector<Block>& GetCorrections() const { return this->Corrections; }
  ///@}

  /**
   * The spectrum of T's kernel for a circular convolution of length `n` (at least
   * GetSize() + GetPadLeft() + GetPadRight(), so that nothing wraps) whose output j sits at
   * PadLeft + j of the extended line, divided by n: n / 2 + 1 complex values, interleaved re, im,
   * computed in double (the same function that makes this object's own spectrum).
   */
  void ComputeKernelSpectrum(int n, std::vector<double>& spectrum) const;

private:
  template <typename T, typename P>
  void ApplyLine(T* x, std::ptrdiff_t stride, Workspace& ws) const;
  template <typename T>
  void ApplyLines(T* data, std::ptrdiff_t sampleStride, std::ptrdiff_t lineStride, int count,
    Workspace& ws) const;
  void Release();

  bool Ready = false;
  bool Single = true;
  int Size = 0;               ///< n
  int N = 0;                  ///< transform length
  int PadLeft = 0;            ///< extension before sample 0
  int PadRight = 0;           ///< extension after sample n - 1
  int Border = 0;             ///< extension mode
  std::vector<double> Kernel; ///< T's kernel: row j reads x[j + Offset + k]
  int Offset = 0;
  std::vector<double> SpectrumD;     ///< kernel spectrum / N, interleaved re, im
  std::vector<float> SpectrumF;      ///< the same in single precision
  std::vector<int> ReachLo, ReachHi; ///< outputs an input sample i can reach: [Lo[i], Hi[i]]
  std::vector<Block> Corrections;    ///< D, near each end
  void* Forward = nullptr;           ///< fftw(f)_plan
  void* Inverse = nullptr;           ///< fftw(f)_plan
};

#endif
// VTK-HeaderTest-Exclude: vtkBloomFFTConvolution.h
