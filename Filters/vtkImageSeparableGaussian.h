// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkImageSeparableGaussian
 * @brief   Exact separable Gaussian smoothing with a choice of kernel and border.
 *
 * Convolves each axis in turn (x, then y, then z) with a normalized one-dimensional Gaussian
 * of standard deviation sigma_a (in pixels) truncated to radius R_a taps each side:
 *
 *   out(x) = sum_{i=-R..R} w_i in(x + i),   sum_i w_i = 1.
 *
 * The kernel is Sampled (exp(-i^2 / 2 sigma^2), seed 004), Integrated (the continuous Gaussian
 * integrated over each pixel, with erf) or Discrete (Lindeberg's e^{-t} I_i(t), t = sigma^2,
 * whose variance is exactly sigma^2, so it does not under-blur below sigma = 0.7); see
 * vtkBloomKernels. Weights are computed in double. R is either given per axis (SetRadius) or,
 * when a radius is negative, ceil(RadiusFactor * sigma).
 *
 * Borders: Clamp repeats the edge pixel, Reflect mirrors half-sample symmetrically (which
 * conserves the image sum exactly and turns a kernel wider than the image into the mean), and
 * Zero treats outside pixels as 0. Borders are those of the whole extent, so streamed pieces
 * equal the whole result bit for bit.
 *
 * sigma = 0 (or radius 0) on an axis is an exact identity on that axis. Every component,
 * alpha included, is smoothed. Input must be float or double with 1 to 4 components.
 *
 * Unlike vtkImageGaussianSmooth, whose default 1.5 sigma cut-off keeps only 55-67 % of the
 * variance, the default here keeps 4 sigma (a truncation error near 3e-5).
 *
 * Methods (SetMethod). EXACT is the convolution above. The fast methods cost O(1) per sample
 * whatever sigma is, approximate the continuous Gaussian of variance sigma^2 and ignore Radius
 * and KernelType; all run in double precision, whatever the scalar type:
 * - BOX_CASCADE_3 and BOX_CASCADE_5: 3 or 5 passes of Gwosdek's extended box (window sums),
 *   each carrying sigma^2 / K of the variance, so the variance is exact for every sigma (plain
 *   boxes would snap sigma to integer radii). Support K (r + 1) each side.
 * - RECURSIVE: the third-order Young-van Vliet recursive filter (van Vliet, Young and Verbeek
 *   1998 poles, scaled so that the variance is exactly sigma^2) with Triggs and Sdika's exact
 *   boundary initialization for clamp and zero borders, and an exact periodic steady state for
 *   reflect. Its state is kept in double, so it is stable in float32 images for any sigma (the
 *   float32 failure above sigma ~ 100 that Getreuer reports does not occur); the round-off of
 *   the double recursion grows like sigma^4 and stays below 1e-6 of the signal up to sigma ~
 *   250. With reflect and sigma >= 3 n (n the line length) the result is the line mean, which
 *   the Gaussian equals there to 1e-19. Below sigma 0.5, where no third-order recursion reaches
 *   the variance, it convolves with Lindeberg's discrete kernel instead. Its support is
 *   infinite: beyond 4 sigma its response stays within 0.4 % of the peak, with negative lobes
 *   of about -0.5 % of the peak (-1.4 % at sigma 0.5).
 * Error against the continuous Gaussian (maximum absolute error of the impulse response over
 * its peak, sigma 0.5..64; docs/numerics.md has the error model and the measured table): EXACT
 * sampled at 4 sigma <= 4e-4; BOX_CASCADE_3 <= 0.065; BOX_CASCADE_5 <= 0.035 (0.09 below sigma
 * 2); RECURSIVE <= 0.013 for sigma >= 4, 0.025 for sigma >= 2, 0.04 for sigma >= 1 and 0.1
 * below. The fast methods have exactly the variance sigma^2.
 *
 * How EXACT applies its kernel (SetConvolutionMode): DIRECT sums the taps (2R + 1 multiply-adds
 * per sample and axis); FFT applies the same weights to whole lines through FFTW
 * (vtkBloomFFTConvolution: the line is extended by the border mode, transformed, multiplied by
 * the kernel's spectrum and transformed back), about log2 of the line length per sample
 * whatever sigma is; AUTOMATIC (the default) takes, per axis, whichever the cost model of
 * vtkBloomFFTConvolution says is cheaper, which is the FFT from about sigma 4 at 1080p. The FFT
 * runs in single precision for float images and in double for double images; it agrees with
 * DIRECT to about 1e-7 relative L2 in single precision (<= 1e-6 tested for sigma 8 to 64) and
 * 1e-15 in double (docs/numerics.md). GetLastFFTAxes() says which axes the last update ran
 * through the FFT.
 *
 * The fast methods and FFT axes need whole lines, so on every filtered axis they request the whole
 * extent; each line is computed the same way whatever the piece, so streamed pieces still equal the
 * whole result bit for bit.
 *
 * Non-finite input (SanitizeNonFinite, the same policy as vtkImageBloom):
 * - On (the default): before filtering, NaN becomes 0, +Inf the largest finite value of the
 *   scalar type and -Inf the lowest; the result is clamped to the finite range of the scalar
 *   type (an overflow that made NaN becomes 0). Every output sample is finite.
 * - Off: every method filters the input with its non-finite samples taken as 0, then marks the
 *   outputs whose support holds a non-finite sample: +Inf if all those samples are +Inf, -Inf
 *   if all are -Inf, NaN otherwise. The support is the separable box of the kernel: the
 *   non-zero taps for EXACT (borders folded in), K (r + 1) for the box cascades, and
 *   ceil(RadiusFactor sigma) for RECURSIVE (whose true support is infinite: the recursion
 *   itself never sees a non-finite value, so one NaN cannot poison a whole line). Outputs
 *   outside that box are finite.
 * Finite input gives the same output bit for bit either way.
 */

#ifndef vtkImageSeparableGaussian_h
#define vtkImageSeparableGaussian_h

#include "vtkBloomParameters.h"    // For the convolution modes
#include "vtkFiltersBloomModule.h" // For export macro
#include "vtkImageSeparableAlgorithm.h"

#include <memory> // For the FFT convolutions

class VTKFILTERSBLOOM_EXPORT vtkImageSeparableGaussian : public vtkImageSeparableAlgorithm
{
public:
  static vtkImageSeparableGaussian* New();
  vtkTypeMacro(vtkImageSeparableGaussian, vtkImageSeparableAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum KernelTypes
  {
    SAMPLED = 0,
    INTEGRATED = 1,
    DISCRETE = 2
  };

  enum BorderModes
  {
    CLAMP = 0,
    REFLECT = 1,
    ZERO = 2
  };

  enum Methods
  {
    EXACT = 0,
    BOX_CASCADE_3 = 1,
    BOX_CASCADE_5 = 2,
    RECURSIVE = 3
  };

  ///@{
  /// Method: EXACT (default), BOX_CASCADE_3, BOX_CASCADE_5 or RECURSIVE.
  vtkSetClampMacro(Method, int, EXACT, RECURSIVE);
  vtkGetMacro(Method, int);
  void SetMethodToExact() { this->SetMethod(EXACT); }
  void SetMethodToBoxCascade3() { this->SetMethod(BOX_CASCADE_3); }
  void SetMethodToBoxCascade5() { this->SetMethod(BOX_CASCADE_5); }
  void SetMethodToRecursive() { this->SetMethod(RECURSIVE); }
  const char* GetMethodAsString() { return vtkImageSeparableGaussian::GetMethodName(this->Method); }
  static const char* GetMethodName(int method);
  ///@}

  /// The convolution modes, valued as vtkBloomParameters defines them (one set for the library).
  enum ConvolutionModes
  {
    CONVOLUTION_AUTOMATIC = vtkBloomParameters::CONVOLUTION_AUTOMATIC,
    CONVOLUTION_DIRECT = vtkBloomParameters::CONVOLUTION_DIRECT,
    CONVOLUTION_FFT = vtkBloomParameters::CONVOLUTION_FFT
  };

  ///@{
  /**
   * How EXACT applies its kernel on each axis: AUTOMATIC (default: the cheaper of the two by
   * vtkBloomFFTConvolution's cost model), DIRECT (sum the taps) or FFT (where the operator has a
   * convolution interior, which is every axis whose line is longer than the kernel's support).
   */
  vtkSetClampMacro(ConvolutionMode, int, CONVOLUTION_AUTOMATIC, CONVOLUTION_FFT);
  vtkGetMacro(ConvolutionMode, int);
  void SetConvolutionModeToAutomatic() { this->SetConvolutionMode(CONVOLUTION_AUTOMATIC); }
  void SetConvolutionModeToDirect() { this->SetConvolutionMode(CONVOLUTION_DIRECT); }
  void SetConvolutionModeToFFT() { this->SetConvolutionMode(CONVOLUTION_FFT); }
  ///@}

  /// The axes (bit a for axis a) the last update convolved through the FFT.
  vtkGetMacro(LastFFTAxes, int);

  ///@{
  /// Replace non-finite input and clamp the output (see the class description). Default on.
  vtkSetMacro(SanitizeNonFinite, bool);
  vtkGetMacro(SanitizeNonFinite, bool);
  vtkBooleanMacro(SanitizeNonFinite, bool);
  ///@}

  ///@{
  /**
   * Standard deviation per axis, in pixels (not world units). Must be >= 0; 0 leaves the axis
   * untouched. Default (2, 2, 0).
   */
  vtkSetVector3Macro(StandardDeviations, double);
  vtkGetVector3Macro(StandardDeviations, double);
  void SetStandardDeviation(double sigma) { this->SetStandardDeviations(sigma, sigma, sigma); }
  ///@}

  ///@{
  /**
   * Kernel radius per axis, in taps each side of the centre. A negative radius (the default,
   * -1) means ceil(RadiusFactor * sigma).
   */
  vtkSetVector3Macro(Radius, int);
  vtkGetVector3Macro(Radius, int);
  ///@}

  ///@{
  /// Multiple of sigma kept when the radius is automatic. Default 4.
  vtkSetClampMacro(RadiusFactor, double, 0.0, 64.0);
  vtkGetMacro(RadiusFactor, double);
  ///@}

  ///@{
  /// Kernel: SAMPLED (default), INTEGRATED or DISCRETE.
  vtkSetClampMacro(KernelType, int, SAMPLED, DISCRETE);
  vtkGetMacro(KernelType, int);
  void SetKernelTypeToSampled() { this->SetKernelType(SAMPLED); }
  void SetKernelTypeToIntegrated() { this->SetKernelType(INTEGRATED); }
  void SetKernelTypeToDiscrete() { this->SetKernelType(DISCRETE); }
  const char* GetKernelTypeAsString();
  ///@}

  ///@{
  /// Border: CLAMP (default, as seed 004), REFLECT or ZERO.
  vtkSetClampMacro(BorderMode, int, CLAMP, ZERO);
  vtkGetMacro(BorderMode, int);
  void SetBorderModeToClamp() { this->SetBorderMode(CLAMP); }
  void SetBorderModeToReflect() { this->SetBorderMode(REFLECT); }
  void SetBorderModeToZero() { this->SetBorderMode(ZERO); }
  const char* GetBorderModeAsString();
  ///@}

  /// The normalized half kernel used on `axis` (centre first), for inspection and testing.
  std::vector<double> GetHalfKernel(int axis);

protected:
  vtkImageSeparableGaussian();
  ~vtkImageSeparableGaussian() override;

  bool BuildTerms(const int inWhole[6], const int outWhole[6], std::vector<Term>& terms) override;

  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  void ThreadedRequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector, vtkImageData*** inData, vtkImageData** outData,
    int outExt[6], int threadId) override;

  /**
   * The fast methods and EXACT with FFT axes (`fftAxes`): whole lines along each filtered axis,
   * threaded over lines.
   */
  void ExecuteLines(vtkImageData* input, vtkImageData* output, const int outExt[6], int fftAxes);

  enum Precisions
  {
    SINGLE_PRECISION,
    DOUBLE_PRECISION,
    ANY_PRECISION
  };

  /**
   * For EXACT, the axes to convolve through the FFT for an input of whole extent `inWhole`
   * (bit a for axis a), with this->FFT[a] built for them in `precision` (ANY_PRECISION: the
   * choice only, keeping a convolution of either precision).
   */
  int ChooseFFTAxes(const int inWhole[6], int precision);

  /// The one-dimensional operator whose non-zero pattern is the support on `axis`.
  vtkBloomLinearOperator SupportOperator(int axis, int n);

  double StandardDeviations[3];
  int Radius[3];
  double RadiusFactor;
  int KernelType;
  int BorderMode;
  int Method;
  int ConvolutionMode;
  int LastFFTAxes;
  bool SanitizeNonFinite;

  /// The FFT convolution of each axis and what it was built for (rebuilt when that changes).
  struct FFTAxis;
  std::unique_ptr<FFTAxis> FFT[3];

  /// The input with its non-finite samples replaced, for this execution only (or null).
  vtkImageData* CleanInput;

private:
  vtkImageSeparableGaussian(const vtkImageSeparableGaussian&) = delete;
  void operator=(const vtkImageSeparableGaussian&) = delete;
};

#endif
