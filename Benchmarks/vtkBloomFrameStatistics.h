// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// The statistics of a benchmark's samples, shared by the CPU and GPU benchmark executables: the
// median (the mean of the middle two for an even count; 0 for none), and the mean, the 99th
// percentile and the maximum beside it, since a median alone hides a stutter.
#ifndef vtkBloomFrameStatistics_h
#define vtkBloomFrameStatistics_h

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

inline double vtkBloomMedian(std::vector<double> v)
{
  if (v.empty())
  {
    return 0.0;
  }
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

struct vtkBloomFrameStatistics
{
  double Median = 0.0;
  double Mean = 0.0;
  double P99 = 0.0; ///< the nearest-rank 99th percentile
  double Max = 0.0;

  explicit vtkBloomFrameStatistics(std::vector<double> v)
  {
    if (v.empty())
    {
      return;
    }
    this->Median = vtkBloomMedian(v);
    std::sort(v.begin(), v.end());
    this->Mean = std::accumulate(v.begin(), v.end(), 0.0) / v.size();
    const size_t rank = static_cast<size_t>(std::ceil(0.99 * v.size()));
    this->P99 = v[std::min(v.size(), std::max<size_t>(rank, 1)) - 1];
    this->Max = v.back();
  }
};

#endif
