// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// vtkImageSeparableGaussian: against direct 2-D and 3-D convolutions of the float64 reference,
// and its documented properties (normalization, variance, identities, symmetry, borders).
#include "vtkBloomReference.h"
#include "vtkBloomTestSupport.h"

#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkExecutive.h>
#include <vtkImageData.h>
#include <vtkImageSeparableGaussian.h>
#include <vtkNew.h>
#include <vtkPointData.h>

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using vtkBloomRef::Texture;

namespace
{
struct Settings
{
  double Sigma[3] = { 2.0, 2.0, 0.0 };
  int Radius[3] = { -1, -1, -1 };
  int Kind = vtkImageSeparableGaussian::SAMPLED;
  int Border = vtkImageSeparableGaussian::CLAMP;
};

vtkSmartPointer<vtkImageData> Smooth(vtkImageData* input, const Settings& s)
{
  vtkNew<vtkImageSeparableGaussian> filter;
  filter->SetStandardDeviations(s.Sigma[0], s.Sigma[1], s.Sigma[2]);
  filter->SetRadius(s.Radius[0], s.Radius[1], s.Radius[2]);
  filter->SetKernelType(s.Kind);
  filter->SetBorderMode(s.Border);
  return vtkBloomTest::RunAndCopy(filter, input);
}

// The radius the class documents for a negative Radius: ceil(4 sigma) (RadiusFactor 4).
int DefaultRadius(double sigma)
{
  return sigma > 0.0 ? static_cast<int>(std::ceil(4.0 * sigma - 1e-9)) : 0;
}

double Sum(vtkImageData* image)
{
  vtkDataArray* s = image->GetPointData()->GetScalars();
  double sum = 0.0;
  for (vtkIdType t = 0; t < s->GetNumberOfValues(); ++t)
  {
    sum += s->GetVariantValue(t).ToDouble();
  }
  return sum;
}

const char* BorderName(int b)
{
  return b == 0 ? "clamp" : (b == 1 ? "reflect" : "zero");
}
}

// All 3 kernels x 3 borders x sigma 0.3, 1, 2.5, 7, on sizes down to 1x1 (smaller than the
// kernel), against a direct 2-D convolution with the outer-product kernel: rel L2 <= 1e-10 in
// double and 1e-5 in float.
TEST(FiltersGaussian, MatchesReference)
{
  const std::pair<int, int> sizes[] = { { 1, 1 }, { 2, 3 }, { 5, 4 }, { 17, 9 }, { 40, 31 } };
  unsigned seed = 100;
  for (const auto& size : sizes)
  {
    const Texture image = vtkBloomRef::RandomImage(size.first, size.second, ++seed, -1.0, 5.0);
    for (double sigma : { 0.3, 1.0, 2.5, 7.0 })
    {
      for (int kind = 0; kind < 3; ++kind)
      {
        const int rx = DefaultRadius(sigma);
        // y gets a different sigma and an explicit radius, so the axes cannot be mixed up.
        const double sigmaY = 0.6 * sigma;
        const int ry = 3;
        const auto kx =
          vtkBloomRef::GaussianKernel(sigma, rx, static_cast<vtkBloomRef::GaussianKind>(kind));
        const auto ky =
          vtkBloomRef::GaussianKernel(sigmaY, ry, static_cast<vtkBloomRef::GaussianKind>(kind));
        for (int border = 0; border < 3; ++border)
        {
          const Texture expected =
            vtkBloomRef::Convolve2D(image, kx, ky, static_cast<vtkBloomRef::Border>(border));
          Settings s;
          s.Sigma[0] = sigma;
          s.Sigma[1] = sigmaY;
          s.Radius[1] = ry;
          s.Kind = kind;
          s.Border = border;
          for (int type : { VTK_DOUBLE, VTK_FLOAT })
          {
            auto out = Smooth(vtkBloomRef::ToImage(image, 4, type), s);
            const double error = vtkBloomRef::RelativeL2(vtkBloomRef::FromImage(out), expected);
            EXPECT_LE(error, type == VTK_DOUBLE ? 1e-10 : 1e-5)
              << size.first << "x" << size.second << " sigma " << sigma << " kind " << kind
              << " border " << BorderName(border) << (type == VTK_DOUBLE ? " double" : " float");
          }
        }
      }
    }
  }
}

