// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// vtkImagePyramidDown: the three kernels (and the Karis average) against the float64 reference
// on every size from 1x1 to 67x67 (box) or a dense subset (the others), with a non-zero extent,
// origin and spacing; output geometry; constants; mean preservation; 3-D input.
#include "vtkBloomReference.h"
#include "vtkBloomTestSupport.h"

#include <vtkImageData.h>
#include <vtkImagePyramidDown.h>
#include <vtkNew.h>

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

using vtkBloomRef::Texture;

namespace
{
const double Origin[3] = { 0.25, -1.5, 2.0 };
const double Spacing[3] = { 0.5, 1.25, 3.0 };
const int Lo[2] = { -3, 5 };

vtkSmartPointer<vtkImageData> Down(vtkImageData* input, int kernel, bool karis)
{
  vtkNew<vtkImagePyramidDown> filter;
  filter->SetKernel(kernel);
  filter->SetKarisAverage(karis);
  return vtkBloomTest::RunAndCopy(filter, input);
}

vtkSmartPointer<vtkImageData> Placed(const Texture& t, int components, int type)
{
  auto image = vtkBloomRef::ToImage(t, components, type, Lo);
  image->SetOrigin(const_cast<double*>(Origin));
  image->SetSpacing(const_cast<double*>(Spacing));
  return image;
}

double Mean(const Texture& t, int c)
{
  double sum = 0.0;
  for (const auto& p : t.Texels)
  {
    sum += p[c];
  }
  return sum / t.Texels.size();
}

// Collects failures of a long loop, so that a broken filter reports a few cases, not thousands.
struct Failures
{
  std::vector<std::string> List;
  void Add(const std::string& s) { this->List.push_back(s); }
  std::string Summary() const
  {
    std::ostringstream os;
    os << this->List.size() << " failures";
    for (size_t i = 0; i < this->List.size() && i < 15; ++i)
    {
      os << "\n  " << this->List[i];
    }
    return os.str();
  }
};

// One size: geometry, values against the reference, constants (and the mean for BOX).
void CheckSize(int w, int h, int kernel, bool karis, Failures& failures)
{
  std::ostringstream tag;
  tag << w << "x" << h << " kernel " << kernel << (karis ? " karis" : "") << ": ";
  const Texture image = vtkBloomRef::RandomImage(w, h, 1000 + 97 * w + h, 0.0, 4.0);
  auto input = Placed(image, 4, VTK_DOUBLE);
  auto out = Down(input, kernel, karis);

  // Geometry: size max(1, floor(n / 2)), start floor(lo / 2), spacing s n / n', the same
  // physical footprint [o + (lo - 1/2) s, o + (hi + 1/2) s].
  int ext[6];
  out->GetExtent(ext);
  const double* origin = out->GetOrigin();
  const double* spacing = out->GetSpacing();
  const int n[2] = { w, h };
  for (int a = 0; a < 2; ++a)
  {
    const int m = std::max(1, n[a] / 2);
    const int start = static_cast<int>(std::floor(Lo[a] / 2.0));
    if (ext[2 * a] != start || ext[2 * a + 1] - ext[2 * a] + 1 != m)
    {
      failures.Add(tag.str() + "extent axis " + std::to_string(a));
      return;
    }
    if (std::abs(spacing[a] - Spacing[a] * n[a] / m) > 1e-12)
    {
      failures.Add(tag.str() + "spacing axis " + std::to_string(a));
    }
    const double inLo = Origin[a] + (Lo[a] - 0.5) * Spacing[a];
    const double inHi = Origin[a] + (Lo[a] + n[a] - 1 + 0.5) * Spacing[a];
    const double outLo = origin[a] + (ext[2 * a] - 0.5) * spacing[a];
    const double outHi = origin[a] + (ext[2 * a + 1] + 0.5) * spacing[a];
    if (std::abs(outLo - inLo) > 1e-12 || std::abs(outHi - inHi) > 1e-12)
    {
      std::ostringstream os;
      os << tag.str() << "footprint axis " << a << ": [" << outLo << ", " << outHi << "] vs ["
         << inLo << ", " << inHi << "]";
      failures.Add(os.str());
    }
  }
  if (ext[4] != 0 || ext[5] != 0 || origin[2] != Origin[2] || spacing[2] != Spacing[2])
  {
    failures.Add(tag.str() + "z geometry changed");
  }

  // Values.
  const Texture expected =
    vtkBloomRef::PyramidDown(image, static_cast<vtkBloomRef::DownKernel>(kernel), karis);
  const double error = vtkBloomRef::RelativeL2(vtkBloomRef::FromImage(out), expected);
  if (!(error <= 1e-12))
  {
    failures.Add(tag.str() + "rel L2 vs reference " + std::to_string(error));
  }
  if (kernel == vtkImagePyramidDown::BOX)
  {
    // The exact area resample preserves the mean, odd sizes included.
    for (int c = 0; c < 4; ++c)
    {
      const double before = Mean(image, c);
      const double after = Mean(vtkBloomRef::FromImage(out), c);
      if (std::abs(after - before) > 1e-12 * std::abs(before))
      {
        failures.Add(tag.str() + "mean " + std::to_string(after) + " vs " + std::to_string(before));
      }
    }
  }

  // A constant stays constant.
  Texture constant(w, h);
  for (auto& p : constant.Texels)
  {
    p = { 3.7, 0.25, 12.0, 0.5 };
  }
  auto flat = Down(Placed(constant, 4, VTK_DOUBLE), kernel, karis);
  const Texture result = vtkBloomRef::FromImage(flat);
  for (const auto& p : result.Texels)
  {
    if (std::abs(p[0] - 3.7) > 1e-12 * 3.7 || std::abs(p[1] - 0.25) > 1e-12 * 0.25 ||
      std::abs(p[2] - 12.0) > 1e-12 * 12.0 || std::abs(p[3] - 0.5) > 1e-12 * 0.5)
    {
      failures.Add(tag.str() + "constant not preserved");
      break;
    }
  }
}

std::vector<int> DenseSizes()
{
  std::vector<int> sizes;
  for (int n = 1; n <= 23; ++n)
  {
    sizes.push_back(n);
  }
  for (int p : { 29, 31, 37, 41, 43, 47, 53, 59, 61, 64, 67 })
  {
    sizes.push_back(p);
  }
  return sizes;
}
}

