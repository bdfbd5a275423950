// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// Error handling, PrintSelf and progress of every filter of the module.
#include "vtkBloomReference.h"
#include "vtkBloomTestSupport.h"

#include <vtkCommand.h>
#include <vtkExecutive.h>
#include <vtkImageAlgorithm.h>
#include <vtkImageBloom.h>
#include <vtkImageBloomThreshold.h>
#include <vtkImageData.h>
#include <vtkImagePyramidDown.h>
#include <vtkImagePyramidUp.h>
#include <vtkImageSeparableGaussian.h>
#include <vtkNew.h>
#include <vtkPointData.h>

#include <gtest/gtest.h>

#include <functional>
#include <sstream>
#include <string>
#include <vector>

namespace
{
// Counts events and remembers the progress values and the last message.
class EventLog : public vtkCommand
{
public:
  static EventLog* New() { return new EventLog; }
  void Execute(vtkObject*, unsigned long event, void* data) override
  {
    ++this->Count;
    if (event == vtkCommand::ProgressEvent && data)
    {
      this->Progress.push_back(*static_cast<double*>(data));
    }
    else if (event == vtkCommand::ErrorEvent && data)
    {
      this->Message = static_cast<const char*>(data);
    }
  }
  int Count = 0;
  std::vector<double> Progress;
  std::string Message;
};

struct Named
{
  std::string Name;
  std::function<vtkSmartPointer<vtkImageAlgorithm>()> Make;
  bool TwoInputs = false;
};

std::vector<Named> Filters()
{
  return {
    { "vtkImageBloomThreshold",
      []() {
        return vtkSmartPointer<vtkImageAlgorithm>(vtkSmartPointer<vtkImageBloomThreshold>::New());
      } },
    { "vtkImageSeparableGaussian",
      []() {
        return vtkSmartPointer<vtkImageAlgorithm>(
          vtkSmartPointer<vtkImageSeparableGaussian>::New());
      } },
    { "vtkImagePyramidDown",
      []()
      { return vtkSmartPointer<vtkImageAlgorithm>(vtkSmartPointer<vtkImagePyramidDown>::New()); } },
    { "vtkImagePyramidUp",
      []()
      {
        auto up = vtkSmartPointer<vtkImagePyramidUp>::New();
        up->SetFineWeight(1.0);
        return vtkSmartPointer<vtkImageAlgorithm>(up);
      },
      true },
    { "vtkImageBloom",
      []() { return vtkSmartPointer<vtkImageAlgorithm>(vtkSmartPointer<vtkImageBloom>::New()); } },
  };
}

vtkSmartPointer<vtkImageData> Image(int w, int h, int components, int type)
{
  const int ext[6] = { 0, w - 1, 0, h - 1, 0, 0 };
  return vtkBloomTest::MakeImage(ext, components, type,
    [](int i, int j, int, int c) { return 1.0 + ((i * 3 + j * 5 + c) % 7); });
}

std::string Print(vtkObject* o)
{
  std::ostringstream os;
  o->Print(os);
  return os.str();
}
}

// Unsupported scalar types (short, unsigned char, int) and 5 components: an ErrorEvent on the
// filter and an output without points or scalars, for every filter.
TEST(FiltersErrors, UnsupportedInputs)
{
  const std::pair<int, int> inputs[] = { { VTK_SHORT, 3 }, { VTK_UNSIGNED_CHAR, 4 }, { VTK_INT, 1 },
    { VTK_FLOAT, 5 }, { VTK_DOUBLE, 6 } };
  for (const Named& f : Filters())
  {
    for (const auto& in : inputs)
    {
      auto filter = f.Make();
      vtkNew<EventLog> errors;
      vtkNew<EventLog> executiveErrors;
      filter->AddObserver(vtkCommand::ErrorEvent, errors);
      filter->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, executiveErrors);
      auto image = Image(9, 7, in.second, in.first);
      filter->SetInputData(0, image);
      if (f.TwoInputs)
      {
        filter->SetInputData(1, Image(18, 14, in.second, in.first));
      }
      filter->Update();
      const std::string what =
        f.Name + " with " + image->GetScalarTypeAsString() + " x " + std::to_string(in.second);
      EXPECT_GE(errors->Count, 1) << what;
      vtkImageData* out = vtkImageData::SafeDownCast(filter->GetOutputDataObject(0));
      ASSERT_NE(out, nullptr) << what;
      EXPECT_EQ(out->GetNumberOfPoints(), 0) << what;
      EXPECT_EQ(out->GetPointData()->GetScalars(), nullptr) << what;
    }
  }
}

