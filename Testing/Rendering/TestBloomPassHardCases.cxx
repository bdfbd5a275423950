// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// The numerical hard cases of issue 4 on the GPU: vtkBloomPass::ApplyToImage on NaN/Inf input,
// fireflies, every half value, wide dynamic range, tiny and odd sizes, the threshold at its edge
// and negative input. Inputs come from vtkBloomHardCases, as for the CPU suite
// (Testing/Numerics/TestNumericsHardCases.cxx). Each case asserts a stated property; where the
// CPU vtkImageBloom is the reference it runs with the same parameters (the pass's own
// vtkBloomParameters, shared) in REFERENCE mode, the double-precision chain.
// One file for all of them (about 860 lines), so that the GPU cases sit beside each other as
// the CPU suite's do and share one fixture (GpuBloom); each TEST is independent and short.
#include "vtkBloomChain.h"
#include "vtkBloomHardCases.h"
#include "vtkBloomPass.h"
#include "vtkBloomTestSupport.h"

#include "vtkBloomVTKCompat.h"
#include "vtkDataArray.h"
#include "vtkImageBloom.h"
#include "vtkImageBloomThreshold.h"
#include "vtkImageData.h"
#include "vtkImagePyramidDown.h"
#include "vtkImagePyramidUp.h"
#include "vtkNew.h"
#include "vtkOpenEXRReader.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace
{
using vtkBloomHardCases::CountNonFinite;
using vtkBloomHardCases::Values;

// float32 unit roundoff.
constexpr double Unit = 0.5 * std::numeric_limits<float>::epsilon();

// An offscreen window that provides the context, and the pass that blooms images in it.
struct GpuBloom
{
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkBloomPass> Pass;

  explicit GpuBloom(int precision = vtkBloomPass::FLOAT32)
  {
    this->Window->SetOffScreenRendering(1);
    this->Window->SetMultiSamples(0);
    this->Window->SetSize(16, 16);
    // ApplyToImage stores the image at the pass's precision; 32-bit keeps it as given.
    this->Pass->SetFloatPrecision(precision);
  }
  ~GpuBloom() { this->Pass->ReleaseGraphicsResources(this->Window); }

  vtkBloomParameters* Parameters() { return this->Pass->GetParameters(); }

  /// The GPU result (float RGBA), or null after an error.
  vtkSmartPointer<vtkImageData> Apply(vtkImageData* input)
  {
    auto output = vtkSmartPointer<vtkImageData>::New();
    const bool ok =
      this->Pass->ApplyToImage(vtkOpenGLRenderWindow::SafeDownCast(this->Window), input, output);
    EXPECT_TRUE(ok);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    return ok ? output : nullptr;
  }

  /// The CPU filter with the pass's parameters, in its REFERENCE (double) mode.
  vtkSmartPointer<vtkImageData> Cpu(vtkImageData* input)
  {
    vtkNew<vtkImageBloom> cpu;
    cpu->SetParameters(this->Parameters());
    cpu->SetExecutionModeToReference();
    cpu->SetInputData(input);
    return vtkBloomTest::UpdateAndCopy(cpu);
  }
};

vtkSmartPointer<vtkImageData> ReadExr(const std::string& path)
{
  vtkNew<vtkOpenEXRReader> reader;
  reader->SetFileName(path.c_str());
  return vtkBloomTest::UpdateAndCopy(reader);
}

double Get(vtkImageData* image, vtkIdType p, int c)
{
  return image->GetPointData()->GetScalars()->GetComponent(p, c);
}

// A rectangle of pixels, inclusive; empty when X0 > X1.
struct Box
{
  int X0 = 0, X1 = -1, Y0 = 0, Y1 = -1;
  bool Contains(int i, int j) const { return i >= X0 && i <= X1 && j >= Y0 && j <= Y1; }
};

// Output samples of `op` that read, with a non-zero weight, at least one marked input sample.
std::vector<bool> Reach(const vtkBloomLinearOperator& op, const std::vector<bool>& in)
{
  std::vector<bool> out(static_cast<size_t>(op.OutputSize), false);
  for (int j = 0; j < op.OutputSize; ++j)
  {
    for (int k = 0; k < op.Width; ++k)
    {
      const int i = op.First[static_cast<size_t>(j)] + k;
      if (op.Weights[static_cast<size_t>(j) * op.Width + k] != 0.0 && i >= 0 &&
        i < static_cast<int>(in.size()) && in[static_cast<size_t>(i)])
      {
        out[static_cast<size_t>(j)] = true;
      }
    }
  }
  return out;
}

std::vector<bool> Union(std::vector<bool> a, const std::vector<bool>& b)
{
  for (size_t i = 0; i < a.size() && i < b.size(); ++i)
  {
    a[i] = a[i] || b[i];
  }
  return a;
}

/**
 * The pixels that input pixel (cx, cy) can change through the bloom: the marked row and column
 * pushed through every operator of vtkBloomChain (source fetch, pyramid, blur, accumulation,
 * final fetch) along each axis. Every step is a sum of separable terms, so the exact footprint
 * is a union of boxes inside this one. Outside it the bloom term is exactly 0.
 */
Box Support(vtkBloomParameters* parameters, int w, int h, int cx, int cy)
{
  vtkBloomChain chain;
  chain.Build(parameters, w, h);
  Box box;
  if (chain.Levels.empty())
  {
    return box;
  }
  auto along = [&chain](int axis, int n, int centre)
  {
    auto op = [axis](const vtkBloomChain::Term& t) -> const vtkBloomLinearOperator&
    { return axis == 0 ? t.X : t.Y; };
    std::vector<bool> image(static_cast<size_t>(n), false);
    image[static_cast<size_t>(centre)] = true;
    const size_t levels = chain.Levels.size();
    std::vector<std::vector<bool>> blurred(levels);
    std::vector<bool> level = chain.SourceIsIdentity ? image : Reach(op(chain.Source), image);
    for (size_t i = 0; i < levels; ++i)
    {
      const vtkBloomChain::Level& l = chain.Levels[i];
      if (i > 0)
      {
        std::vector<bool> next(static_cast<size_t>(l.Size[axis]), false);
        for (const auto& term : l.Down)
        {
          next = Union(next, Reach(op(term), level));
        }
        level = next;
      }
      blurred[i] = l.Blur ? Reach(op(l.BlurPass), level) : level;
    }
    std::vector<bool> bloom(static_cast<size_t>(n), false);
    if (chain.AccumulateMode == vtkBloomParameters::CASCADE)
    {
      std::vector<bool> a(blurred[levels - 1].size(), false);
      for (size_t i = levels; i-- > 0;)
      {
        const vtkBloomChain::Level& l = chain.Levels[i];
        if (i + 1 < levels)
        {
          a = Reach(op(l.Up), a);
        }
        if (l.Weight != 0.0)
        {
          a = Union(a, blurred[i]);
        }
      }
      bloom = chain.FinalIsIdentity ? a : Reach(op(chain.Final), a);
    }
    else
    {
      for (size_t i = 0; i < levels; ++i)
      {
        if (chain.Levels[i].Weight != 0.0)
        {
          bloom = Union(bloom, Reach(op(chain.Levels[i].Full), blurred[i]));
        }
      }
    }
    const auto first = std::find(bloom.begin(), bloom.end(), true);
    const auto last = std::find(bloom.rbegin(), bloom.rend(), true);
    return first == bloom.end() ? std::make_pair(0, -1)
                                : std::make_pair(static_cast<int>(first - bloom.begin()),
                                    static_cast<int>(bloom.rend() - last) - 1);
  };
  const auto x = along(0, w, cx);
  const auto y = along(1, h, cy);
  box.X0 = x.first;
  box.X1 = x.second;
  box.Y0 = y.first;
  box.Y1 = y.second;
  return box;
}

// Relative L2 of a against b over the colour channels of the pixels where `use` is true.
template <typename Predicate>
double ColourRelativeL2(vtkImageData* a, vtkImageData* b, Predicate use)
{
  int dims[3];
  a->GetDimensions(dims);
  double num = 0.0, den = 0.0;
  for (vtkIdType p = 0; p < a->GetNumberOfPoints(); ++p)
  {
    if (!use(static_cast<int>(p % dims[0]), static_cast<int>(p / dims[0])))
    {
      continue;
    }
    for (int c = 0; c < 3; ++c)
    {
      const double x = Get(a, p, c), y = Get(b, p, c);
      num += (x - y) * (x - y);
      den += y * y;
    }
  }
  return den > 0.0 ? std::sqrt(num / den) : std::sqrt(num);
}

// Neumaier-compensated float64 sum of the Rec. 709 luminance of every pixel.
double LuminanceSum(vtkImageData* image)
{
  double sum = 0.0, compensation = 0.0;
  for (vtkIdType p = 0; p < image->GetNumberOfPoints(); ++p)
  {
    const double l =
      0.2126 * Get(image, p, 0) + 0.7152 * Get(image, p, 1) + 0.0722 * Get(image, p, 2);
    const double t = sum + l;
    compensation += std::fabs(sum) >= std::fabs(l) ? (sum - t) + l : (l - t) + sum;
    sum = t;
  }
  return sum + compensation;
}

// A copy of `image` with its scalars converted to `type`, with 3 colour components (a one-
// component image is repeated into R, G and B).
vtkSmartPointer<vtkImageData> AsRGB(vtkImageData* image, int type)
{
  auto out = vtkSmartPointer<vtkImageData>::New();
  out->SetExtent(image->GetExtent());
  const int nc = image->GetNumberOfScalarComponents();
  out->AllocateScalars(type, std::max(nc, 3));
  for (vtkIdType p = 0; p < image->GetNumberOfPoints(); ++p)
  {
    for (int c = 0; c < std::max(nc, 3); ++c)
    {
      out->GetPointData()->GetScalars()->SetComponent(p, c, Get(image, p, nc == 1 ? 0 : c));
    }
  }
  return out;
}

/**
 * The relative float32 rounding bound of the chain's bloom on non-negative data. Every sample
 * of every step is a sum of non-negative products (non-negative input, a bright pass that keeps
 * it non-negative, non-negative weights), so with m roundings on every path from the input to
 * an output (one per tap of each operator, one for its float32 weight, one for the product,
 * plus the point-wise steps) the output has a relative error of at most gamma_m = m u /
 * (1 - m u) (Higham, Accuracy and Stability of Numerical Algorithms, 2nd ed., sec. 3.1), and
 * so has any sum of outputs. m is taken over all operators of the chain, not only one path. A
 * knee is not linear: its factor's rounding is a few u of lum x slope <= 3 / (4 knee), that is
 * a few u of the pixel, which an ADDITIVE output (input + bloom) contains; the 8 point-wise
 * roundings cover it for knee 0.5.
 */
double ChainRoundingBound(vtkBloomParameters* parameters, int w, int h)
{
  vtkBloomChain chain;
  chain.Build(parameters, w, h);
  double m = 8.0; // bright pass, Karis steps and the composite
  auto add = [&m](const vtkBloomChain::Term& t) { m += t.X.Width + t.Y.Width + 4.0; };
  if (!chain.SourceIsIdentity)
  {
    add(chain.Source);
  }
  for (const auto& level : chain.Levels)
  {
    for (const auto& term : level.Down)
    {
      add(term);
    }
    if (level.Blur)
    {
      add(level.BlurPass);
    }
    if (level.Up.X.Width > 0)
    {
      add(level.Up);
    }
    if (level.Full.X.Width > 0)
    {
      add(level.Full);
    }
  }
  if (!chain.FinalIsIdentity)
  {
    add(chain.Final);
  }
  return m * Unit / (1.0 - m * Unit);
}
}