// BOX on every size from 1x1 to 67x67.
TEST(FiltersPyramidDown, BoxEverySize)
{
  Failures failures;
  for (int h = 1; h <= 67; ++h)
  {
    for (int w = 1; w <= 67; ++w)
    {
      CheckSize(w, h, vtkImagePyramidDown::BOX, false, failures);
    }
  }
  EXPECT_TRUE(failures.List.empty()) << failures.Summary();
}

// JIMENEZ13 (with and without the Karis average) and BINOMIAL on all sizes up to 23 and the
// primes up to 67 (and 64), on both axes.
TEST(FiltersPyramidDown, Jimenez13DenseSizes)
{
  Failures failures;
  for (int h : DenseSizes())
  {
    for (int w : DenseSizes())
    {
      CheckSize(w, h, vtkImagePyramidDown::JIMENEZ13, false, failures);
    }
  }
  EXPECT_TRUE(failures.List.empty()) << failures.Summary();
}

TEST(FiltersPyramidDown, KarisDenseSizes)
{
  Failures failures;
  for (int h : DenseSizes())
  {
    for (int w : DenseSizes())
    {
      CheckSize(w, h, vtkImagePyramidDown::JIMENEZ13, true, failures);
    }
  }
  EXPECT_TRUE(failures.List.empty()) << failures.Summary();
}

TEST(FiltersPyramidDown, BinomialDenseSizes)
{
  Failures failures;
  for (int h : DenseSizes())
  {
    for (int w : DenseSizes())
    {
      CheckSize(w, h, vtkImagePyramidDown::BINOMIAL, false, failures);
    }
  }
  EXPECT_TRUE(failures.List.empty()) << failures.Summary();
}

// The Karis average really changes the result of a firefly (so the test above is not blind),
// and pulls the output towards the dim surroundings.
TEST(FiltersPyramidDown, KarisSuppressesFireflies)
{
  Texture image(8, 8);
  for (auto& p : image.Texels)
  {
    p = { 0.1, 0.1, 0.1, 1.0 };
  }
  image.At(3, 3) = { 1000.0, 1000.0, 1000.0, 1.0 };
  auto input = vtkBloomRef::ToImage(image, 4, VTK_DOUBLE);
  const Texture plain = vtkBloomRef::FromImage(Down(input, vtkImagePyramidDown::JIMENEZ13, false));
  const Texture karis = vtkBloomRef::FromImage(Down(input, vtkImagePyramidDown::JIMENEZ13, true));
  // Output (1, 1) sits on the firefly: 195.4 plain, 154.3 with Karis. Its neighbours, which
  // only see it through their outer boxes, drop from 23.5 to 0.46.
  EXPECT_LT(karis.At(1, 1)[0], 0.85 * plain.At(1, 1)[0]);
  EXPECT_GT(karis.At(1, 1)[0], 100.0);
  EXPECT_LT(karis.At(2, 1)[0], 0.05 * plain.At(2, 1)[0]);
  EXPECT_LT(karis.At(1, 2)[0], 0.05 * plain.At(1, 2)[0]);
  EXPECT_NEAR(karis.At(3, 3)[0], 0.1, 1e-12); // far away: untouched background
}

