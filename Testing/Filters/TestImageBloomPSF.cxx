// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// vtkImageBloom's PSF mode: every PSF is normalized (sums to 1, non-negative; Airy and Gaussians
// point-symmetric, Airy wider for longer wavelengths); with reflect borders the bloom's energy
// is the bright pass's energy times the strength, per channel; the result agrees with an
// independent float64 gather convolution over a reflect-extended image; a measured PSF spreads
// a single bright pixel into itself, unflipped; bad parameters give errors and empty outputs.
#include <vtkImageBloom.h>
#include <vtkImageBloomThreshold.h>

#include "vtkBloomTestSupport.h"

#include <vtkCommand.h>
#include <vtkDoubleArray.h>
#include <vtkExecutive.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <iostream>
#include <numeric>
#include <vector>

namespace
{
vtkSmartPointer<vtkImageData> Image(
  int w, int h, int nc, int type, const std::function<double(int, int, int)>& value, int slices = 1)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(w, h, slices);
  image->AllocateScalars(type, nc);
  for (int k = 0; k < slices; ++k)
  {
    for (int j = 0; j < h; ++j)
    {
      for (int i = 0; i < w; ++i)
      {
        for (int c = 0; c < nc; ++c)
        {
          image->SetScalarComponentFromDouble(i, j, k, c, value(i, j, c));
        }
      }
    }
  }
  return image;
}

// A dim background with bright discs, one of them cut by the image's corner.
vtkSmartPointer<vtkImageData> Scene(int w, int h, int nc, int type)
{
  return Image(w, h, nc, type,
    [=](int i, int j, int c)
    {
      const double d0 = std::hypot(i - 0.3 * w, j - 0.6 * h);
      const double d1 = std::hypot(i - (w - 3), j - 2.0);
      double v = 0.1 + 0.05 * std::sin(0.37 * i + 0.11 * j + c);
      if (d0 < 6.0)
      {
        v += 4.0 + c;
      }
      if (d1 < 4.0)
      {
        v += 9.0 - c;
      }
      return v;
    });
}

vtkSmartPointer<vtkImageBloom> PSFBloom(int type)
{
  auto bloom = vtkSmartPointer<vtkImageBloom>::New();
  bloom->SetBloomModeToPSF();
  bloom->SetPSFType(type);
  bloom->SetThresholdMode(vtkImageBloomThreshold::SMOOTHSTEP_KNEE);
  bloom->SetThreshold(1.0);
  bloom->SetKnee(0.5);
  bloom->SetAiryRadius(2.0);
  bloom->SetPSFGaussians({ 1.0, 5.0 }, { 0.7, 0.3 });
  bloom->SetStrength(0.7);
  bloom->SetLevelWeight(0, 0.0); // level weights belong to the pyramid: PSF mode ignores them
  return bloom;
}

double Sum(vtkImageData* image, int c)
{
  vtkDataArray* s = image->GetPointData()->GetScalars();
  double sum = 0.0;
  for (vtkIdType t = 0; t < s->GetNumberOfTuples(); ++t)
  {
    sum += s->GetComponent(t, c);
  }
  return sum;
}

vtkSmartPointer<vtkImageData> BrightPass(vtkImageData* input)
{
  vtkNew<vtkImageBloomThreshold> threshold;
  threshold->SetMode(vtkImageBloomThreshold::SMOOTHSTEP_KNEE);
  threshold->SetThreshold(1.0);
  threshold->SetKnee(0.5);
  threshold->SetInputData(input);
  threshold->Update();
  return threshold->GetOutput();
}
}

TEST(FiltersPSF, EveryPSFIsNormalizedAndSymmetric)
{
  for (int type : { vtkBloomParameters::PSF_AIRY, vtkBloomParameters::PSF_GAUSSIANS })
  {
    auto bloom = PSFBloom(type);
    double peak[3];
    for (int c = 0; c < 3; ++c)
    {
      int r = 0;
      const std::vector<double> psf = bloom->ComputePSF(c, r);
      const int n = 2 * r + 1;
      ASSERT_EQ(psf.size(), static_cast<size_t>(n) * n);
      EXPECT_NEAR(std::accumulate(psf.begin(), psf.end(), 0.0), 1.0, 1e-12);
      for (size_t i = 0; i < psf.size(); ++i)
      {
        ASSERT_GE(psf[i], 0.0);
        ASSERT_NEAR(psf[i], psf[psf.size() - 1 - i], 1e-15); // point symmetry
        const size_t y = i / n, x = i % n;
        ASSERT_NEAR(psf[i], psf[x * n + y], 1e-15); // and the diagonal mirror
      }
      peak[c] = psf[static_cast<size_t>(r) * n + r];
      EXPECT_EQ(*std::max_element(psf.begin(), psf.end()), peak[c]);
    }
    if (type == vtkBloomParameters::PSF_AIRY)
    {
      // Diffraction spreads longer wavelengths wider: red's peak is lowest, blue's highest.
      EXPECT_LT(peak[0], peak[1]);
      EXPECT_LT(peak[1], peak[2]);
    }
  }
}

