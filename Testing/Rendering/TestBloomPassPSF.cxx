// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// Tests of vtkBloomPass's PSF mode (vtkBloomParameters::BLOOM_PSF; the FFT of
// vtkBloomPassFFT): the GPU against vtkImageBloom's PSF mode on the same float render for each
// kind of PSF, both borders, an odd and an even size and a PSF as wide as the frame; the energy
// of the bloom term with REFLECT; a delta's bloom against the PSF itself, per channel; the same
// on grids with a line longer than 4096 samples (vtkBloomPassFFT's four-step transform).
#include "vtkBloomExampleScenes.h"
#include "vtkBloomParameters.h"
#include "vtkBloomPass.h"
#include "vtkBloomPassTestWindow.h"
#include "vtkBloomPassTesting.h"
#include "vtkBloomTestSupport.h"

#include "vtkBloomVTKCompat.h"
#include "vtkCommand.h"
#include "vtkFloatArray.h"
#include "vtkImageBloom.h"
#include "vtkImageBloomThreshold.h"
#include "vtkImageData.h"
#include "vtkImageSeparableGaussian.h"
#include "vtkNew.h"
#include "vtkPointData.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace
{
enum PSFKind
{
  AIRY,
  GAUSSIANS,
  IMAGE
};

// A non-symmetric, per-channel PSF image (2 r + 1 square, 3 components): a flip, a transpose
// or a swap of channels changes the convolution.
vtkSmartPointer<vtkImageData> LopsidedPSF(int r)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(2 * r + 1, 2 * r + 1, 1);
  image->AllocateScalars(VTK_DOUBLE, 3);
  vtkDataArray* values = image->GetPointData()->GetScalars();
  for (int y = 0; y <= 2 * r; ++y)
  {
    for (int x = 0; x <= 2 * r; ++x)
    {
      const double dx = x - r, dy = y - r;
      const vtkIdType p = static_cast<vtkIdType>(y) * (2 * r + 1) + x;
      values->SetComponent(p, 0, std::exp(-(dx * dx + 4.0 * dy * dy) / (r * r)) * (x > r ? 2 : 1));
      values->SetComponent(p, 1, std::exp(-(4.0 * dx * dx + dy * dy) / (r * r)) * (y > r ? 3 : 1));
      values->SetComponent(p, 2, 1.0 / (1.0 + std::abs(dx + 0.5 * dy)) + (x + y) % 3);
    }
  }
  return image;
}

// PSF mode of `kind` with `radius` (-1: automatic) and `border` on `parameters`.
void SetPSF(vtkBloomParameters* parameters, PSFKind kind, int radius, int border)
{
  parameters->SetBloomModeToPSF();
  parameters->SetPSFRadius(radius);
  parameters->SetPSFBorderMode(border);
  switch (kind)
  {
    case AIRY:
      parameters->SetPSFType(vtkBloomParameters::PSF_AIRY);
      parameters->SetAiryRadius(2.5);
      break;
    case GAUSSIANS:
      parameters->SetPSFType(vtkBloomParameters::PSF_GAUSSIANS);
      parameters->SetPSFGaussians(
        { 2.0, 9.0, radius > 0 ? radius / 3.0 : 20.0 }, { 1.0, 0.3, 0.1 });
      break;
    case IMAGE:
      parameters->SetPSFType(vtkBloomParameters::PSF_IMAGE);
      parameters->SetPSFImage(LopsidedPSF(radius > 0 ? radius : 15));
      break;
  }
}

struct Agreement
{
  double Colour = 1.0; ///< relative L2 of the composited colour
  double Bloom = 1.0;  ///< relative L2 of the bloom term alone
};

