// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkBloomKernels
 * @brief   The one definition of every kernel weight and tap position used by vtk-bloom.
 *
 * The CPU filters and the GLSL render pass both take their weights from here, so a weight is
 * never typed twice. Kernels are described as taps: an offset in texels of the *source* image,
 * measured from the point an output sample maps to, and a weight. A fractional offset means a
 * bilinear fetch, exactly as a GPU texture unit would do it (texel centres at (i + 0.5) / n).
 *
 * Symmetric one-dimensional kernels are stored as half kernels: `half[0]` is the centre weight
 * and `half[i]` the weight at both +i and -i, so that the full kernel sums to
 * `half[0] + 2 * sum(half[1..R])`.
 *
 * The Gaussian kernels follow Lindeberg (1990) and Getreuer (IPOL 2013):
 * - Sampled:    w_i = exp(-i^2 / (2 sigma^2)), normalized over the taps (seed 004).
 * - Integrated: w_i = Phi((i + 1/2) / sigma) - Phi((i - 1/2) / sigma), the box-integrated
 *   continuous Gaussian, normalized over the taps.
 * - Discrete:   w_i = exp(-t) I_i(t) with t = sigma^2, Lindeberg's discrete analogue of the
 *   Gaussian whose variance is exactly sigma^2 (I_i is the modified Bessel function).
 * In every kind sigma = 0 gives the single tap {1}: an exact identity.
 */

#ifndef vtkBloomKernels_h
#define vtkBloomKernels_h

#include "vtkFiltersBloomModule.h" // For export macro

#include <vector>

class VTKFILTERSBLOOM_EXPORT vtkBloomKernels
{
public:
  /// One tap: offset in source texels and its weight.
  struct Tap
  {
    double Offset;
    double Weight;
  };

  enum GaussianKind
  {
    GAUSSIAN_SAMPLED = 0,
    GAUSSIAN_INTEGRATED = 1,
    GAUSSIAN_DISCRETE = 2
  };

  /**
   * The half kernel of a Gaussian of standard deviation `sigma` truncated to `radius` taps
   * each side, normalized so the full kernel sums to 1 (computed in double).
   * sigma <= 0 or radius <= 0 give {1}.
   */
  static std::vector<double> GaussianHalfKernel(double sigma, int radius, int kind);

  /// The radius that keeps `factor` standard deviations, ceil(factor * sigma), at least 0.
  static int RadiusForSigma(double sigma, double factor);

  /// Divide a half kernel by its full sum (half[0] + 2 sum half[i]). Empty or zero sums give {1}.
  static std::vector<double> NormalizeHalfKernel(const std::vector<double>& half);

  /// Variance of the full kernel described by a half kernel, in texels^2.
  static double HalfKernelVariance(const std::vector<double>& half);

  /// Expand a half kernel into taps at offsets k * spacing, k = -R..R.
  static std::vector<Tap> SymmetricTaps(const std::vector<double>& half, double spacing);

  ///@{
  /**
   * Named tap sets, each of unit sum.
   * - Bilinear: one tap at 0 (a plain bilinear fetch).
   * - Tent: -1, 0, +1 with 1/4, 1/2, 1/4. Its tensor product is the 3x3 tent 1 2 1 / 2 4 2 /
   *   1 2 1 over 16 used for upsampling (Jimenez 2014).
   * - HalfTexelPair: -1/2 and +1/2 with 1/2 each. Its tensor product is the inner 2x2 box of
   *   the 13-tap downsample.
   * - Binomial5: offsets -2..2 with 1 4 6 4 1 over 16.
   * - LeftPair / RightPair: {-1, 0} and {0, +1} with 1/2 each; the four outer boxes of the
   *   13-tap downsample are their tensor products.
   */
  static std::vector<Tap> BilinearTaps();
  static std::vector<Tap> TentTaps();
  static std::vector<Tap> HalfTexelPairTaps();
  static std::vector<Tap> Binomial5Taps();
  static std::vector<Tap> LeftPairTaps();
  static std::vector<Tap> RightPairTaps();
  ///@}

  /**
   * Jimenez (2014) 13-tap downsample as a sum of two separable terms:
   * 13tap = 1/2 (HalfTexelPair x HalfTexelPair) + 1/2 (Tent x Tent).
   * That gives the centre 1/8, the four inner taps 1/8 each, the four edge taps 1/16 each and
   * the four corners 1/32 each, which sum to 1 (seed 000 sums to 1.375; fixed here).
   * The Karis average weights the inner box by 1/2 and each outer box by 1/8.
   */
  static constexpr double Jimenez13InnerWeight = 0.5;
  static constexpr double Jimenez13OuterWeight = 0.125;

