// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// The hard cases of issue 4 on the CPU filters: NaN/Inf input, fireflies, every half value,
// wide dynamic range, every size at every pyramid depth, the threshold at its edge, and the
// clamp of half-float output. Inputs and expectations come from vtkBloomHardCases, which the
// GPU suites share.
#include "vtkBloomHardCases.h"
#include "vtkBloomTestSupport.h"

#include <vtkDataArray.h>
#include <vtkImageBloom.h>
#include <vtkImageBloomThreshold.h>
#include <vtkImageData.h>
#include <vtkImagePyramidDown.h>
#include <vtkImagePyramidUp.h>
#include <vtkImageSeparableGaussian.h>
#include <vtkNew.h>
#include <vtkOpenEXRReader.h>
#include <vtkOpenEXRWriter.h>
#include <vtkPointData.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace
{
using vtkBloomHardCases::CountNonFinite;
using vtkBloomHardCases::Values;

vtkSmartPointer<vtkImageData> ReadExr(const std::string& path)
{
  vtkNew<vtkOpenEXRReader> reader;
  reader->SetFileName(path.c_str());
  return vtkBloomTest::UpdateAndCopy(reader);
}

vtkSmartPointer<vtkImageData> Bloom(vtkImageData* input, bool sanitize,
  const char* preset = "webgpu-market", double clampLuminance = VTK_FLOAT_MAX)
{
  vtkNew<vtkImageBloom> bloom;
  bloom->SetPreset(preset);
  bloom->SetSanitizeNonFinite(sanitize);
  bloom->SetClampLuminance(clampLuminance);
  return vtkBloomTest::RunAndCopy(bloom, input);
}

vtkSmartPointer<vtkImageData> Gaussian(
  vtkImageData* input, int method, double sigma, int border, bool sanitize)
{
  vtkNew<vtkImageSeparableGaussian> filter;
  filter->SetMethod(method);
  filter->SetStandardDeviations(sigma, sigma, 0.0);
  filter->SetBorderMode(border);
  filter->SetSanitizeNonFinite(sanitize);
  return vtkBloomTest::RunAndCopy(filter, input);
}

// Sanitize on: every output finite. Off: an output sample is non-finite exactly where the input
// sample is (the bright pass maps non-finite values, so only the composite carries them).
void ExpectBloomNonFinitePolicy(vtkImageData* input, const char* what)
{
  ASSERT_GT(CountNonFinite(input), 0) << what << " should hold non-finite samples";
  for (const char* preset : { "webgpu-market", "mip-atlas", "crt-halfres" })
  {
    auto on = Bloom(input, true, preset);
    EXPECT_EQ(CountNonFinite(on), 0) << what << " " << preset;
    auto off = Bloom(input, false, preset);
    const auto in = Values(input);
    const auto out = Values(off);
    ASSERT_EQ(in.size(), out.size());
    vtkIdType mismatches = 0;
    for (size_t e = 0; e < in.size(); ++e)
    {
      mismatches += std::isfinite(in[e]) != std::isfinite(out[e]) ? 1 : 0;
    }
    EXPECT_EQ(mismatches, 0) << what << " " << preset;
  }
  for (int method = 0; method < 4; ++method)
  {
    auto on = Gaussian(input, method, 3.0, vtkImageSeparableGaussian::CLAMP, true);
    EXPECT_EQ(CountNonFinite(on), 0) << what << " Gaussian method " << method;
  }
}
}

// NaN and +/-Inf in a real HDR image.
TEST(NumericsHardCases, NanInfImage)
{
  VTKBLOOM_REQUIRE_DATA(path, vtkBloomHardCases::NanInfImage());
  auto input = ReadExr(path);
  ExpectBloomNonFinitePolicy(input, "BrightRingsNanInf");
}

