// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file    vtkBloomHardCases.h
 * @brief   The numerical hard cases of issue 4: inputs, float64 references and expectations.
 *
 * Shared by the CPU suites (Testing/Numerics) and, later, the GPU pass suites, so that both run
 * the same cases against the same expectations. Nothing here uses the library under test: the
 * Gaussian reference is written from its formula, sums are compensated float64, and the images
 * are generated from closed forms.
 */

#ifndef vtkBloomHardCases_h
#define vtkBloomHardCases_h

#include <vtkImageData.h>
#include <vtkSmartPointer.h>

#include <string>
#include <vector>

namespace vtkBloomHardCases
{
///@{
/// The standard deviations of the accuracy study and its hard cases.
std::vector<double> StudySigmas();   ///< 0.5, 1, 2, 4, 8, 16, 32, 64
std::vector<double> FireflyValues(); ///< 1e4, 1e10, 1e30
constexpr double FireflyBackground = 0.01;
constexpr int LargestSweepSize = 67; ///< sizes 1..67 on each axis
///@}

///@{
/**
 * The float64 continuous-Gaussian reference of the accuracy study: the density of N(0, sigma^2)
 * sampled at the integers i - centre, i = 0..n-1, with no truncation, normalized to unit sum
 * over the whole line (the line must hold +/- 10 sigma; Poisson summation puts the normalization
 * within 1e-17 of the density's own for sigma >= 1).
 */
std::vector<double> ContinuousGaussian(double sigma, int n, int centre);

/// Error of a measured impulse response h (impulse at `centre`) against ContinuousGaussian.
struct ImpulseError
{
  double MaxAbs = 0.0;          ///< max |h - g| / max g
  double Rms = 0.0;             ///< sqrt(mean over |i - centre| <= 4 sigma of (h - g)^2) / max g
  double VarianceRatio = 0.0;   ///< sum h (i - centre)^2 / sum h, over sigma^2
  double MinimumOverPeak = 0.0; ///< min h / max g (negative lobes)
};
ImpulseError CompareImpulse(const std::vector<double>& h, double sigma, int centre);

/**
 * The documented bound (docs/numerics.md, vtkImageSeparableGaussian.h) on ImpulseError::MaxAbs
 * for a vtkImageSeparableGaussian method (EXACT with the default sampled kernel at 4 sigma,
 * BOX_CASCADE_3, BOX_CASCADE_5, RECURSIVE) at sigma.
 */
double DocumentedMaxAbsBound(int method, double sigma);
/// The documented bound on |VarianceRatio - 1|.
double DocumentedVarianceBound(int method, double sigma);
///@}

///@{
/// Images (x fastest, 2-D, z extent 0).
/// A constant `background` with one pixel of `value` in every colour channel at (cx, cy); alpha 1.
vtkSmartPointer<vtkImageData> Firefly(
  int w, int h, int cx, int cy, double value, double background, int scalarType, int components);
/// Values log-uniform over [1e-8, 1e8] from a portable hash, every channel; alpha 1.
vtkSmartPointer<vtkImageData> WideRange(int w, int h, int scalarType, int components);
/// A constant image.
vtkSmartPointer<vtkImageData> Constant(int w, int h, double value, int scalarType, int components);
/// A one-row image holding `values` (1 component).
vtkSmartPointer<vtkImageData> Row(const std::vector<double>& values, int scalarType);
/// A copy of `image` with every value replaced by its magnitude.
vtkSmartPointer<vtkImageData> Magnitudes(vtkImageData* image);
///@}

///@{
/// Checks, in float64.
vtkIdType CountNonFinite(vtkImageData* image);
/// Neumaier-compensated sum of component c (all components when c < 0) over finite samples.
double CompensatedSum(vtkImageData* image, int c = -1);
/// max |value - reference| / |reference| over all samples.
double MaxRelativeDeviationFrom(vtkImageData* image, double reference);
/// Scalars as doubles, in storage order.
std::vector<double> Values(vtkImageData* image);
///@}

///@{
/**
 * The threshold policy at the edge cases, as the vtkImageBloomThreshold class documents it, for
 * a one-component pixel of value v with threshold T and knee 0 (v = T exactly): SMOOTHSTEP_KNEE
 * keeps it (contribution [v >= T]), QUADRATIC_KNEE, HARD_LUMINANCE and PER_CHANNEL give 0.
 * Negative input never emits light: the bright part of a negative pixel is 0 in every mode but
 * NONE (which is the identity).
 */
double ExpectedBrightPassAtThreshold(int mode, double threshold);
///@}

/// The shared-data path of a hard-case EXR (relative to ../shared/data).
inline std::string NanInfImage()
{
  return "exr/TestImages_BrightRingsNanInf.exr";
}
inline std::string AllHalfValuesImage()
{
  return "exr/TestImages_AllHalfValues.exr";
}
inline std::string WideFloatRangeImage()
{
  return "exr/TestImages_WideFloatRange.exr";
}
}

#endif