//------------------------------------------------------------------------------
// NaN and +-Inf (TestImages_BrightRingsNanInf.exr). Sanitize on: every output sample is finite,
// and away from the bloom of the former +-Inf pixels the GPU agrees with the CPU filter. Off: an
// output sample is non-finite exactly where the CPU filter's is, which is exactly where the
// input's is, and the finite samples agree with the CPU filter.
TEST(RenderingBloomPassHardCases, NanInfImage)
{
  VTKBLOOM_REQUIRE_DATA(path, vtkBloomHardCases::NanInfImage());
  auto input = ReadExr(path);
  ASSERT_EQ(input->GetNumberOfScalarComponents(), 3);
  int dims[3];
  input->GetDimensions(dims);
  GpuBloom gpu;
  for (const char* preset : { "webgpu-market", "mip-atlas", "crt-halfres" })
  {
    ASSERT_TRUE(gpu.Pass->SetPreset(preset));
    // The pixels within the bloom's reach of an infinite input sample.
    std::vector<Box> infinite;
    for (vtkIdType p = 0; p < input->GetNumberOfPoints(); ++p)
    {
      for (int c = 0; c < 3; ++c)
      {
        if (std::isinf(Get(input, p, c)))
        {
          infinite.push_back(Support(gpu.Parameters(), dims[0], dims[1],
            static_cast<int>(p % dims[0]), static_cast<int>(p / dims[0])));
        }
      }
    }
    ASSERT_FALSE(infinite.empty());
    auto awayFromInfinity = [&infinite](int i, int j)
    {
      return std::none_of(
        infinite.begin(), infinite.end(), [i, j](const Box& b) { return b.Contains(i, j); });
    };
    vtkIdType away = 0;
    for (int j = 0; j < dims[1]; ++j)
    {
      for (int i = 0; i < dims[0]; ++i)
      {
        away += awayFromInfinity(i, j) ? 1 : 0;
      }
    }

    gpu.Parameters()->SetSanitizeNonFinite(true);
    auto on = gpu.Apply(input);
    ASSERT_TRUE(on);
    EXPECT_EQ(CountNonFinite(on), 0) << preset;
    auto cpuOn = gpu.Cpu(input);
    // mip-atlas's deepest levels reach the whole image; the others leave most of it.
    EXPECT_TRUE(away > 0 || std::string(preset) == "mip-atlas") << preset;
    const double errorOn = ColourRelativeL2(on, cpuOn, awayFromInfinity);
    EXPECT_LE(errorOn, 1e-5) << preset;

    gpu.Parameters()->SetSanitizeNonFinite(false);
    auto off = gpu.Apply(input);
    ASSERT_TRUE(off);
    auto cpuOff = gpu.Cpu(input);
    vtkIdType nonFinite = 0;
    for (vtkIdType p = 0; p < input->GetNumberOfPoints(); ++p)
    {
      for (int c = 0; c < 3; ++c)
      {
        const bool finite = std::isfinite(Get(off, p, c));
        ASSERT_EQ(finite, std::isfinite(Get(cpuOff, p, c)))
          << preset << " sample " << p << "," << c;
        ASSERT_EQ(finite, std::isfinite(Get(input, p, c))) << preset << " sample " << p << "," << c;
        nonFinite += finite ? 0 : 1;
      }
    }
    EXPECT_EQ(nonFinite, CountNonFinite(input));
    auto finiteInput = [&input, &dims](int i, int j)
    {
      const vtkIdType p = static_cast<vtkIdType>(j) * dims[0] + i;
      return std::isfinite(Get(input, p, 0)) && std::isfinite(Get(input, p, 1)) &&
        std::isfinite(Get(input, p, 2));
    };
    const double errorOff = ColourRelativeL2(off, cpuOff, finiteInput);
    EXPECT_LE(errorOff, 1e-5) << preset;
    std::cout << "[ nan-inf ] " << preset << ": sanitize on, relative L2 vs CPU on the " << away
              << " pixels away from the infinities " << errorOn
              << "; sanitize off, on finite pixels " << errorOff << ", " << nonFinite
              << " non-finite samples where the input has them\n";
  }
}

