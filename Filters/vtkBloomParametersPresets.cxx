// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// vtkBloomParameters' presets and copy: the four seed bloom systems as
// ../shared/seeds/PRESETS.md pins them, with their known defects fixed (docs/presets.md lists
// each deviation). A table of parameter values, apart from the accessors in vtkBloomParameters.cxx.
#include "vtkBloomParameters.h"

#include "vtkBloomKernels.h"
#include "vtkImageBloomThreshold.h"
#include "vtkImageData.h"
#include "vtkImagePyramidDown.h"
#include "vtkImagePyramidUp.h"

#include <algorithm>
#include <string>
#include <vector>

//------------------------------------------------------------------------------
std::vector<std::string> vtkBloomParameters::GetPresetNames()
{
  return { "webgpu-market", "mip-atlas", "ping-pong", "crt-halfres" };
}

//------------------------------------------------------------------------------
std::string vtkBloomParameters::GetPresetNamesList()
{
  std::string list;
  for (const std::string& name : vtkBloomParameters::GetPresetNames())
  {
    list += (list.empty() ? "" : ", ") + name;
  }
  return list;
}

//------------------------------------------------------------------------------
std::string vtkBloomParameters::GetDefaultPresetName()
{
  return vtkBloomParameters::GetPresetNames().front();
}

//------------------------------------------------------------------------------
std::string vtkBloomParameters::CheckPresetName(const char* name)
{
  const std::string preset = name ? name : "";
  const auto names = vtkBloomParameters::GetPresetNames();
  if (std::find(names.begin(), names.end(), preset) != names.end())
  {
    return std::string();
  }
  return "Unknown bloom preset '" + preset + "'; expected " +
    vtkBloomParameters::GetPresetNamesList() + ".";
}

//------------------------------------------------------------------------------
bool vtkBloomParameters::SetPreset(const char* name)
{
  const std::string error = vtkBloomParameters::CheckPresetName(name);
  if (!error.empty())
  {
    vtkErrorMacro(<< error);
    return false;
  }
  const std::string preset = name;
  // Shared defaults; each preset then states what it changes. A seed's sizes are pixels.
  this->BloomMode = BLOOM_PYRAMID;
  this->ReferenceHeight = 0;
  this->ClampLuminance = VTK_FLOAT_MAX;
  this->Knee = 0.5;
  this->LimitLevelsToImageSize = false;
  this->DownsampleKernel = vtkImagePyramidDown::JIMENEZ13;
  this->KarisAverage = false;
  this->BlurTapSpacing = 1.0;
  this->BlurIterations = 1;
  this->UpsampleKernel = vtkImagePyramidUp::TENT;
  this->AccumulateMode = CASCADE;
  this->LevelWeights.clear();
  this->CompositeMode = ADDITIVE;
  this->Tint[0] = this->Tint[1] = this->Tint[2] = 1.0;

  if (preset == "webgpu-market")
  {
    // Seed 000: threshold into half-res mip 0, 13-tap down x4, 9-tap blur with taps
    // radius = 0.5 texels apart, tent up-and-add, original + bloom * strength.
    this->ThresholdMode = vtkImageBloomThreshold::SMOOTHSTEP_KNEE;
    this->Threshold = 0.8;
    this->StartLevel = 1;
    this->NumberOfLevels = 5;
    this->BlurKernel = BLUR_CUSTOM;
    this->BlurHalfKernel = vtkBloomKernels::WebGPUMarketBlurHalfKernel();
    this->BlurTapSpacing = 0.5;
    this->Strength = 1.0;
  }
  else if (preset == "mip-atlas")
  {
    // Seed 001: the HDR scene's mip chain, LODs 2..8 blurred by a 7x7 binomial, averaged with
    // weights 1 1 1 .8 .8 .6 .4 times 0.14, lerp(colour, bloom, 0.52).
    this->ThresholdMode = vtkImageBloomThreshold::NONE;
    this->Threshold = 0.0;
    this->StartLevel = 0;
    this->NumberOfLevels = 9;
    this->LimitLevelsToImageSize = true;
    this->DownsampleKernel = vtkImagePyramidDown::BOX;
    this->BlurKernel = BLUR_CUSTOM;
    this->BlurHalfKernel = vtkBloomKernels::Binomial7HalfKernel();
    this->AccumulateMode = DIRECT;
    const double lod[7] = { 1.0, 1.0, 1.0, 0.8, 0.8, 0.6, 0.4 };
    this->LevelWeights = { 0.0, 0.0 };
    for (double w : lod)
    {
      this->LevelWeights.push_back(0.14 * w);
    }
    this->CompositeMode = LERP;
    this->Strength = 0.52;
  }
  else if (preset == "ping-pong")
  {
    // Seed 002: hard luminance mask at full resolution, 32 x (horizontal + vertical) 13-tap
    // blur passes, original + blur.
    this->ThresholdMode = vtkImageBloomThreshold::HARD_LUMINANCE;
    this->Threshold = 1.0;
    this->StartLevel = 0;
    this->NumberOfLevels = 1;
    this->BlurKernel = BLUR_CUSTOM;
    this->BlurHalfKernel = vtkBloomKernels::PingPongBlurHalfKernel();
    this->BlurIterations = 32;
    this->Strength = 1.0;
  }
  else // crt-halfres
  {
    // Seed 003: per-channel max(src - 0.8, 0) at half resolution, 9-tap Gaussian sigma 1.8,
    // scene + 1.5 * bloom.
    this->ThresholdMode = vtkImageBloomThreshold::PER_CHANNEL;
    this->Threshold = 0.8;
    this->StartLevel = 1;
    this->NumberOfLevels = 1;
    this->BlurKernel = BLUR_GAUSSIAN;
    this->BlurStandardDeviation = 1.8;
    this->BlurRadius = 4;
    this->BlurGaussianKind = vtkBloomKernels::GAUSSIAN_SAMPLED;
    this->Strength = 1.5;
  }
  this->Modified();
  return true;
}