// A supported input after an unsupported one works again (the error leaves no stale state).
TEST(FiltersErrors, RecoversAfterError)
{
  for (const Named& f : Filters())
  {
    auto filter = f.Make();
    vtkNew<EventLog> errors;
    filter->AddObserver(vtkCommand::ErrorEvent, errors);
    filter->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, errors);
    filter->SetInputData(0, Image(9, 7, 3, VTK_SHORT));
    if (f.TwoInputs)
    {
      filter->SetInputData(1, Image(18, 14, 3, VTK_FLOAT));
    }
    filter->Update();
    ASSERT_GE(errors->Count, 1) << f.Name;
    const int before = errors->Count;
    filter->SetInputData(0, Image(9, 7, 3, VTK_FLOAT));
    filter->Update();
    EXPECT_EQ(errors->Count, before) << f.Name;
    EXPECT_GT(vtkImageData::SafeDownCast(filter->GetOutputDataObject(0))->GetNumberOfPoints(), 0)
      << f.Name;
  }
}

// An unknown preset name: false, an ErrorEvent naming it, and every parameter unchanged.
TEST(FiltersErrors, UnknownPreset)
{
  vtkNew<vtkImageBloom> bloom;
  vtkNew<EventLog> errors;
  bloom->AddObserver(vtkCommand::ErrorEvent, errors);
  ASSERT_TRUE(bloom->SetPreset("crt-halfres"));
  const double threshold = bloom->GetThreshold();
  const int mode = bloom->GetThresholdMode();
  const double strength = bloom->GetStrength();
  const int levels = bloom->GetNumberOfLevels();
  EXPECT_FALSE(bloom->SetPreset("nope"));
  EXPECT_EQ(errors->Count, 1);
  EXPECT_NE(errors->Message.find("nope"), std::string::npos) << errors->Message;
  EXPECT_FALSE(bloom->SetPreset(nullptr));
  EXPECT_FALSE(bloom->SetPreset(""));
  EXPECT_FALSE(bloom->SetPreset("WebGPU-Market")); // names are exact
  EXPECT_EQ(errors->Count, 4);
  EXPECT_EQ(bloom->GetThreshold(), threshold);
  EXPECT_EQ(bloom->GetThresholdMode(), mode);
  EXPECT_EQ(bloom->GetStrength(), strength);
  EXPECT_EQ(bloom->GetNumberOfLevels(), levels);
}

// vtkImagePyramidUp without input 1 (the geometry of its output) errors and produces nothing.
TEST(FiltersErrors, PyramidUpWithoutFineInput)
{
  vtkNew<vtkImagePyramidUp> up;
  vtkNew<EventLog> errors;
  up->AddObserver(vtkCommand::ErrorEvent, errors);
  up->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, errors);
  up->SetInputData(Image(6, 5, 3, VTK_FLOAT));
  up->Update();
  EXPECT_GE(errors->Count, 1);
  EXPECT_EQ(up->GetOutput()->GetNumberOfPoints(), 0);
}

// vtkImagePyramidUp with FineWeight != 0 and a finer level whose components differ errors.
TEST(FiltersErrors, PyramidUpFineMismatch)
{
  vtkNew<vtkImagePyramidUp> up;
  vtkNew<EventLog> errors;
  up->AddObserver(vtkCommand::ErrorEvent, errors);
  up->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, errors);
  up->SetFineWeight(1.0);
  up->SetInputData(Image(6, 5, 3, VTK_FLOAT));
  up->SetFineInputData(Image(12, 10, 4, VTK_FLOAT));
  up->Update();
  EXPECT_GE(errors->Count, 1);
  EXPECT_EQ(up->GetOutput()->GetNumberOfPoints(), 0);
}

