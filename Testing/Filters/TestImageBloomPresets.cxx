// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// vtkImageBloom presets against the independent float64 reference of PRESETS.md, on synthetic
// HDR images of many sizes (1x1 up to 161x91), float and double, 1 to 4 components.
#include "vtkBloomReference.h"
#include "vtkBloomTestSupport.h"

#include <vtkImageBloom.h>
#include <vtkImageBloomThreshold.h>
#include <vtkImageData.h>
#include <vtkImagePyramidDown.h>
#include <vtkImagePyramidUp.h>
#include <vtkImageSeparableGaussian.h>
#include <vtkNew.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <string>
#include <tuple>

using vtkBloomRef::Texture;

namespace
{
const std::pair<int, int> Sizes[] = { { 1, 1 }, { 1, 7 }, { 2, 3 }, { 5, 5 }, { 17, 9 }, { 33, 20 },
  { 64, 64 }, { 161, 91 } };

vtkSmartPointer<vtkImageData> RunPreset(
  const std::string& preset, vtkImageData* input, bool* accepted = nullptr)
{
  vtkNew<vtkImageBloom> bloom;
  const bool ok = bloom->SetPreset(preset.c_str());
  if (accepted)
  {
    *accepted = ok;
  }
  return vtkBloomTest::RunAndCopy(bloom, input);
}

// R = G = B = the red channel, alpha kept: the RGB image a 1-2 component image stands for.
Texture Gray(const Texture& in)
{
  Texture out = in;
  for (vtkBloomRef::Pixel& p : out.Texels)
  {
    p[1] = p[2] = p[0];
  }
  return out;
}

// True when component `c` of both images holds exactly the same values.
bool SameComponent(vtkImageData* a, vtkImageData* b, int ca, int cb)
{
  int ea[6], eb[6];
  a->GetExtent(ea);
  b->GetExtent(eb);
  for (int j = 0; j <= ea[3] - ea[2]; ++j)
  {
    for (int i = 0; i <= ea[1] - ea[0]; ++i)
    {
      if (a->GetScalarComponentAsDouble(ea[0] + i, ea[2] + j, ea[4], ca) !=
        b->GetScalarComponentAsDouble(eb[0] + i, eb[2] + j, eb[4], cb))
      {
        return false;
      }
    }
  }
  return true;
}

using Param = std::tuple<const char*, int>; // preset, image kind (0 scene, 1 random)

class FiltersPresets : public ::testing::TestWithParam<Param>
{
};
}

