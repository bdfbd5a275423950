// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// vtkImageBloomThreshold: every mode against the formulas of its class documentation, on value
// sweeps that cross the threshold, and the documented edge cases (knee 0, value equal to the
// threshold, negative and non-finite input, alpha, the luminance clamp).
#include "vtkBloomBrightPass.h"
#include "vtkBloomReference.h"
#include "vtkBloomTestSupport.h"

#include <vtkDataArray.h>
#include <vtkImageBloom.h>
#include <vtkImageBloomThreshold.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

using vtkBloomRef::Pixel;

namespace
{
struct ThresholdSettings
{
  int Mode = vtkImageBloomThreshold::SMOOTHSTEP_KNEE;
  double Threshold = 1.0;
  double Knee = 0.5;
  double ClampLuminance = VTK_FLOAT_MAX;
};

vtkSmartPointer<vtkImageData> Apply(vtkImageData* input, const ThresholdSettings& s)
{
  vtkNew<vtkImageBloomThreshold> filter;
  filter->SetMode(s.Mode);
  filter->SetThreshold(s.Threshold);
  filter->SetKnee(s.Knee);
  filter->SetClampLuminance(s.ClampLuminance);
  return vtkBloomTest::RunAndCopy(filter, input);
}

// A 1-row image of the given pixels (nc components taken from each Pixel as ToImage does).
vtkSmartPointer<vtkImageData> Row(const std::vector<Pixel>& pixels, int nc, int type)
{
  vtkBloomRef::Texture t(static_cast<int>(pixels.size()), 1);
  t.Texels = pixels;
  return vtkBloomRef::ToImage(t, nc, type);
}

// The sweep: grey values from -0.5 to 3 in steps of 1/64 (exact in float), and coloured pixels
// whose luminance crosses the threshold, with a varying alpha.
std::vector<Pixel> Sweep()
{
  std::vector<Pixel> pixels;
  for (int s = -32; s <= 192; ++s)
  {
    const double v = s / 64.0;
    pixels.push_back({ v, v, v, 0.5 + s / 512.0 });
  }
  const Pixel hues[] = { { 1.0, 0.2, 0.1, 0 }, { 0.1, 1.0, 0.3, 0 }, { 0.2, 0.3, 1.0, 0 },
    { 1.0, 1.0, 0.0, 0 }, { 0.0, 0.0, 1.0, 0 } };
  for (const Pixel& hue : hues)
  {
    for (int s = 0; s <= 80; ++s)
    {
      const double scale = s / 16.0;
      pixels.push_back({ static_cast<float>(hue[0] * scale), static_cast<float>(hue[1] * scale),
        static_cast<float>(hue[2] * scale), 0.25 });
    }
  }
  return pixels;
}

const char* ModeName(int mode)
{
  return vtkImageBloomThreshold::GetModeName(mode);
}
}