// GPU PSF bloom vs vtkImageBloom's PSF mode (REFERENCE) on the same float render, the PSF split
// at `tailScale` (1: not split); `grid` (when given) is the pass's FFT grid.
Agreement PSFAgreement(PSFKind kind, int radius, int border, int width, int height,
  int tailScale = 1, int* grid = nullptr)
{
  BloomWindow w(width, height);
  EXPECT_TRUE(vtkBloomBuildExampleScene("lit-spheres", w.Renderer, w.Bloom));
  w.Bloom->SetEmissionSourceToScene();
  w.Bloom->SetFloatPrecisionTo32Bit();
  SetPSF(w.Bloom->GetParameters(), kind, radius, border);
  w.Bloom->GetParameters()->SetPSFTailScale(tailScale);
  w.Bloom->CaptureResultOn();
  w.Window->Render();
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  vtkNew<vtkImageData> scene, gpu;
  EXPECT_TRUE(w.Bloom->ReadSceneImage(scene));
  EXPECT_TRUE(w.Bloom->ReadResultImage(gpu));
  EXPECT_FALSE(w.Bloom->GetLastFrame()->GetBloomSkipped());
  if (grid)
  {
    w.Bloom->GetLastFrame()->GetPSFGrid(grid);
  }

  vtkNew<vtkImageBloom> cpu;
  cpu->SetParameters(w.Bloom->GetParameters());
  cpu->SetExecutionMode(vtkImageBloom::REFERENCE);
  cpu->SetInputData(scene);
  cpu->Update();
  Agreement a;
  a.Colour = vtkBloomTest::ColourRelativeL2(gpu, cpu->GetOutput());
  a.Bloom = vtkBloomTest::BloomRelativeL2(scene, gpu, cpu->GetOutput());
  // The bloom must change the image, or agreement would be trivial.
  EXPECT_GT(vtkBloomTest::ColourRelativeL2(scene, cpu->GetOutput()), 1e-3);
  return a;
}

// One float RGBA image, zero but for `value` at (x, y) in every colour channel.
vtkSmartPointer<vtkImageData> Delta(int width, int height, int x, int y, double value)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(width, height, 1);
  image->AllocateScalars(VTK_FLOAT, 4);
  auto* values = vtkFloatArray::SafeDownCast(image->GetPointData()->GetScalars());
  values->FillValue(0.0f);
  for (int c = 0; c < 3; ++c)
  {
    values->SetComponent(static_cast<vtkIdType>(y) * width + x, c, value);
  }
  return image;
}

// Every parameter that makes the result scene + PSF * scene: no threshold, strength 1, white.
void PassEverything(vtkBloomParameters* parameters)
{
  parameters->SetThresholdMode(vtkImageBloomThreshold::NONE);
  parameters->SetCompositeMode(vtkBloomParameters::ADDITIVE);
  parameters->SetStrength(1.0);
  parameters->SetTint(1.0, 1.0, 1.0);
}

// How far a delta of 1 at (x0, y0) of a width x height image, bloomed with an image PSF of
// radius r (ZERO borders, so that nothing folds), is from the PSFs themselves:
// out(x0 + dx, y0 + dy) = k_c(R + dx, R + dy). Worst: the largest error away from the delta;
// Largest: the PSFs' peak; Centre: the error at the delta's own pixel, 1 + k(R, R) in float.
struct DeltaError
{
  double Worst = 0.0, Largest = 0.0, Centre = 0.0;
};

DeltaError BloomDelta(int width, int height, int x0, int y0, int r)
{
  DeltaError e;
  BloomWindow w(8, 8);
  w.Bloom->SetFloatPrecisionTo32Bit();
  vtkBloomParameters* parameters = w.Bloom->GetParameters();
  SetPSF(parameters, IMAGE, r, vtkImageSeparableGaussian::ZERO);
  PassEverything(parameters);
  vtkNew<vtkImageData> output;
  EXPECT_TRUE(w.Bloom->ApplyToImage(w.GL(), Delta(width, height, x0, y0, 1.0), output));
  vtkNew<vtkImageBloom> cpu;
  cpu->SetParameters(parameters);
  for (int c = 0; c < 3; ++c)
  {
    int radius = 0;
    const std::vector<double> kernel = cpu->ComputePSF(c, radius);
    EXPECT_EQ(radius, r);
    for (int y = 0; y < height && radius == r; ++y)
    {
      for (int x = 0; x < width; ++x)
      {
        const int kx = x - x0 + r, ky = y - y0 + r;
        const bool inside = kx >= 0 && kx <= 2 * r && ky >= 0 && ky <= 2 * r;
        const double k = inside ? kernel[static_cast<size_t>(ky) * (2 * r + 1) + kx] : 0.0;
        const vtkIdType p = static_cast<vtkIdType>(y) * width + x;
        const double got = output->GetPointData()->GetScalars()->GetComponent(p, c);
        if (x == x0 && y == y0)
        {
          e.Centre = std::max(e.Centre, std::abs(got - 1.0 - k));
          continue;
        }
        e.Worst = std::max(e.Worst, std::abs(got - k));
        e.Largest = std::max(e.Largest, k);
      }
    }
  }
  return e;
}

