// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// vtkImagePyramidUp: tent and bilinear upsampling against the float64 reference, the FineWeight
// term, constants, and the output geometry (that of input 1).
#include "vtkBloomReference.h"
#include "vtkBloomTestSupport.h"

#include <vtkImageData.h>
#include <vtkImagePyramidDown.h>
#include <vtkImagePyramidUp.h>
#include <vtkNew.h>

#include <gtest/gtest.h>

#include <string>

using vtkBloomRef::Texture;

namespace
{
struct UpSettings
{
  int Kernel = vtkImagePyramidUp::TENT;
  double CoarseWeight = 1.0;
  double FineWeight = 0.0;
};

vtkSmartPointer<vtkImageData> Up(vtkImageData* coarse, vtkImageData* fine, const UpSettings& s)
{
  vtkNew<vtkImagePyramidUp> filter;
  filter->SetKernel(s.Kernel);
  filter->SetCoarseWeight(s.CoarseWeight);
  filter->SetFineWeight(s.FineWeight);
  filter->SetFineInputData(fine);
  return vtkBloomTest::RunAndCopy(filter, coarse);
}

Texture Expected(const Texture& coarse, const Texture& fine, const UpSettings& s)
{
  Texture up =
    vtkBloomRef::PyramidUp(coarse, fine.W, fine.H, static_cast<vtkBloomRef::UpKernel>(s.Kernel));
  for (size_t t = 0; t < up.Texels.size(); ++t)
  {
    for (int c = 0; c < 4; ++c)
    {
      up.Texels[t][c] = s.CoarseWeight * up.Texels[t][c] + s.FineWeight * fine.Texels[t][c];
    }
  }
  return up;
}

// (coarse, fine) size pairs: the pyramid's own halvings, and arbitrary ratios.
struct Pair
{
  int Cw, Ch, Fw, Fh;
};
const Pair Pairs[] = { { 1, 1, 1, 1 }, { 1, 1, 2, 3 }, { 2, 2, 5, 5 }, { 8, 4, 17, 9 },
  { 16, 10, 33, 20 }, { 32, 32, 64, 64 }, { 1, 3, 1, 7 }, { 80, 45, 161, 91 }, { 7, 5, 16, 9 },
  { 3, 3, 3, 3 }, { 1, 1, 5, 4 }, { 6, 2, 7, 11 } };
}

// Both kernels, with and without the fine term and a coarse weight, against the reference:
// rel L2 <= 1e-12 (double) / 1e-6 (float); the output takes input 1's extent, origin and
// spacing, whatever the coarse geometry.
TEST(FiltersPyramidUp, MatchesReference)
{
  unsigned seed = 40;
  for (const Pair& p : Pairs)
  {
    const Texture coarse = vtkBloomRef::RandomImage(p.Cw, p.Ch, ++seed, 0.0, 5.0);
    const Texture fine = vtkBloomRef::RandomImage(p.Fw, p.Fh, ++seed, -1.0, 1.0);
    const UpSettings settings[] = { { vtkImagePyramidUp::TENT, 1.0, 0.0 },
      { vtkImagePyramidUp::BILINEAR, 1.0, 0.0 }, { vtkImagePyramidUp::TENT, 0.7, 0.35 },
      { vtkImagePyramidUp::BILINEAR, 1.5, 1.0 } };
    for (const UpSettings& s : settings)
    {
      const Texture expected = Expected(coarse, fine, s);
      for (int type : { VTK_DOUBLE, VTK_FLOAT })
      {
        const int coarseLo[2] = { 4, -2 };
        const int fineLo[2] = { -3, 5 };
        auto c = vtkBloomRef::ToImage(coarse, 4, type, coarseLo);
        c->SetOrigin(100.0, 0.0, 0.0);
        c->SetSpacing(3.0, 0.5, 1.0);
        auto f = vtkBloomRef::ToImage(fine, 4, type, fineLo);
        f->SetOrigin(0.25, -1.5, 2.0);
        f->SetSpacing(0.5, 1.25, 3.0);
        auto out = Up(c, f, s);
        const std::string what = std::to_string(p.Cw) + "x" + std::to_string(p.Ch) + " -> " +
          std::to_string(p.Fw) + "x" + std::to_string(p.Fh) + " kernel " +
          std::to_string(s.Kernel) + " fine weight " + std::to_string(s.FineWeight) +
          (type == VTK_FLOAT ? " float" : " double");
        int ext[6], fineExt[6];
        out->GetExtent(ext);
        f->GetExtent(fineExt);
        for (int a = 0; a < 6; ++a)
        {
          EXPECT_EQ(ext[a], fineExt[a]) << what;
        }
        for (int a = 0; a < 3; ++a)
        {
          EXPECT_EQ(out->GetOrigin()[a], f->GetOrigin()[a]) << what;
          EXPECT_EQ(out->GetSpacing()[a], f->GetSpacing()[a]) << what;
        }
        EXPECT_EQ(out->GetScalarType(), type) << what;
        const double error = vtkBloomRef::RelativeL2(vtkBloomRef::FromImage(out), expected);
        EXPECT_LE(error, type == VTK_DOUBLE ? 1e-12 : 1e-6) << what;
      }
    }
  }
}