// Every mode (and knee 0, 0.25, 0.5, 1 and thresholds 0.8, 1, 2.5) against the documented
// formulas, with 1 (value = luminance = brightness), 3 and 4 components, double and float.
TEST(FiltersThreshold, ModesMatchFormulas)
{
  const std::vector<Pixel> pixels = Sweep();
  for (int mode = 0; mode <= 4; ++mode)
  {
    for (double threshold : { 0.8, 1.0, 2.5 })
    {
      for (double knee : { 0.0, 0.25, 0.5, 1.0 })
      {
        ThresholdSettings s;
        s.Mode = mode;
        s.Threshold = threshold;
        s.Knee = knee;
        for (int nc : { 1, 3, 4 })
        {
          for (int type : { VTK_DOUBLE, VTK_FLOAT })
          {
            auto input = Row(pixels, nc, type);
            auto out = Apply(input, s);
            ASSERT_EQ(out->GetNumberOfPoints(), static_cast<vtkIdType>(pixels.size()));
            int failures = 0;
            // The reference sees exactly the values the filter was given.
            const vtkBloomRef::Texture in = vtkBloomRef::FromImage(input);
            for (size_t i = 0; i < pixels.size() && failures < 5; ++i)
            {
              const Pixel expected =
                vtkBloomRef::BrightPass(in.Texels[i], static_cast<vtkBloomRef::ThresholdMode>(mode),
                  threshold, knee, VTK_FLOAT_MAX, nc == 1 ? 1 : 3);
              for (int c = 0; c < (nc == 1 ? 1 : 3); ++c)
              {
                const double got = vtkBloomTest::Value(out, static_cast<int>(i), 0, 0, c);
                const double tolerance =
                  (type == VTK_DOUBLE ? 1e-14 : 1e-7) * std::max(1.0, std::abs(expected[c]));
                if (!(std::abs(got - expected[c]) <= tolerance))
                {
                  ++failures;
                  ADD_FAILURE() << ModeName(mode) << " T " << threshold << " knee " << knee
                                << " components " << nc << (type == VTK_FLOAT ? " float" : "")
                                << ": pixel " << i << " (" << in.Texels[i][0] << ", "
                                << in.Texels[i][1] << ", " << in.Texels[i][2] << ") channel " << c
                                << " got " << got << " expected " << expected[c];
                }
              }
            }
          }
        }
      }
    }
  }
}

// The sweep really crosses the threshold: some values are dropped, some kept, and the knee
// gives partial values in between (so the comparison above is not trivially satisfied).
TEST(FiltersThreshold, SweepCrossesThreshold)
{
  auto input = Row(Sweep(), 1, VTK_DOUBLE);
  ThresholdSettings s;
  auto out = Apply(input, s);
  int zero = 0, kept = 0, partial = 0;
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    const double v = vtkBloomTest::Value(input, static_cast<int>(i), 0, 0, 0);
    const double r = vtkBloomTest::Value(out, static_cast<int>(i), 0, 0, 0);
    if (r == 0.0)
    {
      ++zero;
    }
    else if (r == v)
    {
      ++kept;
    }
    else
    {
      ++partial;
      EXPECT_LT(r, v);
    }
  }
  EXPECT_GT(zero, 10);
  EXPECT_GT(kept, 10);
  EXPECT_GT(partial, 10);
}

// Knee 0 is well defined: no NaN and no negative output (the seed's smoothstep(t, t, x) is
// undefined; the quadratic knee divides by 4k + 1e-5).
TEST(FiltersThreshold, KneeZeroIsFinite)
{
  const std::vector<Pixel> pixels = Sweep();
  for (int mode :
    { vtkImageBloomThreshold::SMOOTHSTEP_KNEE, vtkImageBloomThreshold::QUADRATIC_KNEE })
  {
    for (double threshold : { 0.0, 1.0 })
    {
      ThresholdSettings s;
      s.Mode = mode;
      s.Knee = 0.0;
      s.Threshold = threshold;
      auto out = Apply(Row(pixels, 3, VTK_DOUBLE), s);
      vtkDataArray* scalars = out->GetPointData()->GetScalars();
      for (vtkIdType t = 0; t < scalars->GetNumberOfValues(); ++t)
      {
        const double v = scalars->GetVariantValue(t).ToDouble();
        EXPECT_TRUE(std::isfinite(v)) << ModeName(mode) << " T " << threshold << " value " << t;
        EXPECT_GE(v, 0.0) << ModeName(mode) << " T " << threshold << " value " << t;
      }
    }
  }
}