// The seed-004 `blur` reading: radius R, sampled, clamp, on 1 and 3 component images too.
TEST(FiltersGaussian, BlurPresetComponents)
{
  const Texture image = vtkBloomRef::SyntheticScene(23, 14, 3);
  for (const auto& rs : { std::make_pair(8, 4.0), std::make_pair(3, 1.0), std::make_pair(1, 0.5) })
  {
    const Texture expected = vtkBloomRef::Blur(image, rs.first, rs.second);
    Settings s;
    s.Sigma[0] = s.Sigma[1] = rs.second;
    s.Radius[0] = s.Radius[1] = rs.first;
    s.Radius[2] = 0;
    for (int nc : { 1, 3, 4 })
    {
      auto out = Smooth(vtkBloomRef::ToImage(image, nc, VTK_DOUBLE), s);
      const double error =
        vtkBloomRef::RelativeL2(vtkBloomRef::FromImage(out), expected, nc == 1 ? 1 : nc);
      EXPECT_LE(error, 1e-12) << "radius " << rs.first << " components " << nc;
    }
  }
}

// GetHalfKernel: length R + 1 with R = ceil(4 sigma) by default, full sum 1, and the weights
// of the reference kernels.
TEST(FiltersGaussian, KernelNormalizedAndCorrect)
{
  vtkNew<vtkImageSeparableGaussian> filter;
  for (int kind = 0; kind < 3; ++kind)
  {
    filter->SetKernelType(kind);
    for (double sigma : { 0.3, 0.7, 1.0, 2.5, 7.0 })
    {
      for (int radius : { -1, 2, 9 })
      {
        filter->SetStandardDeviations(sigma, 1.0, 0.0);
        filter->SetRadius(radius, -1, -1);
        const std::vector<double> half = filter->GetHalfKernel(0);
        const int r = radius >= 0 ? radius : DefaultRadius(sigma);
        ASSERT_EQ(static_cast<int>(half.size()), r + 1)
          << "kind " << kind << " sigma " << sigma << " radius " << radius;
        double sum = half[0];
        for (size_t i = 1; i < half.size(); ++i)
        {
          sum += 2.0 * half[i];
        }
        EXPECT_NEAR(sum, 1.0, 1e-14);
        const auto expected =
          vtkBloomRef::GaussianKernel(sigma, r, static_cast<vtkBloomRef::GaussianKind>(kind));
        for (int i = 0; i <= r; ++i)
        {
          EXPECT_NEAR(half[i], expected[r + i], 1e-13)
            << "kind " << kind << " sigma " << sigma << " i " << i;
        }
      }
    }
  }
  // The z axis with sigma 0 is the single tap {1}.
  filter->SetStandardDeviations(1.0, 1.0, 0.0);
  EXPECT_EQ(filter->GetHalfKernel(2), std::vector<double>{ 1.0 });
}

// The discrete kernel's variance is sigma^2 (1e-9, wide radius), for small sigma too; the
// sampled kernel under-blurs below sigma 0.7, so the difference is real. Measured both on
// GetHalfKernel and on the filtered image of an impulse.
TEST(FiltersGaussian, DiscreteVarianceAndSampledUnderBlur)
{
  vtkNew<vtkImageSeparableGaussian> filter;
  for (double sigma : { 0.3, 0.5, 0.6, 1.0, 2.5 })
  {
    const int radius = 60;
    filter->SetStandardDeviations(sigma, sigma, 0.0);
    filter->SetRadius(radius, radius, 0);
    filter->SetKernelTypeToDiscrete();
    const auto discrete = filter->GetHalfKernel(0);
    filter->SetKernelTypeToSampled();
    const auto sampled = filter->GetHalfKernel(0);
    double vd = 0.0, vs = 0.0;
    for (int i = 1; i <= radius; ++i)
    {
      vd += 2.0 * i * i * discrete[i];
      vs += 2.0 * i * i * sampled[i];
    }
    EXPECT_NEAR(vd, sigma * sigma, 1e-9) << sigma;
    if (sigma < 0.7)
    {
      // Far below sigma^2 at 0.3 (about 0.008 instead of 0.09), still short of it at 0.6.
      EXPECT_LT(vs, sigma * sigma - 5e-3) << sigma;
      EXPECT_GT(std::abs(vs - vd), 5e-3) << sigma;
    }
    if (sigma <= 0.3)
    {
      EXPECT_LT(vs, 0.5 * sigma * sigma) << sigma;
    }

    // The same through the pipeline: the second moment of a blurred impulse along x.
    const int ext[6] = { -64, 64, 0, 0, 0, 0 };
    auto impulse = vtkBloomTest::MakeImage(
      ext, 1, VTK_DOUBLE, [](int i, int, int, int) { return i == 0 ? 1.0 : 0.0; });
    for (int kind : { vtkImageSeparableGaussian::DISCRETE, vtkImageSeparableGaussian::SAMPLED })
    {
      Settings s;
      s.Sigma[0] = sigma;
      s.Sigma[1] = 0.0;
      s.Radius[0] = radius;
      s.Kind = kind;
      auto out = Smooth(impulse, s);
      double m0 = 0.0, m2 = 0.0;
      for (int i = -64; i <= 64; ++i)
      {
        const double v = vtkBloomTest::Value(out, i, 0, 0, 0);
        m0 += v;
        m2 += v * i * i;
      }
      EXPECT_NEAR(m0, 1.0, 1e-13);
      if (kind == vtkImageSeparableGaussian::DISCRETE)
      {
        EXPECT_NEAR(m2, sigma * sigma, 1e-9) << sigma;
      }
      else if (sigma < 0.7)
      {
        EXPECT_LT(m2, sigma * sigma - 5e-3) << sigma;
      }
    }
  }
}