// Every half value (denormals, NaNs and infinities included).
TEST(NumericsHardCases, AllHalfValues)
{
  VTKBLOOM_REQUIRE_DATA(path, vtkBloomHardCases::AllHalfValuesImage());
  auto input = ReadExr(path);
  ExpectBloomNonFinitePolicy(input, "AllHalfValues");
  // Written back as half, a sanitized bloom never turns a finite value into Inf: above 65504
  // the writer clamps.
  auto out = Bloom(input, true);
  const std::string file = vtkBloomTest::OutputPath("AllHalfValuesBloom.exr");
  vtkNew<vtkOpenEXRWriter> writer;
  writer->SetFileName(file.c_str());
  writer->SetPixelTypeToHalf();
  writer->SetInputData(out);
  ASSERT_EQ(writer->Write(), 1);
  auto back = ReadExr(file);
  EXPECT_EQ(CountNonFinite(back), 0);
  for (double v : Values(back))
  {
    EXPECT_LE(std::fabs(v), 65504.0);
  }
}

// Half output: finite values beyond the half range clamp to +/-65504; infinities and NaN stay.
TEST(NumericsHardCases, HalfOutputClamps)
{
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<std::pair<double, double>> cases = { { 65504.0, 65504.0 }, { 7e4, 65504.0 },
    { -7e4, -65504.0 }, { 65519.0, 65504.0 }, { 65520.0, 65504.0 }, { 1e30, 65504.0 },
    { -3.4e38, -65504.0 }, { inf, inf }, { -inf, -inf }, { 1.0, 1.0 } };
  std::vector<double> row;
  for (const auto& c : cases)
  {
    row.push_back(c.first);
  }
  row.push_back(std::numeric_limits<double>::quiet_NaN());
  for (int type : { VTK_FLOAT, VTK_DOUBLE })
  {
    auto image = vtkBloomHardCases::Row(row, type);
    const std::string file = vtkBloomTest::OutputPath("HalfClamp.exr");
    vtkNew<vtkOpenEXRWriter> writer;
    writer->SetFileName(file.c_str());
    writer->SetPixelTypeToHalf();
    writer->SetInputData(image);
    ASSERT_EQ(writer->Write(), 1);
    const auto back = Values(ReadExr(file));
    ASSERT_EQ(back.size(), row.size());
    for (size_t i = 0; i < cases.size(); ++i)
    {
      EXPECT_EQ(back[i], cases[i].second) << "input " << cases[i].first;
    }
    EXPECT_TRUE(std::isnan(back.back()));
  }
}

// One firefly of 1e4, 1e10 and 1e30 on a dim background. The bloom (crt-halfres, clamp 50) is
// finite, never darker than the input, adds at most Strength x ClampLuminance per channel, and
// leaves every pixel outside its support (12 pixels for crt-halfres; 16 checked) exactly as it
// was. The box and exact Gaussians leave nothing outside their support either.
TEST(NumericsHardCases, Fireflies)
{
  const int n = 64, cx = 31, cy = 30;
  const double bg = vtkBloomHardCases::FireflyBackground;
  for (double value : vtkBloomHardCases::FireflyValues())
  {
    for (int type : { VTK_FLOAT, VTK_DOUBLE })
    {
      auto input = vtkBloomHardCases::Firefly(n, n, cx, cy, value, bg, type, 4);
      for (bool sanitize : { true, false })
      {
        auto out = Bloom(input, sanitize, "crt-halfres", 50.0);
        ASSERT_EQ(CountNonFinite(out), 0) << value;
        for (int j = 0; j < n; ++j)
        {
          for (int i = 0; i < n; ++i)
          {
            for (int c = 0; c < 3; ++c)
            {
              const double a = vtkBloomTest::Value(input, i, j, 0, c);
              const double b = vtkBloomTest::Value(out, i, j, 0, c);
              EXPECT_GE(b, a) << value << " at " << i << "," << j;
              EXPECT_LE(b - a, 1.5 * 50.0 * (1 + 1e-6)) << value << " at " << i << "," << j;
              if (std::max(std::abs(i - cx), std::abs(j - cy)) > 16)
              {
                EXPECT_EQ(a, b) << value << " at " << i << "," << j;
              }
            }
          }
        }
      }
      for (int method : { 0, 1, 2 })
      {
        const double sigma = 2.0;
        auto out = Gaussian(input, method, sigma, vtkImageSeparableGaussian::CLAMP, true);
        ASSERT_EQ(CountNonFinite(out), 0);
        const int support = method == 0 ? 8 : (method == 1 ? 9 : 10);
        for (int j = 0; j < n; ++j)
        {
          for (int i = 0; i < n; ++i)
          {
            const double v = vtkBloomTest::Value(out, i, j, 0, 0);
            EXPECT_GE(v, bg * (1 - 1e-6));
            EXPECT_LE(v, value * (1 + 1e-6));
            if (std::max(std::abs(i - cx), std::abs(j - cy)) > support)
            {
              EXPECT_NEAR(v, bg, 1e-6 * bg) << vtkImageSeparableGaussian::GetMethodName(method)
                                            << " " << value << " at " << i << "," << j;
            }
          }
        }
      }
      // The recursive filter has infinite support and small negative lobes (docs/numerics.md):
      // finite, and bounded by the firefly.
      auto out = Gaussian(input, 3, 2.0, vtkImageSeparableGaussian::CLAMP, true);
      ASSERT_EQ(CountNonFinite(out), 0);
      for (double v : Values(out))
      {
        EXPECT_LE(std::fabs(v), value * (1 + 1e-6));
      }
    }
  }
}