// Every preset, sizes 1x1 .. 161x91, against the reference: rel L2 over RGB <= 1e-6 for double
// input and 1e-5 for float; alpha copied bit for bit; 1-2 component images behave as the RGB
// image R = G = B (luminance = the value).
TEST_P(FiltersPresets, MatchesReference)
{
  const std::string preset = std::get<0>(GetParam());
  const int kind = std::get<1>(GetParam());
  unsigned seed = 11;
  for (const auto& size : Sizes)
  {
    ++seed;
    const int w = size.first, h = size.second;
    const Texture image = kind == 0 ? vtkBloomRef::SyntheticScene(w, h, seed)
                                    : vtkBloomRef::RandomImage(w, h, seed, 0.0, 3.0);
    const Texture expected = vtkBloomRef::Preset(preset.c_str(), image);
    const Texture gray = Gray(image);
    const Texture expectedGray = vtkBloomRef::Preset(preset.c_str(), gray);
    // A bloom that does nothing would pass too easily: the reference must differ from the input
    // on the larger images.
    if (w * h >= 25)
    {
      EXPECT_GT(vtkBloomRef::RelativeL2(image, expected, 3), 1e-3)
        << preset << " " << w << "x" << h;
    }

    struct Variant
    {
      int Components;
      int Type;
    };
    const Variant variants[] = { { 4, VTK_DOUBLE }, { 3, VTK_DOUBLE }, { 4, VTK_FLOAT },
      { 3, VTK_FLOAT }, { 1, VTK_DOUBLE }, { 2, VTK_FLOAT } };
    for (const Variant& v : variants)
    {
      const bool grayInput = v.Components < 3;
      // One size uses a non-zero extent: nothing may depend on where the extent starts.
      const int lo[2] = { w == 17 ? -3 : 0, w == 17 ? 5 : 0 };
      auto input = vtkBloomRef::ToImage(grayInput ? gray : image, v.Components, v.Type, lo);
      auto out = RunPreset(preset, input);
      const std::string what = preset + " " + std::to_string(w) + "x" + std::to_string(h) + " " +
        std::to_string(v.Components) + (v.Type == VTK_FLOAT ? " float" : " double");
      ASSERT_EQ(out->GetNumberOfPoints(), static_cast<vtkIdType>(w) * h) << what;
      ASSERT_EQ(out->GetNumberOfScalarComponents(), v.Components) << what;
      EXPECT_EQ(out->GetScalarType(), v.Type) << what;
      int ext[6];
      out->GetExtent(ext);
      EXPECT_EQ(ext[0], lo[0]) << what;
      EXPECT_EQ(ext[2], lo[1]) << what;
      const double tolerance = v.Type == VTK_DOUBLE ? 1e-6 : 1e-5;
      const double error = vtkBloomRef::RelativeL2(
        vtkBloomRef::FromImage(out), grayInput ? expectedGray : expected, 3);
      EXPECT_LE(error, tolerance) << what;
      if (v.Components == 2 || v.Components == 4)
      {
        EXPECT_TRUE(SameComponent(out, input, v.Components - 1, v.Components - 1))
          << what << ": alpha changed";
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Filters, FiltersPresets,
  ::testing::Combine(::testing::Values("webgpu-market", "mip-atlas", "ping-pong", "crt-halfres"),
    ::testing::Values(0, 1)),
  [](const ::testing::TestParamInfo<Param>& info)
  {
    std::string n = std::get<0>(info.param);
    for (char& ch : n)
    {
      ch = ch == '-' ? '_' : ch;
    }
    return n + (std::get<1>(info.param) == 0 ? "_scene" : "_random");
  });

// The closed forms of PRESETS.md through the filter: constant 0.5 -> 0.607421875 under
// webgpu-market, constant c -> 0.88768 c under mip-atlas (all of LODs 2..8 present).
TEST(FiltersPresetsClosedForm, Constants)
{
  const int ext[6] = { 0, 19, 0, 11, 0, 0 };
  auto half = vtkBloomTest::MakeImage(
    ext, 4, VTK_DOUBLE, [](int, int, int, int c) { return c == 3 ? 0.75 : 0.5; });
  auto out = RunPreset("webgpu-market", half);
  EXPECT_NEAR(vtkBloomTest::Value(out, 7, 4, 0, 0), 0.607421875, 1e-9);
  EXPECT_NEAR(vtkBloomTest::Value(out, 0, 11, 0, 2), 0.607421875, 1e-9);
  EXPECT_EQ(vtkBloomTest::Value(out, 3, 3, 0, 3), 0.75);

  const int wide[6] = { 0, 299, 0, 2, 0, 0 };
  auto c =
    vtkBloomTest::MakeImage(wide, 3, VTK_DOUBLE, [](int, int, int, int ch) { return 1.0 + ch; });
  auto atlas = RunPreset("mip-atlas", c);
  for (int ch = 0; ch < 3; ++ch)
  {
    EXPECT_NEAR(vtkBloomTest::Value(atlas, 150, 1, 0, ch), 0.88768 * (1.0 + ch), 1e-12);
  }
}

// Every preset name is accepted and the list is exactly the four seeds.
TEST(FiltersPresetsClosedForm, Names)
{
  const auto names = vtkImageBloom::GetPresetNames();
  ASSERT_EQ(names.size(), 4u);
  for (const char* n : { "webgpu-market", "mip-atlas", "ping-pong", "crt-halfres" })
  {
    EXPECT_NE(std::find(names.begin(), names.end(), n), names.end()) << n;
    vtkNew<vtkImageBloom> bloom;
    EXPECT_TRUE(bloom->SetPreset(n)) << n;
  }
}

// CopyParameters carries every parameter: a filter given a preset's (or a hand-set
// configuration's) parameters by copy computes exactly what the original computes, and copying
// equal parameters leaves the filter unmodified, so it does not re-execute.
TEST(FiltersPresetsClosedForm, CopyParameters)
{
  const int extent[6] = { 0, 40, 0, 23, 0, 0 };
  auto image = vtkBloomTest::MakeImage(extent, 4, VTK_FLOAT,
    [](int i, int j, int, int ch)
    { return (i * 7 + j * 3) % 11 == 0 ? 4.0 + ch : 0.05 * ((i + j + ch) % 5); });
  std::vector<std::function<void(vtkImageBloom*)>> configurations;
  for (const std::string& name : vtkImageBloom::GetPresetNames())
  {
    configurations.emplace_back([name](vtkImageBloom* b) { b->SetPreset(name.c_str()); });
  }
  configurations.emplace_back(
    [](vtkImageBloom* b)
    {
      b->SetThreshold(0.3);
      b->SetKnee(0.0);
      b->SetNumberOfLevels(3);
      b->SetBlurStandardDeviation(2.5);
      b->SetLevelWeights({ 0.5, 1.0, 2.0 });
      b->SetTint(1.0, 0.5, 0.25);
      b->SetStrength(0.7);
      b->SetCompositeMode(vtkBloomParameters::LERP);
    });
  configurations.emplace_back(
    [](vtkImageBloom* b)
    {
      b->SetBloomModeToPSF();
      b->SetPSFGaussians({ 1.0, 3.0 }, { 0.75, 0.25 });
      b->SetExecutionModeToReference();
    });
  for (size_t k = 0; k < configurations.size(); ++k)
  {
    vtkNew<vtkImageBloom> original;
    configurations[k](original);
    vtkNew<vtkImageBloom> copy;
    copy->CopyParameters(original);
    const vtkMTimeType copied = copy->GetMTime();
    copy->CopyParameters(original);
    EXPECT_EQ(copy->GetMTime(), copied) << "configuration " << k;

    original->SetInputData(image);
    copy->SetInputData(image);
    original->Update();
    copy->Update();
    for (int ch = 0; ch < 4; ++ch)
    {
      EXPECT_TRUE(SameComponent(original->GetOutput(), copy->GetOutput(), ch, ch))
        << "configuration " << k << ", component " << ch;
    }
    // A default filter differs from every configuration here: the test can fail.
    vtkNew<vtkImageBloom> plain;
    plain->SetInputData(image);
    plain->Update();
    EXPECT_FALSE(SameComponent(original->GetOutput(), plain->GetOutput(), 0, 0))
      << "configuration " << k;
  }
}

namespace
{
// A vtkImageBloom configuration and the matching reference parameters.
struct GenericCase
{
  std::string Name;
  vtkBloomRef::BloomParameters Ref;
  std::function<void(vtkImageBloom*)> Configure;
  bool WhiteTint = true; // 1-2 component images stand for R = G = B only with a white tint
};

// The reference half kernel (centre first) of a Gaussian blur of the bloom.
std::vector<double> HalfGaussian(double sigma, int radius, vtkBloomRef::GaussianKind kind)
{
  const std::vector<double> full = vtkBloomRef::GaussianKernel(sigma, radius, kind);
  return std::vector<double>(full.begin() + full.size() / 2, full.end());
}

std::vector<GenericCase> GenericCases()
{
  std::vector<GenericCase> cases;
  {
    // The documented defaults: the excess knee at T 1 knee 0.5 (only light above 1 glows),
    // start level 1, 5 levels, 13-tap, sampled Gaussian sigma 1 with radius ceil(3 sigma) = 3,
    // tent cascade, additive, as they apply at the reference height (the test sets
    // ReferenceHeight 0: sizes in pixels).
    GenericCase c;
    c.Name = "defaults";
    c.Ref.Mode = vtkBloomRef::EXCESS_KNEE;
    c.Ref.BlurHalfKernel = HalfGaussian(1.0, 3, vtkBloomRef::SAMPLED);
    c.Configure = [](vtkImageBloom*) {};
    cases.push_back(c);
  }
  {
    // The defaults before the excess knee: the smoothstep knee from T - k to T + k.
    GenericCase c;
    c.Name = "smoothstep-knee";
    c.Ref.BlurHalfKernel = HalfGaussian(1.0, 3, vtkBloomRef::SAMPLED);
    c.Configure = [](vtkImageBloom* b)
    { b->GetParameters()->SetThresholdMode(vtkImageBloomThreshold::SMOOTHSTEP_KNEE); };
    cases.push_back(c);
  }
  {
    GenericCase c;
    c.Name = "quadratic-binomial-lerp-tint";
    c.Ref.Mode = vtkBloomRef::QUADRATIC_KNEE;
    c.Ref.Threshold = 0.7;
    c.Ref.Knee = 0.3;
    c.Ref.StartLevel = 0;
    c.Ref.NumberOfLevels = 3;
    c.Ref.Down = vtkBloomRef::BINOMIAL;
    c.Ref.BlurHalfKernel = HalfGaussian(1.5, 4, vtkBloomRef::DISCRETE);
    c.Ref.TapSpacing = 1.5;
    c.Ref.Iterations = 2;
    c.Ref.Up = vtkBloomRef::BILINEAR;
    c.Ref.LevelWeights = { 0.5, 1.0, 2.0 };
    c.Ref.Lerp = true;
    c.Ref.Strength = 0.3;
    c.Ref.Tint[1] = 0.5;
    c.Ref.Tint[2] = 0.25;
    c.WhiteTint = false;
    c.Configure = [](vtkImageBloom* b)
    {
      b->SetThresholdMode(vtkImageBloomThreshold::QUADRATIC_KNEE);
      b->SetThreshold(0.7);
      b->SetKnee(0.3);
      b->SetStartLevel(0);
      b->SetNumberOfLevels(3);
      b->SetDownsampleKernel(vtkImagePyramidDown::BINOMIAL);
      b->SetBlurStandardDeviation(1.5);
      b->SetBlurRadius(4);
      b->SetBlurGaussianKind(vtkImageSeparableGaussian::DISCRETE);
      b->SetBlurTapSpacing(1.5);
      b->SetBlurIterations(2);
      b->SetUpsampleKernel(vtkImagePyramidUp::BILINEAR);
      b->SetLevelWeights({ 0.5, 1.0, 2.0 });
      b->SetCompositeMode(vtkBloomParameters::LERP);
      b->SetStrength(0.3);
      b->SetTint(1.0, 0.5, 0.25);
    };
    cases.push_back(c);
  }
  {
    GenericCase c;
    c.Name = "hard-box-direct-limited";
    c.Ref.Mode = vtkBloomRef::HARD_LUMINANCE;
    c.Ref.Threshold = 1.2;
    c.Ref.StartLevel = 0; // start 1 has no level at 1x1 once limited
    c.Ref.NumberOfLevels = 7;
    c.Ref.LimitLevels = true;
    c.Ref.Down = vtkBloomRef::BOX;
    c.Ref.BlurHalfKernel = { 0.5, 0.3 }; // custom, not normalized: used as given
    c.Ref.Iterations = 3;
    c.Ref.Direct = true;
    c.Ref.LevelWeights = { 1.0, 0.0, 0.5 };
    c.Ref.Strength = 2.0;
    c.Configure = [](vtkImageBloom* b)
    {
      b->SetThresholdMode(vtkImageBloomThreshold::HARD_LUMINANCE);
      b->SetThreshold(1.2);
      b->SetStartLevel(0);
      b->SetNumberOfLevels(7);
      b->LimitLevelsToImageSizeOn();
      b->SetDownsampleKernel(vtkImagePyramidDown::BOX);
      b->SetBlurKernel(vtkBloomParameters::BLUR_CUSTOM);
      b->SetBlurHalfKernel({ 0.5, 0.3 });
      b->SetBlurIterations(3);
      b->SetAccumulateMode(vtkBloomParameters::DIRECT);
      b->SetLevelWeights({ 1.0, 0.0, 0.5 });
      b->SetStrength(2.0);
    };
    cases.push_back(c);
  }
  {
    GenericCase c;
    c.Name = "perchannel-karis-clamp";
    c.Ref.Mode = vtkBloomRef::PER_CHANNEL;
    c.Ref.Threshold = 0.5;
    c.Ref.ClampLuminance = 50.0;
    c.Ref.NumberOfLevels = 4;
    c.Ref.Karis = true;
    c.Ref.BlurHalfKernel = HalfGaussian(0.8, 3, vtkBloomRef::INTEGRATED);
    c.Ref.TapSpacing = 0.5;
    c.Ref.Direct = true;
    c.Configure = [](vtkImageBloom* b)
    {
      b->SetThresholdMode(vtkImageBloomThreshold::PER_CHANNEL);
      b->SetThreshold(0.5);
      b->SetClampLuminance(50.0);
      b->SetNumberOfLevels(4);
      b->KarisAverageOn();
      b->SetBlurStandardDeviation(0.8);
      b->SetBlurGaussianKind(vtkImageSeparableGaussian::INTEGRATED);
      b->SetBlurTapSpacing(0.5);
      b->SetAccumulateMode(vtkBloomParameters::DIRECT);
    };
    cases.push_back(c);
  }
  {
    GenericCase c;
    c.Name = "none-noblur-bloomonly-deep";
    c.Ref.Mode = vtkBloomRef::NONE;
    c.Ref.StartLevel = 2;
    c.Ref.NumberOfLevels = 9; // beyond 1x1 on small images: 1x1 levels repeat
    c.Ref.Iterations = 0;
    c.Ref.Lerp = true;
    c.Ref.Strength = 1.0;
    c.Configure = [](vtkImageBloom* b)
    {
      b->SetThresholdMode(vtkImageBloomThreshold::NONE);
      b->SetStartLevel(2);
      b->SetNumberOfLevels(9);
      b->SetBlurIterations(0);
      b->SetCompositeMode(vtkBloomParameters::LERP);
      b->SetStrength(1.0);
    };
    cases.push_back(c);
  }
  return cases;
}
}

// vtkImageBloom beyond the presets: every documented stage and option against the general
// reference chain, sizes 1x1 .. 64x64, 1/3/4 components, float and double.
TEST(FiltersBloomGeneric, MatchesReference)
{
  const std::pair<int, int> sizes[] = { { 1, 1 }, { 2, 3 }, { 5, 5 }, { 17, 9 }, { 33, 20 },
    { 64, 64 } };
  for (const GenericCase& c : GenericCases())
  {
    unsigned seed = 300;
    for (const auto& size : sizes)
    {
      const Texture image = vtkBloomRef::SyntheticScene(size.first, size.second, ++seed);
      const Texture expected = vtkBloomRef::Bloom(image, c.Ref);
      const Texture gray = Gray(image);
      const Texture expectedGray = vtkBloomRef::Bloom(gray, c.Ref);
      struct Variant
      {
        int Components;
        int Type;
      };
      for (const Variant& v :
        { Variant{ 4, VTK_DOUBLE }, Variant{ 3, VTK_FLOAT }, Variant{ 1, VTK_DOUBLE } })
      {
        if (v.Components == 1 && !c.WhiteTint)
        {
          continue;
        }
        vtkNew<vtkImageBloom> bloom;
        bloom->SetReferenceHeight(0); // the reference's sizes are pixels
        c.Configure(bloom);
        bloom->SetInputData(
          vtkBloomRef::ToImage(v.Components == 1 ? gray : image, v.Components, v.Type));
        bloom->Update();
        const double error = vtkBloomRef::RelativeL2(vtkBloomRef::FromImage(bloom->GetOutput()),
          v.Components == 1 ? expectedGray : expected, 3);
        EXPECT_LE(error, v.Type == VTK_DOUBLE ? 1e-9 : 1e-5)
          << c.Name << " " << size.first << "x" << size.second << " components " << v.Components;
      }
    }
  }
}

// ComputeLevelSizes: max(1, floor(n / 2)) per level from the start level, repeating at 1x1, or
// cut at floor(log2(max(W, H))) with LimitLevelsToImageSize.
TEST(FiltersBloomGeneric, LevelSizes)
{
  vtkNew<vtkImageBloom> bloom;
  bloom->SetReferenceHeight(0); // sizes in pixels
  bloom->SetStartLevel(1);
  bloom->SetNumberOfLevels(5);
  const std::vector<std::pair<int, int>> expected = { { 80, 45 }, { 40, 22 }, { 20, 11 }, { 10, 5 },
    { 5, 2 } };
  EXPECT_EQ(bloom->ComputeLevelSizes(161, 91), expected);
  bloom->SetNumberOfLevels(4);
  const std::vector<std::pair<int, int>> repeat = { { 1, 3 }, { 1, 1 }, { 1, 1 }, { 1, 1 } };
  EXPECT_EQ(bloom->ComputeLevelSizes(2, 7), repeat);
  bloom->LimitLevelsToImageSizeOn();
  const std::vector<std::pair<int, int>> limited = { { 1, 3 }, { 1, 1 } }; // log2(7) = 2
  EXPECT_EQ(bloom->ComputeLevelSizes(2, 7), limited);
}

// ReferenceHeight: at the reference height the parameters are pixels (the same bits as
// ReferenceHeight 0); at 2^k times it the pyramid starts k levels deeper, so the levels, and the
// blur in level pixels, are those of the reference frame; in between, the blur takes the
// remaining factor; a preset asked for by name keeps its seed's pixels.
TEST(FiltersBloomGeneric, ReferenceHeightScalesThePyramidAndTheBlur)
{
  vtkNew<vtkBloomParameters> p;
  EXPECT_EQ(p->GetReferenceHeight(), 1080);
  EXPECT_EQ(p->GetEffectiveStartLevel(1080), 1);
  EXPECT_EQ(p->GetBlurScale(1080), 1.0);
  EXPECT_EQ(p->GetEffectiveStartLevel(2160), 2);
  EXPECT_EQ(p->GetEffectiveStartLevel(4320), 3);
  EXPECT_EQ(p->GetEffectiveStartLevel(540), 0);
  EXPECT_EQ(p->GetBlurScale(4320), 1.0);
  EXPECT_NEAR(p->GetBlurScale(1440), 1440.0 / 1080.0, 1e-15);
  EXPECT_NEAR(p->GetBlurScale(270), 1.0, 1e-15);
  EXPECT_NEAR(p->GetBlurScale(720), 720.0 / 540.0, 1e-15); // one level shallower, then 4/3
  // 270 rows: two levels shallower than level 1 is above level 0, so the finest level of the
  // reference is dropped; the deepest level keeps its size (1080 / 2^5 = 270 / 2^3).
  EXPECT_EQ(p->GetEffectiveStartLevel(270), 0);
  EXPECT_EQ(p->GetDroppedLevels(270), 1);
  EXPECT_EQ(p->ComputeLevelSizes(480, 270).size(), 4u);
  EXPECT_EQ(
    p->ComputeLevelSizes(480, 270).back().second, p->ComputeLevelSizes(1920, 1080).back().second);
  p->SetLevelWeights({ 0.5, 2.0 });
  EXPECT_EQ(p->GetEffectiveLevelWeight(0, 270), 2.5); // the dropped level folds into level 0
  EXPECT_EQ(p->GetEffectiveLevelWeight(1, 270), 1.0);
  EXPECT_EQ(p->GetEffectiveLevelWeight(0, 1080), 0.5);
  p->SetLevelWeights(std::vector<double>());
  EXPECT_EQ(p->ComputeLevelSizes(3840, 2160).front(), std::make_pair(960, 540));
  EXPECT_EQ(p->ComputeLevelSizes(1920, 1080).front(), std::make_pair(960, 540));
  EXPECT_EQ(p->GetEffectiveBlurHalfKernel(2160), p->GetEffectiveBlurHalfKernel());
  EXPECT_GT(p->GetEffectiveBlurHalfKernel(1440).size(), p->GetEffectiveBlurHalfKernel().size());

  auto image = vtkBloomRef::ToImage(vtkBloomRef::SyntheticScene(33, 20, 5), 4, VTK_FLOAT);
  vtkNew<vtkImageBloom> pixels, reference;
  pixels->SetReferenceHeight(0);
  reference->SetReferenceHeight(20);
  EXPECT_TRUE(vtkBloomTest::BitIdentical(
    vtkBloomTest::RunAndCopy(pixels, image), vtkBloomTest::RunAndCopy(reference, image)));

  for (const std::string& preset : vtkBloomParameters::GetPresetNames())
  {
    vtkNew<vtkBloomParameters> seed;
    seed->SetPreset(preset.c_str());
    EXPECT_EQ(seed->GetReferenceHeight(), 0) << preset;
  }
}

// Strength 0 with ADDITIVE is the identity, bit for bit.
TEST(FiltersBloomGeneric, ZeroStrengthIsIdentity)
{
  auto input = vtkBloomRef::ToImage(vtkBloomRef::SyntheticScene(21, 13, 4), 4, VTK_FLOAT);
  for (const std::string& preset : vtkImageBloom::GetPresetNames())
  {
    if (preset == "mip-atlas")
    {
      continue; // LERP: strength 0 keeps (1 - 0) I, also exact, checked below
    }
    vtkNew<vtkImageBloom> bloom;
    bloom->SetPreset(preset.c_str());
    bloom->SetStrength(0.0);
    bloom->SetInputData(input);
    bloom->Update();
    EXPECT_TRUE(vtkBloomTest::BitIdentical(bloom->GetOutput(), input)) << preset;
  }
  vtkNew<vtkImageBloom> atlas;
  atlas->SetPreset("mip-atlas");
  atlas->SetStrength(0.0);
  atlas->SetInputData(input);
  atlas->Update();
  EXPECT_TRUE(vtkBloomTest::BitIdentical(atlas->GetOutput(), input));
}