const char* BorderName(int border)
{
  return border == vtkImageSeparableGaussian::REFLECT ? "REFLECT" : "ZERO";
}

// A float RGBA image of HDR spots on a dim ripple, different in each channel, so that every
// channel's convolution and the folds of both axes show.
vtkSmartPointer<vtkImageData> Spots(int width, int height)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(width, height, 1);
  image->AllocateScalars(VTK_FLOAT, 4);
  auto* values = vtkFloatArray::SafeDownCast(image->GetPointData()->GetScalars());
  for (int y = 0; y < height; ++y)
  {
    for (int x = 0; x < width; ++x)
    {
      const vtkIdType p = static_cast<vtkIdType>(y) * width + x;
      const double ripple = 0.05 * (1.0 + std::sin(0.013 * x + 0.07 * y));
      const double spot = (7 * x + 13 * y) % 211 == 0 ? 20.0 : 0.0;
      for (int c = 0; c < 3; ++c)
      {
        values->SetComponent(p, c, ripple * (1.0 + 0.3 * c) + spot * (c + 1));
      }
      values->SetComponent(p, 3, 1.0);
    }
  }
  return image;
}

struct FourStepResult
{
  double Colour = 1.0; ///< relative L2 of the GPU's result against the CPU filter's
  double Bloom = 1.0;  ///< the same of the bloom terms alone
  double Energy = 1.0; ///< |sum of the GPU's bloom term - sum of the input| / sum of the input
};

// vtkBloomPass::ApplyToImage of Spots(width, height) in `w`, every pixel blooming
// (PassEverything), against vtkImageBloom's PSF mode (REFERENCE) on the same image.
FourStepResult FourStepAgreement(
  BloomWindow& w, PSFKind kind, int radius, int border, int width, int height)
{
  w.Bloom->SetFloatPrecisionTo32Bit();
  vtkBloomParameters* parameters = w.Bloom->GetParameters();
  SetPSF(parameters, kind, radius, border);
  PassEverything(parameters);
  vtkSmartPointer<vtkImageData> input = Spots(width, height);
  vtkNew<vtkImageData> gpu;
  EXPECT_TRUE(w.Bloom->ApplyToImage(w.GL(), input, gpu));
  EXPECT_FALSE(w.Bloom->GetLastFrame()->GetBloomSkipped());
  vtkNew<vtkImageBloom> cpu;
  cpu->SetParameters(parameters);
  cpu->SetExecutionMode(vtkImageBloom::REFERENCE);
  cpu->SetInputData(input);
  cpu->Update();
  FourStepResult r;
  r.Colour = vtkBloomTest::ColourRelativeL2(gpu, cpu->GetOutput());
  r.Bloom = vtkBloomTest::BloomRelativeL2(input, gpu, cpu->GetOutput());
  double in = 0.0, bloom = 0.0;
  for (vtkIdType p = 0; p < input->GetNumberOfPoints(); ++p)
  {
    for (int c = 0; c < 3; ++c)
    {
      const double s = input->GetPointData()->GetScalars()->GetComponent(p, c);
      in += s;
      bloom += gpu->GetPointData()->GetScalars()->GetComponent(p, c) - s;
    }
  }
  r.Energy = std::abs(bloom - in) / in;
  return r;
}

// FourStepAgreement for Gaussians and an Airy pattern, both borders, on images 4050 or 4100
// wide and 8 high (transposed: 8 wide), within 1e-5 of the CPU filter; REFLECT keeps the energy.
void FourStepCases(bool transposed)
{
  struct Case
  {
    PSFKind Kind;
    int Radius, Long;
  };
  for (const Case& c : { Case{ GAUSSIANS, 40, 4050 }, Case{ AIRY, -1, 4100 } })
  {
    const int width = transposed ? 8 : c.Long, height = transposed ? c.Long : 8;
    BloomWindow w(8, 8); // one for both borders: the PSFs' spectra are made once
    for (int border :
      { int(vtkImageSeparableGaussian::REFLECT), int(vtkImageSeparableGaussian::ZERO) })
    {
      const FourStepResult r = FourStepAgreement(w, c.Kind, c.Radius, border, width, height);
      std::cout << "four-step PSF " << c.Kind << " " << BorderName(border) << " " << width << "x"
                << height << ": colour " << r.Colour << ", bloom " << r.Bloom << ", energy "
                << r.Energy << "\n";
      EXPECT_LE(r.Colour, 1e-5) << "PSF kind " << c.Kind << ", " << BorderName(border);
      EXPECT_LE(r.Bloom, 1e-5) << "PSF kind " << c.Kind << ", " << BorderName(border);
      if (border == vtkImageSeparableGaussian::REFLECT)
      {
        EXPECT_LE(r.Energy, 1e-5) << "PSF kind " << c.Kind;
      }
    }
  }
}

}