// Wide dynamic range: the reflect-border Gaussian conserves the sum to 1e-6 relative (in
// float32 storage) in every method, and the bloom statistics equal a compensated float64 sum.
TEST(NumericsHardCases, WideDynamicRange)
{
  std::vector<std::pair<std::string, vtkSmartPointer<vtkImageData>>> images;
  images.emplace_back("synthetic 1e-8..1e8", vtkBloomHardCases::WideRange(96, 64, VTK_FLOAT, 4));
  const std::string path = vtkBloomTest::SharedDataPath(vtkBloomHardCases::WideFloatRangeImage());
  if (!path.empty())
  {
    // The file holds +/-1.7e38 next to tiny values, so its signed sum cancels to nothing a
    // float32 image can carry; its magnitudes keep every decade and a well-conditioned sum.
    images.emplace_back("WideFloatRange magnitudes", vtkBloomHardCases::Magnitudes(ReadExr(path)));
  }
  else if (vtkBloomTest::RunningInCI())
  {
    FAIL() << "shared test data missing under CI: " << vtkBloomHardCases::WideFloatRangeImage();
  }
  for (const auto& named : images)
  {
    vtkImageData* input = named.second;
    ASSERT_EQ(CountNonFinite(input), 0) << named.first;
    const int nc = input->GetNumberOfScalarComponents();
    for (int method = 0; method < 4; ++method)
    {
      auto out = Gaussian(input, method, 6.0, vtkImageSeparableGaussian::REFLECT, true);
      for (int c = 0; c < nc; ++c)
      {
        const double a = vtkBloomHardCases::CompensatedSum(input, c);
        const double b = vtkBloomHardCases::CompensatedSum(out, c);
        EXPECT_NEAR(b, a, 1e-6 * std::fabs(a))
          << named.first << " " << vtkImageSeparableGaussian::GetMethodName(method) << " c " << c;
      }
    }
    vtkNew<vtkImageBloom> bloom;
    bloom->SetPreset("webgpu-market");
    bloom->SetInputData(input);
    bloom->Update();
    auto luminanceSum = [](vtkImageData* image)
    {
      const int k = image->GetNumberOfScalarComponents();
      const auto v = Values(image);
      double sum = 0.0, comp = 0.0;
      for (size_t p = 0; p + k <= v.size(); p += k)
      {
        const double l = k >= 3 ? 0.2126 * v[p] + 0.7152 * v[p + 1] + 0.0722 * v[p + 2] : v[p];
        const double t = sum + l;
        comp += std::fabs(sum) >= std::fabs(l) ? (sum - t) + l : (l - t) + sum;
        sum = t;
      }
      return sum + comp;
    };
    const double in = luminanceSum(input);
    const double out = luminanceSum(bloom->GetOutput());
    EXPECT_NEAR(bloom->GetEnergyIn(), in, 1e-6 * std::fabs(in)) << named.first;
    EXPECT_NEAR(bloom->GetEnergyOut(), out, 1e-6 * std::fabs(out)) << named.first;
  }
}

