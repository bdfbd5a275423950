// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkBloomParameters.h"

#include "vtkBloomKernels.h"
#include "vtkImageBloomThreshold.h"
#include "vtkImageData.h"
#include "vtkImagePyramidDown.h"
#include "vtkImagePyramidUp.h"
#include "vtkObjectFactory.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>

vtkStandardNewMacro(vtkBloomParameters);

//------------------------------------------------------------------------------
vtkBloomParameters::vtkBloomParameters()
{
  // Light, not white: only what is brighter than display white glows, by its excess.
  this->ThresholdMode = vtkImageBloomThreshold::EXCESS_KNEE;
  this->Threshold = 1.0;
  this->Knee = 0.5;
  this->ClampLuminance = VTK_FLOAT_MAX;
  this->StartLevel = 1;
  this->ReferenceHeight = 1080;
  this->NumberOfLevels = 5;
  this->LimitLevelsToImageSize = false;
  this->DownsampleKernel = vtkImagePyramidDown::JIMENEZ13;
  this->KarisAverage = false;
  this->BlurKernel = BLUR_GAUSSIAN;
  this->BlurStandardDeviation = 1.0;
  this->BlurRadius = -1;
  this->BlurGaussianKind = vtkBloomKernels::GAUSSIAN_SAMPLED;
  this->BlurHalfKernel = { 1.0 };
  this->BlurTapSpacing = 1.0;
  this->BlurIterations = 1;
  this->UpsampleKernel = vtkImagePyramidUp::TENT;
  this->AccumulateMode = CASCADE;
  this->CompositeMode = ADDITIVE;
  this->Strength = 1.0;
  this->Tint[0] = this->Tint[1] = this->Tint[2] = 1.0;
  this->ConvolutionMode = CONVOLUTION_AUTOMATIC;
  this->SkipEmptyBloom = true;
  this->SkipDisabledEffects = true;
  this->TrimPyramid = true;
  this->RestrictToBrightRegion = true;
  this->SanitizeNonFinite = true;
  this->BloomMode = BLOOM_PYRAMID;
  this->PSFType = PSF_AIRY;
  this->AiryRadius = 3.0;
  this->Wavelengths[0] = 610.0;
  this->Wavelengths[1] = 550.0;
  this->Wavelengths[2] = 465.0;
  this->PSFGaussianSigmas = { 1.5, 6.0, 24.0 };
  this->PSFGaussianWeights = { 0.6, 0.3, 0.1 };
  this->PSFRadius = -1;
  this->PSFTailScale = 1;
  this->PSFCoreRadius = -1;
  this->PSFBorderMode = 1;
}

//------------------------------------------------------------------------------
vtkBloomParameters::~vtkBloomParameters() = default;

//------------------------------------------------------------------------------
void vtkBloomParameters::SetBlurHalfKernel(int n, const double* weights)
{
  this->SetBlurHalfKernel(std::vector<double>(weights, weights + std::max(n, 0)));
}

