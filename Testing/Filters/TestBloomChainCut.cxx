// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// vtkBloomChain::Cut and GetInputRange, the chain of a tile with its guard band (issue 36,
// part 2): the frame's chain cut to a part of the frame, evaluated on that part of the input,
// gives the frame's bloom on the tile to double rounding wherever the part holds every sample
// GetInputRange names, for every preset and both accumulations; the tile alone does not. The
// evaluator here is the chain's definition (vtkBloomChain.h) in double precision on plain arrays,
// written apart from the filters and the render pass.
#include "vtkBloomChain.h"
#include "vtkBloomParameters.h"
#include "vtkNew.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace
{
// A single-channel image, row-major, row 0 first.
struct Image
{
  int W = 0;
  int H = 0;
  std::vector<double> V;
  double& At(int i, int j) { return this->V[static_cast<size_t>(j) * this->W + i]; }
  double At(int i, int j) const { return this->V[static_cast<size_t>(j) * this->W + i]; }
};

// out = Weight * Y X in (the separable term of a step).
Image Apply(const vtkBloomChain::Term& t, const Image& in)
{
  Image mid{ t.X.OutputSize, in.H,
    std::vector<double>(static_cast<size_t>(t.X.OutputSize) * in.H) };
  for (int j = 0; j < in.H; ++j)
  {
    for (int i = 0; i < t.X.OutputSize; ++i)
    {
      double sum = 0.0;
      for (int k = 0; k < t.X.Width; ++k)
      {
        sum += t.X.Weights[static_cast<size_t>(i) * t.X.Width + k] * in.At(t.X.First[i] + k, j);
      }
      mid.At(i, j) = sum;
    }
  }
  Image out{ mid.W, t.Y.OutputSize,
    std::vector<double>(static_cast<size_t>(mid.W) * t.Y.OutputSize) };
  for (int j = 0; j < t.Y.OutputSize; ++j)
  {
    for (int i = 0; i < mid.W; ++i)
    {
      double sum = 0.0;
      for (int k = 0; k < t.Y.Width; ++k)
      {
        sum += t.Y.Weights[static_cast<size_t>(j) * t.Y.Width + k] * mid.At(i, t.Y.First[j] + k);
      }
      out.At(i, j) = t.Weight * sum;
    }
  }
  return out;
}

void Add(Image& a, const Image& b, double w = 1.0)
{
  for (size_t k = 0; k < a.V.size(); ++k)
  {
    a.V[k] += w * b.V[k];
  }
}

// The chain's linear part on an already thresholded image (no Karis average: it is not
// linear, and the presets that use it are run without it here).
Image Bloom(const vtkBloomChain& c, const Image& bright)
{
  const size_t n = c.Levels.size();
  std::vector<Image> level(n), blurred(n);
  level[0] = c.SourceIsIdentity ? bright : Apply(c.Source, bright);
  for (size_t i = 1; i < n; ++i)
  {
    level[i] = Apply(c.Levels[i].Down[0], level[i - 1]);
    for (size_t t = 1; t < c.Levels[i].Down.size(); ++t)
    {
      Add(level[i], Apply(c.Levels[i].Down[t], level[i - 1]));
    }
  }
  for (size_t i = 0; i < n; ++i)
  {
    blurred[i] = c.Levels[i].Blur ? Apply(c.Levels[i].BlurPass, level[i]) : level[i];
  }
  Image out{ c.Width, c.Height, std::vector<double>(static_cast<size_t>(c.Width) * c.Height) };
  if (c.AccumulateMode == vtkBloomParameters::DIRECT)
  {
    for (size_t i = 0; i < n; ++i)
    {
      if (c.Levels[i].Weight != 0.0)
      {
        Add(out, Apply(c.Levels[i].Full, blurred[i]), c.Levels[i].Weight);
      }
    }
    return out;
  }
  Image accum = blurred[n - 1];
  for (double& v : accum.V)
  {
    v *= c.Levels[n - 1].Weight;
  }
  for (size_t i = n - 1; i-- > 0;)
  {
    Image up = Apply(c.Levels[i].Up, accum);
    Add(up, blurred[i], c.Levels[i].Weight);
    accum = up;
  }
  return c.FinalIsIdentity ? accum : Apply(c.Final, accum);
}

Image Crop(const Image& in, const int begin[2], const int end[2])
{
  Image out{ end[0] - begin[0], end[1] - begin[1], {} };
  out.V.resize(static_cast<size_t>(out.W) * out.H);
  for (int j = 0; j < out.H; ++j)
  {
    for (int i = 0; i < out.W; ++i)
    {
      out.At(i, j) = in.At(begin[0] + i, begin[1] + j);
    }
  }
  return out;
}

// The largest difference between the frame's bloom and the part's on the tile [t0, t1).
double TileError(const vtkBloomChain& frame, const Image& input, const Image& whole,
  const int t0[2], const int t1[2], const int begin[2], const int end[2])
{
  vtkBloomChain part;
  part.Cut(frame, begin, end);
  const Image bloom = Bloom(part, Crop(input, begin, end));
  double worst = 0.0;
  for (int j = t0[1]; j < t1[1]; ++j)
  {
    for (int i = t0[0]; i < t1[0]; ++i)
    {
      worst = std::max(worst, std::abs(bloom.At(i - begin[0], j - begin[1]) - whole.At(i, j)));
    }
  }
  return worst;
}
}