//------------------------------------------------------------------------------
namespace
{
template <typename T>
void CopyIfDifferent(T& to, const T& from, bool& changed)
{
  if (!(to == from))
  {
    to = from;
    changed = true;
  }
}

void CopyIfDifferent(double (&to)[3], const double (&from)[3], bool& changed)
{
  for (int i = 0; i < 3; ++i)
  {
    CopyIfDifferent(to[i], from[i], changed);
  }
}
}

//------------------------------------------------------------------------------
void vtkBloomParameters::DeepCopy(vtkBloomParameters* source)
{
  if (!source || source == this)
  {
    return;
  }
  bool changed = false;
  CopyIfDifferent(this->ThresholdMode, source->ThresholdMode, changed);
  CopyIfDifferent(this->Threshold, source->Threshold, changed);
  CopyIfDifferent(this->Knee, source->Knee, changed);
  CopyIfDifferent(this->ClampLuminance, source->ClampLuminance, changed);
  CopyIfDifferent(this->StartLevel, source->StartLevel, changed);
  CopyIfDifferent(this->ReferenceHeight, source->ReferenceHeight, changed);
  CopyIfDifferent(this->NumberOfLevels, source->NumberOfLevels, changed);
  CopyIfDifferent(this->LimitLevelsToImageSize, source->LimitLevelsToImageSize, changed);
  CopyIfDifferent(this->DownsampleKernel, source->DownsampleKernel, changed);
  CopyIfDifferent(this->KarisAverage, source->KarisAverage, changed);
  CopyIfDifferent(this->BlurKernel, source->BlurKernel, changed);
  CopyIfDifferent(this->BlurStandardDeviation, source->BlurStandardDeviation, changed);
  CopyIfDifferent(this->BlurRadius, source->BlurRadius, changed);
  CopyIfDifferent(this->BlurGaussianKind, source->BlurGaussianKind, changed);
  CopyIfDifferent(this->BlurHalfKernel, source->BlurHalfKernel, changed);
  CopyIfDifferent(this->BlurTapSpacing, source->BlurTapSpacing, changed);
  CopyIfDifferent(this->BlurIterations, source->BlurIterations, changed);
  CopyIfDifferent(this->UpsampleKernel, source->UpsampleKernel, changed);
  CopyIfDifferent(this->AccumulateMode, source->AccumulateMode, changed);
  CopyIfDifferent(this->LevelWeights, source->LevelWeights, changed);
  CopyIfDifferent(this->CompositeMode, source->CompositeMode, changed);
  CopyIfDifferent(this->Strength, source->Strength, changed);
  CopyIfDifferent(this->Tint, source->Tint, changed);
  CopyIfDifferent(this->SkipEmptyBloom, source->SkipEmptyBloom, changed);
  CopyIfDifferent(this->SkipDisabledEffects, source->SkipDisabledEffects, changed);
  CopyIfDifferent(this->TrimPyramid, source->TrimPyramid, changed);
  CopyIfDifferent(this->RestrictToBrightRegion, source->RestrictToBrightRegion, changed);
  CopyIfDifferent(this->SanitizeNonFinite, source->SanitizeNonFinite, changed);
  CopyIfDifferent(this->ConvolutionMode, source->ConvolutionMode, changed);
  CopyIfDifferent(this->BloomMode, source->BloomMode, changed);
  CopyIfDifferent(this->PSFType, source->PSFType, changed);
  CopyIfDifferent(this->AiryRadius, source->AiryRadius, changed);
  CopyIfDifferent(this->Wavelengths, source->Wavelengths, changed);
  CopyIfDifferent(this->PSFGaussianSigmas, source->PSFGaussianSigmas, changed);
  CopyIfDifferent(this->PSFGaussianWeights, source->PSFGaussianWeights, changed);
  CopyIfDifferent(this->PSFImage, source->PSFImage, changed);
  CopyIfDifferent(this->PSFRadius, source->PSFRadius, changed);
  CopyIfDifferent(this->PSFBorderMode, source->PSFBorderMode, changed);
  CopyIfDifferent(this->PSFTailScale, source->PSFTailScale, changed);
  CopyIfDifferent(this->PSFCoreRadius, source->PSFCoreRadius, changed);
  if (changed)
  {
    this->Modified();
  }
}