//------------------------------------------------------------------------------
// Every half value (TestImages_AllHalfValues.exr: denormals, 65504, NaNs and infinities), stored
// at 32-bit and at 16-bit precision (every value is a half, so both hold the input exactly). A
// finite input sample never gives a non-finite output sample (no new Inf), with sanitize on
// every output sample is finite, and with it off the non-finite samples are the CPU filter's.
TEST(RenderingBloomPassHardCases, AllHalfValues)
{
  VTKBLOOM_REQUIRE_DATA(path, vtkBloomHardCases::AllHalfValuesImage());
  auto input = ReadExr(path);
  ASSERT_GT(CountNonFinite(input), 0);
  for (const int precision : { vtkBloomPass::FLOAT32, vtkBloomPass::FLOAT16 })
  {
    GpuBloom gpu(precision);
    for (const char* preset : { "webgpu-market", "crt-halfres" })
    {
      ASSERT_TRUE(gpu.Pass->SetPreset(preset));
      for (const bool sanitize : { true, false })
      {
        gpu.Parameters()->SetSanitizeNonFinite(sanitize);
        auto out = gpu.Apply(input);
        ASSERT_TRUE(out);
        auto cpu = gpu.Cpu(input);
        vtkIdType newInf = 0, nonFinite = 0, mismatches = 0;
        for (vtkIdType p = 0; p < input->GetNumberOfPoints(); ++p)
        {
          for (int c = 0; c < 3; ++c)
          {
            const bool finite = std::isfinite(Get(out, p, c));
            newInf += !finite && std::isfinite(Get(input, p, c)) ? 1 : 0;
            nonFinite += finite ? 0 : 1;
            mismatches += finite != std::isfinite(Get(cpu, p, c)) ? 1 : 0;
          }
          nonFinite += std::isfinite(Get(out, p, 3)) ? 0 : 1;
        }
        EXPECT_EQ(newInf, 0) << preset << " precision " << precision << " sanitize " << sanitize;
        EXPECT_EQ(mismatches, 0) << preset << " precision " << precision << " sanitize "
                                 << sanitize;
        if (sanitize)
        {
          EXPECT_EQ(nonFinite, 0) << preset << " precision " << precision;
        }
        else
        {
          EXPECT_EQ(nonFinite, CountNonFinite(input)) << preset << " precision " << precision;
        }
      }
    }
  }
}

