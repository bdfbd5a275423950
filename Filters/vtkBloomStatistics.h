// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file    vtkBloomStatistics.h
 * @brief   Internal: the luminance statistics vtkImageBloom attaches to its output.
 *
 * Not installed and not part of the public API. L is the Rec. 709 luminance
 * 0.2126 R + 0.7152 G + 0.0722 B for 3-4 components and the value itself for 1-2, evaluated in
 * double on the scalars as stored. The energy is the exact sum of these doubles rounded once to
 * nearest (Neal's small superaccumulator), so it does not depend on the number of threads or
 * the order of the pixels, and cancellation loses nothing.
 */

#ifndef vtkBloomStatistics_h
#define vtkBloomStatistics_h

#include "vtkType.h"

class vtkImageData;

/// Sum and maximum of L over `extent` (structured indices inside the image's extent).
struct vtkBloomLuminanceStatistics
{
  double Energy = 0.0; ///< sum of L, exact then rounded to nearest
  double Peak = 0.0;   ///< max of L, NaN pixels ignored; -inf when every pixel is NaN
};

/// L statistics of the active point scalars of a float or double image over `extent`.
vtkBloomLuminanceStatistics vtkBloomMeasureLuminance(vtkImageData* image, const int extent[6]);

/**
 * The number of pixels in `extent` whose colour (RGB, or the value for 1-2 components) keeps
 * at least one value > 0 through vtkImageBloomThreshold::BrightPass with the given parameters.
 */
vtkIdType vtkBloomCountBrightPixels(vtkImageData* image, const int extent[6], int mode,
  double threshold, double knee, double clampLuminance);

#endif
// VTK-HeaderTest-Exclude: vtkBloomStatistics.h
