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
 */

#ifndef vtkImageSeparableGaussian_h
#define vtkImageSeparableGaussian_h

#include "vtkFiltersBloomModule.h" // For export macro
#include "vtkImageSeparableAlgorithm.h"

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

  double StandardDeviations[3];
  int Radius[3];
  double RadiusFactor;
  int KernelType;
  int BorderMode;

private:
  vtkImageSeparableGaussian(const vtkImageSeparableGaussian&) = delete;
  void operator=(const vtkImageSeparableGaussian&) = delete;
};

#endif