//------------------------------------------------------------------------------
// One firefly of 1e4, 1e10 and 1e30 on a dim background, with the firefly guard at luminance
// 50. The output is finite; the bloom term (output - input) is non-negative and at most
// Strength x 50 per channel; outside the support of the chain (the firefly's row and column
// pushed through every operator of vtkBloomChain) every output sample equals its input exactly;
// and the bloom term agrees with the CPU filter's. The support is also checked against the
// analytic radius of each chain, so a wrong operator cannot widen it unnoticed.
TEST(RenderingBloomPassHardCases, Fireflies)
{
  struct Case
  {
    const char* Preset;
    int Size;
    int Radius; // analytic bound on the support's half-width, in full-resolution pixels
  };
  // crt-halfres: a bilinear fetch to half size (1 pixel), a 9-tap blur of radius 4 half-size
  // pixels (8), a bilinear fetch back (2 + rounding): 12; ping-pong: 32 passes of the 13-tap
  // blur at full size, radius 32 x 6 = 192.
  const Case cases[] = { { "crt-halfres", 64, 12 }, { "ping-pong", 448, 192 } };
  const double bg = vtkBloomHardCases::FireflyBackground;
  GpuBloom gpu;
  for (const Case& k : cases)
  {
    ASSERT_TRUE(gpu.Pass->SetPreset(k.Preset));
    gpu.Parameters()->SetClampLuminance(50.0);
    const double strength = gpu.Parameters()->GetStrength();
    const int n = k.Size, cx = n / 2 - 1, cy = n / 2 - 2;
    const Box support = Support(gpu.Parameters(), n, n, cx, cy);
    EXPECT_GE(support.X0, cx - k.Radius) << k.Preset;
    EXPECT_LE(support.X1, cx + k.Radius) << k.Preset;
    EXPECT_GE(support.Y0, cy - k.Radius) << k.Preset;
    EXPECT_LE(support.Y1, cy + k.Radius) << k.Preset;
    ASSERT_TRUE(support.Contains(cx, cy));
    // The test would be vacuous if the support covered the image.
    ASSERT_GT(support.X0, 0);
    ASSERT_LT(support.Y1, n - 1);
    for (double value : vtkBloomHardCases::FireflyValues())
    {
      auto input = vtkBloomHardCases::Firefly(n, n, cx, cy, value, bg, VTK_FLOAT, 4);
      for (const bool sanitize : { true, false })
      {
        gpu.Parameters()->SetSanitizeNonFinite(sanitize);
        auto out = gpu.Apply(input);
        ASSERT_TRUE(out);
        ASSERT_EQ(CountNonFinite(out), 0) << k.Preset << " " << value;
        auto cpu = gpu.Cpu(input);
        double largestBloom = 0.0, totalBloom = 0.0, num = 0.0, den = 0.0;
        vtkIdType changedOutside = 0, outOfBounds = 0;
        for (vtkIdType p = 0; p < input->GetNumberOfPoints(); ++p)
        {
          const int i = static_cast<int>(p % n), j = static_cast<int>(p / n);
          for (int c = 0; c < 4; ++c)
          {
            const double a = Get(input, p, c), b = Get(out, p, c);
            const double bloom = b - a;
            if (c == 3)
            {
              outOfBounds += b == a ? 0 : 1; // alpha passes through
              continue;
            }
            outOfBounds += bloom >= 0.0 && bloom <= strength * 50.0 * (1.0 + 1e-6) ? 0 : 1;
            changedOutside += !support.Contains(i, j) && b != a ? 1 : 0;
            largestBloom = std::max(largestBloom, bloom);
            totalBloom += bloom;
            const double cpuBloom = Get(cpu, p, c) - a;
            num += (bloom - cpuBloom) * (bloom - cpuBloom);
            den += cpuBloom * cpuBloom;
          }
        }
        EXPECT_EQ(outOfBounds, 0) << k.Preset << " " << value << " sanitize " << sanitize;
        EXPECT_EQ(changedOutside, 0) << k.Preset << " " << value << " sanitize " << sanitize;
        EXPECT_GT(totalBloom, 1.0) << k.Preset << " the firefly must bloom";
        EXPECT_LE(std::sqrt(num / den), 1e-5) << k.Preset << " " << value;
        if (sanitize && value == 1e30)
        {
          std::cout << "[ firefly ] " << k.Preset << " " << n << "x" << n << ": support x "
                    << support.X0 - cx << ".." << support.X1 - cx << ", y " << support.Y0 - cy
                    << ".." << support.Y1 - cy << ", largest bloom " << largestBloom << " (bound "
                    << strength * 50.0 << "), total " << totalBloom << ", bloom relative L2 vs CPU "
                    << std::sqrt(num / den) << "\n";
        }
      }
    }
  }
}