// The energy statistics are exact sums rounded once, so cancellation loses nothing.
// TestImages_WideFloatRange.exr (one channel, so the luminance is the value) is antisymmetric:
// the value at (i, j) is minus the value at (W-1-i, H-1-j). Its exact sum is 0, and after one
// pixel changes from v to w it is w - v, which a double subtraction rounds correctly. (Rounded
// row sums of up to 6e40 added pairwise returned 0 for a change of 1000.)
TEST(NumericsHardCases, StatisticsSumExactlyThroughCancellation)
{
  VTKBLOOM_REQUIRE_DATA(path, vtkBloomHardCases::WideFloatRangeImage());
  auto input = ReadExr(path);
  ASSERT_EQ(input->GetNumberOfScalarComponents(), 1);
  ASSERT_EQ(input->GetScalarType(), VTK_FLOAT);
  int dims[3];
  input->GetDimensions(dims);
  const int w = dims[0], h = dims[1];
  vtkDataArray* scalars = input->GetPointData()->GetScalars();
  auto at = [w](int i, int j) { return static_cast<vtkIdType>(j) * w + i; };
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      ASSERT_EQ(
        scalars->GetComponent(at(i, j), 0), -scalars->GetComponent(at(w - 1 - i, h - 1 - j), 0))
        << i << "," << j;
    }
  }
  vtkNew<vtkImageBloom> bloom;
  bloom->SetPreset("webgpu-market");
  bloom->SetInputData(input);
  bloom->Update();
  EXPECT_EQ(bloom->GetEnergyIn(), 0.0);
  struct Change
  {
    int I, J;
    float Value;
  };
  const Change changes[] = { { w / 2, h / 2, 1000.0f }, { 0, 0, 0.0f }, { 123, 77, 3e30f },
    { 10, 10, 1.0f }, { w - 1, 3, -2.5e-38f } };
  for (const Change& c : changes)
  {
    auto changed = vtkSmartPointer<vtkImageData>::New();
    changed->DeepCopy(input);
    vtkDataArray* values = changed->GetPointData()->GetScalars();
    const double before = values->GetComponent(at(c.I, c.J), 0);
    values->SetComponent(at(c.I, c.J), 0, c.Value);
    bloom->SetInputData(changed);
    bloom->Update();
    EXPECT_EQ(bloom->GetEnergyIn(), static_cast<double>(c.Value) - before)
      << "pixel " << c.I << "," << c.J << " from " << before << " to " << c.Value;
  }
}