// FineWeight adds exactly FineWeight times the finer level; with 0 the finer values are ignored.
TEST(FiltersPyramidUp, FineWeightAddsFinerLevel)
{
  const Texture coarse = vtkBloomRef::RandomImage(6, 4, 1, 0.0, 5.0);
  const Texture fine = vtkBloomRef::RandomImage(13, 9, 2, 1.0, 3.0);
  const Texture other = vtkBloomRef::RandomImage(13, 9, 3, -9.0, 9.0);
  auto c = vtkBloomRef::ToImage(coarse, 3, VTK_DOUBLE);
  auto f = vtkBloomRef::ToImage(fine, 3, VTK_DOUBLE);
  UpSettings s;
  auto without = Up(c, f, s);
  // The finer values do not matter with FineWeight 0, only its geometry.
  EXPECT_TRUE(
    vtkBloomTest::BitIdentical(without, Up(c, vtkBloomRef::ToImage(other, 3, VTK_DOUBLE), s)));
  s.FineWeight = 0.5;
  auto with = Up(c, f, s);
  for (int j = 0; j < 9; ++j)
  {
    for (int i = 0; i < 13; ++i)
    {
      for (int comp = 0; comp < 3; ++comp)
      {
        EXPECT_NEAR(
          vtkBloomTest::Value(with, i, j, 0, comp) - vtkBloomTest::Value(without, i, j, 0, comp),
          0.5 * fine.At(i, j)[comp], 1e-13);
      }
    }
  }
}

// A constant coarse level upsamples to the same constant, for both kernels and any ratio.
TEST(FiltersPyramidUp, ConstantStaysConstant)
{
  for (const Pair& p : Pairs)
  {
    for (int kernel : { vtkImagePyramidUp::TENT, vtkImagePyramidUp::BILINEAR })
    {
      const int cext[6] = { 0, p.Cw - 1, 0, p.Ch - 1, 0, 0 };
      const int fext[6] = { 0, p.Fw - 1, 0, p.Fh - 1, 0, 0 };
      auto c = vtkBloomTest::MakeImage(
        cext, 4, VTK_DOUBLE, [](int, int, int, int comp) { return 0.3 + 2.1 * comp; });
      auto f = vtkBloomTest::MakeImage(fext, 4, VTK_DOUBLE, [](int, int, int, int) { return 9.0; });
      UpSettings s;
      s.Kernel = kernel;
      auto out = Up(c, f, s);
      ASSERT_EQ(out->GetNumberOfPoints(), static_cast<vtkIdType>(p.Fw) * p.Fh);
      for (int j = 0; j < p.Fh; ++j)
      {
        for (int i = 0; i < p.Fw; ++i)
        {
          for (int comp = 0; comp < 4; ++comp)
          {
            const double v = 0.3 + 2.1 * comp;
            EXPECT_NEAR(vtkBloomTest::Value(out, i, j, 0, comp), v, 1e-12 * v);
          }
        }
      }
    }
  }
}

// 1 and 2 component images against the reference run on R = G = B.
TEST(FiltersPyramidUp, Components)
{
  Texture coarse = vtkBloomRef::RandomImage(5, 3, 8, 0.0, 5.0);
  Texture fine = vtkBloomRef::RandomImage(11, 7, 9, 0.0, 1.0);
  for (Texture* t : { &coarse, &fine })
  {
    for (auto& p : t->Texels)
    {
      p[1] = p[2] = p[0];
    }
  }
  for (int kernel : { vtkImagePyramidUp::TENT, vtkImagePyramidUp::BILINEAR })
  {
    UpSettings s;
    s.Kernel = kernel;
    s.FineWeight = 0.25;
    const Texture expected = Expected(coarse, fine, s);
    for (int nc : { 1, 2, 3 })
    {
      auto out = Up(vtkBloomRef::ToImage(coarse, nc, VTK_DOUBLE),
        vtkBloomRef::ToImage(fine, nc, VTK_DOUBLE), s);
      EXPECT_LE(
        vtkBloomRef::RelativeL2(vtkBloomRef::FromImage(out), expected, nc == 2 ? 4 : 3), 1e-12)
        << "kernel " << kernel << " components " << nc;
    }
  }
}

// In a pipeline behind vtkImagePyramidDown, the footprints line up: a down-then-up of a smooth
// linear ramp (in the interior, away from the clamped edges) returns the ramp, because both
// place samples at the GPU positions (j + 1/2) n / n' - 1/2.
TEST(FiltersPyramidUp, RoundTripAlignsFootprints)
{
  const int ext[6] = { -3, 36, 5, 28, 0, 0 }; // 40 x 24
  auto ramp = vtkBloomTest::MakeImage(
    ext, 1, VTK_DOUBLE, [](int i, int j, int, int) { return 0.5 * i - 0.25 * j; });
  ramp->SetOrigin(0.25, -1.5, 2.0);
  ramp->SetSpacing(0.5, 1.25, 3.0);
  vtkNew<vtkImagePyramidDown> down;
  down->SetKernelToBox();
  down->SetInputData(ramp);
  vtkNew<vtkImagePyramidUp> up;
  up->SetKernelToBilinear();
  up->SetInputConnection(down->GetOutputPort());
  up->SetFineInputData(ramp);
  up->Update();
  vtkImageData* out = up->GetOutput();
  int outExt[6];
  out->GetExtent(outExt);
  for (int a = 0; a < 6; ++a)
  {
    EXPECT_EQ(outExt[a], ext[a]);
  }
  for (int j = ext[2] + 2; j <= ext[3] - 2; ++j)
  {
    for (int i = ext[0] + 2; i <= ext[1] - 2; ++i)
    {
      EXPECT_NEAR(vtkBloomTest::Value(out, i, j, 0, 0), 0.5 * i - 0.25 * j, 1e-12)
        << i << ", " << j;
    }
  }
}
