// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// Tests of vtkBloomPass's wide blurs through an FFT in compute shaders (vtkBloomPassFFTBlur):
// with ConvolutionMode FFT, the ping-pong preset (32 clamped passes folded into one operator,
// whose border corrections are not zero) and a wide Gaussian at level 0 agree with
// vtkImageBloom's REFERENCE chain at odd and even sizes, with bright spots on the borders; the
// profile names the FFT passes; AUTOMATIC picks the FFT for ping-pong and the direct passes
// for the default preset; without compute shaders the direct passes run.
#include "vtkBloomOpenGLEnvironment.h"
#include "vtkBloomParameters.h"
#include "vtkBloomPass.h"
#include "vtkBloomPassTestWindow.h"
#include "vtkBloomPassTesting.h"
#include "vtkBloomTestSupport.h"

#include "vtkBloomVTKCompat.h"
#include "vtkDataArray.h"
#include "vtkImageBloom.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace
{
// A dim RGBA float image with bright spots, some of them on the borders and in the corners
// (where the repeated clamped passes leave their correction), alpha 1.
vtkSmartPointer<vtkImageData> SpotImage(int width, int height)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(width, height, 1);
  image->AllocateScalars(VTK_FLOAT, 4);
  vtkDataArray* values = image->GetPointData()->GetScalars();
  for (int y = 0; y < height; ++y)
  {
    for (int x = 0; x < width; ++x)
    {
      const vtkIdType p = static_cast<vtkIdType>(y) * width + x;
      const double ramp = 0.2 + 0.3 * x / width;
      values->SetComponent(p, 0, ramp);
      values->SetComponent(p, 1, 0.5 - 0.2 * y / height);
      values->SetComponent(p, 2, 0.3);
      values->SetComponent(p, 3, 1.0);
    }
  }
  const int spots[][2] = { { 0, 0 }, { width - 1, 3 }, { width / 3, height - 1 },
    { width / 2, height / 2 }, { 2, height / 3 }, { width - 2, height - 2 } };
  int index = 0;
  for (const auto& s : spots)
  {
    for (int dy = -1; dy <= 1; ++dy)
    {
      for (int dx = -1; dx <= 1; ++dx)
      {
        const int x = s[0] + dx, y = s[1] + dy;
        if (x < 0 || y < 0 || x >= width || y >= height)
        {
          continue;
        }
        const vtkIdType p = static_cast<vtkIdType>(y) * width + x;
        values->SetComponent(p, 0, 8.0 + index);
        values->SetComponent(p, 1, 3.0 * (index % 3));
        values->SetComponent(p, 2, 20.0 - 2.0 * index);
      }
    }
    ++index;
  }
  return image;
}

// The names of the last render's profiled passes.
std::vector<std::string> PassNames(vtkBloomPass* bloom)
{
  std::vector<std::string> names;
  for (const auto& pass : vtkBloomPassTesting::GetProfile(bloom))
  {
    names.push_back(pass.Name);
  }
  return names;
}

bool Has(const std::vector<std::string>& names, const std::string& name)
{
  for (const std::string& n : names)
  {
    if (n == name)
    {
      return true;
    }
  }
  return false;
}

// The parameters of one case: a preset, or the default preset with one wide Gaussian level.
void UseCase(vtkBloomPass* bloom, const std::string& which)
{
  if (which == "wide-gaussian")
  {
    ASSERT_TRUE(bloom->SetPreset("webgpu-market"));
    vtkBloomParameters* p = bloom->GetParameters();
    p->SetStartLevel(0);
    p->SetNumberOfLevels(2);
    p->SetBlurKernel(vtkBloomParameters::BLUR_GAUSSIAN);
    p->SetBlurTapSpacing(1.0);
    p->SetBlurStandardDeviation(40.0);
    p->SetBlurRadius(-1);
  }
  else
  {
    ASSERT_TRUE(bloom->SetPreset(which.c_str()));
  }
}

struct Result
{
  double Error = 1.0; ///< bloom term against the CPU REFERENCE
  std::vector<std::string> Profile;
};

// The GPU bloom of SpotImage(width, height) for `which` and `mode`, against vtkImageBloom's
// REFERENCE chain with the same parameters.
Result Agreement(const std::string& which, int mode, int width, int height, bool compute = true,
  int precision = vtkBloomPass::FLOAT32)
{
  BloomWindow w(16, 16);
  UseCase(w.Bloom, which);
  w.Bloom->GetParameters()->SetConvolutionMode(mode);
  w.Bloom->SetFloatPrecision(precision);
  w.Bloom->SetUseComputeShaders(compute);
  vtkBloomPassTesting::SetProfilePasses(w.Bloom, true);
  vtkSmartPointer<vtkImageData> input = SpotImage(width, height);
  vtkNew<vtkImageData> gpu;
  Result r;
  EXPECT_TRUE(w.Bloom->ApplyToImage(w.GL(), input, gpu));
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  r.Profile = PassNames(w.Bloom);
  vtkNew<vtkImageBloom> cpu;
  cpu->SetParameters(w.Bloom->GetParameters());
  cpu->SetExecutionModeToReference();
  cpu->SetInputData(input);
  cpu->Update();
  r.Error = vtkBloomTest::BloomRelativeL2(input, gpu, cpu->GetOutput());
  std::cout << "[ fft-blur ] " << which << " " << width << "x" << height << " mode " << mode
            << (compute ? "" : " (fragments)") << " bloom relative L2 " << r.Error << "\n";
  return r;
}