// A value exactly equal to the threshold: SMOOTHSTEP with knee 0 keeps it (lum >= T),
// HARD_LUMINANCE drops it (strictly greater), and the quadratic and per-channel knees give 0.
TEST(FiltersThreshold, ValueEqualToThreshold)
{
  for (double t : { 1.0, 0.75, 2.5 })
  {
    for (int type : { VTK_DOUBLE, VTK_FLOAT })
    {
      for (int nc : { 1, 2 })
      {
        auto input = Row({ { t, t, t, 0.5 } }, nc, type);
        ThresholdSettings s;
        s.Threshold = t;
        s.Knee = 0.0;
        s.Mode = vtkImageBloomThreshold::SMOOTHSTEP_KNEE;
        EXPECT_EQ(vtkBloomTest::Value(Apply(input, s), 0, 0, 0, 0), t) << t;
        s.Mode = vtkImageBloomThreshold::HARD_LUMINANCE;
        EXPECT_EQ(vtkBloomTest::Value(Apply(input, s), 0, 0, 0, 0), 0.0) << t;
        s.Mode = vtkImageBloomThreshold::QUADRATIC_KNEE;
        EXPECT_EQ(vtkBloomTest::Value(Apply(input, s), 0, 0, 0, 0), 0.0) << t;
        s.Mode = vtkImageBloomThreshold::PER_CHANNEL;
        EXPECT_EQ(vtkBloomTest::Value(Apply(input, s), 0, 0, 0, 0), 0.0) << t;
        // Just above: HARD keeps it.
        const double above = type == VTK_FLOAT ? std::nextafter(static_cast<float>(t), 10.0f)
                                               : std::nextafter(t, 10.0);
        auto up = Row({ { above, above, above, 0.5 } }, nc, type);
        s.Mode = vtkImageBloomThreshold::HARD_LUMINANCE;
        EXPECT_EQ(vtkBloomTest::Value(Apply(up, s), 0, 0, 0, 0), above) << t;
        // Just below: SMOOTHSTEP knee 0 drops it.
        const double below =
          type == VTK_FLOAT ? std::nextafter(static_cast<float>(t), 0.0f) : std::nextafter(t, 0.0);
        auto down = Row({ { below, below, below, 0.5 } }, nc, type);
        s.Mode = vtkImageBloomThreshold::SMOOTHSTEP_KNEE;
        EXPECT_EQ(vtkBloomTest::Value(Apply(down, s), 0, 0, 0, 0), 0.0) << t;
      }
    }
  }
}

// Negative input never emits light in modes 0..3, mixed-sign colours included; NONE is an
// exact identity (bit for bit, negative values and all).
TEST(FiltersThreshold, NegativeInput)
{
  std::vector<Pixel> pixels;
  for (int s = 0; s < 64; ++s)
  {
    const double a = -4.0 + s / 8.0;
    pixels.push_back({ -std::abs(a) - 0.1, -0.5, -3.0, -1.0 });
    pixels.push_back({ 6.0 + a, -2.0, 4.0, 0.5 }); // bright overall, one negative channel
    pixels.push_back({ -0.0, a, -a, 1.0 });
  }
  for (int type : { VTK_DOUBLE, VTK_FLOAT })
  {
    for (int nc : { 1, 3, 4 })
    {
      auto input = Row(pixels, nc, type);
      for (int mode = 0; mode < 4; ++mode)
      {
        for (double knee : { 0.0, 0.5 })
        {
          ThresholdSettings s;
          s.Mode = mode;
          s.Knee = knee;
          auto out = Apply(input, s);
          for (size_t i = 0; i < pixels.size(); ++i)
          {
            for (int c = 0; c < std::min(nc, 3); ++c)
            {
              EXPECT_GE(vtkBloomTest::Value(out, static_cast<int>(i), 0, 0, c), 0.0)
                << ModeName(mode) << " pixel " << i << " channel " << c;
            }
          }
        }
      }
      ThresholdSettings none;
      none.Mode = vtkImageBloomThreshold::NONE;
      none.ClampLuminance = 0.5; // NONE ignores even the clamp
      EXPECT_TRUE(vtkBloomTest::BitIdentical(Apply(input, none), input));
    }
  }
}