//------------------------------------------------------------------------------
TEST(FiltersBloomChainCut, ATilesChainIsTheFramesWhereItsPartHoldsWhatItReads)
{
  std::mt19937 random(7);
  std::uniform_real_distribution<double> value(0.0, 4.0);
  for (const std::string& preset : vtkBloomParameters::GetPresetNames())
  {
    for (int mode : { vtkBloomParameters::CASCADE, vtkBloomParameters::DIRECT })
    {
      SCOPED_TRACE(preset + (mode == vtkBloomParameters::DIRECT ? " direct" : " cascade"));
      vtkNew<vtkBloomParameters> p;
      ASSERT_TRUE(p->SetPreset(preset.c_str()));
      p->SetAccumulateMode(mode);
      p->SetKarisAverage(false);
      const int W = 203, H = 141; // odd sizes: the levels' resamples are not exact halvings
      vtkBloomChain frame;
      frame.Build(p, W, H);
      Image input{ W, H, std::vector<double>(static_cast<size_t>(W) * H) };
      for (double& v : input.V)
      {
        v = value(random) * (value(random) > 3.6 ? 1.0 : 0.0); // sparse bright samples
      }
      const Image whole = Bloom(frame, input);
      // An inner tile and a corner tile of a 4 x 3 tiling.
      for (const auto& tile : { std::vector<int>{ 51, 47, 102, 94 }, { 153, 94, 203, 141 } })
      {
        const int t0[2] = { tile[0], tile[1] }, t1[2] = { tile[2], tile[3] };
        int begin[2], end[2];
        for (int a = 0; a < 2; ++a)
        {
          frame.GetInputRange(a, t0[a], t1[a] - 1, begin[a], end[a]);
          ++end[a];
          EXPECT_LE(begin[a], t0[a]);
          EXPECT_GE(end[a], t1[a]);
        }
        EXPECT_LT(TileError(frame, input, whole, t0, t1, begin, end), 1e-12);
        // Without the band (the tile alone) the tile's bloom is not the frame's.
        EXPECT_GT(TileError(frame, input, whole, t0, t1, t0, t1), 1e-6);
      }
    }
  }
}

//------------------------------------------------------------------------------
TEST(FiltersBloomChainCut, TheInputRangeOfTheWholeFrameIsTheFrame)
{
  vtkNew<vtkBloomParameters> p;
  vtkBloomChain frame;
  frame.Build(p, 320, 240);
  int lo, hi;
  frame.GetInputRange(0, 0, 319, lo, hi);
  EXPECT_EQ(lo, 0);
  EXPECT_EQ(hi, 319);
  // One sample in the middle reads a band around it, wider than the blur's first level.
  frame.GetInputRange(1, 120, 120, lo, hi);
  EXPECT_LT(lo, 110);
  EXPECT_GT(hi, 130);
}
