// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkBloomLineFilters.h
 * @brief  (private to FiltersBloom) the fast one-dimensional Gaussian filters of
 *         vtkImageSeparableGaussian: a direct convolution with a short kernel, Gwosdek's extended
 *         box cascade, and the recursive (Young - van Vliet) Gaussian with exact border
 *         initialization, each on one line of samples.
 *
 * A line holds `n` samples of `lanes` independent values each, sample-major ([n][lanes]);
 * lanes are components and neighbouring lines, so the inner loops run over contiguous memory
 * and vectorize. `border` is a vtkBloomLinearOperator border mode.
 */
#ifndef vtkBloomLineFilters_h
#define vtkBloomLineFilters_h

#include "vtkBloomKernels.h"

#include <array>
#include <vector>

namespace vtkBloomLineFilters
{
/// Gwosdek's extended box applied `passes` times.
void BoxCascadeLine(double* line, int n, int lanes, int border,
  const vtkBloomKernels::ExtendedBox& box, int passes, std::vector<double>& scratch);

/// A direct convolution with a short symmetric half kernel.
void DirectLine(double* line, int n, int lanes, int border, const std::vector<double>& half,
  std::vector<double>& scratch);

/// The affine map of one period of the recursion, for reflect borders (see RecursiveLine).
using Matrix3 = std::array<std::array<double, 3>, 3>;
Matrix3 PeriodicSteadyState(const vtkBloomKernels::RecursiveGaussian& c, long long period);

/// The recursive Gaussian on one line; `periodic` is PeriodicSteadyState(c, 2 n) for reflect.
void RecursiveLine(double* line, int n, int lanes, int border,
  const vtkBloomKernels::RecursiveGaussian& c, const Matrix3& periodic,
  std::vector<double>& scratch);
}

#endif
// VTK-HeaderTest-Exclude: vtkBloomLineFilters.h