// Alpha (the 2nd of 2, the 4th of 4 components) passes through bit for bit in every mode,
// whatever its value.
TEST(FiltersThreshold, AlphaPassesThrough)
{
  const double alphas[] = { 0.0, -0.0, 1.0, 0.3, -7.5, 1e30,
    std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(), 1e-40 };
  std::vector<Pixel> pixels;
  for (int s = 0; s < 90; ++s)
  {
    const double v = s / 10.0;
    pixels.push_back({ v, 0.5 * v, 2.0 * v, alphas[s % 9] });
  }
  for (int type : { VTK_DOUBLE, VTK_FLOAT })
  {
    for (int nc : { 2, 4 })
    {
      auto input = Row(pixels, nc, type);
      for (int mode = 0; mode <= 4; ++mode)
      {
        ThresholdSettings s;
        s.Mode = mode;
        s.ClampLuminance = 3.0;
        auto out = Apply(input, s);
        const int size = input->GetScalarSize();
        for (size_t i = 0; i < pixels.size(); ++i)
        {
          const char* a =
            static_cast<const char*>(input->GetScalarPointer(static_cast<int>(i), 0, 0));
          const char* b =
            static_cast<const char*>(out->GetScalarPointer(static_cast<int>(i), 0, 0));
          EXPECT_EQ(std::memcmp(a + (nc - 1) * size, b + (nc - 1) * size, size), 0)
            << ModeName(mode) << " components " << nc << " pixel " << i;
        }
      }
    }
  }
}

// ClampLuminance bounds the output luminance in every mode but NONE, and the clamp preserves
// the hue (a pure clamp, with everything above the knee, is a uniform scale).
TEST(FiltersThreshold, ClampLuminanceBoundsLuminance)
{
  std::vector<Pixel> pixels;
  for (int s = 0; s < 100; ++s)
  {
    const double scale = std::pow(10.0, s / 20.0); // 1 .. 1e5
    pixels.push_back({ scale, 0.3 * scale, 0.05 * scale, 1.0 });
    pixels.push_back({ 0.1 * scale, scale, 2.0 * scale, 1.0 });
  }
  const double limit = 20.0;
  for (int mode = 0; mode < 4; ++mode)
  {
    ThresholdSettings s;
    s.Mode = mode;
    s.ClampLuminance = limit;
    auto input = Row(pixels, 3, VTK_DOUBLE);
    auto out = Apply(input, s);
    const vtkBloomRef::Texture result = vtkBloomRef::FromImage(out);
    for (size_t i = 0; i < pixels.size(); ++i)
    {
      EXPECT_LE(vtkBloomRef::Luminance(result.Texels[i]), limit * (1 + 1e-12))
        << ModeName(mode) << " pixel " << i;
      const Pixel expected = vtkBloomRef::BrightPass(
        pixels[i], static_cast<vtkBloomRef::ThresholdMode>(mode), 1.0, 0.5, limit);
      for (int c = 0; c < 3; ++c)
      {
        EXPECT_NEAR(result.Texels[i][c], expected[c], 1e-12 * std::max(1.0, expected[c]))
          << ModeName(mode) << " pixel " << i;
      }
    }
    if (mode == vtkImageBloomThreshold::SMOOTHSTEP_KNEE ||
      mode == vtkImageBloomThreshold::HARD_LUMINANCE)
    {
      // Far above the threshold the factor is 1: the colour is scaled to luminance 20 exactly.
      const Pixel& p = result.Texels[pixels.size() - 2];
      EXPECT_NEAR(vtkBloomRef::Luminance(p), limit, 1e-12 * limit);
      EXPECT_NEAR(p[1] / p[0], 0.3, 1e-12);
      EXPECT_NEAR(p[2] / p[0], 0.05, 1e-12);
    }
  }
}