// sigma = 0 and radius 0 are bit-exact identities (all components, float and double, values
// that a multiply-add by 1 and 0 would not preserve: negative zero, huge and tiny numbers).
TEST(FiltersGaussian, ZeroSigmaAndZeroRadiusAreIdentities)
{
  const int ext[6] = { 2, 12, -4, 3, 0, 0 };
  auto f = [](int i, int j, int, int c)
  {
    const double values[] = { -0.0, 1e30, -3.25e-30, 0.1, 7.0 / 3.0, 65504.5 };
    return values[(i * 7 + j * 3 + c) % 6] * (1 + c);
  };
  for (int type : { VTK_FLOAT, VTK_DOUBLE })
  {
    auto input = vtkBloomTest::MakeImage(ext, 4, type, f);
    Settings zeroSigma;
    zeroSigma.Sigma[0] = zeroSigma.Sigma[1] = zeroSigma.Sigma[2] = 0.0;
    EXPECT_TRUE(vtkBloomTest::BitIdentical(Smooth(input, zeroSigma), input));
    Settings zeroRadius;
    zeroRadius.Sigma[0] = zeroRadius.Sigma[1] = 2.5;
    zeroRadius.Radius[0] = zeroRadius.Radius[1] = zeroRadius.Radius[2] = 0;
    for (int border = 0; border < 3; ++border)
    {
      zeroRadius.Border = border;
      EXPECT_TRUE(vtkBloomTest::BitIdentical(Smooth(input, zeroRadius), input));
    }
  }
}

// Mirroring the input in x mirrors the output (all borders, all kinds).
TEST(FiltersGaussian, MirrorSymmetry)
{
  const int w = 13, h = 6;
  const Texture image = vtkBloomRef::RandomImage(w, h, 77, 0.0, 10.0);
  Texture mirrored = image;
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      mirrored.At(i, j) = image.At(w - 1 - i, j);
    }
  }
  for (int kind = 0; kind < 3; ++kind)
  {
    for (int border = 0; border < 3; ++border)
    {
      Settings s;
      s.Sigma[0] = 2.2;
      s.Sigma[1] = 1.1;
      s.Kind = kind;
      s.Border = border;
      const Texture a =
        vtkBloomRef::FromImage(Smooth(vtkBloomRef::ToImage(image, 4, VTK_DOUBLE), s));
      const Texture b =
        vtkBloomRef::FromImage(Smooth(vtkBloomRef::ToImage(mirrored, 4, VTK_DOUBLE), s));
      double worst = 0.0;
      for (int j = 0; j < h; ++j)
      {
        for (int i = 0; i < w; ++i)
        {
          for (int c = 0; c < 4; ++c)
          {
            worst = std::max(worst, std::abs(a.At(i, j)[c] - b.At(w - 1 - i, j)[c]));
          }
        }
      }
      EXPECT_LE(worst, 1e-12) << "kind " << kind << " border " << BorderName(border);
    }
  }
}