//------------------------------------------------------------------------------
TEST(RenderingBloomPassPSF, AgreesWithTheCPUFilterForEveryPSFAndBorder)
{
  for (int border :
    { int(vtkImageSeparableGaussian::REFLECT), int(vtkImageSeparableGaussian::ZERO) })
  {
    for (PSFKind kind : { AIRY, GAUSSIANS, IMAGE })
    {
      for (const auto& size : { std::make_pair(301, 207), std::make_pair(256, 160) })
      {
        // Airy's automatic radius (12 rings of the reddest channel), the others 40 pixels.
        const Agreement a =
          PSFAgreement(kind, kind == AIRY ? -1 : 40, border, size.first, size.second);
        std::cout << "PSF " << kind << " " << BorderName(border) << " " << size.first << "x"
                  << size.second << ": colour " << a.Colour << ", bloom " << a.Bloom << "\n";
        EXPECT_LE(a.Colour, 1e-5) << "PSF kind " << kind << ", " << BorderName(border) << ", "
                                  << size.first << "x" << size.second;
        EXPECT_LE(a.Bloom, 1e-5) << "PSF kind " << kind << ", " << BorderName(border);
      }
    }
  }
}

//------------------------------------------------------------------------------
TEST(RenderingBloomPassPSF, ASplitPSFAgreesWithTheCPUFiltersSplit)
{
  // vtkBloomPassPSFSplit (the grid, the tail's FFT there, the core direct) against the CPU
  // filter's split (the core and the tail each through FFTW), on an odd size; the tail's grid
  // is the pass's FFT grid, about scale times smaller a side than the exact one (472 x 378).
  for (int border :
    { int(vtkImageSeparableGaussian::REFLECT), int(vtkImageSeparableGaussian::ZERO) })
  {
    for (PSFKind kind : { AIRY, GAUSSIANS })
    {
      for (int scale : { 2, 4, 8 })
      {
        int grid[2] = { 0, 0 };
        const Agreement a = PSFAgreement(kind, 80, border, 301, 207, scale, grid);
        std::cout << "split PSF " << kind << " " << BorderName(border) << " scale " << scale
                  << " (grid " << grid[0] << "x" << grid[1] << "): colour " << a.Colour
                  << ", bloom " << a.Bloom << "\n";
        EXPECT_LE(a.Colour, 1e-5) << "PSF kind " << kind << ", scale " << scale;
        EXPECT_LE(a.Bloom, 1e-5) << "PSF kind " << kind << ", scale " << scale;
        EXPECT_LE(grid[0], 2 * 472 / scale) << "scale " << scale;
        EXPECT_GT(grid[0], 0) << "scale " << scale;
      }
    }
  }
}

//------------------------------------------------------------------------------
TEST(RenderingBloomPassPSF, AgreesWithTheCPUFilterForAPSFWiderThanTheFrame)
{
  // Radius 301 at 301 x 207: a grid of 960 x 810 (radices 4, 2, 3 and 5), and REFLECT folds
  // light back more than once across the frame.
  for (int border :
    { int(vtkImageSeparableGaussian::REFLECT), int(vtkImageSeparableGaussian::ZERO) })
  {
    for (PSFKind kind : { GAUSSIANS, IMAGE })
    {
      const Agreement a = PSFAgreement(kind, 301, border, 301, 207);
      std::cout << "wide PSF " << kind << " " << BorderName(border) << ": colour " << a.Colour
                << ", bloom " << a.Bloom << "\n";
      EXPECT_LE(a.Colour, 1e-5) << "PSF kind " << kind << ", " << BorderName(border);
      EXPECT_LE(a.Bloom, 1e-5) << "PSF kind " << kind << ", " << BorderName(border);
    }
  }
}

