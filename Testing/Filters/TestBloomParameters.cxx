// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// vtkBloomParameters: one parameter set for the filter and the render pass. A filter given
// another's parameters shares them (an edit through either re-executes both), a copy changes
// nothing when the values are equal, the filter's shortcuts and its enum names are the
// parameters' own, and presets are named in one place.
#include "vtkBloomParameters.h"
#include "vtkBloomTestSupport.h"
#include "vtkImageBloom.h"
#include "vtkImageSeparableGaussian.h"

#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace
{
// The old enum names of vtkImageBloom and vtkImageSeparableGaussian are the parameters' values.
static_assert(int(vtkImageBloom::BLUR_CUSTOM) == int(vtkBloomParameters::BLUR_CUSTOM), "");
static_assert(int(vtkImageBloom::DIRECT) == int(vtkBloomParameters::DIRECT), "");
static_assert(int(vtkImageBloom::LERP) == int(vtkBloomParameters::LERP), "");
static_assert(int(vtkImageBloom::BLOOM_PSF) == int(vtkBloomParameters::BLOOM_PSF), "");
static_assert(int(vtkImageBloom::PSF_IMAGE) == int(vtkBloomParameters::PSF_IMAGE), "");
static_assert(int(vtkImageBloom::CONVOLUTION_FFT) == int(vtkBloomParameters::CONVOLUTION_FFT), "");
static_assert(
  int(vtkImageSeparableGaussian::CONVOLUTION_DIRECT) == int(vtkBloomParameters::CONVOLUTION_DIRECT),
  "");

// The messages of the ErrorEvents an object sends.
class ErrorLog : public vtkCommand
{
public:
  static ErrorLog* New() { return new ErrorLog; }
  void Execute(vtkObject*, unsigned long, void* data) override
  {
    this->Messages.emplace_back(data ? static_cast<const char*>(data) : "");
  }
  std::vector<std::string> Messages;
};

vtkSmartPointer<vtkImageData> BrightDots()
{
  const int extent[6] = { 0, 31, 0, 19, 0, 0 };
  return vtkBloomTest::MakeImage(extent, 3, VTK_FLOAT,
    [](int i, int j, int, int c) { return (i * 5 + j * 3) % 13 == 0 ? 3.0 + c : 0.1; });
}

double Sample(vtkImageBloom* filter, vtkIdType point)
{
  return filter->GetOutput()->GetPointData()->GetScalars()->GetComponent(point, 1);
}
}

TEST(FiltersParameters, FiltersSharingParametersFollowEveryEdit)
{
  auto image = BrightDots();
  vtkNew<vtkImageBloom> a, b;
  b->SetParameters(a->GetParameters());
  EXPECT_EQ(a->GetParameters(), b->GetParameters());
  a->SetInputData(image);
  b->SetInputData(image);
  a->Update();
  b->Update();
  const vtkIdType p = 5 * 32 + 7;
  const double before = Sample(b, p);
  EXPECT_EQ(Sample(a, p), before);

  // An edit through a's shortcut reaches b: b re-executes with the new strength.
  a->SetStrength(3.0);
  EXPECT_EQ(b->GetStrength(), 3.0);
  b->Update();
  EXPECT_NE(Sample(b, p), before);
  a->Update();
  EXPECT_EQ(Sample(a, p), Sample(b, p));

  // A null pointer is ignored; the filter keeps its parameters.
  b->SetParameters(nullptr);
  EXPECT_EQ(b->GetParameters(), a->GetParameters());
}

TEST(FiltersParameters, DeepCopyModifiesOnlyOnChange)
{
  vtkNew<vtkBloomParameters> source, copy;
  source->SetPreset("mip-atlas");
  source->SetPSFGaussians({ 2.0 }, { 1.0 });
  copy->DeepCopy(source);
  EXPECT_EQ(copy->GetStrength(), 0.52);
  EXPECT_EQ(copy->GetLevelWeights(), source->GetLevelWeights());
  EXPECT_EQ(copy->GetPSFGaussianSigmas(), std::vector<double>{ 2.0 });
  const vtkMTimeType copied = copy->GetMTime();
  copy->DeepCopy(source);
  EXPECT_EQ(copy->GetMTime(), copied);
  source->SetThreshold(7.0);
  copy->DeepCopy(source);
  EXPECT_GT(copy->GetMTime(), copied);
  EXPECT_EQ(copy->GetThreshold(), 7.0);
}

TEST(FiltersParameters, PresetsAreNamedOnce)
{
  const auto names = vtkBloomParameters::GetPresetNames();
  ASSERT_EQ(names.size(), 4u);
  EXPECT_EQ(vtkImageBloom::GetPresetNames(), names);
  std::string joined;
  for (const std::string& name : names)
  {
    joined += (joined.empty() ? "" : ", ") + name;
    vtkNew<vtkBloomParameters> p;
    EXPECT_TRUE(p->SetPreset(name.c_str()));
  }
  EXPECT_EQ(vtkBloomParameters::GetPresetNamesList(), joined);

  // An unknown name is one error naming every preset, and changes nothing.
  vtkNew<vtkBloomParameters> p;
  vtkNew<ErrorLog> errors;
  p->AddObserver(vtkCommand::ErrorEvent, errors);
  const vtkMTimeType before = p->GetMTime();
  EXPECT_FALSE(p->SetPreset("glare"));
  ASSERT_EQ(errors->Messages.size(), 1u);
  EXPECT_NE(errors->Messages[0].find(joined), std::string::npos) << errors->Messages[0];
  EXPECT_EQ(p->GetMTime(), before);
}

TEST(FiltersParameters, ValidateNamesTheFirstNonFiniteValue)
{
  vtkNew<vtkBloomParameters> p;
  EXPECT_EQ(p->Validate(), "");
  p->SetTint(1.0, std::numeric_limits<double>::infinity(), 1.0);
  EXPECT_NE(p->Validate().find("Tint"), std::string::npos);
  p->SetTint(1.0, 1.0, 1.0);
  p->SetLevelWeights({ 1.0, std::nan("") });
  EXPECT_NE(p->Validate().find("Level weights"), std::string::npos);
}