//------------------------------------------------------------------------------
void vtkBloomParameters::SetBlurHalfKernel(const std::vector<double>& weights)
{
  if (weights != this->BlurHalfKernel)
  {
    this->BlurHalfKernel = weights;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
std::vector<double> vtkBloomParameters::GetEffectiveBlurHalfKernel() const
{
  if (this->BlurKernel == BLUR_CUSTOM)
  {
    return this->BlurHalfKernel.empty() ? std::vector<double>{ 1.0 } : this->BlurHalfKernel;
  }
  const int radius = this->BlurRadius >= 0
    ? this->BlurRadius
    : vtkBloomKernels::RadiusForSigma(this->BlurStandardDeviation, 3.0);
  return vtkBloomKernels::GaussianHalfKernel(
    this->BlurStandardDeviation, radius, this->BlurGaussianKind);
}

//------------------------------------------------------------------------------
int vtkBloomParameters::GetLevelShift(int height) const
{
  if (this->ReferenceHeight <= 0 || height <= 0)
  {
    return 0;
  }
  return static_cast<int>(
    std::lround(std::log2(static_cast<double>(height) / this->ReferenceHeight)));
}

//------------------------------------------------------------------------------
int vtkBloomParameters::GetEffectiveStartLevel(int height) const
{
  return std::min(std::max(this->StartLevel + this->GetLevelShift(height), 0), 16);
}

//------------------------------------------------------------------------------
int vtkBloomParameters::GetDroppedLevels(int height) const
{
  return this->GetEffectiveStartLevel(height) - (this->StartLevel + this->GetLevelShift(height));
}

//------------------------------------------------------------------------------
double vtkBloomParameters::GetBlurScale(int height) const
{
  if (this->ReferenceHeight <= 0 || height <= 0)
  {
    return 1.0;
  }
  // What the shift by whole levels leaves of height / ReferenceHeight: within [0.71, 1.42].
  return static_cast<double>(height) / this->ReferenceHeight *
    std::ldexp(1.0, -this->GetLevelShift(height));
}

//------------------------------------------------------------------------------
double vtkBloomParameters::GetEffectiveLevelWeight(int level, int height) const
{
  const int dropped = this->GetDroppedLevels(height);
  if (level > 0 || dropped == 0)
  {
    return this->GetLevelWeight(level + dropped);
  }
  // The first level stands for the finer levels the frame has no room for: their weights
  // fold into it, so that the weights keep their sum.
  double sum = 0.0;
  for (int j = 0; j <= std::min(dropped, this->NumberOfLevels - 1); ++j)
  {
    sum += this->GetLevelWeight(j);
  }
  return sum;
}

//------------------------------------------------------------------------------
std::vector<double> vtkBloomParameters::GetEffectiveBlurHalfKernel(int height) const
{
  const double scale = this->GetBlurScale(height);
  if (this->BlurKernel == BLUR_CUSTOM || scale == 1.0)
  {
    return this->GetEffectiveBlurHalfKernel(); // a custom kernel scales by its spacing
  }
  const double sigma = this->BlurStandardDeviation * scale;
  const int radius = this->BlurRadius >= 0 ? static_cast<int>(std::lround(this->BlurRadius * scale))
                                           : vtkBloomKernels::RadiusForSigma(sigma, 3.0);
  return vtkBloomKernels::GaussianHalfKernel(sigma, radius, this->BlurGaussianKind);
}

//------------------------------------------------------------------------------
double vtkBloomParameters::GetEffectiveBlurTapSpacing(int height) const
{
  return this->BlurKernel == BLUR_CUSTOM ? this->BlurTapSpacing * this->GetBlurScale(height)
                                         : this->BlurTapSpacing;
}

//------------------------------------------------------------------------------
void vtkBloomParameters::SetLevelWeight(int level, double weight)
{
  if (level < 0 || level >= 1024)
  {
    vtkErrorMacro(<< "Level index " << level << " out of range [0, 1024).");
    return;
  }
  if (static_cast<int>(this->LevelWeights.size()) <= level)
  {
    this->LevelWeights.resize(level + 1, 1.0);
  }
  if (this->LevelWeights[level] != weight)
  {
    this->LevelWeights[level] = weight;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
double vtkBloomParameters::GetLevelWeight(int level) const
{
  return level >= 0 && level < static_cast<int>(this->LevelWeights.size())
    ? this->LevelWeights[level]
    : 1.0;
}

//------------------------------------------------------------------------------
void vtkBloomParameters::SetLevelWeights(int n, const double* weights)
{
  this->SetLevelWeights(std::vector<double>(weights, weights + std::max(n, 0)));
}

//------------------------------------------------------------------------------
void vtkBloomParameters::SetLevelWeights(const std::vector<double>& weights)
{
  if (weights != this->LevelWeights)
  {
    this->LevelWeights = weights;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkBloomParameters::SetPSFGaussians(
  const std::vector<double>& sigmas, const std::vector<double>& weights)
{
  if (sigmas != this->PSFGaussianSigmas || weights != this->PSFGaussianWeights)
  {
    this->PSFGaussianSigmas = sigmas;
    this->PSFGaussianWeights = weights;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkBloomParameters::SetPSFImage(vtkImageData* image)
{
  if (this->PSFImage != image)
  {
    this->PSFImage = image;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkBloomParameters::SetPSFTailScale(int scale)
{
  if (scale != 1 && scale != 2 && scale != 4 && scale != 8)
  {
    vtkErrorMacro(<< "PSFTailScale must be 1 (no split), 2, 4 or 8; got " << scale << ".");
    return;
  }
  if (scale != this->PSFTailScale)
  {
    this->PSFTailScale = scale;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkBloomParameters::SetPSFCoreRadius(int radius)
{
  if (radius != -1 && (radius < 1 || radius > 2048))
  {
    vtkErrorMacro(<< "PSFCoreRadius must be -1 (automatic) or 1 to 2048; got " << radius << ".");
    return;
  }
  if (radius != this->PSFCoreRadius)
  {
    this->PSFCoreRadius = radius;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
int vtkBloomParameters::GetEffectivePSFCoreRadius() const
{
  return this->PSFCoreRadius > 0 ? this->PSFCoreRadius : 16;
}

//------------------------------------------------------------------------------
vtkImageData* vtkBloomParameters::GetPSFImage()
{
  return this->PSFImage;
}

//------------------------------------------------------------------------------
vtkMTimeType vtkBloomParameters::GetMTime()
{
  vtkMTimeType time = this->Superclass::GetMTime();
  if (this->PSFImage)
  {
    time = std::max(time, this->PSFImage->GetMTime());
  }
  return time;
}

//------------------------------------------------------------------------------
std::vector<std::pair<int, int>> vtkBloomParameters::ComputeLevelSizes(int width, int height) const
{
  std::vector<std::pair<int, int>> sizes;
  if (width <= 0 || height <= 0)
  {
    return sizes;
  }
  // The deepest level keeps its size relative to the frame too, so that a frame too small to
  // start as deep as the reference drops its finest levels rather than add coarser ones.
  const int start = this->GetEffectiveStartLevel(height);
  int deepest =
    std::max(start, this->StartLevel + this->GetLevelShift(height) + this->NumberOfLevels - 1);
  if (this->LimitLevelsToImageSize)
  {
    // A full mip chain has floor(log2(max(W, H))) + 1 levels, counting level 0.
    int maxLevel = 0;
    for (int n = std::max(width, height); n > 1; n /= 2)
    {
      ++maxLevel;
    }
    deepest = std::min(deepest, maxLevel);
  }
  int w = width, h = height;
  for (int k = 0; k <= deepest; ++k)
  {
    if (k >= start)
    {
      sizes.emplace_back(w, h);
    }
    w = vtkImagePyramidDown::HalvedSize(w);
    h = vtkImagePyramidDown::HalvedSize(h);
  }
  return sizes;
}

//------------------------------------------------------------------------------
bool vtkBloomParameters::IsBloomDisabled(int colours, size_t levels, int height) const
{
  double tint[3] = { this->Tint[0], this->Tint[1], this->Tint[2] };
  if (colours == 1)
  {
    tint[0] = vtkBloomKernels::LuminanceR * tint[0] + vtkBloomKernels::LuminanceG * tint[1] +
      vtkBloomKernels::LuminanceB * tint[2];
  }
  bool zeroTerm = true;
  for (int c = 0; c < colours; ++c)
  {
    zeroTerm &= this->Strength * tint[c] == 0.0;
  }
  bool zeroWeights = true;
  for (size_t i = 0; i < levels; ++i)
  {
    zeroWeights &= this->GetEffectiveLevelWeight(static_cast<int>(i), height) == 0.0;
  }
  return zeroTerm || (levels > 0 && zeroWeights);
}

//------------------------------------------------------------------------------
std::string vtkBloomParameters::Validate() const
{
  for (double v : { this->Threshold, this->Strength, this->Tint[0], this->Tint[1], this->Tint[2] })
  {
    if (!std::isfinite(v))
    {
      return "Threshold, Strength and Tint must be finite.";
    }
  }
  for (double w : this->GetEffectiveBlurHalfKernel())
  {
    if (!std::isfinite(w))
    {
      return "The blur kernel has a non-finite weight.";
    }
  }
  for (double w : this->LevelWeights)
  {
    if (!std::isfinite(w))
    {
      return "Level weights must be finite.";
    }
  }
  return std::string();
}

//------------------------------------------------------------------------------
void vtkBloomParameters::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  auto list = [&os](const std::vector<double>& values)
  {
    os << "(";
    for (size_t i = 0; i < values.size(); ++i)
    {
      os << (i ? ", " : "") << values[i];
    }
    os << ")\n";
  };
  // An enum's name, or its number where it has none.
  auto named = [](int value, std::initializer_list<const char*> names) -> std::string
  {
    return value >= 0 && value < static_cast<int>(names.size()) ? *(names.begin() + value)
                                                                : std::to_string(value);
  };
  auto onOff = [](bool value) { return value ? "On" : "Off"; };
  os << indent << "ThresholdMode: " << vtkImageBloomThreshold::GetModeName(this->ThresholdMode)
     << "\n";
  os << indent << "Threshold: " << this->Threshold << "\n";
  os << indent << "Knee: " << this->Knee << "\n";
  os << indent << "ClampLuminance: " << this->ClampLuminance << "\n";
  os << indent << "StartLevel: " << this->StartLevel << "\n";
  os << indent << "ReferenceHeight: " << this->ReferenceHeight << "\n";
  os << indent << "NumberOfLevels: " << this->NumberOfLevels << "\n";
  os << indent << "LimitLevelsToImageSize: " << onOff(this->LimitLevelsToImageSize) << "\n";
  os << indent
     << "DownsampleKernel: " << named(this->DownsampleKernel, { "Jimenez13", "Box", "Binomial" })
     << "\n";
  os << indent << "KarisAverage: " << onOff(this->KarisAverage) << "\n";
  os << indent << "BlurKernel: " << named(this->BlurKernel, { "Gaussian", "Custom" }) << "\n";
  os << indent << "BlurStandardDeviation: " << this->BlurStandardDeviation << "\n";
  os << indent << "BlurRadius: " << this->BlurRadius << "\n";
  os << indent << "BlurGaussianKind: "
     << named(this->BlurGaussianKind, { "Sampled", "Integrated", "Discrete" }) << "\n";
  os << indent << "BlurHalfKernel: ";
  list(this->BlurHalfKernel);
  os << indent << "BlurTapSpacing: " << this->BlurTapSpacing << "\n";
  os << indent << "BlurIterations: " << this->BlurIterations << "\n";
  os << indent << "UpsampleKernel: " << named(this->UpsampleKernel, { "Tent", "Bilinear" }) << "\n";
  os << indent << "AccumulateMode: " << named(this->AccumulateMode, { "Cascade", "Direct" })
     << "\n";
  os << indent << "LevelWeights: ";
  list(this->LevelWeights);
  os << indent << "CompositeMode: " << named(this->CompositeMode, { "Additive", "Lerp" }) << "\n";
  os << indent << "Strength: " << this->Strength << "\n";
  os << indent << "Tint: (" << this->Tint[0] << ", " << this->Tint[1] << ", " << this->Tint[2]
     << ")\n";
  os << indent
     << "ConvolutionMode: " << named(this->ConvolutionMode, { "Automatic", "Direct", "FFT" })
     << "\n";
  os << indent << "SkipEmptyBloom: " << onOff(this->SkipEmptyBloom) << "\n";
  os << indent << "SkipDisabledEffects: " << onOff(this->SkipDisabledEffects) << "\n";
  os << indent << "TrimPyramid: " << onOff(this->TrimPyramid) << "\n";
  os << indent << "RestrictToBrightRegion: " << onOff(this->RestrictToBrightRegion) << "\n";
  os << indent << "SanitizeNonFinite: " << onOff(this->SanitizeNonFinite) << "\n";
  os << indent << "BloomMode: " << named(this->BloomMode, { "Pyramid", "PSF" }) << "\n";
  os << indent << "PSFType: " << named(this->PSFType, { "Airy", "Gaussians", "Image" }) << "\n";
  os << indent << "AiryRadius: " << this->AiryRadius << "\n";
  os << indent << "Wavelengths: (" << this->Wavelengths[0] << ", " << this->Wavelengths[1] << ", "
     << this->Wavelengths[2] << ")\n";
  os << indent << "PSFGaussianSigmas: ";
  list(this->PSFGaussianSigmas);
  os << indent << "PSFGaussianWeights: ";
  list(this->PSFGaussianWeights);
  os << indent << "PSFImage: " << this->PSFImage.Get() << "\n";
  os << indent << "PSFRadius: " << this->PSFRadius << "\n";
  os << indent << "PSFTailScale: " << this->PSFTailScale << "\n";
  os << indent << "PSFCoreRadius: " << this->PSFCoreRadius << "\n";
  os << indent << "PSFBorderMode: " << named(this->PSFBorderMode, { "Clamp", "Reflect", "Zero" })
     << "\n";
}
