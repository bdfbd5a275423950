// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// The fast chain (vtkImageBloom's default ExecutionMode) against the double-precision reference
// (ExecutionMode REFERENCE): every preset, odd and even sizes, 1 to 4 components.
#include "vtkBloomPerformanceScenes.h"

#include <gtest/gtest.h>

#include "vtkImagePyramidDown.h"

#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
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
    bloom->SetBlurKernel(vtkBloomParameters::BLUR_GAUSSIAN);
    bloom->SetBlurStandardDeviation(2.0);
    bloom->SetUpsampleKernel(1);
    bloom->SetCompositeMode(vtkBloomParameters::LERP);
    bloom->SetStrength(0.3);
    bloom->SetTint(1.0, 0.8, 0.6);
    bloom->SetLevelWeights({ 1.0, 0.8, 0.6, 0.5, 0.4, 0.3 });
    bloom->SetExecutionMode(mode);
    out[mode] = vtkBloomTest::RunAndCopy(bloom, input);
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

// Finite input near FLT_MAX whose bloom pushes the sums past it. The double reference overflows
// only when it casts its result; the float32 chain saturates its levels at FLT_MAX (an
// overflowing sum must not become Inf, and then NaN where a zero band weight meets it, which
// would drop the bloom). Sanitizing: every output finite and FLT_MAX exactly where the reference
// gives FLT_MAX. Not sanitizing: no NaN, and >= FLT_MAX where the reference gives +Inf. The
// composite's short form for clean input must leave the overflow to the general loop.
TEST(PerformanceFastPath, OverflowOfCleanInput)
{
  // The left half at 3e38 in every colour (its bloom is of the same order), the right half dim.
  auto input = MakeScene(BLOB, 64, 48, 4);
  float* v = static_cast<float*>(input->GetScalarPointer());
  for (vtkIdType t = 0; t < input->GetNumberOfPoints(); ++t)
  {
    for (int c = 0; c < 3; ++c)
    {
      v[t * 4 + c] = t % 64 < 32 ? 3.0e38f : 0.1f;
    }
  }
  for (bool sanitize : { true, false })
  {
    vtkNew<vtkImageBloom> fast, reference;
    for (vtkImageBloom* bloom : { fast.Get(), reference.Get() })
    {
      bloom->SetPreset("webgpu-market");
      bloom->SetClampLuminance(VTK_FLOAT_MAX);
      bloom->SetSanitizeNonFinite(sanitize);
      bloom->SetInputData(input);
    }
    reference->SetExecutionMode(vtkImageBloom::REFERENCE);
    fast->Update();
    reference->Update();
    ASSERT_TRUE(fast->GetLastRunWasFast());
    auto* f = static_cast<const float*>(fast->GetOutput()->GetScalarPointer());
    auto* r = static_cast<const float*>(reference->GetOutput()->GetScalarPointer());
    const float largest = std::numeric_limits<float>::max();
    int overflowed = 0;
    for (vtkIdType s = 0; s < input->GetNumberOfPoints() * 4; ++s)
    {
      ASSERT_FALSE(std::isnan(f[s])) << "sample " << s;
      if (sanitize)
      {
        ASSERT_TRUE(std::isfinite(f[s])) << "sample " << s;
        if (r[s] == largest)
        {
          ++overflowed;
          ASSERT_EQ(f[s], largest) << "sample " << s;
        }
      }
      else if (std::isinf(r[s]))
      {
        ++overflowed;
        ASSERT_GE(f[s], largest) << "sample " << s;
      }
    }
    EXPECT_GT(overflowed, 0) << "the scene must overflow somewhere";
    EXPECT_TRUE(AlphaCopied(input, fast->GetOutput()));
  }
}

// vtkImageBloom keeps its chain's operators between updates: a changed parameter (each kind of
// setter) or input size must rebuild them, so a re-used filter equals a fresh one bit for bit.
TEST(PerformanceFastPath, ReusedFilterEqualsAFreshOne)
{
  auto small = MakeScene(BLOB, 37, 53, 4);
  auto large = MakeScene(BLOB, 64, 48, 4);
  vtkNew<vtkImageBloom> reused;
  reused->SetPreset("webgpu-market");
  reused->SetInputData(small);
  reused->Update();
  const std::vector<std::function<void(vtkImageBloom*)>> changes = {
    [](vtkImageBloom* b) { b->SetBlurTapSpacing(1.5); },
    [](vtkImageBloom* b) { b->SetNumberOfLevels(3); },
    [](vtkImageBloom* b) { b->SetLevelWeight(1, 0.25); },
    [](vtkImageBloom* b)
    {
      const double half[] = { 0.5, 0.2, 0.05 };
      b->SetBlurHalfKernel(3, half);
    },
    [](vtkImageBloom* b) { b->SetDownsampleKernel(vtkImagePyramidDown::BOX); },
    [](vtkImageBloom* b) { b->SetPreset("crt-halfres"); },
  };
  for (size_t i = 0; i < changes.size(); ++i)
  {
    vtkImageData* input = i % 2 ? large : small;
    changes[i](reused);
    reused->SetInputData(input);
    reused->Update();
    vtkNew<vtkImageBloom> copy; // the same parameters in a filter that never ran
    copy->SetPreset("webgpu-market");
    for (size_t k = 0; k <= i; ++k)
    {
      changes[k](copy);
    }
    copy->SetInputData(input);
    copy->Update();
    ASSERT_TRUE(reused->GetLastRunWasFast());
    EXPECT_TRUE(vtkBloomTest::BitIdentical(reused->GetOutput(), copy->GetOutput()))
      << "change " << i;
  }
}