// PrintSelf prints every parameter by name.
TEST(FiltersErrors, PrintSelfNamesParameters)
{
  vtkNew<vtkImageBloomThreshold> threshold;
  vtkNew<vtkImageSeparableGaussian> gaussian;
  vtkNew<vtkImagePyramidDown> down;
  vtkNew<vtkImagePyramidUp> up;
  vtkNew<vtkImageBloom> bloom;
  const std::pair<vtkObject*, std::vector<std::string>> expected[] = {
    { threshold, { "Mode", "Threshold", "Knee", "ClampLuminance" } },
    { gaussian, { "StandardDeviations", "Radius", "RadiusFactor", "KernelType", "BorderMode" } },
    { down, { "Kernel", "KarisAverage" } },
    { up, { "Kernel", "CoarseWeight", "FineWeight" } },
    { bloom,
      { "ThresholdMode", "Threshold", "Knee", "ClampLuminance", "StartLevel", "NumberOfLevels",
        "LimitLevelsToImageSize", "DownsampleKernel", "KarisAverage", "BlurKernel",
        "BlurStandardDeviation", "BlurRadius", "BlurGaussianKind", "BlurHalfKernel",
        "BlurTapSpacing", "BlurIterations", "UpsampleKernel", "AccumulateMode", "LevelWeights",
        "CompositeMode", "Strength", "Tint", "ConvolutionMode", "BloomMode", "PSFType",
        "AiryRadius", "Wavelengths", "PSFGaussianSigmas", "PSFGaussianWeights", "PSFRadius",
        "PSFTailScale", "PSFCoreRadius", "PSFBorderMode", "SkipEmptyBloom", "SkipDisabledEffects",
        "TrimPyramid", "RestrictToBrightRegion", "SanitizeNonFinite", "ExecutionMode", "UseAVX2",
        "ComputeStatistics", "LastRunWasFast", "LastBloomSkipped", "LastLevelsBuilt",
        "LastWorkspaceBytes", "LastRunUsedAVX2", "LastFFTBlurs" } },
  };
  for (const auto& e : expected)
  {
    const std::string text = Print(e.first);
    for (const std::string& name : e.second)
    {
      EXPECT_NE(text.find(name + ":"), std::string::npos)
        << e.first->GetClassName() << " does not print " << name;
    }
  }
  // The printed values follow the parameters.
  gaussian->SetBorderModeToReflect();
  EXPECT_NE(Print(gaussian).find("Reflect"), std::string::npos);
  bloom->SetPreset("mip-atlas");
  EXPECT_NE(Print(bloom).find("0.52"), std::string::npos);
  // Enums by name, not number.
  bloom->SetDownsampleKernel(vtkImagePyramidDown::BINOMIAL);
  bloom->SetConvolutionMode(vtkBloomParameters::CONVOLUTION_FFT);
  bloom->SetPSFType(vtkBloomParameters::PSF_GAUSSIANS);
  const std::string text = Print(bloom);
  for (const char* named : { "DownsampleKernel: Binomial", "ConvolutionMode: FFT",
         "PSFType: Gaussians", "PSFBorderMode: Reflect", "BlurGaussianKind: " })
  {
    EXPECT_NE(text.find(named), std::string::npos) << named << " in\n" << text;
  }
  EXPECT_EQ(text.find("BlurGaussianKind: 0"), std::string::npos) << text;
}

// Every filter reports progress through ProgressEvent, including intermediate values, and ends
// at 1.
TEST(FiltersErrors, ProgressEvents)
{
  for (const Named& f : Filters())
  {
    auto filter = f.Make();
    vtkNew<EventLog> progress;
    filter->AddObserver(vtkCommand::ProgressEvent, progress);
    filter->SetInputData(0, Image(64, 48, 4, VTK_DOUBLE));
    if (f.TwoInputs)
    {
      filter->SetInputData(1, Image(128, 96, 4, VTK_DOUBLE));
    }
    filter->Update();
    ASSERT_GE(progress->Count, 1) << f.Name;
    EXPECT_EQ(progress->Progress.back(), 1.0) << f.Name;
    bool intermediate = false;
    for (double p : progress->Progress)
    {
      EXPECT_GE(p, 0.0) << f.Name;
      EXPECT_LE(p, 1.0) << f.Name;
      intermediate = intermediate || (p > 0.0 && p < 1.0);
    }
    EXPECT_TRUE(intermediate) << f.Name << " reports no progress between 0 and 1";
  }
}