//------------------------------------------------------------------------------
// Wide dynamic range: the synthetic 1e-8..1e8 image and the magnitudes of
// TestImages_WideFloatRange.exr (5.9e-39..1.7e38, repeated into RGB). The float64 reference is the
// CPU filter on the same values stored as double (its chain and output are then double
// throughout). The GPU's total output luminance is within the chain's float32 rounding bound
// (ChainRoundingBound: about 1e-5 for these chains) of the float64 total; a lost level, a
// wrong weight or an overflow would be orders of magnitude beyond it.
TEST(RenderingBloomPassHardCases, WideDynamicRangeKeepsTheEnergy)
{
  std::vector<std::pair<std::string, vtkSmartPointer<vtkImageData>>> images;
  images.emplace_back("synthetic 1e-8..1e8", vtkBloomHardCases::WideRange(96, 64, VTK_FLOAT, 4));
  const std::string path = vtkBloomTest::SharedDataPath(vtkBloomHardCases::WideFloatRangeImage());
  if (!path.empty())
  {
    images.emplace_back(
      "WideFloatRange magnitudes", AsRGB(vtkBloomHardCases::Magnitudes(ReadExr(path)), VTK_FLOAT));
  }
  else if (vtkBloomTest::RunningInCI())
  {
    FAIL() << "shared test data missing under CI: " << vtkBloomHardCases::WideFloatRangeImage();
  }
  GpuBloom gpu;
  for (const auto& named : images)
  {
    vtkImageData* input = named.second;
    auto asDouble = AsRGB(input, VTK_DOUBLE);
    for (int configuration = 0; configuration < 2; ++configuration)
    {
      vtkBloomParameters* p = gpu.Parameters();
      if (configuration == 0)
      {
        // The additive preset; its bloom of 1.7e38 would exceed the float range, so only the
        // synthetic image runs it.
        if (named.first != "synthetic 1e-8..1e8")
        {
          continue;
        }
        p->SetPreset("webgpu-market");
      }
      else
      {
        // An energy-conserving chain: no threshold, weights summing to 1, LERP with strength
        // 1, so that no intermediate exceeds the largest input.
        p->SetPreset("mip-atlas");
        p->SetLimitLevelsToImageSize(false);
        p->SetNumberOfLevels(5);
        p->SetLevelWeights(std::vector<double>(5, 0.2));
        p->SetAccumulateMode(vtkBloomParameters::CASCADE);
        p->SetStrength(1.0);
      }
      // The input is finite; sanitizing would change nothing (FiniteValuesAboveVtkFloatMaxAreKept).
      p->SetSanitizeNonFinite(false);
      auto out = gpu.Apply(input);
      ASSERT_TRUE(out);
      ASSERT_EQ(CountNonFinite(out), 0) << named.first;
      auto reference = gpu.Cpu(asDouble);
      ASSERT_EQ(reference->GetScalarType(), VTK_DOUBLE);
      int dims[3];
      input->GetDimensions(dims);
      const double bound = ChainRoundingBound(p, dims[0], dims[1]);
      const double a = LuminanceSum(out), b = LuminanceSum(reference);
      EXPECT_LE(std::fabs(a - b), bound * b) << named.first << " configuration " << configuration;
      std::cout << "[ energy ] " << named.first << ", "
                << (configuration == 0 ? "webgpu-market" : "energy-conserving chain") << ": GPU "
                << a << ", float64 " << b << ", relative " << std::fabs(a - b) / b << " (bound "
                << bound << ")\n";
    }
  }
}