// The Airy pattern against one computed another way: J1 from Bessel's integral
// J1(v) = (1 / 2 pi) int_0^2pi cos(t - v sin t) dt by the trapezoid rule (exact to rounding
// once the points outnumber v by a margin), averaged over the same 5 x 5 samples a pixel. The
// PSF reaches v = 108 in its corners, where the filter's J1 is Hankel's asymptotic expansion.
TEST(FiltersPSF, AiryPatternAgreesWithBesselsIntegral)
{
  auto bloom = PSFBloom(vtkBloomParameters::PSF_AIRY);
  bloom->SetPSFRadius(40);
  int r = 0;
  const std::vector<double> psf = bloom->ComputePSF(1, r); // green: the Airy radius itself
  ASSERT_EQ(r, 40);
  const double r0 = 2.0, pi = 3.14159265358979323846;
  auto j1 = [&](double v)
  {
    const int n = 2 * static_cast<int>(v) + 64;
    double sum = 0.0;
    for (int m = 0; m < n; ++m)
    {
      const double t = 2.0 * pi * m / n;
      sum += std::cos(t - v * std::sin(t));
    }
    return sum / n;
  };
  auto intensity = [&](double x, double y)
  {
    const double v = 3.8317059702075125 * std::hypot(x, y) / r0;
    const double a = v < 1e-8 ? 1.0 : 2.0 * j1(v) / v;
    return a * a;
  };
  const int n = 2 * r + 1;
  std::vector<double> reference(psf.size());
  for (int y = 0; y < n; ++y)
  {
    for (int x = 0; x < n; ++x)
    {
      double sum = 0.0;
      for (int sy = -2; sy <= 2; ++sy)
      {
        for (int sx = -2; sx <= 2; ++sx)
        {
          sum += intensity(x - r + 0.2 * sx, y - r + 0.2 * sy);
        }
      }
      reference[static_cast<size_t>(y) * n + x] = sum;
    }
  }
  const double total = std::accumulate(reference.begin(), reference.end(), 0.0);
  double worst = 0.0;
  for (size_t i = 0; i < psf.size(); ++i)
  {
    const double expected = reference[i] / total;
    worst = std::max(worst, std::abs(psf[i] - expected) / expected);
  }
  std::cout << "Airy PSF against Bessel's integral: largest relative error " << worst << "\n";
  EXPECT_LT(worst, 1e-9);
}

TEST(FiltersPSF, ReflectBordersConserveTheBrightPassEnergy)
{
  for (int type : { vtkBloomParameters::PSF_AIRY, vtkBloomParameters::PSF_GAUSSIANS })
  {
    auto bloom = PSFBloom(type); // one filter for every size: its prepared plans follow
    for (int nc : { 1, 3, 4 })
    {
      auto input = Scene(97 - 10 * nc, 64, nc, VTK_DOUBLE);
      bloom->SetPSFBorderMode(1);
      bloom->SetInputData(input);
      bloom->Update();
      vtkImageData* out = bloom->GetOutput();
      auto bright = BrightPass(input);
      for (int c = 0; c < std::min(nc, 3); ++c)
      {
        const double added = Sum(out, c) - Sum(input, c);
        const double expected = 0.7 * Sum(bright, c);
        EXPECT_NEAR(added / expected, 1.0, 1e-6) << "type " << type << " nc " << nc << " c " << c;
      }
      // Zero borders let the energy that reaches past the edges go.
      bloom->SetPSFBorderMode(2);
      bloom->Update();
      const double kept = Sum(bloom->GetOutput(), 0) - Sum(input, 0);
      EXPECT_LT(kept, 0.7 * Sum(bright, 0) * (1.0 - 1e-4)) << "type " << type;
    }
  }
}

