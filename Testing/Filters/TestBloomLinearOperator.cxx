// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// vtkBloomLinearOperator::FindInvariantRange, which the fused CPU chain and vtkBloomPass use to
// run an operator's interior with one set of weights: every row of the range repeats its
// predecessor one period back (moved by Stride inputs, same float32 weights), the range cannot
// be extended at either end, and operators without such a run report none.
#include <vtkBloomKernels.h>
#include <vtkBloomLinearOperator.h>

#include <gtest/gtest.h>

#include <string>

namespace
{
// Row b repeats row a moved by `stride` inputs (brute force, float32 weights).
bool Repeats(const vtkBloomLinearOperator& op, int a, int b, int stride)
{
  if (op.First[b] != op.First[a] + stride)
  {
    return false;
  }
  for (int k = 0; k < op.Width; ++k)
  {
    if (static_cast<float>(op.Weights[static_cast<size_t>(a) * op.Width + k]) !=
      static_cast<float>(op.Weights[static_cast<size_t>(b) * op.Width + k]))
    {
      return false;
    }
  }
  return true;
}

void ExpectMaximalRange(const vtkBloomLinearOperator& op, int period, int stride,
  bool readsPastTheBorders, const std::string& what)
{
  const auto range = op.FindInvariantRange(period, 8);
  ASSERT_LT(range.Begin, range.End) << what;
  EXPECT_EQ(range.Period, period) << what;
  EXPECT_EQ(range.Stride, stride) << what;
  for (int j = range.Begin + period; j < range.End; ++j)
  {
    ASSERT_TRUE(Repeats(op, j - period, j, stride)) << what << " row " << j;
  }
  if (range.Begin > 0)
  {
    EXPECT_FALSE(Repeats(op, range.Begin - 1, range.Begin - 1 + period, stride)) << what;
  }
  if (range.End < op.OutputSize)
  {
    EXPECT_FALSE(Repeats(op, range.End - period, range.End, stride)) << what;
  }
  // Where taps reach past the ends, the clamp is folded into the border rows' weights, so they
  // are not part of the range; an exact 2:1 fetch never leaves the input and is invariant
  // throughout.
  EXPECT_EQ(range.Begin > 0, readsPastTheBorders) << what;
  EXPECT_EQ(range.End < op.OutputSize, readsPastTheBorders) << what;
}
}

TEST(FiltersLinearOperator, InvariantRangeOfConvolutionsAndResamples)
{
  using K = vtkBloomKernels;
  const int clamp = vtkBloomLinearOperator::BORDER_CLAMP;
  const auto blur =
    vtkBloomLinearOperator::Convolve(64, K::SymmetricTaps({ 0.4, 0.2, 0.1 }, 1.5), clamp);
  ExpectMaximalRange(blur, 1, 1, true, "blur");
  const auto down = vtkBloomLinearOperator::Resample(64, 32, K::BilinearTaps(), clamp);
  ExpectMaximalRange(down, 1, 2, false, "2:1 fetch");
  const auto up = vtkBloomLinearOperator::Resample(32, 64, K::TentTaps(), clamp);
  ExpectMaximalRange(up, 2, 1, true, "1:2 tent");
  // The two phases of the 1:2 resample differ: no period-1 run.
  EXPECT_EQ(up.FindInvariantRange(1, 8).Begin, up.FindInvariantRange(1, 8).End);
  // Too few rows, and an odd (non-periodic) resample.
  EXPECT_EQ(blur.FindInvariantRange(1, 65).End, 0);
  const auto odd = vtkBloomLinearOperator::Resample(61, 29, K::BilinearTaps(), clamp);
  for (int period : { 1, 2 })
  {
    const auto r = odd.FindInvariantRange(period, 8);
    EXPECT_EQ(r.Begin, r.End) << "period " << period;
  }
}
