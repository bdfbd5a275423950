// The median of a benchmark's samples (the mean of the middle two for an even count; 0 for
// none), shared by the CPU and GPU benchmark executables.
#ifndef vtkBloomMedian_h
#define vtkBloomMedian_h

#include <algorithm>
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

#endif