TEST(FiltersPSF, AgreesWithADirectReflectConvolution)
{
  const int w = 41, h = 29;
  auto input = Scene(w, h, 3, VTK_DOUBLE);
  auto bloom = PSFBloom(vtkBloomParameters::PSF_AIRY);
  bloom->SetPSFRadius(9);
  bloom->SetInputData(input);
  bloom->Update();
  auto bright = BrightPass(input);
  auto mirror = [](int i, int n)
  {
    while (i < 0 || i >= n)
    {
      i = i < 0 ? -1 - i : 2 * n - 1 - i;
    }
    return i;
  };
  double num = 0.0, den = 0.0;
  for (int c = 0; c < 3; ++c)
  {
    int r = 0;
    const std::vector<double> psf = bloom->ComputePSF(c, r);
    const int n = 2 * r + 1;
    for (int j = 0; j < h; ++j)
    {
      for (int i = 0; i < w; ++i)
      {
        double sum = 0.0;
        for (int dy = -r; dy <= r; ++dy)
        {
          for (int dx = -r; dx <= r; ++dx)
          {
            sum += psf[static_cast<size_t>(dy + r) * n + (dx + r)] *
              bright->GetScalarComponentAsDouble(mirror(i - dx, w), mirror(j - dy, h), 0, c);
          }
        }
        const double expected = input->GetScalarComponentAsDouble(i, j, 0, c) + 0.7 * sum;
        const double got = bloom->GetOutput()->GetScalarComponentAsDouble(i, j, 0, c);
        num += (got - expected) * (got - expected);
        den += expected * expected;
      }
    }
  }
  EXPECT_LE(std::sqrt(num / den), 1e-6);
}

TEST(FiltersPSF, AMeasuredPSFSpreadsAPixelIntoItself)
{
  // An asymmetric 5 x 5 PSF; one bright pixel in a black image blooms into exactly that shape.
  auto psf =
    Image(5, 5, 1, VTK_FLOAT, [](int i, int j, int) { return i == 4 ? 3.0 : 0.1 * (j + 1); });
  const double total = Sum(psf, 0);
  auto input =
    Image(21, 17, 1, VTK_DOUBLE, [](int i, int j, int) { return i == 8 && j == 9 ? 10.0 : 0.0; });
  auto bloom = PSFBloom(vtkBloomParameters::PSF_IMAGE);
  bloom->SetThresholdMode(vtkImageBloomThreshold::NONE);
  bloom->SetStrength(1.0);
  bloom->SetPSFImage(psf);
  bloom->SetInputData(input);
  bloom->Update();
  vtkImageData* out = bloom->GetOutput();
  for (int j = 0; j < 17; ++j)
  {
    for (int i = 0; i < 21; ++i)
    {
      const int dx = i - 8, dy = j - 9;
      const double expected = (i == 8 && j == 9 ? 10.0 : 0.0) +
        (std::abs(dx) <= 2 && std::abs(dy) <= 2
            ? 10.0 * psf->GetScalarComponentAsDouble(dx + 2, dy + 2, 0, 0) / total
            : 0.0);
      ASSERT_NEAR(out->GetScalarComponentAsDouble(i, j, 0, 0), expected, 1e-5) << i << " " << j;
    }
  }
  // Editing the PSF image re-executes the filter.
  psf->SetScalarComponentFromDouble(4, 2, 0, 0, 30.0);
  psf->Modified();
  bloom->Update();
  const double before = 10.0 * 0.3 / total; // the PSF's (4, 2) before the edit
  EXPECT_GT(bloom->GetOutput()->GetScalarComponentAsDouble(10, 9, 0, 0), 2.0 * before);
}

TEST(FiltersPSF, BadParametersGiveErrorsAndEmptyOutputs)
{
  auto input = Scene(20, 16, 3, VTK_FLOAT);
  auto check = [&](vtkImageBloom* bloom, vtkImageData* in, const char* what)
  {
    vtkNew<vtkBloomTest::EventCounter> errors; // keeps them off the terminal
    bloom->AddObserver(vtkCommand::ErrorEvent, errors);
    bloom->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, errors);
    bloom->SetInputData(in);
    bloom->Update();
    EXPECT_GT(errors->Count, 0) << what;
    EXPECT_EQ(bloom->GetOutput()->GetNumberOfPoints(), 0) << what;
  };
  {
    auto bloom = PSFBloom(vtkBloomParameters::PSF_IMAGE); // no image
    check(bloom, input, "no PSF image");
  }
  {
    auto bloom = PSFBloom(vtkBloomParameters::PSF_IMAGE);
    bloom->SetPSFImage(Image(4, 4, 1, VTK_FLOAT, [](int, int, int) { return 1.0; }));
    check(bloom, input, "even size");
  }
  {
    auto bloom = PSFBloom(vtkBloomParameters::PSF_IMAGE);
    bloom->SetPSFImage(Image(3, 3, 1, VTK_FLOAT, [](int i, int, int) { return i - 1.0; }));
    check(bloom, input, "negative values");
  }
  {
    auto bloom = PSFBloom(vtkBloomParameters::PSF_GAUSSIANS);
    bloom->SetPSFGaussians({ 1.0, 2.0 }, { 1.0 });
    check(bloom, input, "mismatched Gaussians");
  }
  {
    auto bloom = PSFBloom(vtkBloomParameters::PSF_AIRY);
    check(bloom,
      Image(
        8, 8, 3, VTK_FLOAT, [](int, int, int) { return 2.0; }, 3),
      "a volume");
  }
}