// The reflect border conserves the image sum (rel 1e-12 in double), also with kernels wider
// than the image; a kernel much wider than the image gives the mean everywhere.
TEST(FiltersGaussian, ReflectConservesSumAndWideKernelGivesMean)
{
  const Texture image = vtkBloomRef::RandomImage(7, 5, 5, 0.0, 10.0);
  auto input = vtkBloomRef::ToImage(image, 3, VTK_DOUBLE);
  const double sum = Sum(input);
  for (int kind = 0; kind < 3; ++kind)
  {
    for (const auto& sr : { std::make_pair(1.0, -1), std::make_pair(2.5, -1),
           std::make_pair(7.0, -1), std::make_pair(30.0, 150) })
    {
      Settings s;
      s.Sigma[0] = s.Sigma[1] = sr.first;
      s.Radius[0] = s.Radius[1] = sr.second;
      s.Kind = kind;
      s.Border = vtkImageSeparableGaussian::REFLECT;
      auto out = Smooth(input, s);
      EXPECT_NEAR(Sum(out), sum, 1e-12 * std::abs(sum)) << "kind " << kind << " sigma " << sr.first;
    }
  }
  // sigma 400 on a 7 x 5 image: every output pixel is the mean of its channel.
  Settings wide;
  wide.Sigma[0] = wide.Sigma[1] = 400.0;
  wide.Radius[0] = wide.Radius[1] = 1600;
  wide.Border = vtkImageSeparableGaussian::REFLECT;
  auto out = Smooth(input, wide);
  for (int c = 0; c < 3; ++c)
  {
    double mean = 0.0, spread = 0.0;
    for (const auto& p : image.Texels)
    {
      mean += p[c] / image.Texels.size();
    }
    for (const auto& p : image.Texels)
    {
      spread = std::max(spread, std::abs(p[c] - mean));
    }
    ASSERT_GT(spread, 1.0); // the input is far from constant
    for (int j = 0; j < 5; ++j)
    {
      for (int i = 0; i < 7; ++i)
      {
        EXPECT_NEAR(vtkBloomTest::Value(out, i, j, 0, c), mean, 1e-5 * mean) << i << "," << j;
      }
    }
  }
}

// The zero border loses energy at the edges (the sum decreases for a positive image) while
// the interior, farther than the radius from every edge, matches the clamp border.
TEST(FiltersGaussian, ZeroBorderLosesEnergyInteriorMatchesClamp)
{
  const int w = 30, h = 20, radius = 4;
  const Texture image = vtkBloomRef::RandomImage(w, h, 9, 0.5, 2.0);
  auto input = vtkBloomRef::ToImage(image, 4, VTK_DOUBLE);
  Settings s;
  s.Sigma[0] = s.Sigma[1] = 1.5;
  s.Radius[0] = s.Radius[1] = radius;
  s.Border = vtkImageSeparableGaussian::ZERO;
  auto zero = Smooth(input, s);
  s.Border = vtkImageSeparableGaussian::CLAMP;
  auto clamp = Smooth(input, s);
  EXPECT_LT(Sum(zero), 0.97 * Sum(input));
  // An edge pixel of a zero-border blur of a positive image is darker than with clamp.
  EXPECT_LT(vtkBloomTest::Value(zero, 0, 0, 0, 0), vtkBloomTest::Value(clamp, 0, 0, 0, 0));
  for (int j = radius; j < h - radius; ++j)
  {
    for (int i = radius; i < w - radius; ++i)
    {
      for (int c = 0; c < 4; ++c)
      {
        EXPECT_NEAR(
          vtkBloomTest::Value(zero, i, j, 0, c), vtkBloomTest::Value(clamp, i, j, 0, c), 1e-13);
      }
    }
  }
}

// A negative sigma is refused with an error event and an empty output.
TEST(FiltersGaussian, NegativeSigmaIsAnError)
{
  const int ext[6] = { 0, 5, 0, 4, 0, 0 };
  auto input = vtkBloomTest::MakeImage(ext, 3, VTK_FLOAT, [](int i, int, int, int) { return i; });
  for (int axis = 0; axis < 3; ++axis)
  {
    vtkNew<vtkImageSeparableGaussian> filter;
    vtkNew<vtkBloomTest::EventCounter> errors;
    filter->AddObserver(vtkCommand::ErrorEvent, errors);
    filter->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, errors);
    double sigma[3] = { 1.0, 1.0, 0.0 };
    sigma[axis] = -0.5;
    filter->SetStandardDeviations(sigma);
    filter->SetInputData(input);
    filter->Update();
    EXPECT_GE(errors->Count, 1) << "axis " << axis;
    EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 0) << "axis " << axis;
  }
}