//------------------------------------------------------------------------------
TEST(RenderingBloomPassPSF, AgreesWithTheCPUFilterForAnAiryPatternWiderThanTheFrame)
{
  // A smaller frame: an Airy pattern costs 25 Bessel evaluations per PSF sample.
  for (int border :
    { int(vtkImageSeparableGaussian::REFLECT), int(vtkImageSeparableGaussian::ZERO) })
  {
    const Agreement a = PSFAgreement(AIRY, 64, border, 64, 48);
    std::cout << "wide Airy " << BorderName(border) << ": colour " << a.Colour << ", bloom "
              << a.Bloom << "\n";
    EXPECT_LE(a.Colour, 1e-5) << BorderName(border);
    EXPECT_LE(a.Bloom, 1e-5) << BorderName(border);
  }
}

//------------------------------------------------------------------------------
TEST(RenderingBloomPassPSF, AgreesWithTheCPUFilterOnRowsLongerThan4096)
{
  // Grid rows of more than 4096 samples, transformed in four steps (vtkBloomPassFFT::Split):
  // Gaussians of radius 40 on 4050 x 8 (grid 4320 x 90, 4320 = 72 x 60; REFLECT folds the
  // light back across the 8 rows five times) and an Airy pattern (its automatic radius) on
  // 4100 x 8. Thin grids: llvmpipe transforms about a million samples a second.
  FourStepCases(false);
}

//------------------------------------------------------------------------------
TEST(RenderingBloomPassPSF, AgreesWithTheCPUFilterOnColumnsLongerThan4096)
{
  // The same, transposed: 8 x 4050 and 8 x 4100.
  FourStepCases(true);
}

//------------------------------------------------------------------------------
TEST(RenderingBloomPassPSF, ADeltaBloomsIntoThePSFItselfOnLinesLongerThan4096)
{
  // As ADeltaBloomsIntoThePSFItself, on 4100 x 9 and 9 x 4400 (grids 4320 x 50, 4320 = 72 x 60,
  // and 50 x 4500, 4500 = 75 x 60), and 9 x 2400 (a column of 2500 = 50 x 50: columns longer
  // than 2048 take four steps too): the four-step transform's twiddle, its order of the
  // spectrum (the multiply's -k) and its inverse must all be right for the lopsided PSF to come
  // back in place.
  const int r = 20;
  for (const auto& size :
    { std::make_pair(4100, 9), std::make_pair(9, 4400), std::make_pair(9, 2400) })
  {
    const int width = size.first, height = size.second;
    const int along = std::max(width, height) * 2 / 3;
    const int x0 = width > height ? along : 4, y0 = width > height ? 4 : along;
    const DeltaError e = BloomDelta(width, height, x0, y0, r);
    std::cout << "four-step delta " << width << "x" << height << ": largest error " << e.Worst
              << " for a PSF peak of " << e.Largest << "; at the delta " << e.Centre << "\n";
    EXPECT_LE(e.Worst, 1e-5 * e.Largest) << width << "x" << height;
    EXPECT_LE(e.Centre, 2e-7) << width << "x" << height; // 1 + k(R, R) rounds by 2^-24
  }
}

