#include "vtkBloomStatistics.h"

#include "vtkBloomKernels.h"
#include "vtkImageBloomThreshold.h"
#include "vtkImageData.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace
{
// Rec. 709 luminance of the pixel at v: RGB for 3-4 components, the value for 1-2.
template <typename T>
double PixelLuminance(const T* v, int nc)
{
  return nc >= 3 ? vtkBloomKernels::LuminanceR * static_cast<double>(v[0]) +
      vtkBloomKernels::LuminanceG * static_cast<double>(v[1]) +
      vtkBloomKernels::LuminanceB * static_cast<double>(v[2])
                 : static_cast<double>(v[0]);
}

// Neumaier (1974) compensated summation: the running error of each addition is kept and added
// back at the end, so a row of a million pixels loses no more than a few ulps.
class CompensatedSum
{
public:
  void Add(double x)
  {
    const double t = this->Sum + x;
    this->Compensation +=
      std::abs(this->Sum) >= std::abs(x) ? (this->Sum - t) + x : (x - t) + this->Sum;
    this->Sum = t;
  }
  double Get() const { return this->Sum + this->Compensation; }

private:
  double Sum = 0.0;
  double Compensation = 0.0;
};

// Pairwise sum of v[begin, end): O(log n) rounding growth, and a fixed order of additions.
double PairwiseSum(const std::vector<double>& v, size_t begin, size_t end)
{
  if (end - begin <= 8)
  {
    double sum = 0.0;
    for (size_t i = begin; i < end; ++i)
    {
      sum += v[i];
    }
    return sum;
  }
  const size_t middle = begin + (end - begin) / 2;
  return PairwiseSum(v, begin, middle) + PairwiseSum(v, middle, end);
}

template <typename T>
void MeasureRow(const T* row, int n, int nc, double& energy, double& peak)
{
  CompensatedSum sum;
  for (int i = 0; i < n; ++i)
  {
    const double lum = PixelLuminance(row + static_cast<size_t>(i) * nc, nc);
    sum.Add(lum);
    if (lum > peak) // false for NaN, which is ignored
    {
      peak = lum;
    }
  }
  energy = sum.Get();
}

template <typename T>
vtkIdType CountRow(
  const T* row, int n, int nc, int mode, double threshold, double knee, double clampLuminance)
{
  const int colours = nc >= 3 ? 3 : 1;
  vtkIdType count = 0;
  for (int i = 0; i < n; ++i)
  {
    double colour[3];
    for (int c = 0; c < colours; ++c)
    {
      colour[c] = static_cast<double>(row[static_cast<size_t>(i) * nc + c]);
    }
    vtkImageBloomThreshold::BrightPass(colour, colours, mode, threshold, knee, clampLuminance);
    bool bright = false;
    for (int c = 0; c < colours; ++c)
    {
      bright = bright || colour[c] > 0.0;
    }
    count += bright ? 1 : 0;
  }
  return count;
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
  std::vector<double> energies(rows);
  std::vector<double> peaks(rows, -std::numeric_limits<double>::infinity());
  ForEachRow(image, extent,
    [&](vtkIdType r, void* row)
    {
      if (isFloat)
      {
        MeasureRow(static_cast<const float*>(row), n, nc, energies[r], peaks[r]);
      }
      else
      {
        MeasureRow(static_cast<const double*>(row), n, nc, energies[r], peaks[r]);
      }
    });
  result.Energy = PairwiseSum(energies, 0, energies.size());
  result.Peak = *std::max_element(peaks.begin(), peaks.end());
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