//------------------------------------------------------------------------------
// Every size from 1x1 to 17x17 and some odd large ones: a constant stays constant through the
// whole chain (no threshold, 7 levels from full resolution, weights 1/7, LERP with strength 1),
// with the downsample kernel, upsample kernel, accumulation and Karis average varied as in the
// CPU suite. Each level's operators have weights that sum to 1 in double; in float32 the sum of
// a row of k rounded weights is within k u of 1, so over the chain the constant moves by at most
// ChainRoundingBound.
TEST(RenderingBloomPassHardCases, TinyAndOddSizesKeepConstants)
{
  const double value = 0.625;
  const int levels = 7;
  std::vector<std::pair<int, int>> sizes;
  for (int h = 1; h <= 17; ++h)
  {
    for (int w = 1; w <= 17; ++w)
    {
      sizes.emplace_back(w, h);
    }
  }
  for (const auto& size : { std::make_pair(255, 1), std::make_pair(1, 255),
         std::make_pair(641, 479), std::make_pair(1023, 31), std::make_pair(1919, 1079) })
  {
    sizes.push_back(size);
  }
  GpuBloom gpu;
  vtkBloomParameters* p = gpu.Parameters();
  p->SetThresholdMode(vtkImageBloomThreshold::NONE);
  p->SetStartLevel(0);
  p->SetNumberOfLevels(levels);
  p->SetLevelWeights(std::vector<double>(levels, 1.0 / levels));
  p->SetCompositeMode(vtkBloomParameters::LERP);
  p->SetStrength(1.0);
  double worst = 0.0;
  int configuration = 0;
  for (const auto& size : sizes)
  {
    const int w = size.first, h = size.second;
    p->SetDownsampleKernel(configuration % 3);
    p->SetUpsampleKernel((configuration / 3) % 2);
    p->SetAccumulateMode((configuration / 6) % 2);
    p->SetKarisAverage(configuration % 5 == 0);
    auto input = vtkBloomHardCases::Constant(w, h, value, VTK_FLOAT, 4);
    auto out = gpu.Apply(input);
    ASSERT_TRUE(out);
    // Alpha is the input's, 0.625 as well.
    const double deviation = vtkBloomHardCases::MaxRelativeDeviationFrom(out, value);
    const double bound = ChainRoundingBound(p, w, h);
    ASSERT_LE(deviation, bound) << w << "x" << h << " configuration " << configuration % 12;
    worst = std::max(worst, deviation);
    ++configuration;
  }
  std::cout << "[ constant ] " << sizes.size() << " sizes, largest relative deviation " << worst
            << "\n";
}