//------------------------------------------------------------------------------
TEST(RenderingBloomPassPSF, FollowsAChangeOfPSFOrStrengthBetweenFrames)
{
  // The PSFs and their spectra are kept between frames: a new PSF (or split) must replace them,
  // a new strength must not need them remade. Each frame is checked against the filter.
  BloomWindow w(150, 100);
  ASSERT_TRUE(vtkBloomBuildExampleScene("lit-spheres", w.Renderer, w.Bloom));
  w.Bloom->SetEmissionSourceToScene();
  w.Bloom->SetFloatPrecisionTo32Bit();
  w.Bloom->CaptureResultOn();
  vtkBloomParameters* parameters = w.Bloom->GetParameters();
  SetPSF(parameters, GAUSSIANS, 30, vtkImageSeparableGaussian::REFLECT);
  vtkNew<vtkImageBloom> cpu;
  cpu->SetParameters(parameters);
  auto check = [&](const char* what)
  {
    w.Window->Render();
    vtkNew<vtkImageData> scene, gpu;
    ASSERT_TRUE(w.Bloom->ReadSceneImage(scene));
    ASSERT_TRUE(w.Bloom->ReadResultImage(gpu));
    cpu->SetInputData(scene);
    cpu->Update();
    EXPECT_LE(vtkBloomTest::ColourRelativeL2(gpu, cpu->GetOutput()), 1e-5) << what;
  };
  check("first PSF");
  parameters->SetPSFGaussians({ 1.0, 6.0 }, { 1.0, 0.5 });
  check("new Gaussians");
  parameters->SetStrength(0.25);
  check("new strength");
  parameters->SetPSFType(vtkBloomParameters::PSF_IMAGE);
  parameters->SetPSFImage(LopsidedPSF(12));
  check("an image PSF");
  parameters->SetPSFBorderMode(vtkImageSeparableGaussian::ZERO);
  check("ZERO borders");
  // Split and exact in turn: each convolution's resources go when the other takes over.
  parameters->SetPSFType(vtkBloomParameters::PSF_GAUSSIANS);
  parameters->SetPSFTailScale(4);
  check("split");
  parameters->SetPSFCoreRadius(8);
  check("a narrower core");
  parameters->SetPSFTailScale(1);
  check("exact again");
  parameters->SetPSFTailScale(2);
  check("split again");
}

//------------------------------------------------------------------------------
TEST(RenderingBloomPassPSF, ReflectConservesTheBrightPassEnergy)
{
  for (PSFKind kind : { GAUSSIANS, IMAGE })
  {
    BloomWindow w(301, 207);
    ASSERT_TRUE(vtkBloomBuildExampleScene("lit-spheres", w.Renderer, w.Bloom));
    w.Bloom->SetEmissionSourceToScene();
    w.Bloom->SetFloatPrecisionTo32Bit();
    SetPSF(w.Bloom->GetParameters(), kind, 120, vtkImageSeparableGaussian::REFLECT);
    PassEverything(w.Bloom->GetParameters());
    w.Bloom->CaptureResultOn();
    w.Window->Render();
    vtkNew<vtkImageData> scene, result;
    ASSERT_TRUE(w.Bloom->ReadSceneImage(scene));
    ASSERT_TRUE(w.Bloom->ReadResultImage(result));
    // With no threshold the bright pass is the scene's colour.
    double bright = 0.0, bloom = 0.0;
    for (vtkIdType p = 0; p < scene->GetNumberOfPoints(); ++p)
    {
      for (int c = 0; c < 3; ++c)
      {
        const double s = scene->GetPointData()->GetScalars()->GetComponent(p, c);
        bright += s;
        bloom += result->GetPointData()->GetScalars()->GetComponent(p, c) - s;
      }
    }
    ASSERT_GT(bright, 0.0);
    const double error = std::abs(bloom - bright) / bright;
    std::cout << "energy " << kind << ": relative error " << error << "\n";
    EXPECT_LE(error, 1e-5) << "PSF kind " << kind << ": bloom " << bloom << ", bright " << bright;
  }
}

//------------------------------------------------------------------------------
TEST(RenderingBloomPassPSF, ADeltaBloomsIntoThePSFItself)
{
  // A delta away from the borders (ZERO: nothing folds) blooms into its channel's PSF, centred
  // on it: out(x0 + dx, y0 + dy) = k_c(R + dx, R + dy). A wrong twiddle, stage, separation of
  // red from green, or a flipped axis all break it. Grids 144 x 120, and 81 x 125: odd sizes,
  // where the kernels' Hermitian half spectra keep rows 0 to 62 of 125.
  struct Case
  {
    int Width, Height, X0, Y0;
  };
  for (const Case& c : { Case{ 97, 75, 40, 33 }, Case{ 41, 85, 20, 42 } })
  {
    const DeltaError e = BloomDelta(c.Width, c.Height, c.X0, c.Y0, 20);
    std::cout << "delta " << c.Width << "x" << c.Height << ": largest error " << e.Worst
              << " for a PSF peak of " << e.Largest << "; at the delta " << e.Centre << "\n";
    EXPECT_LE(e.Worst, 1e-5 * e.Largest) << c.Width << "x" << c.Height;
    EXPECT_LE(e.Centre, 2e-7) << c.Width << "x" << c.Height; // 1 + k(R, R) rounds by 2^-24
  }
}