// A 3-D input: x, y and z are all smoothed, z with its own sigma, against a direct 3-D
// convolution (each border, each kind).
TEST(FiltersGaussian, ThreeDimensional)
{
  const int nx = 6, ny = 5, nz = 9, nc = 2;
  const int ext[6] = { 1, nx, -2, ny - 3, 4, nz + 3 };
  std::vector<double> values;
  for (int k = 0; k < nz; ++k)
  {
    for (int j = 0; j < ny; ++j)
    {
      for (int i = 0; i < nx; ++i)
      {
        for (int c = 0; c < nc; ++c)
        {
          values.push_back(static_cast<float>(
            10.0 * vtkBloomRef::HashUniform(3, ((k * ny + j) * nx + i) * nc + c)));
        }
      }
    }
  }
  auto input = vtkBloomTest::MakeImage(ext, nc, VTK_DOUBLE,
    [&](int i, int j, int k, int c)
    { return values[(((k - ext[4]) * ny + (j - ext[2])) * nx + (i - ext[0])) * nc + c]; });
  const double sigmas[2][3] = { { 0.0, 0.0, 1.5 }, { 0.8, 1.2, 2.0 } };
  for (const auto& sigma : sigmas)
  {
    for (int kind = 0; kind < 3; ++kind)
    {
      for (int border = 0; border < 3; ++border)
      {
        Settings s;
        for (int a = 0; a < 3; ++a)
        {
          s.Sigma[a] = sigma[a];
        }
        s.Kind = kind;
        s.Border = border;
        auto out = Smooth(input, s);
        std::vector<double> k[3];
        for (int a = 0; a < 3; ++a)
        {
          k[a] = vtkBloomRef::GaussianKernel(
            sigma[a], DefaultRadius(sigma[a]), static_cast<vtkBloomRef::GaussianKind>(kind));
        }
        const auto expected = vtkBloomRef::Convolve3D(
          values, nx, ny, nz, nc, k[0], k[1], k[2], static_cast<vtkBloomRef::Border>(border));
        double num = 0.0, den = 0.0;
        for (int z = 0; z < nz; ++z)
        {
          for (int y = 0; y < ny; ++y)
          {
            for (int x = 0; x < nx; ++x)
            {
              for (int c = 0; c < nc; ++c)
              {
                const double e = expected[(((z * ny) + y) * nx + x) * nc + c];
                const double d =
                  vtkBloomTest::Value(out, ext[0] + x, ext[2] + y, ext[4] + z, c) - e;
                num += d * d;
                den += e * e;
              }
            }
          }
        }
        EXPECT_LE(std::sqrt(num / den), 1e-10)
          << "sigma z " << sigma[2] << " kind " << kind << " border " << BorderName(border);
      }
    }
  }
  // The z blur is real: without it the result differs.
  Settings flat;
  flat.Sigma[2] = 0.0;
  Settings deep;
  deep.Sigma[2] = 1.5;
  EXPECT_GT(vtkBloomTest::MaxAbsDifference(Smooth(input, flat), Smooth(input, deep)), 0.1);
}

// The documented defaults.
TEST(FiltersGaussian, Defaults)
{
  vtkNew<vtkImageSeparableGaussian> filter;
  EXPECT_EQ(filter->GetStandardDeviations()[0], 2.0);
  EXPECT_EQ(filter->GetStandardDeviations()[1], 2.0);
  EXPECT_EQ(filter->GetStandardDeviations()[2], 0.0);
  EXPECT_EQ(filter->GetRadius()[0], -1);
  EXPECT_EQ(filter->GetRadiusFactor(), 4.0);
  EXPECT_EQ(filter->GetKernelType(), vtkImageSeparableGaussian::SAMPLED);
  EXPECT_EQ(filter->GetBorderMode(), vtkImageSeparableGaussian::CLAMP);
  EXPECT_EQ(filter->GetHalfKernel(0).size(), 9u); // ceil(4 * 2) + 1
}
