// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkBloomPSFSplit
 * @brief   A point-spread function split into a full-resolution core and a coarse tail
 *          (vtkBloomParameters' PSFTailScale), for vtkImageBloom's PSF mode and vtkBloomPass's.
 *
 * For a kernel k of radius R (row-major, (2R + 1)^2 values centred on (R, R)), a tail scale f
 * and a core radius rc < R:
 * - Core = k w, w(r) = 1 for r <= rc / 2, (1 + cos(pi (r - rc / 2) / (rc / 2))) / 2 up to rc,
 *   0 beyond (r the offset's length); radius rc.
 * - Tail, on the coarse grid: K(J) = t(f J) - Laplacian(t(f .))(J) / 6 with t = k (1 - w),
 *   |J| <= R / f, then scaled so that f^2 sum K = sum t. The two interpolations below each
 *   spread the tail by a tent of variance about 1/6 of a coarse cell (squared) per axis; less
 *   (1/3) / 2 of the Laplacian undoes that to second order.
 *
 * The coarse grid of an image n pixels wide has CoarseSize(n, f) = ceil(n / f) nodes per axis;
 * node j sits at the centre of pixels [f j, f j + f). Pixel i reads (and is spread onto) the
 * nodes around u = (i + 1/2) / f - 1/2, clamped to [0, nodes - 1], by the tent weights
 * (TentWeights). bloom = core * b + Up(Tail * Down(b)): Down spreads each pixel onto its nodes
 * (the transpose of Up, so it keeps the sum and the centroid), Up interpolates bilinearly.
 * With rc >= R there is no tail and the core is k: the exact convolution.
 */

#ifndef vtkBloomPSFSplit_h
#define vtkBloomPSFSplit_h

#include "vtkFiltersBloomModule.h" // For export macro

#include <vector>

class VTKFILTERSBLOOM_EXPORT vtkBloomPSFSplit
{
public:
  /// A kernel: (2 Radius + 1)^2 values, row-major, centred on (Radius, Radius).
  struct Kernel
  {
    int Radius = 0;
    std::vector<double> Values;
  };

  int Scale = 1;
  Kernel Core; ///< k w, full resolution
  Kernel Tail; ///< on the coarse grid; no values where there is no tail

  bool HasTail() const { return !this->Tail.Values.empty(); }

  /// What the coarse grid's convolution takes: the tail, or a zero kernel for a PSF with none
  /// (the other channels may have one).
  Kernel GridKernel() const { return this->HasTail() ? this->Tail : Kernel{ 0, { 0.0 } }; }

  /// The split of `kernel` at tail scale `scale` (>= 2) and core radius `coreRadius` (>= 1).
  static vtkBloomPSFSplit Make(const Kernel& kernel, int scale, int coreRadius);

  /// Nodes of the coarse grid along an axis of n pixels: ceil(n / scale).
  static int CoarseSize(int n, int scale) { return (n + scale - 1) / scale; }

  /**
   * Pixel i of an axis with `nodes` coarse nodes reads nodes j0 (weight 1 - t) and j1 (weight
   * t): u = (i + 1/2) / scale - 1/2 clamped to [0, nodes - 1], j0 = floor(u),
   * j1 = min(j0 + 1, nodes - 1), t = u - j0. The pass's shaders compute the same.
   */
  static void TentWeights(int i, int scale, int nodes, int& j0, int& j1, double& t);

  /**
   * `coarse` (CoarseSize(width) x CoarseSize(height), nc components, overwritten) = `image`
   * (width x height, nc interleaved components) spread onto the nodes.
   */
  static void Down(const double* image, int width, int height, int nc, int scale, double* coarse);

  /// `image` += `coarse` (the coarse grid of `image`, as Down makes it) interpolated bilinearly.
  static void AddUp(const double* coarse, int width, int height, int nc, int scale, double* image);
};

#endif
// VTK-HeaderTest-Exclude: vtkBloomPSFSplit.h
