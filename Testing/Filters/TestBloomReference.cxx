// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// Sanity checks of the float64 reference itself (vtkBloomReference), against closed forms
// stated in ../shared/seeds/PRESETS.md and against independent evaluations. If the reference
// were wrong, every comparison of a filter against it would be meaningless.
#include "vtkBloomReference.h"
#include "vtkBloomTestSupport.h"

#include <vtkImageData.h>
#include <vtkType.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace vtkBloomRef;

namespace
{
Texture Constant(int w, int h, const Pixel& p)
{
  Texture t(w, h);
  for (Pixel& q : t.Texels)
  {
    q = p;
  }
  return t;
}
}

// PRESETS.md: "a constant 0.5 input becomes 0.607421875" for webgpu-market.
TEST(FiltersReference, WebGPUMarketConstantHalf)
{
  for (const auto& size : { std::make_pair(1, 1), std::make_pair(17, 9), std::make_pair(40, 33) })
  {
    const Texture out = WebGPUMarket(Constant(size.first, size.second, { 0.5, 0.5, 0.5, 0.3 }));
    for (const Pixel& p : out.Texels)
    {
      EXPECT_NEAR(p[0], 0.607421875, 1e-9);
      EXPECT_NEAR(p[2], 0.607421875, 1e-9);
      EXPECT_EQ(p[3], 0.3);
    }
  }
}

// PRESETS.md: mip-atlas turns a constant c into 0.88768 c once all of LODs 2..8 exist
// (max(W, H) >= 256), and into 0.48 c when none does (max(W, H) < 4).
TEST(FiltersReference, MipAtlasConstant)
{
  const Texture full = MipAtlas(Constant(256, 3, { 2.0, 1.0, 4.0, 1.0 }));
  for (const Pixel& p : full.Texels)
  {
    EXPECT_NEAR(p[0], 0.88768 * 2.0, 1e-12);
    EXPECT_NEAR(p[2], 0.88768 * 4.0, 1e-12);
  }
  const Texture small = MipAtlas(Constant(3, 2, { 2.0, 1.0, 4.0, 1.0 }));
  for (const Pixel& p : small.Texels)
  {
    EXPECT_NEAR(p[1], 0.48, 1e-15);
  }
}

// A ping-pong pass preserves a constant above the threshold (normalized weights), and a
// constant below it gets no bloom at all.
TEST(FiltersReference, PingPongAndCrtConstants)
{
  const Texture bright = PingPong(Constant(6, 5, { 2.0, 2.0, 2.0, 1.0 }));
  EXPECT_NEAR(bright.At(3, 2)[0], 4.0, 1e-12);
  const Texture dim = PingPong(Constant(6, 5, { 1.0, 1.0, 1.0, 1.0 })); // lum > 1 is strict
  EXPECT_NEAR(dim.At(3, 2)[0], 1.0, 1e-15);
  // crt-halfres: c + 1.5 max(c - 0.8, 0).
  const Texture crt = CrtHalfres(Constant(7, 4, { 1.8, 0.5, 0.8, 1.0 }));
  EXPECT_NEAR(crt.At(2, 3)[0], 1.8 + 1.5, 1e-12);
  EXPECT_NEAR(crt.At(2, 3)[1], 0.5, 1e-15);
  EXPECT_NEAR(crt.At(2, 3)[2], 0.8, 1e-15);
}

// e^{-t} I_n(t) by power series against the standard library's Bessel function.
TEST(FiltersReference, DiscreteGaussianMatchesBessel)
{
  for (double t : { 0.09, 1.0, 6.25, 49.0 })
  {
    for (int n = 0; n <= 12; ++n)
    {
      const double expected = std::exp(-t) * std::cyl_bessel_i(static_cast<double>(n), t);
      EXPECT_NEAR(DiscreteGaussianWeight(n, t), expected, 1e-12 * std::max(expected, 1e-300))
        << "t = " << t << ", n = " << n;
    }
  }
  // Its full sum is 1 and its variance is t, exactly (untruncated).
  const double t = 2.5 * 2.5;
  double sum = 0.0, variance = 0.0;
  for (int n = -80; n <= 80; ++n)
  {
    sum += DiscreteGaussianWeight(n, t);
    variance += n * n * DiscreteGaussianWeight(n, t);
  }
  EXPECT_NEAR(sum, 1.0, 1e-13);
  EXPECT_NEAR(variance, t, 1e-11);
}

// The three Gaussian kinds are normalized and symmetric, and differ as the theory says.
TEST(FiltersReference, GaussianKernels)
{
  for (GaussianKind kind : { SAMPLED, INTEGRATED, DISCRETE })
  {
    const std::vector<double> k = GaussianKernel(1.3, 6, kind);
    ASSERT_EQ(k.size(), 13u);
    double sum = 0.0;
    for (size_t i = 0; i < k.size(); ++i)
    {
      sum += k[i];
      EXPECT_DOUBLE_EQ(k[i], k[k.size() - 1 - i]);
    }
    EXPECT_NEAR(sum, 1.0, 1e-15);
  }
  // The integrated kernel's centre tap is the mass of [-1/2, 1/2] (before renormalization).
  const std::vector<double> wide = GaussianKernel(0.8, 40, INTEGRATED);
  EXPECT_NEAR(wide[40], std::erf(0.5 / (0.8 * std::sqrt(2.0))), 1e-15);
  EXPECT_EQ(GaussianKernel(0.0, 5, SAMPLED).size(), 1u);
}