// NaN and infinite colours never leave the bright pass as NaN or Inf (modes 0..3).
TEST(FiltersThreshold, NonFiniteInputGivesFiniteOutput)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<Pixel> pixels = { { nan, 1.0, 1.0, 1.0 }, { inf, 0.0, 0.0, 1.0 },
    { -inf, 2.0, 2.0, 1.0 }, { inf, inf, inf, 1.0 }, { nan, nan, nan, 1.0 },
    { 5.0, inf, nan, 1.0 } };
  for (int type : { VTK_DOUBLE, VTK_FLOAT })
  {
    for (int nc : { 1, 3, 4 })
    {
      for (int mode = 0; mode < 4; ++mode)
      {
        for (double clamp : { static_cast<double>(VTK_FLOAT_MAX), 50.0 })
        {
          ThresholdSettings s;
          s.Mode = mode;
          s.ClampLuminance = clamp;
          auto out = Apply(Row(pixels, nc, type), s);
          for (size_t i = 0; i < pixels.size(); ++i)
          {
            for (int c = 0; c < std::min(nc, 3); ++c)
            {
              const double v = vtkBloomTest::Value(out, static_cast<int>(i), 0, 0, c);
              EXPECT_TRUE(std::isfinite(v) && v >= 0.0)
                << ModeName(mode) << " clamp " << clamp << " pixel " << i << " channel " << c
                << " -> " << v;
            }
          }
        }
      }
    }
  }
}

// The documented defaults and mode names.
TEST(FiltersThreshold, Defaults)
{
  vtkNew<vtkImageBloomThreshold> filter;
  EXPECT_EQ(filter->GetMode(), vtkImageBloomThreshold::SMOOTHSTEP_KNEE);
  EXPECT_EQ(filter->GetThreshold(), 1.0);
  EXPECT_EQ(filter->GetKnee(), 0.5);
  EXPECT_EQ(filter->GetClampLuminance(), static_cast<double>(VTK_FLOAT_MAX));
  filter->SetKnee(3.0); // clamped to [0, 1]
  EXPECT_EQ(filter->GetKnee(), 1.0);
  filter->SetModeToPerChannel();
  EXPECT_EQ(filter->GetMode(), vtkImageBloomThreshold::PER_CHANNEL);
  EXPECT_STRNE(ModeName(0), ModeName(1));
}

// vtkBloomBrightPassIsZero lets the fused chain skip the full formula for dark samples, so it must
// never claim zero for a colour that the formula keeps, in float and in double, at the exact
// edges, for negative, huge and non-finite colours; and it must recognise clearly dark colours
// (otherwise the fast path never runs).
namespace
{
template <int N, typename Real>
void CheckIsZeroIsSound(int mode, double threshold, double knee, double clampLuminance)
{
  const Real k = static_cast<Real>(threshold * knee);
  const Real t = static_cast<Real>(threshold);
  const Real inf = std::numeric_limits<Real>::infinity();
  const Real special[] = { Real(0), -Real(0), t, t - k, t + k, std::nextafter(t - k, -inf),
    std::nextafter(t - k, inf), std::nextafter(t, -inf), std::nextafter(t, inf), Real(-1),
    Real(1e30), std::numeric_limits<Real>::max(), inf, -inf,
    std::numeric_limits<Real>::quiet_NaN() };
  std::mt19937 rng(17u + static_cast<unsigned>(mode));
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  int claimed = 0;
  for (int trial = 0; trial < 20000; ++trial)
  {
    Real colour[N];
    for (int c = 0; c < N; ++c)
    {
      const double u = uniform(rng);
      colour[c] = trial % 3 == 0
        ? special[static_cast<size_t>(u * (sizeof(special) / sizeof(special[0]))) %
            (sizeof(special) / sizeof(special[0]))]
        : static_cast<Real>(4.0 * threshold * (u - 0.25));
    }
    if (trial % 7 == 0)
    {
      for (int c = 0; c < N; ++c)
      {
        colour[c] = colour[0]; // grey: the luminance equals the value, edges are hit exactly
      }
    }
    const bool zero = vtkBloomBrightPassIsZero<N>(colour, mode, threshold, knee, clampLuminance);
    Real out[N];
    std::copy(colour, colour + N, out);
    vtkBloomMapNonFinite<N>(out, std::min(clampLuminance, static_cast<double>(VTK_FLOAT_MAX)));
    vtkBloomBrightPass<N>(out, mode, threshold, knee, clampLuminance);
    if (zero)
    {
      ++claimed;
      for (int c = 0; c < N; ++c)
      {
        ASSERT_EQ(out[c], Real(0))
          << "mode " << mode << " knee " << knee << " colour[" << c << "] " << colour[c];
      }
    }
  }
  EXPECT_GT(claimed, 1000) << "mode " << mode; // dark colours are recognised
}
}

