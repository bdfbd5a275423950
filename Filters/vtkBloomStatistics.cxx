// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkBloomStatistics.h"

#include "vtkBloomBrightPass.h"
#include "vtkBloomExactSum.h"
#include "vtkBloomKernels.h"
#include "vtkImageBloomThreshold.h"
#include "vtkImageData.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

namespace
{
// Rec. 709 luminance of the pixel at v: RGB for 3-4 components, the value for 1-2.
template <typename T>
double PixelLuminance(const T* v, int nc)
{
  return nc >= 3 ? vtkBloomKernels::Luminance(static_cast<double>(v[0]), static_cast<double>(v[1]),
                     static_cast<double>(v[2]))
                 : static_cast<double>(v[0]);
}

// L of the n pixels of a row (nc components) into `out`, and `peak` raised to their maximum
// (NaN is ignored). The component count is a constant in each loop, so the loops vectorize.
template <int NC, typename T>
void RowLuminances(const T* __restrict row, int n, double* __restrict out, double& peak)
{
  double p = peak;
  for (int i = 0; i < n; ++i)
  {
    const double l = PixelLuminance(row + static_cast<size_t>(i) * NC, NC);
    out[i] = l;
    p = l > p ? l : p;
  }
  peak = p;
}

template <typename T>
void RowLuminances(const T* row, int n, int nc, double* out, double& peak)
{
  switch (nc)
  {
    case 1:
      RowLuminances<1>(row, n, out, peak);
      break;
    case 2:
      RowLuminances<2>(row, n, out, peak);
      break;
    case 3:
      RowLuminances<3>(row, n, out, peak);
      break;
    default:
      RowLuminances<4>(row, n, out, peak);
      break;
  }
}

// Add a row's luminances to `energy` and raise `peak` to their maximum; `scratch` holds them.
template <typename T>
void MeasureRow(
  const T* row, int n, int nc, vtkBloomExactSum& energy, double& peak, std::vector<double>& scratch)
{
  scratch.resize(static_cast<size_t>(n));
  RowLuminances(row, n, nc, scratch.data(), peak);
  energy.AddRow(scratch.data(), n);
}

template <int Colours, int Mode, typename T>
vtkIdType CountRow(
  const T* row, int n, int nc, double threshold, double knee, double clampLuminance)
{
  vtkIdType count = 0;
  for (int i = 0; i < n; ++i)
  {
    double colour[Colours];
    for (int c = 0; c < Colours; ++c)
    {
      colour[c] = static_cast<double>(row[static_cast<size_t>(i) * nc + c]);
    }
    // Most pixels of an image are below the threshold's zero edge, which is decided without
    // the formula (vtkBloomBrightPassIsZero answers true only where the formula gives zero;
    // with the mode a constant, it is a few comparisons).
    if (vtkBloomBrightPassIsZero<Colours>(colour, Mode, threshold, knee, clampLuminance))
    {
      continue;
    }
    count +=
      vtkBloomBrightPassKeepsAny<Colours>(colour, Mode, threshold, knee, clampLuminance) ? 1 : 0;
  }
  return count;
}

template <int Colours, typename T>
vtkIdType CountRow(
  const T* row, int n, int nc, int mode, double threshold, double knee, double clampLuminance)
{
  return vtkBloomWithThresholdMode(mode,
    [&](auto m)
    { return CountRow<Colours, decltype(m)::value>(row, n, nc, threshold, knee, clampLuminance); });
}

template <typename T>
vtkIdType CountRow(
  const T* row, int n, int nc, int mode, double threshold, double knee, double clampLuminance)
{
  return nc >= 3 ? CountRow<3>(row, n, nc, mode, threshold, knee, clampLuminance)
                 : CountRow<1>(row, n, nc, mode, threshold, knee, clampLuminance);
}

// Call f(row index, pointer to the first pixel of row (j, k)) for every row of the extent, in
// parallel; f must only write to its own row's slot.
template <typename F>
void ForEachRow(vtkImageData* image, const int extent[6], F&& f)
{
  const int rowsPerSlice = extent[3] - extent[2] + 1;
  const vtkIdType rows = static_cast<vtkIdType>(rowsPerSlice) * (extent[5] - extent[4] + 1);
  vtkSMPTools::For(0, rows,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType r = begin; r < end; ++r)
      {
        const int j = extent[2] + static_cast<int>(r % rowsPerSlice);
        const int k = extent[4] + static_cast<int>(r / rowsPerSlice);
        f(r, image->GetScalarPointer(extent[0], j, k));
      }
    });
}

vtkIdType NumberOfRows(const int extent[6])
{
  if (extent[1] < extent[0] || extent[3] < extent[2] || extent[5] < extent[4])
  {
    return 0;
  }
  return static_cast<vtkIdType>(extent[3] - extent[2] + 1) * (extent[5] - extent[4] + 1);
}
}

//------------------------------------------------------------------------------
vtkBloomLuminanceStatistics vtkBloomMeasureLuminance(vtkImageData* image, const int extent[6])
{
  vtkBloomLuminanceStatistics result;
  const vtkIdType rows = NumberOfRows(extent);
  if (rows == 0)
  {
    return result;
  }
  const int n = extent[1] - extent[0] + 1;
  const int nc = image->GetNumberOfScalarComponents();
  const bool isFloat = image->GetScalarType() == VTK_FLOAT;
  // One exact sum per thread: exact sums do not depend on how the rows are shared out.
  vtkSMPThreadLocal<vtkBloomExactSum> energies;
  vtkSMPThreadLocal<double> peaks(-std::numeric_limits<double>::infinity());
  vtkSMPThreadLocal<std::vector<double>> scratch;
  ForEachRow(image, extent,
    [&](vtkIdType, void* row)
    {
      if (isFloat)
      {
        MeasureRow(
          static_cast<const float*>(row), n, nc, energies.Local(), peaks.Local(), scratch.Local());
      }
      else
      {
        MeasureRow(
          static_cast<const double*>(row), n, nc, energies.Local(), peaks.Local(), scratch.Local());
      }
    });
  vtkBloomExactSum total;
  for (const vtkBloomExactSum& energy : energies)
  {
    total.Add(energy);
  }
  result.Energy = total.Get();
  result.Peak = -std::numeric_limits<double>::infinity();
  for (double peak : peaks)
  {
    result.Peak = std::max(result.Peak, peak);
  }
  return result;
}

//------------------------------------------------------------------------------
vtkIdType vtkBloomCountBrightPixels(vtkImageData* image, const int extent[6], int mode,
  double threshold, double knee, double clampLuminance)
{
  const vtkIdType rows = NumberOfRows(extent);
  if (rows == 0)
  {
    return 0;
  }
  const int n = extent[1] - extent[0] + 1;
  const int nc = image->GetNumberOfScalarComponents();
  const bool isFloat = image->GetScalarType() == VTK_FLOAT;
  std::vector<vtkIdType> counts(rows, 0);
  ForEachRow(image, extent,
    [&](vtkIdType r, void* row)
    {
      counts[r] = isFloat
        ? CountRow(static_cast<const float*>(row), n, nc, mode, threshold, knee, clampLuminance)
        : CountRow(static_cast<const double*>(row), n, nc, mode, threshold, knee, clampLuminance);
    });
  vtkIdType total = 0;
  for (vtkIdType c : counts)
  {
    total += c;
  }
  return total;
}