// Half-sample symmetric reflection: d c b a | a b c d | d c b a, periodic with period 2n.
TEST(FiltersReference, ReflectFold)
{
  const int expected[16] = { 3, 2, 1, 0, 0, 1, 2, 3, 3, 2, 1, 0, 0, 1, 2, 3 };
  for (int i = -4; i < 12; ++i)
  {
    EXPECT_EQ(FoldIndex(i, 4, REFLECT), expected[i + 4]) << i;
  }
  EXPECT_EQ(FoldIndex(-9, 4, CLAMP), 0);
  EXPECT_EQ(FoldIndex(9, 4, CLAMP), 3);
  EXPECT_EQ(FoldIndex(4, 4, ZERO), -1);
}

// Bilinear sampling: exact at texel centres, halfway in between, clamped outside.
TEST(FiltersReference, BilinearAndGeometry)
{
  Texture t(3, 1);
  t.At(0, 0) = { 0.0, 0.0, 0.0, 0.0 };
  t.At(1, 0) = { 1.0, 0.0, 0.0, 0.0 };
  t.At(2, 0) = { 4.0, 0.0, 0.0, 0.0 };
  EXPECT_DOUBLE_EQ(t.Bilinear(1.5 / 3, 0.5)[0], 1.0);
  EXPECT_DOUBLE_EQ(t.Bilinear(2.0 / 3, 0.5)[0], 2.5);
  EXPECT_DOUBLE_EQ(t.Bilinear(-1.0, 0.5)[0], 0.0);
  EXPECT_DOUBLE_EQ(t.Bilinear(2.0, 0.5)[0], 4.0);
  EXPECT_EQ(HalfSize(1), 1);
  EXPECT_EQ(HalfSize(3), 1);
  EXPECT_EQ(HalfSize(67), 33);
  // The 3 -> 1 area resample is the mean; the 13-tap of a 3-pixel row is 1/4 1/2 1/4 around
  // the centre plus the inner pair.
  EXPECT_DOUBLE_EQ(AreaResample(t, 1, 1).At(0, 0)[0], 5.0 / 3.0);
  // 13-tap at p = 1 on a 1-pixel-high row: 1/2 (pair at +-1/2) + 1/2 (tent 1/4 1/2 1/4).
  const double pair = 0.5 * (0.5 * 0.0 + 0.5 * 1.0) + 0.5 * (0.5 * 1.0 + 0.5 * 4.0);
  const double tent = 0.25 * 0.0 + 0.5 * 1.0 + 0.25 * 4.0;
  EXPECT_NEAR(Downsample13(t).At(0, 0)[0], 0.5 * pair + 0.5 * tent, 1e-15);
}

// The synthetic images are float-representable and deterministic.
TEST(FiltersReference, SyntheticImages)
{
  const Texture a = SyntheticScene(33, 20, 5);
  const Texture b = SyntheticScene(33, 20, 5);
  double peak = 0.0;
  for (size_t t = 0; t < a.Texels.size(); ++t)
  {
    for (int c = 0; c < 4; ++c)
    {
      EXPECT_EQ(a.Texels[t][c], b.Texels[t][c]);
      EXPECT_EQ(a.Texels[t][c], static_cast<double>(static_cast<float>(a.Texels[t][c])));
      peak = std::max(peak, a.Texels[t][c]);
    }
  }
  EXPECT_GT(peak, 2.0 * 0.3);
  EXPECT_LE(peak, 200.0);
}

//------------------------------------------------------------------------------
// The comparison helpers every suite bounds: images that cannot be compared give NaN, which
// fails every bound, rather than 0 (an empty first image) or a read past the second.
TEST(FiltersReference, ComparisonsRefuseImagesOfAnotherShape)
{
  const int large[6] = { 0, 9, 0, 7, 0, 0 }, small[6] = { 0, 4, 0, 7, 0, 0 };
  const int none[6] = { 0, -1, 0, -1, 0, 0 };
  auto colour = [](int i, int j, int, int c) { return 0.1 * (i + 2 * j + c); };
  auto a = vtkBloomTest::MakeImage(large, 3, VTK_FLOAT, colour);
  auto b = vtkBloomTest::MakeImage(large, 3, VTK_FLOAT, colour);
  auto narrower = vtkBloomTest::MakeImage(small, 3, VTK_FLOAT, colour);
  auto empty = vtkBloomTest::MakeImage(none, 3, VTK_FLOAT, colour);
  auto grey = vtkBloomTest::MakeImage(large, 1, VTK_FLOAT, colour);
  EXPECT_EQ(vtkBloomTest::ColourRelativeL2(a, b), 0.0);
  EXPECT_EQ(vtkBloomTest::BloomRelativeL2(a, a, b), 0.0);
  for (vtkImageData* other : { narrower.Get(), empty.Get(), grey.Get() })
  {
    EXPECT_TRUE(std::isnan(vtkBloomTest::ColourRelativeL2(a, other)));
    EXPECT_TRUE(std::isnan(vtkBloomTest::ColourRelativeL2(other, a)));
    EXPECT_TRUE(std::isnan(vtkBloomTest::BloomRelativeL2(a, a, other)));
    EXPECT_TRUE(std::isnan(vtkBloomTest::BloomRelativeL2(other, a, b)));
    EXPECT_TRUE(std::isnan(vtkBloomTest::RelativeL2(a, other)));
    EXPECT_TRUE(std::isnan(vtkBloomTest::MaxAbsDifference(a, other)));
  }
  EXPECT_TRUE(std::isnan(vtkBloomTest::ColourRelativeL2(empty, empty)));
}