//------------------------------------------------------------------------------
TEST(RenderingBloomPassPSF, WithoutComputeShadersTheSceneRendersUnbloomedWithOneError)
{
  // vtkBloomPassTesting::SetSimulateComputeShaderFailure stands for a context without OpenGL 4.3.
  BloomWindow w(120, 90);
  ASSERT_TRUE(vtkBloomBuildExampleScene("lit-spheres", w.Renderer, w.Bloom));
  w.Bloom->SetEmissionSourceToScene();
  w.Bloom->SetFloatPrecisionTo32Bit();
  w.Bloom->GetParameters()->SetBloomModeToPSF();
  vtkBloomPassTesting::SetSimulateComputeShaderFailure(w.Bloom, true);
  w.Bloom->CaptureResultOn();
  vtkNew<vtkBloomTest::EventCounter> errors;
  w.Bloom->AddObserver(vtkCommand::ErrorEvent, errors);
  for (int frame = 0; frame < 3; ++frame)
  {
    w.Window->Render();
  }
  EXPECT_EQ(errors->Count, 1);
  EXPECT_TRUE(w.Bloom->GetLastFrame()->GetBloomSkipped());
  vtkNew<vtkImageData> scene, result;
  ASSERT_TRUE(w.Bloom->ReadSceneImage(scene));
  ASSERT_TRUE(w.Bloom->ReadResultImage(result));
  EXPECT_EQ(vtkBloomTest::ColourRelativeL2(result, scene), 0.0);
}

//------------------------------------------------------------------------------
TEST(RenderingBloomPassPSF, ASplitCoreWiderThanTheGPUsLimitIsRefusedWithOneError)
{
  // vtkBloomPassPSFSplit::MaximumCoreRadius (256): a wider core is refused, once, and the
  // scene renders unbloomed; a core within the limit then blooms again.
  BloomWindow w(64, 48);
  ASSERT_TRUE(vtkBloomBuildExampleScene("lit-spheres", w.Renderer, w.Bloom));
  w.Bloom->SetEmissionSourceToScene();
  w.Bloom->CaptureResultOn();
  vtkBloomParameters* parameters = w.Bloom->GetParameters();
  SetPSF(parameters, GAUSSIANS, 300, vtkImageSeparableGaussian::REFLECT);
  parameters->SetPSFTailScale(4);
  parameters->SetPSFCoreRadius(257);
  vtkNew<vtkBloomTest::EventCounter> errors;
  w.Bloom->AddObserver(vtkCommand::ErrorEvent, errors);
  for (int frame = 0; frame < 2; ++frame)
  {
    w.Window->Render();
  }
  EXPECT_EQ(errors->Count, 1);
  EXPECT_TRUE(w.Bloom->GetLastFrame()->GetBloomSkipped());
  parameters->SetPSFCoreRadius(256);
  w.Window->Render();
  EXPECT_EQ(errors->Count, 1);
  EXPECT_FALSE(w.Bloom->GetLastFrame()->GetBloomSkipped());
}

//------------------------------------------------------------------------------
TEST(RenderingBloomPassPSF, ThePyramidModeIsUnchangedAfterPSFMode)
{
  // Switching PSF mode on and off again renders the pyramid's bloom as before, bit for bit.
  BloomWindow w(160, 120);
  ASSERT_TRUE(vtkBloomBuildExampleScene("lit-spheres", w.Renderer, w.Bloom));
  w.Bloom->SetEmissionSourceToScene();
  w.Bloom->CaptureResultOn();
  w.Window->Render();
  vtkNew<vtkImageData> before, psf, after;
  ASSERT_TRUE(w.Bloom->ReadResultImage(before));
  w.Bloom->GetParameters()->SetBloomModeToPSF();
  w.Window->Render();
  ASSERT_TRUE(w.Bloom->ReadResultImage(psf));
  EXPECT_GT(vtkBloomTest::ColourRelativeL2(psf, before), 1e-3);
  w.Bloom->GetParameters()->SetBloomMode(vtkBloomParameters::BLOOM_PYRAMID);
  w.Window->Render();
  ASSERT_TRUE(w.Bloom->ReadResultImage(after));
  EXPECT_EQ(vtkBloomTest::ColourRelativeL2(after, before), 0.0);
}
