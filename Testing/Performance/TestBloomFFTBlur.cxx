// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// The level blurs through the FFT (vtkImageBloom::ConvolutionMode): they agree with the direct
// blurs for every preset, the ping-pong preset through them still matches its independent
// float64 reference, the content-aware work stays bit-exact through them, and AUTOMATIC picks
// the FFT for the ping-pong preset's 385-tap blur at 1080p but not for the default preset's
// 9-tap ones.
#include "vtkBloomPerformanceScenes.h"
#include "vtkBloomReference.h"

#include <gtest/gtest.h>

#include <cstring>

using namespace vtkBloomPerformanceTest;

namespace
{
vtkSmartPointer<vtkImageData> RunWithConvolution(vtkImageData* input, const std::string& preset,
  int convolution, bool adaptive = true, int* fftBlurs = nullptr)
{
  vtkNew<vtkImageBloom> bloom;
  bloom->SetConvolutionMode(convolution);
  auto out = RunBloom(input, preset, vtkImageBloom::FAST, adaptive, bloom);
  if (fftBlurs)
  {
    *fftBlurs = bloom->GetLastFFTBlurs();
  }
  return out;
}

// Relative L2 of the bloom terms out - in (colours only), which the composite's input term would
// otherwise dilute.
double BloomRelativeL2(vtkImageData* input, vtkImageData* a, vtkImageData* b)
{
  vtkDataArray* si = input->GetPointData()->GetScalars();
  vtkDataArray* sa = a->GetPointData()->GetScalars();
  vtkDataArray* sb = b->GetPointData()->GetScalars();
  const int colours = si->GetNumberOfComponents() >= 3 ? 3 : 1;
  double num = 0.0, den = 0.0;
  for (vtkIdType t = 0; t < si->GetNumberOfTuples(); ++t)
  {
    for (int c = 0; c < colours; ++c)
    {
      const double in = si->GetComponent(t, c);
      const double d = sa->GetComponent(t, c) - sb->GetComponent(t, c);
      num += d * d;
      den += (sb->GetComponent(t, c) - in) * (sb->GetComponent(t, c) - in);
    }
  }
  return std::sqrt(num / den);
}
}

TEST(PerformanceFFTBlur, AgreesWithTheDirectBlurForEveryPreset)
{
  for (const std::string& preset : vtkImageBloom::GetPresetNames())
  {
    for (int scene : { BLOB, RANDOM })
    {
      for (int nc : { 1, 4 })
      {
        auto input = MakeScene(scene, 640, 480, nc);
        int fftBlurs = 0;
        auto fft =
          RunWithConvolution(input, preset, vtkBloomParameters::CONVOLUTION_FFT, true, &fftBlurs);
        auto direct = RunWithConvolution(input, preset, vtkBloomParameters::CONVOLUTION_DIRECT);
        const std::string what = preset + " " + SceneName(scene) + " nc " + std::to_string(nc);
        EXPECT_GT(fftBlurs, 0) << what;
        EXPECT_LE(ColourRelativeL2(fft, direct), 1e-6) << what;
        EXPECT_LE(BloomRelativeL2(input, fft, direct), 1e-5) << what;
      }
    }
  }
}

TEST(PerformanceFFTBlur, PingPongMatchesItsFloat64Reference)
{
  auto input = MakeScene(BLOB, 512, 420, 4);
  const vtkBloomRef::Texture reference =
    vtkBloomRef::Preset("ping-pong", vtkBloomRef::FromImage(input));
  int fftBlurs = 0;
  auto fft =
    RunWithConvolution(input, "ping-pong", vtkBloomParameters::CONVOLUTION_FFT, true, &fftBlurs);
  EXPECT_EQ(fftBlurs, 2);
  EXPECT_LE(vtkBloomRef::RelativeL2(vtkBloomRef::FromImage(fft), reference, 3), 1e-6);
  // The bloom term alone: the reference minus its input.
  vtkBloomRef::Texture inTexture = vtkBloomRef::FromImage(input);
  vtkBloomRef::Texture bloomRef = reference, bloomFFT = vtkBloomRef::FromImage(fft);
  for (size_t i = 0; i < bloomRef.Texels.size(); ++i)
  {
    for (int c = 0; c < 4; ++c)
    {
      bloomRef.Texels[i][c] -= inTexture.Texels[i][c];
      bloomFFT.Texels[i][c] -= inTexture.Texels[i][c];
    }
  }
  EXPECT_LE(vtkBloomRef::RelativeL2(bloomFFT, bloomRef, 3), 1e-5);
}

TEST(PerformanceFFTBlur, ContentAwareWorkStaysExactThroughTheFFT)
{
  for (const char* preset : { "ping-pong", "webgpu-market" })
  {
    for (int scene : { EMPTY, SINGLE, BLOB, RANDOM, SPECIAL })
    {
      for (int nc : { 1, 4 })
      {
        auto input = MakeScene(scene, 430, 401, nc);
        auto on = RunWithConvolution(input, preset, vtkBloomParameters::CONVOLUTION_FFT, true);
        auto off = RunWithConvolution(input, preset, vtkBloomParameters::CONVOLUTION_FFT, false);
        vtkDataArray* a = on->GetPointData()->GetScalars();
        vtkDataArray* b = off->GetPointData()->GetScalars();
        ASSERT_EQ(a->GetNumberOfValues(), b->GetNumberOfValues());
        const float* pa = static_cast<const float*>(a->GetVoidPointer(0));
        const float* pb = static_cast<const float*>(b->GetVoidPointer(0));
        EXPECT_EQ(0, std::memcmp(pa, pb, sizeof(float) * a->GetNumberOfValues()))
          << preset << " " << SceneName(scene) << " nc " << nc;
      }
    }
  }
}

TEST(PerformanceFFTBlur, AutomaticChoosesByCost)
{
  auto input = MakeScene(SINGLE, 1920, 1080, 3);
  int fftBlurs = -1;
  RunWithConvolution(
    input, "ping-pong", vtkBloomParameters::CONVOLUTION_AUTOMATIC, true, &fftBlurs);
  EXPECT_EQ(fftBlurs, 2); // both axes of the one 385-tap level blur
  RunWithConvolution(
    input, "webgpu-market", vtkBloomParameters::CONVOLUTION_AUTOMATIC, true, &fftBlurs);
  EXPECT_EQ(fftBlurs, 0); // 9 taps: direct is cheaper
  RunWithConvolution(input, "ping-pong", vtkBloomParameters::CONVOLUTION_DIRECT, true, &fftBlurs);
  EXPECT_EQ(fftBlurs, 0);
}
