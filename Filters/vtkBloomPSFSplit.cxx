// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// A PSF split into a full-resolution core and a coarse tail (see vtkBloomPSFSplit.h).
#include "vtkBloomPSFSplit.h"

#include "vtkMath.h"

#include <algorithm>
#include <cmath>

namespace
{
// The core's window: 1 up to half the core radius, a raised cosine down to 0 at the radius.
double CoreWindow(double r, double coreRadius)
{
  const double half = 0.5 * coreRadius;
  if (r <= half)
  {
    return 1.0;
  }
  if (r >= coreRadius)
  {
    return 0.0;
  }
  return 0.5 + 0.5 * std::cos(vtkMath::Pi() * (r - half) / half);
}

// Every pixel's tent weights along an axis of n pixels and `nodes` nodes.
struct AxisTents
{
  std::vector<int> J0, J1;
  std::vector<double> T;
  AxisTents(int n, int scale, int nodes)
    : J0(n)
    , J1(n)
    , T(n)
  {
    for (int i = 0; i < n; ++i)
    {
      vtkBloomPSFSplit::TentWeights(i, scale, nodes, this->J0[i], this->J1[i], this->T[i]);
    }
  }
};
}

//------------------------------------------------------------------------------
vtkBloomPSFSplit vtkBloomPSFSplit::Make(const Kernel& kernel, int scale, int coreRadius)
{
  vtkBloomPSFSplit split;
  split.Scale = scale;
  const int r = kernel.Radius, n = 2 * r + 1;
  if (coreRadius >= r)
  {
    split.Core = kernel;
    return split;
  }
  // The core, radius rc, and the tail t = k (1 - w) over the whole kernel.
  const int rc = coreRadius, nc = 2 * rc + 1;
  split.Core.Radius = rc;
  split.Core.Values.assign(static_cast<size_t>(nc) * nc, 0.0);
  std::vector<double> tail(kernel.Values);
  double tailSum = 0.0;
  for (int y = -r; y <= r; ++y)
  {
    for (int x = -r; x <= r; ++x)
    {
      const size_t at = static_cast<size_t>(y + r) * n + (x + r);
      const double w = CoreWindow(std::hypot(x, y), rc);
      if (w > 0.0)
      {
        split.Core.Values[static_cast<size_t>(y + rc) * nc + (x + rc)] = kernel.Values[at] * w;
      }
      tail[at] = kernel.Values[at] * (1.0 - w);
      tailSum += tail[at];
    }
  }
  // Sampled every `scale` pixels, less a sixth of the samples' Laplacian, scaled to the share.
  const int rt = r / scale, nt = 2 * rt + 1;
  const auto sample = [&](int jx, int jy)
  {
    if (std::abs(jx) > rt || std::abs(jy) > rt)
    {
      return 0.0;
    }
    return tail[static_cast<size_t>(jy * scale + r) * n + (jx * scale + r)];
  };
  split.Tail.Radius = rt;
  split.Tail.Values.resize(static_cast<size_t>(nt) * nt);
  double sum = 0.0;
  for (int jy = -rt; jy <= rt; ++jy)
  {
    for (int jx = -rt; jx <= rt; ++jx)
    {
      const double laplacian = sample(jx - 1, jy) + sample(jx + 1, jy) + sample(jx, jy - 1) +
        sample(jx, jy + 1) - 4.0 * sample(jx, jy);
      const double v = sample(jx, jy) - laplacian / 6.0;
      split.Tail.Values[static_cast<size_t>(jy + rt) * nt + (jx + rt)] = v;
      sum += v;
    }
  }
  const double share = sum > 0.0 ? tailSum / (sum * scale * scale) : 0.0;
  for (double& v : split.Tail.Values)
  {
    v *= share;
  }
  return split;
}

//------------------------------------------------------------------------------
void vtkBloomPSFSplit::TentWeights(int i, int scale, int nodes, int& j0, int& j1, double& t)
{
  const double u = std::min(std::max((i + 0.5) / scale - 0.5, 0.0), static_cast<double>(nodes - 1));
  j0 = static_cast<int>(std::floor(u));
  j1 = std::min(j0 + 1, nodes - 1);
  t = u - j0;
}

//------------------------------------------------------------------------------
void vtkBloomPSFSplit::Down(
  const double* image, int width, int height, int nc, int scale, double* coarse)
{
  const int cw = CoarseSize(width, scale), ch = CoarseSize(height, scale);
  std::fill(coarse, coarse + static_cast<size_t>(cw) * ch * nc, 0.0);
  const AxisTents across(width, scale, cw), down(height, scale, ch);
  const std::vector<int>& x0 = across.J0;
  const std::vector<int>& x1 = across.J1;
  const std::vector<double>& tx = across.T;
  for (int y = 0; y < height; ++y)
  {
    const double ty = down.T[y];
    const double* row = image + static_cast<size_t>(y) * width * nc;
    double* r0 = coarse + static_cast<size_t>(down.J0[y]) * cw * nc;
    double* r1 = coarse + static_cast<size_t>(down.J1[y]) * cw * nc;
    for (int x = 0; x < width; ++x)
    {
      for (int c = 0; c < nc; ++c)
      {
        const double v = row[x * nc + c];
        r0[x0[x] * nc + c] += (1 - ty) * (1 - tx[x]) * v;
        r0[x1[x] * nc + c] += (1 - ty) * tx[x] * v;
        r1[x0[x] * nc + c] += ty * (1 - tx[x]) * v;
        r1[x1[x] * nc + c] += ty * tx[x] * v;
      }
    }
  }
}

//------------------------------------------------------------------------------
void vtkBloomPSFSplit::AddUp(
  const double* coarse, int width, int height, int nc, int scale, double* image)
{
  const int cw = CoarseSize(width, scale), ch = CoarseSize(height, scale);
  const AxisTents across(width, scale, cw), down(height, scale, ch);
  const std::vector<int>& x0 = across.J0;
  const std::vector<int>& x1 = across.J1;
  const std::vector<double>& tx = across.T;
  for (int y = 0; y < height; ++y)
  {
    const double ty = down.T[y];
    const double* r0 = coarse + static_cast<size_t>(down.J0[y]) * cw * nc;
    const double* r1 = coarse + static_cast<size_t>(down.J1[y]) * cw * nc;
    double* row = image + static_cast<size_t>(y) * width * nc;
    for (int x = 0; x < width; ++x)
    {
      for (int c = 0; c < nc; ++c)
      {
        const double top = (1 - tx[x]) * r0[x0[x] * nc + c] + tx[x] * r0[x1[x] * nc + c];
        const double bottom = (1 - tx[x]) * r1[x0[x] * nc + c] + tx[x] * r1[x1[x] * nc + c];
        row[x * nc + c] += (1 - ty) * top + ty * bottom;
      }
    }
  }
}