// Every size 1x1..67x67 at every pyramid depth: a constant stays constant through the whole
// chain (threshold NONE, 7 levels from full resolution, weights 1/7, LERP with strength 1), for
// each downsample kernel, upsample kernel and accumulation mode in turn.
TEST(NumericsHardCases, EverySizeEveryDepthKeepsConstants)
{
  const double value = 0.625;
  const int levels = 7;
  const std::vector<double> weights(levels, 1.0 / levels);
  int configuration = 0;
  for (int h = 1; h <= vtkBloomHardCases::LargestSweepSize; ++h)
  {
    for (int w = 1; w <= vtkBloomHardCases::LargestSweepSize; ++w, ++configuration)
    {
      auto input = vtkBloomHardCases::Constant(w, h, value, VTK_FLOAT, 4);
      vtkNew<vtkImageBloom> bloom;
      bloom->SetThresholdMode(vtkImageBloomThreshold::NONE);
      bloom->SetStartLevel(0);
      bloom->SetNumberOfLevels(levels);
      bloom->SetLevelWeights(weights);
      bloom->SetCompositeMode(vtkBloomParameters::LERP);
      bloom->SetStrength(1.0);
      bloom->SetDownsampleKernel(configuration % 3);
      bloom->SetUpsampleKernel((configuration / 3) % 2);
      bloom->SetAccumulateMode((configuration / 6) % 2);
      bloom->SetKarisAverage(configuration % 5 == 0);
      bloom->SetInputData(input);
      bloom->Update();
      ASSERT_LE(vtkBloomHardCases::MaxRelativeDeviationFrom(bloom->GetOutput(), value), 1e-6)
        << w << "x" << h << " configuration " << configuration % 12;
    }
  }
  // The pyramid filters themselves, down to 1x1 and back, on every square size.
  for (int n = 1; n <= vtkBloomHardCases::LargestSweepSize; ++n)
  {
    for (int kernel = 0; kernel < 3; ++kernel)
    {
      vtkSmartPointer<vtkImageData> current =
        vtkBloomHardCases::Constant(n, n, value, VTK_FLOAT, 3);
      std::vector<vtkSmartPointer<vtkImageData>> chain{ current };
      for (int depth = 0; depth < 7; ++depth)
      {
        vtkNew<vtkImagePyramidDown> down;
        down->SetKernel(kernel);
        current = vtkBloomTest::RunAndCopy(down, current);
        EXPECT_LE(vtkBloomHardCases::MaxRelativeDeviationFrom(current, value), 1e-6)
          << n << " down " << depth;
        chain.push_back(current);
      }
      for (int depth = 6; depth >= 0; --depth)
      {
        vtkNew<vtkImagePyramidUp> up;
        up->SetKernel(depth % 2);
        up->SetFineInputData(chain[static_cast<size_t>(depth)]);
        current = vtkBloomTest::RunAndCopy(up, current);
        EXPECT_LE(vtkBloomHardCases::MaxRelativeDeviationFrom(current, value), 1e-6)
          << n << " up " << depth;
      }
    }
  }
}

// The threshold at its edge: a pixel exactly at the threshold with knee 0 gives the documented
// value in every mode (no NaN, never negative), and negative input never emits light: the
// bloom of an all-negative image is exactly the input.
TEST(NumericsHardCases, ThresholdEdgeAndNegativeInput)
{
  for (double threshold : { 0.0, 1e-30, 0.8, 1.0, 3.0, 1e30 })
  {
    for (int mode = 0; mode <= 4; ++mode)
    {
      auto input = vtkBloomHardCases::Constant(3, 2, threshold, VTK_DOUBLE, 1);
      vtkNew<vtkImageBloomThreshold> filter;
      filter->SetMode(mode);
      filter->SetThreshold(threshold);
      filter->SetKnee(0.0);
      filter->SetInputData(input);
      filter->Update();
      for (double v : Values(filter->GetOutput()))
      {
        EXPECT_EQ(v, vtkBloomHardCases::ExpectedBrightPassAtThreshold(mode, threshold))
          << vtkImageBloomThreshold::GetModeName(mode) << " T " << threshold;
      }
    }
  }
  auto negative = vtkBloomHardCases::Constant(23, 17, -2.5, VTK_FLOAT, 4);
  for (bool sanitize : { true, false })
  {
    for (const char* preset : { "webgpu-market", "ping-pong", "crt-halfres" })
    {
      auto out = Bloom(negative, sanitize, preset);
      EXPECT_TRUE(vtkBloomTest::BitIdentical(out, negative)) << preset;
    }
    for (int mode = 0; mode < 4; ++mode)
    {
      vtkNew<vtkImageBloom> bloom;
      bloom->SetThresholdMode(mode);
      bloom->SetThreshold(0.0);
      bloom->SetKnee(0.0);
      bloom->SetSanitizeNonFinite(sanitize);
      bloom->SetInputData(negative);
      bloom->Update();
      EXPECT_TRUE(vtkBloomTest::BitIdentical(bloom->GetOutput(), negative)) << mode;
    }
  }
}