// The AVX2 copy of the fast chain computes every sample as the baseline copy does: the output is
// the same bit for bit, for every preset and a LERP Gaussian chain, with and without
// sanitizing, over sizes around the vector widths, every component count and -0/NaN/Inf input.
TEST(PerformanceFastPath, AVX2GivesTheBaselineBits)
{
  if (!vtkImageBloom::IsAVX2Available())
  {
    GTEST_SKIP() << "this build or CPU has no AVX2 code path";
  }
  const int sizes[][2] = { { 1, 1 }, { 7, 5 }, { 37, 53 }, { 161, 91 }, { 300, 17 } };
  std::vector<std::function<void(vtkImageBloom*)>> configs;
  for (const char* preset : Presets)
  {
    configs.push_back([preset](vtkImageBloom* b) { b->SetPreset(preset); });
  }
  configs.push_back(
    [](vtkImageBloom* b)
    {
      b->SetThresholdMode(1);
      b->SetStartLevel(1);
      b->SetNumberOfLevels(6);
      b->SetBlurKernel(vtkBloomParameters::BLUR_GAUSSIAN);
      b->SetBlurStandardDeviation(2.0);
      b->SetCompositeMode(vtkBloomParameters::LERP);
      b->SetStrength(0.3);
      b->SetTint(1.0, 0.8, 0.6);
    });
  for (size_t config = 0; config < configs.size(); ++config)
  {
    for (const auto& size : sizes)
    {
      for (int nc = 1; nc <= 4; ++nc)
      {
        for (int scene : { SINGLE, BLOB, RANDOM, SPECIAL })
        {
          for (bool sanitize : { true, false })
          {
            auto input = MakeScene(scene, size[0], size[1], nc);
            vtkSmartPointer<vtkImageData> out[2];
            for (int avx2 = 0; avx2 < 2; ++avx2)
            {
              vtkNew<vtkImageBloom> bloom;
              configs[config](bloom);
              bloom->SetUseAVX2(avx2 == 1);
              bloom->SetSanitizeNonFinite(sanitize);
              bloom->ComputeStatisticsOff();
              bloom->SetInputData(input);
              bloom->Update();
              ASSERT_TRUE(bloom->GetLastRunWasFast());
              ASSERT_EQ(bloom->GetLastRunUsedAVX2(), avx2 == 1);
              out[avx2] = vtkSmartPointer<vtkImageData>::New();
              out[avx2]->DeepCopy(bloom->GetOutput());
            }
            EXPECT_TRUE(vtkBloomTest::BitIdentical(out[0], out[1]))
              << "config " << config << " " << size[0] << "x" << size[1] << " nc " << nc << " "
              << SceneName(scene) << " sanitize " << sanitize;
          }
        }
      }
    }
  }
}

// The fast chain keeps its levels between updates and zeroes only what a pass reads outside
// the region it computed. A filter that first ran on a frame bright everywhere (every level
// full of non-zero samples) must give, on every later frame, the bits of a fresh filter.
TEST(PerformanceFastPath, ReusedWorkspaceHoldsNoStaleSamples)
{
  for (const char* preset : Presets)
  {
    for (int mode : { vtkBloomParameters::CASCADE, vtkBloomParameters::DIRECT })
    {
      for (int nc : { 1, 4 })
      {
        vtkNew<vtkImageBloom> reused;
        reused->SetPreset(preset);
        reused->SetAccumulateMode(mode);
        reused->ComputeStatisticsOff();
        for (int scene : { RANDOM, BLOB, SINGLE, EMPTY, SPECIAL, SINGLE })
        {
          auto input = MakeScene(scene, 161, 91, nc);
          reused->SetInputData(input);
          reused->Update();
          vtkNew<vtkImageBloom> fresh;
          fresh->SetPreset(preset);
          fresh->SetAccumulateMode(mode);
          fresh->ComputeStatisticsOff();
          fresh->SetInputData(input);
          fresh->Update();
          ASSERT_TRUE(reused->GetLastRunWasFast());
          EXPECT_TRUE(vtkBloomTest::BitIdentical(reused->GetOutput(), fresh->GetOutput()))
            << preset << " accumulate " << mode << " nc " << nc << " " << SceneName(scene);
        }
      }
    }
  }
}
