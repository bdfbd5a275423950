// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// Content-aware work is exact: the output is bit-identical with every switch on, with all off
// and with each one off, in both execution modes, over empty, sparse, full and non-finite
// scenes, odd sizes and every preset.
#include "vtkBloomPerformanceScenes.h"

#include <gtest/gtest.h>

using namespace vtkBloomPerformanceTest;

namespace
{
const char* const Presets[] = { "webgpu-market", "mip-atlas", "ping-pong", "crt-halfres" };

vtkSmartPointer<vtkImageData> RunWith(vtkImageData* input, const char* preset, int mode, int off,
  double strength = -1.0, vtkImageBloom* keep = nullptr)
{
  vtkNew<vtkImageBloom> local;
  vtkImageBloom* bloom = keep ? keep : local.Get();
  bloom->SetPreset(preset);
  if (strength >= 0.0)
  {
    bloom->SetStrength(strength);
  }
  bloom->SetExecutionMode(mode);
  // off: -1 none, 4 all, else the index of the one switch turned off.
  bloom->SetSkipEmptyBloom(!(off == 0 || off == 4));
  bloom->SetSkipDisabledEffects(!(off == 1 || off == 4));
  bloom->SetTrimPyramid(!(off == 2 || off == 4));
  bloom->SetRestrictToBrightRegion(!(off == 3 || off == 4));
  bloom->ComputeStatisticsOff();
  return vtkBloomTest::RunAndCopy(bloom, input);
}
}

TEST(PerformanceContentAware, BitIdenticalWithEachSwitchOnAndOff)
{
  const int sizes[][2] = { { 37, 53 }, { 6, 5 }, { 1, 1 } };
  for (int mode : { vtkImageBloom::FAST, vtkImageBloom::REFERENCE })
  {
    for (const char* preset : Presets)
    {
      for (int scene : { EMPTY, SINGLE, BLOB, RANDOM, SPECIAL })
      {
        for (const auto& size : sizes)
        {
          for (int nc : { 1, 4 })
          {
            for (bool sanitize : { true, false })
            {
              auto input = MakeScene(scene, size[0], size[1], nc);
              vtkNew<vtkImageBloom> on;
              on->SetSanitizeNonFinite(sanitize);
              auto reference = RunWith(input, preset, mode, -1, -1.0, on);
              for (int off = 0; off <= 4; ++off)
              {
                vtkNew<vtkImageBloom> other;
                other->SetSanitizeNonFinite(sanitize);
                auto result = RunWith(input, preset, mode, off, -1.0, other);
                EXPECT_TRUE(vtkBloomTest::BitIdentical(reference, result))
                  << "mode " << mode << " " << preset << " " << SceneName(scene) << " " << size[0]
                  << "x" << size[1] << " nc " << nc << " sanitize " << sanitize << " switch off "
                  << off;
              }
            }
          }
        }
      }
    }
  }
}

// Strength 0 (ADDITIVE and LERP) skips the bloom and still matches the full computation.
TEST(PerformanceContentAware, DisabledEffectsSkipExactly)
{
  for (int mode : { vtkImageBloom::FAST, vtkImageBloom::REFERENCE })
  {
    for (const char* preset : Presets)
    {
      auto input = MakeScene(RANDOM, 23, 19, 4);
      vtkNew<vtkImageBloom> on;
      auto a = RunWith(input, preset, mode, -1, 0.0, on);
      EXPECT_TRUE(on->GetLastBloomSkipped()) << preset;
      auto b = RunWith(input, preset, mode, 4, 0.0);
      EXPECT_TRUE(vtkBloomTest::BitIdentical(a, b)) << preset << " mode " << mode;
    }
  }
}

// An empty frame costs one read pass: the output shares the input scalars, unless the input
// holds a sample that "in + 0" would change (-0 here), and both match the full computation.
TEST(PerformanceContentAware, EmptyFramePassesThrough)
{
  auto input = MakeScene(EMPTY, 64, 48, 4);
  vtkNew<vtkImageBloom> bloom;
  bloom->SetPreset("webgpu-market");
  bloom->SetInputData(input);
  bloom->Update();
  EXPECT_TRUE(bloom->GetLastRunWasFast());
  EXPECT_TRUE(bloom->GetLastBloomSkipped());
  EXPECT_TRUE(bloom->GetLastPassedThrough());
  EXPECT_EQ(bloom->GetOutput()->GetPointData()->GetScalars(), input->GetPointData()->GetScalars());
  auto full = RunWith(input, "webgpu-market", vtkImageBloom::FAST, 4);
  EXPECT_TRUE(vtkBloomTest::BitIdentical(bloom->GetOutput(), full));

  static_cast<float*>(input->GetScalarPointer(5, 5, 0))[1] = -0.0f;
  input->Modified();
  bloom->Update();
  EXPECT_TRUE(bloom->GetLastBloomSkipped());
  EXPECT_FALSE(bloom->GetLastPassedThrough());
  auto fullNegativeZero = RunWith(input, "webgpu-market", vtkImageBloom::FAST, 4);
  EXPECT_TRUE(vtkBloomTest::BitIdentical(bloom->GetOutput(), fullNegativeZero));
}

// A sparse scene builds the pyramid over the bright region only; an empty frame builds none.
TEST(PerformanceContentAware, LevelsBuilt)
{
  vtkNew<vtkImageBloom> bloom;
  bloom->SetPreset("webgpu-market");
  bloom->SetInputData(MakeScene(BLOB, 64, 48, 4));
  bloom->Update();
  EXPECT_EQ(bloom->GetLastLevelsBuilt(), 5);
  bloom->SetInputData(MakeScene(EMPTY, 64, 48, 4));
  bloom->Update();
  EXPECT_EQ(bloom->GetLastLevelsBuilt(), 0);
  // mip-atlas: weights end non-zero, so nothing is trimmed; a zero tail is.
  bloom->SetPreset("webgpu-market");
  bloom->SetLevelWeights({ 1.0, 1.0, 0.0, 0.0, 0.0 });
  bloom->SetInputData(MakeScene(BLOB, 64, 48, 4));
  bloom->Update();
  EXPECT_EQ(bloom->GetLastLevelsBuilt(), 2);
}