// FAST measures the statistics in its composite, four pixels at a time (vtkBloomStatisticsRows);
// REFERENCE measures them in passes of their own. Over hostile inputs (NaN, +-Inf, fireflies
// above the clamp, negative and subnormal values, every component count, widths that leave a
// remainder of 1-3 pixels), every threshold mode, knee 0 and a bloom that covers part of the
// frame, the input side (EnergyIn, PeakLuminanceIn, NumberOfBrightPixels) is the same bit for
// bit, and FAST's output side equals the separate passes run over FAST's output.
TEST(NumericsHardCases, StatisticsInTheCompositeEqualSeparatePasses)
{
  const float inf = std::numeric_limits<float>::infinity();
  const float specials[] = { std::numeric_limits<float>::quiet_NaN(), inf, -inf, 1e30f, -3.0f,
    1e-40f, 0.95f, 1.0f, 1.05f, 2.5f };
  int checked = 0;
  for (int nc = 1; nc <= 4; ++nc)
  {
    // Hostile widths, and a clean frame whose bloom covers part of each row (the composite
    // then copies the rest of the row, which is measured once for input and output).
    for (int width : { 37, 66, 131, -61 })
    {
      const bool hostile = width > 0;
      width = std::abs(width);
      const int height = 23;
      auto input = vtkSmartPointer<vtkImageData>::New();
      input->SetDimensions(width, height, 1);
      input->AllocateScalars(VTK_FLOAT, nc);
      float* p = static_cast<float*>(input->GetScalarPointer());
      for (vtkIdType i = 0; i < static_cast<vtkIdType>(width) * height * nc; ++i)
      {
        // A dim field, a lamp in one corner, and the special values scattered.
        const vtkIdType pixel = i / nc, x = pixel % width, y = pixel / width;
        p[i] = 0.3f * static_cast<float>((i * 7919) % 101) / 101.0f;
        p[i] = x < 6 && y < 5 ? 3.0f + static_cast<float>(i % 5) : p[i];
        p[i] = hostile && i % 29 == 0 ? specials[(i / 29) % 10] : p[i];
      }
      for (int mode = 0; mode <= 5; ++mode)
      {
        for (double knee : { 0.0, 0.5 })
        {
          vtkNew<vtkImageBloom> fast, reference, output;
          for (vtkImageBloom* b : { fast.Get(), reference.Get() })
          {
            b->SetThresholdMode(mode);
            b->SetThreshold(0.9);
            b->SetKnee(knee);
            b->GetParameters()->SetClampLuminance(20.0);
            b->SetInputData(input);
          }
          reference->SetExecutionMode(vtkImageBloom::REFERENCE);
          fast->Update();
          reference->Update();
          ASSERT_TRUE(fast->GetLastRunWasFast());
          const std::string what = "nc " + std::to_string(nc) + ", width " + std::to_string(width) +
            ", mode " + std::to_string(mode) + ", knee " + std::to_string(knee);
          auto same = [](double a, double b) { return a == b || (a != a && b != b); };
          EXPECT_TRUE(same(fast->GetEnergyIn(), reference->GetEnergyIn())) << what;
          EXPECT_EQ(fast->GetPeakLuminanceIn(), reference->GetPeakLuminanceIn()) << what;
          EXPECT_EQ(fast->GetNumberOfBrightPixels(), reference->GetNumberOfBrightPixels()) << what;
          output->SetExecutionMode(vtkImageBloom::REFERENCE);
          output->SetInputData(fast->GetOutput());
          output->Update();
          EXPECT_TRUE(same(fast->GetEnergyOut(), output->GetEnergyIn())) << what;
          EXPECT_EQ(fast->GetPeakLuminanceOut(), output->GetPeakLuminanceIn()) << what;
          ++checked;
        }
      }
    }
  }
  EXPECT_EQ(checked, 4 * 4 * 6 * 2);
}
