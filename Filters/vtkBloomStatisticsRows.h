// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file    vtkBloomStatisticsRows.h
 * @brief   Internal: vtkImageBloom's statistics gathered in the rows the fast chain composites.
 *
 * Not installed and not part of the public API. The same values as vtkBloomMeasureLuminance
 * and vtkBloomCountBrightPixels over the same rows, bit for bit, measured while the fast
 * chain's composite has the rows in the cache instead of in passes of their own over the
 * frame (vtkBloomFastChain). Float pixels only. Each row is measured four pixels at a time in
 * vector lanes (GCC vector types, compiled for AVX2 too where the compiler clones functions):
 * first the luminances and largest colour values, their extremes and whether all are finite,
 * in one loop; then the bright count, only when the bright pass's zero test cannot rule out
 * the row's largest values, as brightness * factor > 0 (vtkBloomBrightPassFactor), exact
 * because the factor is never negative and rounding is monotone, with the colours that are not
 * finite or above the firefly clamp sent through vtkBloomBrightPass itself; and the
 * luminances' exact sum (vtkBloomExactSum::AddRow, bounded by the extremes). A row the
 * composite copied from the input is measured once, for both.
 */

#ifndef vtkBloomStatisticsRows_h
#define vtkBloomStatisticsRows_h

#include "vtkBloomExactSum.h"
#include "vtkBloomStatistics.h"
#include "vtkType.h"

#include <limits>
#include <vector>

/// One per thread, merged at the end: exact sums do not depend on how the rows were shared out.
class vtkBloomStatisticsRows
{
public:
  vtkBloomStatisticsRows() = default; // for vtkSMPThreadLocal; use the one below
  vtkBloomStatisticsRows(int mode, double threshold, double knee, double clampLuminance);

  /**
   * One row of n input pixels of nc components, and the output row written from it, which
   * differs from the input only in pixels [begin, end) (elsewhere it is the input bit for bit,
   * and measured once for both); a null `output` is the input row throughout.
   */
  void AddRow(const float* input, const float* output, int n, int nc, int begin, int end);

  /// Add the rows another instance has seen.
  void Merge(const vtkBloomStatisticsRows& other);

  vtkBloomLuminanceStatistics In() const;
  vtkBloomLuminanceStatistics Out() const;
  vtkIdType BrightPixels() const { return this->Bright; }

private:
  int Mode = 0;
  double Threshold = 0.0, Knee = 0.0, ClampLuminance = 0.0;
  vtkBloomExactSum EnergyIn, EnergyOut;
  double PeakIn = -std::numeric_limits<double>::infinity();
  double PeakOut = -std::numeric_limits<double>::infinity();
  vtkIdType Bright = 0;
  std::vector<double> Luminance, Brightness; ///< a row's L and largest colour values
};

#endif
// VTK-HeaderTest-Exclude: vtkBloomStatisticsRows.h
