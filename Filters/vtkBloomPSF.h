// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file    vtkBloomPSF.h
 * @brief   Internal: point-spread functions and their convolution, for vtkImageBloom's PSF mode.
 *
 * Not installed and not part of the public API.
 *
 * A kernel is a (2R + 1) x (2R + 1) image, row-major, centred on (R, R), normalized to sum 1:
 * - Airy: the diffraction pattern of a circular aperture, I(r) = (2 J1(v) / v)^2 with
 *   v = 3.8317 r / r0 (r0 the radius of the first dark ring, in pixels), averaged over each
 *   pixel with 5 x 5 samples.
 * - Gaussians: sum_k w_k exp(-r^2 / (2 s_k^2)) / (2 pi s_k^2), sampled at the pixel centres.
 * - An image: a user's measured PSF, odd width and height, centred, finite and non-negative.
 * Each is truncated to its radius and then normalized, so it sums to 1 whatever the truncation.
 *
 * Convolve scatters every sample of the input through the kernel: the full linear convolution
 * (zero padded, through a two-dimensional real FFT in single precision, threaded by FFTW) is
 * computed and what falls outside the image is folded back in by half-sample reflection
 * (REFLECT) or dropped (ZERO). Folding moves energy without changing it, so with REFLECT the
 * output sums to the input's sum for any kernel that sums to 1 (up to the FFT's rounding, about
 * 1e-7 relative). For a point-symmetric kernel (Airy, Gaussians) the scatter equals the gather
 * convolution over a reflect-extended input. Each channel is scaled by a power of two before
 * its transform so that nothing overflows.
 */

#ifndef vtkBloomPSF_h
#define vtkBloomPSF_h

#include "vtkBloomPSFSplit.h" // For the kernel type

#include <memory>
#include <string>
#include <vector>

class vtkImageData;
struct vtkBloomBuffer;

/// A PSF: (2 Radius + 1)^2 values, row-major (the whole PSF sums to 1; its split parts do not).
using vtkBloomPSFKernel = vtkBloomPSFSplit::Kernel;

/**
 * The convolution of an image size with a set of kernels, prepared once: FFTW's plans and
 * buffers (one two-dimensional transform per distinct kernel radius) and each distinct kernel's
 * spectrum. Convolve then costs one forward and one inverse transform per channel.
 */
class vtkBloomPSFConvolution
{
public:
  vtkBloomPSFConvolution();
  ~vtkBloomPSFConvolution();
  vtkBloomPSFConvolution(const vtkBloomPSFConvolution&) = delete;
  vtkBloomPSFConvolution& operator=(const vtkBloomPSFConvolution&) = delete;

  /// Plan for width x height images and one kernel per channel (the last serves the rest).
  void Prepare(int width, int height, const std::vector<vtkBloomPSFKernel>& kernels);

  /// Whether Prepare was called for this size.
  bool IsPreparedFor(int width, int height) const;

  /**
   * out = each component c of `in` (a 2-D block of the prepared size) scattered through its
   * kernel, with REFLECT (`reflect`) or ZERO borders. `out` takes the shape of `in`.
   */
  void Convolve(const vtkBloomBuffer& in, bool reflect, vtkBloomBuffer& out);

private:
  struct Internals;
  std::unique_ptr<Internals> Impl;
};

/**
 * vtkImageBloom's PSFs and their prepared convolution, kept between updates until a parameter
 * (or the PSF image) or the image size changes.
 */
struct vtkBloomPSFKernels
{
  std::vector<vtkBloomPSFKernel> Kernels; ///< one per colour channel
  unsigned long long Time = 0;            ///< the filter's MTime they were built at
  int Colours = 0;
  /// Split PSFs (PSFTailScale > 1): Convolution takes the cores, TailConvolution the tails on
  /// the coarse grid; TailScale 1 when the PSFs are not split or none has a tail.
  int TailScale = 1;
  vtkBloomPSFConvolution Convolution;
  vtkBloomPSFConvolution TailConvolution;

  /// Split the kernels (scale > 1) or not, and plan the convolutions for width x height.
  void Prepare(int width, int height, int scale, int coreRadius);
  /// bloom = the bright pass `bright` convolved with the kernels (see vtkBloomPSFSplit).
  void Convolve(const vtkBloomBuffer& bright, bool reflect, vtkBloomBuffer& bloom);
};

namespace vtkBloomPSF
{
/// Airy pattern with first dark ring at `firstZero` pixels, truncated at `radius`.
vtkBloomPSFKernel Airy(double firstZero, int radius);

/// Sum of Gaussians (sigma_k, weight_k) in pixels, truncated at `radius`.
vtkBloomPSFKernel Gaussians(
  const std::vector<double>& sigmas, const std::vector<double>& weights, int radius);

/**
 * Component `component` of `image` (clamped to its components) as a kernel. False, with
 * `error` set, for an image that is not a finite, non-negative 2-D float or double image of
 * odd width and height, at most 2 maxRadius + 1 wide, with a positive sum.
 */
bool FromImage(
  vtkImageData* image, int component, int maxRadius, vtkBloomPSFKernel& kernel, std::string& error);

/// Scale the values so that they sum to 1 (false when the sum is not positive and finite).
bool Normalize(vtkBloomPSFKernel& kernel);
}

#endif
// VTK-HeaderTest-Exclude: vtkBloomPSF.h