//------------------------------------------------------------------------------
// The threshold at its edge with knee 0: a grey image exactly at the threshold T (a power of 2,
// so that its Rec. 709 luminance is exactly T in float and in double) gives no NaN and no
// negative value, and the documented bright pass (vtkBloomHardCases::
// ExpectedBrightPassAtThreshold: kept by SMOOTHSTEP_KNEE and NONE, 0 otherwise). With one level
// at full resolution and ADDITIVE strength 1, the output is T + bright pass. Negative input
// never emits light: the bloom of an all-negative image is exactly the input, alpha included.
TEST(RenderingBloomPassHardCases, ThresholdEdgeKneeZeroAndNegativeInput)
{
  GpuBloom gpu;
  vtkBloomParameters* p = gpu.Parameters();
  for (const double threshold :
    { 0.0, std::ldexp(1.0, -100), 0.75, 1.0, 4.0, std::ldexp(1.0, 100) })
  {
    for (int mode = 0; mode <= 4; ++mode)
    {
      ASSERT_TRUE(p->SetPreset("crt-halfres"));
      p->SetStartLevel(0);
      p->SetStrength(1.0);
      p->SetThresholdMode(mode);
      p->SetThreshold(threshold);
      p->SetKnee(0.0);
      auto input = vtkBloomHardCases::Constant(9, 7, threshold, VTK_FLOAT, 3);
      auto out = gpu.Apply(input);
      ASSERT_TRUE(out);
      const double expected =
        threshold + vtkBloomHardCases::ExpectedBrightPassAtThreshold(mode, threshold);
      for (vtkIdType q = 0; q < out->GetNumberOfPoints(); ++q)
      {
        for (int c = 0; c < 3; ++c)
        {
          const double v = Get(out, q, c);
          ASSERT_FALSE(std::isnan(v))
            << vtkImageBloomThreshold::GetModeName(mode) << " T " << threshold;
          ASSERT_GE(v, 0.0);
          ASSERT_NEAR(v, expected, 1e-6 * expected)
            << vtkImageBloomThreshold::GetModeName(mode) << " T " << threshold;
        }
      }
    }
  }
  auto negative = vtkBloomHardCases::Constant(23, 17, -2.5, VTK_FLOAT, 4);
  for (const bool sanitize : { true, false })
  {
    for (const char* preset : { "webgpu-market", "ping-pong", "crt-halfres" })
    {
      ASSERT_TRUE(p->SetPreset(preset));
      p->SetSanitizeNonFinite(sanitize);
      auto out = gpu.Apply(negative);
      ASSERT_TRUE(out);
      EXPECT_TRUE(vtkBloomTest::BitIdentical(out, negative)) << preset;
    }
    for (int mode = 0; mode < 4; ++mode)
    {
      ASSERT_TRUE(p->SetPreset("webgpu-market"));
      p->SetThresholdMode(mode);
      p->SetThreshold(0.0);
      p->SetKnee(0.0);
      p->SetSanitizeNonFinite(sanitize);
      auto out = gpu.Apply(negative);
      ASSERT_TRUE(out);
      EXPECT_TRUE(vtkBloomTest::BitIdentical(out, negative))
        << vtkImageBloomThreshold::GetModeName(mode);
    }
  }
}

//------------------------------------------------------------------------------
// With SanitizeNonFinite on, the pass clamps its source and its result to the largest float
// (3.4028235e38), as vtkImageBloom does, not to VTK_FLOAT_MAX (which VTK defines as 1e38): +Inf
// becomes 3.4028235e38 and finite input between 1e38 and 3.4e38 is left alone. (Clamping to
// 1e38 was the ~0.7 relative L2 of TestBloomPass NonFiniteInputFollowsTheCPUPolicy.) Level
// weights 0 leave only the composite.
TEST(RenderingBloomPassHardCases, FiniteValuesAboveVtkFloatMaxAreKept)
{
  GpuBloom gpu;
  gpu.Pass->SetPreset("webgpu-market");
  gpu.Parameters()->SetLevelWeights(std::vector<double>(5, 0.0));
  auto input = vtkBloomHardCases::Constant(1, 1, 0.5, VTK_FLOAT, 3);
  input->GetPointData()->GetScalars()->SetComponent(0, 0, 2e38);
  input->GetPointData()->GetScalars()->SetComponent(0, 1, std::numeric_limits<double>::infinity());
  for (const bool sanitize : { true, false })
  {
    gpu.Parameters()->SetSanitizeNonFinite(sanitize);
    auto out = gpu.Apply(input);
    ASSERT_TRUE(out);
    auto cpu = gpu.Cpu(input);
    EXPECT_EQ(Get(cpu, 0, 0), static_cast<double>(2e38f));
    EXPECT_EQ(Get(cpu, 0, 1),
      sanitize ? std::numeric_limits<float>::max() : std::numeric_limits<double>::infinity());
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_EQ(Get(out, 0, c), Get(cpu, 0, c)) << "sanitize " << sanitize << " channel " << c;
    }
  }
}