  /// Half kernel of the 7-tap binomial 1 6 15 20 15 6 1 over 64 (seed 001).
  static std::vector<double> Binomial7HalfKernel();

  /// Half kernel of the 9-tap blur used by seed 000 (LearnOpenGL weights, sum 1).
  static std::vector<double> WebGPUMarketBlurHalfKernel();

  /// Half kernel of seed 002's 13-tap blur, divided by its symmetric sum 1.0179994.
  static std::vector<double> PingPongBlurHalfKernel();

  ///@{
  /// Rec. 709 luminance weights, used by every luminance-based threshold.
  static constexpr double LuminanceR = 0.2126;
  static constexpr double LuminanceG = 0.7152;
  static constexpr double LuminanceB = 0.0722;
  /// R G B to luminance with these weights, evaluated as (R' + G') + B' (scalars or GCC vectors).
  template <typename Real>
  static Real Luminance(Real r, Real g, Real b)
  {
    return LuminanceR * r + LuminanceG * g + LuminanceB * b;
  }
  ///@}

  ///@{
  /**
   * Gwosdek, Grewenig, Bruhn and Weickert (2011), "Theoretical foundations of Gaussian
   * convolution by extended box filtering": an extended box of radius r weighs 1 at |i| <= r and
   * alpha in [0, 1) at |i| = r + 1, divided by c = 2r + 1 + 2 alpha. Its variance is
   * (r (r + 1) (2r + 1) / 3 + 2 alpha (r + 1)^2) / c, which is continuous in alpha, so a cascade
   * of K such boxes hits any variance sigma^2 exactly (each box carries sigma^2 / K) instead of
   * snapping sigma to the integer radii of plain boxes.
   */
  struct ExtendedBox
  {
    int Radius = 0;
    double Alpha = 0.0;
  };
  /// The extended box of the given variance (r is the largest radius with r (r + 1) / 3 <= v).
  static ExtendedBox ExtendedBoxForVariance(double variance);
  /// Its normalized half kernel: r + 2 entries (r + 1 when Alpha is 0).
  static std::vector<double> ExtendedBoxHalfKernel(const ExtendedBox& box);
  ///@}

  ///@{
  /**
   * Third-order recursive Gaussian (Young and van Vliet 1995; van Vliet, Young and Verbeek
   * 1998): a causal pass followed by an anti-causal pass,
   *
   *   w[n] = Gain x[n] - F1 w[n-1] - F2 w[n-2] - F3 w[n-3]
   *   y[n] = Gain w[n] - F1 y[n+1] - F2 y[n+2] - F3 y[n+3],
   *
   * whose causal part has the poles p_i = d_i^(-1/q) with the 1998 L-infinity poles for sigma 2,
   * d = 1.86543 and 1.41650 +/- 1.00829 i. Instead of the published fit of q(sigma), q is solved
   * here (by bisection, in double) so that the variance of the two passes, 2 sum_i p_i / (1 -
   * p_i)^2, equals sigma^2 exactly; Gain = prod_i (1 - p_i) makes the DC gain 1.
   *
   * Boundary (Triggs and Sdika 2006): beyond the last sample the signal continues as a constant
   * u (the last sample for clamp, 0 for zero), and then (y[N], y[N+1], y[N+2]) - u = Boundary *
   * (w[N-1] - u, w[N-2] - u, w[N-3] - u), exactly for the infinitely extended signal. Boundary
   * is computed by running the homogeneous recursions over the decay length of the response
   * (until it falls below 1e-20), which is equivalent to Triggs and Sdika's closed form.
   *
   * Every coefficient is double; the filter state must be kept in double too (at sigma = 200 the
   * poles are within 1e-2 of 1 and float32 state loses about five digits).
   */
  struct RecursiveGaussian
  {
    double Sigma = 0.0;
    double Q = 0.0;
    double Gain = 1.0;
    double Feedback[3] = { 0.0, 0.0, 0.0 };
    double Boundary[3][3] = { { 0.0, 0.0, 0.0 }, { 0.0, 0.0, 0.0 }, { 0.0, 0.0, 0.0 } };
    int DecayLength = 0; ///< samples after which the response is below 1e-20 of its start
  };
  /// Coefficients for standard deviation sigma > 0 (in samples); sigma <= 0 gives the identity.
  static RecursiveGaussian RecursiveGaussianCoefficients(double sigma);
  /// Variance of the two-pass recursive filter for the 1998 poles scaled by q.
  static double RecursiveGaussianVariance(double q);
  ///@}
};

#endif
// VTK-HeaderTest-Exclude: vtkBloomKernels.h