TEST(FiltersThreshold, ZeroTestOfTheFusedChainIsSound)
{
  for (int mode : { vtkImageBloomThreshold::SMOOTHSTEP_KNEE, vtkImageBloomThreshold::QUADRATIC_KNEE,
         vtkImageBloomThreshold::HARD_LUMINANCE, vtkImageBloomThreshold::PER_CHANNEL })
  {
    for (double knee : { 0.0, 0.5, 1.0 })
    {
      for (double clampLuminance : { 1e4, static_cast<double>(VTK_FLOAT_MAX) })
      {
        CheckIsZeroIsSound<3, float>(mode, 0.8, knee, clampLuminance);
        CheckIsZeroIsSound<1, float>(mode, 0.8, knee, clampLuminance);
        CheckIsZeroIsSound<3, double>(mode, 1.0, knee, clampLuminance);
      }
    }
  }
  // NONE keeps every colour: nothing is ever claimed zero.
  const float dark[3] = { 0.0f, 0.0f, 0.0f };
  EXPECT_FALSE(vtkBloomBrightPassIsZero<3>(dark, vtkImageBloomThreshold::NONE, 1.0, 0.5, 1e4));
}

// vtkImageBloom's NumberOfBrightPixels (which decides most pixels dark without the formula)
// counts exactly the pixels this filter keeps: some colour value > 0 after the bright pass.
// Every mode, knee 0, a luminance clamp, float and double input, negative and non-finite values.
TEST(FiltersThreshold, BloomCountsThePixelsTheFilterKeeps)
{
  std::vector<Pixel> pixels = Sweep();
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const Pixel& p : std::vector<Pixel>{ { nan, 0.1, 0.1, 1 }, { inf, 0.0, 0.0, 1 },
         { -inf, 2.0, 2.0, 1 }, { 0.2, nan, 5.0, 1 }, { -0.0, -0.0, -0.0, 1 } })
  {
    pixels.push_back(p);
  }
  int partial = 0;
  for (int mode = 0; mode <= 4; ++mode)
  {
    for (double knee : { 0.0, 0.5 })
    {
      for (double clamp : { static_cast<double>(VTK_FLOAT_MAX), 1.5 })
      {
        for (int nc : { 1, 3, 4 })
        {
          for (int type : { VTK_DOUBLE, VTK_FLOAT })
          {
            ThresholdSettings s;
            s.Mode = mode;
            s.Knee = knee;
            s.ClampLuminance = clamp;
            auto input = Row(pixels, nc, type);
            // The filter in double on exactly the values of the input.
            auto kept =
              Apply(vtkBloomRef::ToImage(vtkBloomRef::FromImage(input), nc, VTK_DOUBLE), s);
            vtkIdType expected = 0;
            for (vtkIdType i = 0; i < kept->GetNumberOfPoints(); ++i)
            {
              bool bright = false;
              for (int c = 0; c < (nc == 1 ? 1 : 3); ++c)
              {
                bright = bright || vtkBloomTest::Value(kept, static_cast<int>(i), 0, 0, c) > 0.0;
              }
              expected += bright ? 1 : 0;
            }
            vtkNew<vtkImageBloom> bloom;
            bloom->SetThresholdMode(mode);
            bloom->SetThreshold(s.Threshold);
            bloom->SetKnee(knee);
            bloom->SetClampLuminance(clamp);
            bloom->ComputeStatisticsOn();
            bloom->SetInputData(input);
            bloom->Update();
            EXPECT_EQ(bloom->GetNumberOfBrightPixels(), expected)
              << ModeName(mode) << " knee " << knee << " clamp " << clamp << " nc " << nc
              << (type == VTK_FLOAT ? " float" : " double");
            partial += expected > 0 && expected < input->GetNumberOfPoints() ? 1 : 0;
          }
        }
      }
    }
  }
  EXPECT_GT(partial, 0) << "the sweep must keep some pixels and drop others";
}