//------------------------------------------------------------------------------
// Strength 0, or a tint channel of 0, leaves the input in those channels even when the bloom
// would overflow float32 (webgpu-market adds five levels: a source of 1e38 accumulates
// 5e38 > 3.4e38), so the composite must not form 0 x Inf = NaN: the bloom is clamped to the
// float range before Strength x Tint, as the CPU composite does, with sanitizing on and off.
// (Before 8b79787 the GPU gave NaN with sanitize off and 0 with it on.)
TEST(RenderingBloomPassHardCases, ZeroStrengthOrTintIgnoresAnOverflowingBloom)
{
  struct Case
  {
    const char* Name;
    double Strength;
    double Tint[3];
    int FirstKept; ///< the channels from this one on keep the input
  };
  const Case cases[] = { { "strength 0", 0.0, { 1.0, 1.0, 1.0 }, 0 },
    { "tint (1, 0, 0)", 1.0, { 1.0, 0.0, 0.0 }, 1 } };
  auto input = vtkBloomHardCases::Constant(1, 1, 1e38, VTK_FLOAT, 3);
  for (const Case& c : cases)
  {
    GpuBloom gpu;
    gpu.Pass->SetPreset("webgpu-market");
    gpu.Parameters()->SetStrength(c.Strength);
    gpu.Parameters()->SetTint(c.Tint[0], c.Tint[1], c.Tint[2]);
    for (const bool sanitize : { true, false })
    {
      gpu.Parameters()->SetSanitizeNonFinite(sanitize);
      auto out = gpu.Apply(input);
      ASSERT_TRUE(out);
      auto cpu = gpu.Cpu(input);
      for (int ch = c.FirstKept; ch < 3; ++ch)
      {
        ASSERT_EQ(Get(cpu, 0, ch), static_cast<double>(1e38f)) << c.Name;
        EXPECT_EQ(Get(out, 0, ch), static_cast<double>(1e38f))
          << c.Name << ", sanitize " << sanitize << ", channel " << ch;
      }
    }
  }
}

//------------------------------------------------------------------------------
// Operators wider than 32 taps: the shader's tap masks hold 32 taps, and a shift by 32 or more is
// undefined in GLSL, so the taps beyond are tested by their weight. Level blurs of 33, 63, 65
// (two passes of 33) and 385 taps (the ping-pong preset) on the GPU agree with the CPU filter's
// REFERENCE chain to float rounding, both as tables (near the borders) and as periodic
// interiors, exact and fast.
TEST(RenderingBloomPassHardCases, OperatorsWiderThan32TapsMatchTheCPU)
{
  struct Wide
  {
    const char* Name;
    int HalfTaps;
    int Iterations;
  };
  const Wide cases[] = { { "33 taps", 17, 1 }, { "63 taps", 32, 1 }, { "65 taps", 17, 2 },
    { "385 taps (ping-pong)", 0, 0 } };
  // Bright dots, a few pixels wide, on a dim ramp: the fast mode's bilinear pairs (8-bit
  // filtering weights) stay within their documented error on it.
  const int extent[6] = { 0, 210, 0, 96, 0, 0 };
  auto input = vtkBloomTest::MakeImage(extent, 4, VTK_FLOAT,
    [](int i, int j, int, int ch)
    {
      const double dx = (i % 37) - 18.0, dy = (j % 29) - 14.0;
      return ch == 3 ? 1.0 : 0.1 + 0.002 * i + 6.0 * std::exp(-(dx * dx + dy * dy) / 6.0);
    });
  for (const Wide& c : cases)
  {
    GpuBloom gpu;
    vtkBloomParameters* p = gpu.Parameters();
    if (c.HalfTaps == 0)
    {
      p->SetPreset("ping-pong");
    }
    else
    {
      p->SetReferenceHeight(0);
      p->SetThresholdMode(vtkImageBloomThreshold::NONE);
      p->SetStartLevel(0);
      p->SetNumberOfLevels(1);
      p->SetBlurKernel(vtkBloomParameters::BLUR_CUSTOM);
      // Unequal weights, so that a dropped or doubled tap shows.
      std::vector<double> half(c.HalfTaps);
      for (int k = 0; k < c.HalfTaps; ++k)
      {
        half[k] = 1.0 / (2.0 * c.HalfTaps) * (1.0 + 0.5 * std::cos(0.7 * k));
      }
      p->SetBlurHalfKernel(half);
      p->SetBlurIterations(c.Iterations);
    }
    auto cpu = gpu.Cpu(input);
    auto out = gpu.Apply(input);
    ASSERT_TRUE(out);
    EXPECT_LE(ColourRelativeL2(out, cpu, [](int, int) { return true; }), 1e-5) << c.Name;
  }
}