bool ComputeShaders()
{
  return vtkBloomTestComputePassesRun();
}
}

//------------------------------------------------------------------------------
TEST(RenderingBloomPassFFTBlur, WideOperatorsThroughTheFFTAgreeWithTheReference)
{
  if (!ComputeShaders())
  {
    GTEST_SKIP() << "no OpenGL 4.3 compute shaders";
  }
  for (const std::string which : { "ping-pong", "wide-gaussian" })
  {
    for (const auto& size :
      { std::vector<int>{ 481, 409 }, std::vector<int>{ 480, 400 }, std::vector<int>{ 390, 512 } })
    {
      const Result r = Agreement(which, vtkBloomParameters::CONVOLUTION_FFT, size[0], size[1]);
      EXPECT_LE(r.Error, 1e-5) << which << " " << size[0] << "x" << size[1];
      EXPECT_TRUE(Has(r.Profile, "blur-x-fft L0")) << which;
      EXPECT_TRUE(Has(r.Profile, "blur-x-fft-finish L0")) << which;
      EXPECT_TRUE(Has(r.Profile, "blur-y-fft L0")) << which;
      EXPECT_TRUE(Has(r.Profile, "blur-y-fft-finish L0")) << which;
      EXPECT_FALSE(Has(r.Profile, "blur-x L0")) << which;
    }
  }
}

//------------------------------------------------------------------------------
TEST(RenderingBloomPassFFTBlur, HalfFloatTargetsThroughTheFFT)
{
  if (!ComputeShaders())
  {
    GTEST_SKIP() << "no OpenGL 4.3 compute shaders";
  }
  // ApplyToImage stores the input itself in half floats: against the REFERENCE, the FFT must
  // do as well as the direct passes on the same targets.
  const Result r = Agreement(
    "ping-pong", vtkBloomParameters::CONVOLUTION_FFT, 481, 409, true, vtkBloomPass::FLOAT16);
  const Result direct = Agreement(
    "ping-pong", vtkBloomParameters::CONVOLUTION_DIRECT, 481, 409, true, vtkBloomPass::FLOAT16);
  EXPECT_LE(r.Error, 1.1 * direct.Error + 1e-4);
  EXPECT_TRUE(Has(r.Profile, "blur-y-fft L0"));
}

//------------------------------------------------------------------------------
TEST(RenderingBloomPassFFTBlur, AutomaticChoosesByTheCostModel)
{
  if (!ComputeShaders())
  {
    GTEST_SKIP() << "no OpenGL 4.3 compute shaders";
  }
  // 385 taps per sample against a transform of about 2 N log2 N / n per sample: the FFT (the
  // lines must be longer than the operator, or it has no convolution interior).
  const Result pingPong =
    Agreement("ping-pong", vtkBloomParameters::CONVOLUTION_AUTOMATIC, 480, 400);
  EXPECT_TRUE(Has(pingPong.Profile, "blur-x-fft L0"));
  EXPECT_LE(pingPong.Error, 1e-5);
  // A few taps per sample: the direct passes.
  const Result market =
    Agreement("webgpu-market", vtkBloomParameters::CONVOLUTION_AUTOMATIC, 301, 207);
  // (its x and y halves as one tiled pass, or inside the level's upsample, where vtkBloomPass
  // fuses them, as on a GPU)
  EXPECT_TRUE(Has(market.Profile, "blur-x L1") || Has(market.Profile, "blur-xy L1") ||
    Has(market.Profile, "up-xy L1"));
  for (const std::string& name : market.Profile)
  {
    EXPECT_EQ(name.find("-fft"), std::string::npos) << name;
  }
  // DIRECT never takes the FFT.
  const Result direct = Agreement("ping-pong", vtkBloomParameters::CONVOLUTION_DIRECT, 480, 400);
  EXPECT_TRUE(Has(direct.Profile, "blur-x L0") || Has(direct.Profile, "blur-xy L0"));
  EXPECT_FALSE(Has(direct.Profile, "blur-x-fft L0"));
}

//------------------------------------------------------------------------------
TEST(RenderingBloomPassFFTBlur, WithoutComputeShadersTheDirectPassesRun)
{
  const Result r =
    Agreement("ping-pong", vtkBloomParameters::CONVOLUTION_FFT, 120, 81, /*compute=*/false);
  EXPECT_LE(r.Error, 1e-5);
  EXPECT_TRUE(Has(r.Profile, "blur-x L0"));
  EXPECT_FALSE(Has(r.Profile, "blur-x-fft L0"));
}
