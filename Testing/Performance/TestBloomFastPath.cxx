// The fast chain (vtkImageBloom's default ExecutionMode) against the double-precision reference
// (ExecutionMode REFERENCE): every preset, odd and even sizes, 1 to 4 components.
#include "vtkBloomPerformanceScenes.h"

#include <gtest/gtest.h>

#include <cstring>
#include <vector>

using namespace vtkBloomPerformanceTest;

namespace
{
const char* const Presets[] = { "webgpu-market", "mip-atlas", "ping-pong", "crt-halfres" };
const int Sizes[][2] = { { 1, 1 }, { 2, 3 }, { 7, 5 }, { 37, 53 }, { 64, 48 }, { 161, 91 } };

// Alpha of `out` equals alpha of `in` bit for bit.
bool AlphaCopied(vtkImageData* in, vtkImageData* out)
{
  const int nc = in->GetNumberOfScalarComponents();
  if (nc != 2 && nc != 4)
  {
    return true;
  }
  auto* a = static_cast<const float*>(in->GetScalarPointer());
  auto* b = static_cast<const float*>(out->GetScalarPointer());
  for (vtkIdType t = 0; t < in->GetNumberOfPoints(); ++t)
  {
    if (std::memcmp(a + t * nc + nc - 1, b + t * nc + nc - 1, sizeof(float)) != 0)
    {
      return false;
    }
  }
  return true;
}
}

// Float32 arithmetic against double: relative L2 <= 1e-5 over the colour components.
TEST(PerformanceFastPath, AgreesWithReferenceForEveryPreset)
{
  for (const char* preset : Presets)
  {
    for (const auto& size : Sizes)
    {
      for (int nc = 1; nc <= 4; ++nc)
      {
        for (int scene : { SINGLE, BLOB, RANDOM })
        {
          auto input = MakeScene(scene, size[0], size[1], nc);
          vtkNew<vtkImageBloom> fast;
          auto f = RunBloom(input, preset, vtkImageBloom::FAST, true, fast);
          ASSERT_TRUE(fast->GetLastRunWasFast()) << preset;
          auto r = RunBloom(input, preset, vtkImageBloom::REFERENCE, true);
          EXPECT_LE(ColourRelativeL2(f, r), 1e-5) << preset << " " << size[0] << "x" << size[1]
                                                  << " nc " << nc << " " << SceneName(scene);
          EXPECT_TRUE(AlphaCopied(input, f)) << preset;
        }
      }
    }
  }
}

// The configuration of the OpenCV-like benchmark chain (quadratic knee, 6 levels, Gaussian
// sigma 2, bilinear upsample, LERP) agrees too.
TEST(PerformanceFastPath, AgreesWithReferenceForAGaussianChain)
{
  auto input = MakeScene(RANDOM, 97, 61, 4);
  vtkSmartPointer<vtkImageData> out[2];
  for (int mode : { vtkImageBloom::FAST, vtkImageBloom::REFERENCE })
  {
    vtkNew<vtkImageBloom> bloom;
    bloom->SetThresholdMode(1);
    bloom->SetThreshold(1.0);
    bloom->SetStartLevel(1);
    bloom->SetNumberOfLevels(6);
    bloom->SetDownsampleKernel(1);
    bloom->SetBlurKernel(vtkImageBloom::BLUR_GAUSSIAN);
    bloom->SetBlurStandardDeviation(2.0);
    bloom->SetUpsampleKernel(1);
    bloom->SetCompositeMode(vtkImageBloom::LERP);
    bloom->SetStrength(0.3);
    bloom->SetTint(1.0, 0.8, 0.6);
    bloom->SetLevelWeights({ 1.0, 0.8, 0.6, 0.5, 0.4, 0.3 });
    bloom->SetExecutionMode(mode);
    bloom->SetInputData(input);
    bloom->Update();
    out[mode] = vtkSmartPointer<vtkImageData>::New();
    out[mode]->DeepCopy(bloom->GetOutput());
  }
  EXPECT_LE(ColourRelativeL2(out[0], out[1]), 1e-5);
}

// Double input asks for double precision: FAST runs the reference for it, bit for bit.
TEST(PerformanceFastPath, DoubleInputRunsTheReference)
{
  auto input = MakeScene(BLOB, 41, 29, 4, VTK_DOUBLE);
  vtkNew<vtkImageBloom> fast;
  auto f = RunBloom(input, "webgpu-market", vtkImageBloom::FAST, true, fast);
  EXPECT_FALSE(fast->GetLastRunWasFast());
  auto r = RunBloom(input, "webgpu-market", vtkImageBloom::REFERENCE, true);
  EXPECT_TRUE(vtkBloomTest::BitIdentical(f, r));
}

// SanitizeNonFinite in the fast chain: on, every output is finite; off, a non-finite input
// sample reaches only its own output pixel.
TEST(PerformanceFastPath, NonFiniteInput)
{
  for (const char* preset : Presets)
  {
    auto input = MakeScene(SPECIAL, 45, 33, 4);
    for (bool sanitize : { true, false })
    {
      vtkNew<vtkImageBloom> bloom;
      bloom->SetPreset(preset);
      bloom->SetSanitizeNonFinite(sanitize);
      bloom->SetInputData(input);
      bloom->Update();
      ASSERT_TRUE(bloom->GetLastRunWasFast());
      auto* in = static_cast<const float*>(input->GetScalarPointer());
      auto* out = static_cast<const float*>(bloom->GetOutput()->GetScalarPointer());
      for (vtkIdType s = 0; s < input->GetNumberOfPoints() * 4; ++s)
      {
        if (sanitize || std::isfinite(in[s]))
        {
          ASSERT_TRUE(std::isfinite(out[s])) << preset << " sample " << s;
        }
      }
    }
  }
}

// The intermediate buffers of the default preset stay well under 1.5 frames.
TEST(PerformanceFastPath, WorkspaceIsSmall)
{
  auto input = MakeScene(RANDOM, 480, 270, 4);
  vtkNew<vtkImageBloom> bloom;
  bloom->SetInputData(input);
  bloom->SetPreset("webgpu-market");
  bloom->Update();
  const double frame = 480.0 * 270.0 * 4 * sizeof(float);
  EXPECT_GT(bloom->GetLastWorkspaceBytes(), 0);
  EXPECT_LE(bloom->GetLastWorkspaceBytes(), 1.5 * frame);
  bloom->ReleaseWorkspace();
  EXPECT_EQ(bloom->GetLastWorkspaceBytes(), 0);
}