// 1 and 2 component images (Karis luma = the value) and float input, against the reference run
// on the RGB image R = G = B.
TEST(FiltersPyramidDown, ComponentsAndFloat)
{
  for (const auto& size : { std::make_pair(9, 7), std::make_pair(16, 5), std::make_pair(1, 12) })
  {
    Texture image = vtkBloomRef::RandomImage(size.first, size.second, 31, 0.0, 8.0);
    for (auto& p : image.Texels)
    {
      p[1] = p[2] = p[0];
    }
    for (int kernel = 0; kernel < 3; ++kernel)
    {
      for (bool karis : { false, true })
      {
        if (karis && kernel != vtkImagePyramidDown::JIMENEZ13)
        {
          continue;
        }
        const Texture expected =
          vtkBloomRef::PyramidDown(image, static_cast<vtkBloomRef::DownKernel>(kernel), karis);
        for (int nc : { 1, 2, 3, 4 })
        {
          for (int type : { VTK_DOUBLE, VTK_FLOAT })
          {
            auto out = Down(vtkBloomRef::ToImage(image, nc, type), kernel, karis);
            const double error = vtkBloomRef::RelativeL2(
              vtkBloomRef::FromImage(out), expected, nc == 1 ? 3 : (nc == 2 ? 4 : nc));
            EXPECT_LE(error, type == VTK_DOUBLE ? 1e-12 : 1e-6)
              << size.first << "x" << size.second << " kernel " << kernel << " karis " << karis
              << " components " << nc << (type == VTK_FLOAT ? " float" : " double");
          }
        }
      }
    }
  }
}

// A 3-D input keeps its Z extent, origin and spacing, and each slice is filtered on its own.
TEST(FiltersPyramidDown, ThreeDKeepsZ)
{
  const int ext[6] = { 0, 8, 0, 5, 2, 5 };
  auto input = vtkBloomTest::MakeImage(ext, 3, VTK_DOUBLE,
    [](int i, int j, int k, int c)
    { return 1.0 + vtkBloomRef::HashUniform(k, (j * 9 + i) * 3 + c) * (k + 1); });
  input->SetOrigin(1.0, 2.0, 7.0);
  input->SetSpacing(1.0, 1.0, 0.3);
  for (int kernel = 0; kernel < 3; ++kernel)
  {
    auto out = Down(input, kernel, false);
    int outExt[6];
    out->GetExtent(outExt);
    EXPECT_EQ(outExt[4], 2);
    EXPECT_EQ(outExt[5], 5);
    EXPECT_EQ(out->GetOrigin()[2], 7.0);
    EXPECT_EQ(out->GetSpacing()[2], 0.3);
    for (int k = 0; k < 4; ++k)
    {
      const Texture slice = vtkBloomRef::FromImage(input, k);
      const Texture expected =
        vtkBloomRef::PyramidDown(slice, static_cast<vtkBloomRef::DownKernel>(kernel));
      EXPECT_LE(vtkBloomRef::RelativeL2(vtkBloomRef::FromImage(out, k), expected, 3), 1e-12)
        << "kernel " << kernel << " slice " << k;
    }
  }
}

// The static geometry helper agrees with the class description on a few hand-worked cases.
TEST(FiltersPyramidDown, ComputeOutputGeometry)
{
  EXPECT_EQ(vtkImagePyramidDown::HalvedSize(1), 1);
  EXPECT_EQ(vtkImagePyramidDown::HalvedSize(2), 1);
  EXPECT_EQ(vtkImagePyramidDown::HalvedSize(3), 1);
  EXPECT_EQ(vtkImagePyramidDown::HalvedSize(67), 33);
  const int inExt[6] = { 0, 4, -1, 0, 0, 2 }; // 5 x 2 x 3
  const double o[3] = { 0.0, 0.0, 0.0 }, s[3] = { 1.0, 1.0, 1.0 };
  int outExt[6];
  double outOrigin[3], outSpacing[3];
  vtkImagePyramidDown::ComputeOutputGeometry(inExt, o, s, outExt, outOrigin, outSpacing);
  // x: 5 -> 2 pixels of 2.5, footprint [-0.5, 4.5], centres at 0.75 and 3.25.
  EXPECT_EQ(outExt[0], 0);
  EXPECT_EQ(outExt[1], 1);
  EXPECT_DOUBLE_EQ(outSpacing[0], 2.5);
  EXPECT_DOUBLE_EQ(outOrigin[0], 0.75);
  // y: 2 -> 1 pixel of 2, extent starting at floor(-1 / 2) = -1, centre at -0.5.
  EXPECT_EQ(outExt[2], -1);
  EXPECT_EQ(outExt[3], -1);
  EXPECT_DOUBLE_EQ(outSpacing[1], 2.0);
  EXPECT_DOUBLE_EQ(outOrigin[1] + (-1) * outSpacing[1], -0.5);
  // z untouched.
  EXPECT_EQ(outExt[4], 0);
  EXPECT_EQ(outExt[5], 2);
}
