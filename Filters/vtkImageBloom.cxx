#include "vtkImageBloom.h"

#include "vtkBloomPieces.h"

#include "vtkBloomChain.h"
#include "vtkBloomFastChain.h"
#include "vtkBloomImageOps.h"
#include "vtkBloomKernels.h"
#include "vtkBloomPSF.h"
#include "vtkBloomStatistics.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkImageBloomThreshold.h"
#include "vtkImageData.h"
#include "vtkImagePyramidDown.h"
#include "vtkImagePyramidUp.h"
#include "vtkImageSeparableAlgorithm.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <initializer_list>
#include <limits>
#include <string>

vtkStandardNewMacro(vtkImageBloom);

//------------------------------------------------------------------------------
vtkImageBloom::vtkImageBloom()
{
  this->ThresholdMode = vtkImageBloomThreshold::SMOOTHSTEP_KNEE;
  this->Threshold = 1.0;
  this->Knee = 0.5;
  this->ClampLuminance = VTK_FLOAT_MAX;
  this->StartLevel = 1;
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
  this->ComputeStatistics = true;
  this->SanitizeNonFinite = true;
  this->ExecutionMode = FAST;
  this->SkipEmptyBloom = true;
  this->SkipDisabledEffects = true;
  this->TrimPyramid = true;
  this->RestrictToBrightRegion = true;
  this->UseAVX2 = true;
  this->ConvolutionMode = CONVOLUTION_AUTOMATIC;
  this->BloomMode = BLOOM_PYRAMID;
  this->PSFType = PSF_AIRY;
  this->AiryRadius = 3.0;
  this->Wavelengths[0] = 610.0;
  this->Wavelengths[1] = 550.0;
  this->Wavelengths[2] = 465.0;
  this->PSFGaussianSigmas = { 1.5, 6.0, 24.0 };
  this->PSFGaussianWeights = { 0.6, 0.3, 0.1 };
  this->PSFRadius = -1;
  this->PSFBorderMode = 1;
  this->LastRunWasFast = false;
  this->LastBloomSkipped = false;
  this->LastPassedThrough = false;
  this->LastLevelsBuilt = 0;
  this->LastWorkspaceBytes = 0;
  this->LastRunUsedAVX2 = false;
  this->LastFFTBlurs = 0;
  this->FastChain = new vtkBloomFastChain;
  this->PSFKernels = new vtkBloomPSFKernels;
  this->Chain = new vtkBloomChain;
  this->ChainSize[0] = this->ChainSize[1] = -1;
  this->ResetStatistics();
}

//------------------------------------------------------------------------------
vtkImageBloom::~vtkImageBloom()
{
  delete this->FastChain;
  delete this->PSFKernels;
  delete this->Chain;
}

//------------------------------------------------------------------------------
bool vtkImageBloom::IsAVX2Available()
{
  return vtkBloomFastChain::AVX2Available();
}

//------------------------------------------------------------------------------
void vtkImageBloom::ReleaseWorkspace()
{
  this->FastChain->ReleaseWorkspace();
  delete this->PSFKernels;
  this->PSFKernels = new vtkBloomPSFKernels;
  this->LastWorkspaceBytes = 0;
}

//------------------------------------------------------------------------------
bool vtkImageBloom::BloomIsDisabled(int colours, size_t levels) const
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
    zeroWeights &= this->GetLevelWeight(static_cast<int>(i)) == 0.0;
  }
  return zeroTerm || (levels > 0 && zeroWeights);
}

//------------------------------------------------------------------------------
void vtkImageBloom::SetBlurHalfKernel(int n, const double* weights)
{
  this->SetBlurHalfKernel(std::vector<double>(weights, weights + std::max(n, 0)));
}

//------------------------------------------------------------------------------
void vtkImageBloom::SetBlurHalfKernel(const std::vector<double>& weights)
{
  if (weights != this->BlurHalfKernel)
  {
    this->BlurHalfKernel = weights;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
std::vector<double> vtkImageBloom::GetEffectiveBlurHalfKernel() const
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
void vtkImageBloom::SetLevelWeight(int level, double weight)
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
double vtkImageBloom::GetLevelWeight(int level) const
{
  return level >= 0 && level < static_cast<int>(this->LevelWeights.size())
    ? this->LevelWeights[level]
    : 1.0;
}

//------------------------------------------------------------------------------
void vtkImageBloom::SetLevelWeights(int n, const double* weights)
{
  this->SetLevelWeights(std::vector<double>(weights, weights + std::max(n, 0)));
}

//------------------------------------------------------------------------------
void vtkImageBloom::SetLevelWeights(const std::vector<double>& weights)
{
  if (weights != this->LevelWeights)
  {
    this->LevelWeights = weights;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
std::vector<std::pair<int, int>> vtkImageBloom::ComputeLevelSizes(int width, int height) const
{
  std::vector<std::pair<int, int>> sizes;
  if (width <= 0 || height <= 0)
  {
    return sizes;
  }
  int deepest = this->StartLevel + this->NumberOfLevels - 1;
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
    if (k >= this->StartLevel)
    {
      sizes.emplace_back(w, h);
    }
    w = vtkImagePyramidDown::HalvedSize(w);
    h = vtkImagePyramidDown::HalvedSize(h);
  }
  return sizes;
}

//------------------------------------------------------------------------------
bool vtkImageBloom::CheckParameters()
{
  const double values[4] = { this->Threshold, this->Strength, this->Tint[0] + this->Tint[1],
    this->Tint[2] };
  for (double v : values)
  {
    if (!std::isfinite(v))
    {
      vtkErrorMacro(<< "Threshold, Strength and Tint must be finite.");
      return false;
    }
  }
  for (double w : this->GetEffectiveBlurHalfKernel())
  {
    if (!std::isfinite(w))
    {
      vtkErrorMacro(<< "The blur kernel has a non-finite weight.");
      return false;
    }
  }
  for (double w : this->LevelWeights)
  {
    if (!std::isfinite(w))
    {
      vtkErrorMacro(<< "Level weights must be finite.");
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
int vtkImageBloom::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  // Under MPI each rank computes its own piece of the output...
  int piece[6]; // unused: the call marks the output as producing sub-extents
  vtkBloomExecutionExtent(outputVector->GetInformationObject(0), piece);
  // ... but the pyramid reaches across the whole image, so every piece needs all of the input.
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  int whole[6];
  inInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), whole);
  // As one piece: under MPI each rank's producer would otherwise give only its own piece.
  vtkBloomRequestExactExtent(inInfo, whole);
  return 1;
}

//------------------------------------------------------------------------------
int vtkImageBloom::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkImageData* input = vtkImageData::GetData(inputVector[0]);
  vtkImageData* output = vtkImageData::GetData(outInfo);
  this->ResetStatistics();
  this->LastRunWasFast = false;
  this->LastBloomSkipped = false;
  this->LastPassedThrough = false;
  this->LastLevelsBuilt = -1;
  this->LastRunUsedAVX2 = false;
  this->LastFFTBlurs = 0;
  if (!this->CheckInput(input))
  {
    output->Initialize();
    return 0;
  }
  vtkBloomMatchOutputScalars(outInfo, input);
  if (this->BloomMode == BLOOM_PSF)
  {
    return this->ExecutePSF(input, outInfo, output);
  }
  int inExt[6];
  input->GetExtent(inExt);
  const int width = inExt[1] - inExt[0] + 1;
  const int height = inExt[3] - inExt[2] + 1;
  this->UpdateChain(width, height);
  int levelsUsed = 0;
  if (this->ExecutionMode == FAST && this->ExecuteFast(input, outInfo, output, levelsUsed))
  {
    this->ComputeOutputStatistics(input, output, levelsUsed);
    this->UpdateProgress(1.0);
    return 1;
  }

  // REFERENCE, in double precision: the chain's steps one after the other.
  this->AllocateOutputData(output, outInfo);
  std::vector<vtkBloomBuffer> levels;
  const bool bright = this->ThresholdStep(input, levels, levelsUsed); // 1. bright pass
  if (bright)
  {
    this->DownsampleStep(levels); // 2. pyramid down
    this->BlurStep(levels);       // 3. blur the levels
  }
  if (this->AbortExecute)
  {
    return 1;
  }
  vtkBloomBuffer bloom;
  if (bright)
  {
    this->UpsampleStep(levels, width, height, bloom); // 4. up and accumulate
  }
  this->Composite(input, bright ? &bloom : nullptr, output); // 5. composite
  this->ComputeOutputStatistics(input, output, levelsUsed);  // 6. statistics
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
bool vtkImageBloom::CheckInput(vtkImageData* input)
{
  if (!input || !input->GetPointData()->GetScalars())
  {
    vtkErrorMacro(<< "Input has no point scalars.");
    return false;
  }
  const int nc = input->GetNumberOfScalarComponents();
  if (!vtkImageSeparableAlgorithm::IsSupportedInput(input->GetScalarType(), nc))
  {
    vtkErrorMacro(<< "Input scalars must be float or double with 1 to 4 components; got "
                  << input->GetScalarTypeAsString() << " with " << nc << " components.");
    return false;
  }
  if (!this->CheckParameters())
  {
    return false;
  }
  int inExt[6];
  input->GetExtent(inExt);
  if (inExt[1] < inExt[0] || inExt[3] < inExt[2] || inExt[5] < inExt[4])
  {
    vtkErrorMacro(<< "Input is empty.");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkImageBloom::UpdateChain(int width, int height)
{
  // The operators of every step, shared by both paths here and by vtkBloomPass; built again
  // only when a parameter (this filter's MTime) or the size changed.
  if (this->GetMTime() > this->ChainTime || width != this->ChainSize[0] ||
    height != this->ChainSize[1])
  {
    this->Chain->Build(this, width, height);
    this->ChainTime.Modified();
    this->ChainSize[0] = width;
    this->ChainSize[1] = height;
  }
}

//------------------------------------------------------------------------------
bool vtkImageBloom::ExecuteFast(
  vtkImageData* input, vtkInformation* outInfo, vtkImageData* output, int& levelsUsed)
{
  int inExt[6];
  input->GetExtent(inExt);
  const int width = inExt[1] - inExt[0] + 1;
  const int height = inExt[3] - inExt[2] + 1;
  vtkBloomFastChainParameters p;
  p.ThresholdMode = this->ThresholdMode;
  p.Threshold = this->Threshold;
  p.Knee = this->Knee;
  p.ClampLuminance = this->ClampLuminance;
  p.Chain = this->Chain;
  p.LevelSizes = this->ComputeLevelSizes(width, height);
  for (size_t i = 0; i < p.LevelSizes.size(); ++i)
  {
    p.LevelWeights.push_back(this->GetLevelWeight(static_cast<int>(i)));
  }
  p.DownsampleKernel = this->DownsampleKernel;
  p.KarisAverage = this->KarisAverage;
  p.BlurIterations = this->BlurIterations;
  p.AccumulateMode = this->AccumulateMode;
  p.CompositeMode = this->CompositeMode;
  p.Strength = this->Strength;
  std::copy(this->Tint, this->Tint + 3, p.Tint);
  p.SanitizeNonFinite = this->SanitizeNonFinite;
  p.SkipEmpty = this->SkipEmptyBloom;
  p.TrimPyramid = this->TrimPyramid;
  p.RestrictToBrightRegion = this->RestrictToBrightRegion;
  p.SkipDisabled = this->SkipDisabledEffects;
  p.UseAVX2 = this->UseAVX2;
  p.ConvolutionMode = this->ConvolutionMode;
  p.ChainTime = this->ChainTime.GetMTime();
  if (!vtkBloomFastChain::Supports(p, input))
  {
    return false;
  }
  levelsUsed = static_cast<int>(p.LevelSizes.size());
  int outExt[6];
  std::copy(inExt, inExt + 6, outExt);
  if (outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT()))
  {
    outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), outExt);
  }
  vtkBloomFastChainReport report;
  this->FastChain->Execute(p, input, outExt, output, report, this);
  this->LastRunWasFast = true;
  this->LastBloomSkipped = report.ChainSkipped;
  this->LastPassedThrough = report.PassedThrough;
  this->LastLevelsBuilt = report.LevelsBuilt;
  this->LastWorkspaceBytes = static_cast<vtkIdType>(report.WorkspaceBytes);
  this->LastRunUsedAVX2 = report.UsedAVX2;
  this->LastFFTBlurs = report.FFTBlurs;
  return true;
}

//------------------------------------------------------------------------------
void vtkImageBloom::ResetStatistics()
{
  this->EnergyIn = 0.0;
  this->EnergyOut = 0.0;
  this->NumberOfBrightPixels = 0;
  this->PeakLuminanceIn = 0.0;
  this->PeakLuminanceOut = 0.0;
  this->NumberOfLevelsUsed = 0;
}

//------------------------------------------------------------------------------
void vtkImageBloom::ComputeOutputStatistics(
  vtkImageData* input, vtkImageData* output, int levelsUsed)
{
  // The executive initializes the output (field data included) before every execution, so
  // with statistics off there is nothing stale to remove.
  if (!this->ComputeStatistics)
  {
    return;
  }
  // Over the output extent: the input there is what the output piece was composited from.
  int ext[6];
  output->GetExtent(ext);
  const vtkBloomLuminanceStatistics in = vtkBloomMeasureLuminance(input, ext);
  const vtkBloomLuminanceStatistics out = vtkBloomMeasureLuminance(output, ext);
  this->EnergyIn = in.Energy;
  this->EnergyOut = out.Energy;
  this->PeakLuminanceIn = in.Peak;
  this->PeakLuminanceOut = out.Peak;
  this->NumberOfBrightPixels = vtkBloomCountBrightPixels(
    input, ext, this->ThresholdMode, this->Threshold, this->Knee, this->ClampLuminance);
  this->NumberOfLevelsUsed = levelsUsed;

  vtkFieldData* fd = output->GetFieldData();
  auto attach = [fd](vtkDataArray* array, const char* name, double value)
  {
    array->SetName(name);
    array->SetNumberOfTuples(1);
    array->SetTuple1(0, value);
    fd->AddArray(array);
  };
  attach(vtkNew<vtkDoubleArray>(), GetEnergyInArrayName(), this->EnergyIn);
  attach(vtkNew<vtkDoubleArray>(), GetEnergyOutArrayName(), this->EnergyOut);
  attach(vtkNew<vtkIdTypeArray>(), GetNumberOfBrightPixelsArrayName(),
    static_cast<double>(this->NumberOfBrightPixels));
  attach(vtkNew<vtkDoubleArray>(), GetPeakLuminanceInArrayName(), this->PeakLuminanceIn);
  attach(vtkNew<vtkDoubleArray>(), GetPeakLuminanceOutArrayName(), this->PeakLuminanceOut);
  attach(vtkNew<vtkIntArray>(), GetNumberOfLevelsUsedArrayName(), levelsUsed);
}

//------------------------------------------------------------------------------
void vtkImageBloom::PrintSelf(ostream& os, vtkIndent indent)
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
  os << indent << "ThresholdMode: " << vtkImageBloomThreshold::GetModeName(this->ThresholdMode)
     << "\n";
  os << indent << "Threshold: " << this->Threshold << "\n";
  os << indent << "Knee: " << this->Knee << "\n";
  os << indent << "ClampLuminance: " << this->ClampLuminance << "\n";
  os << indent << "StartLevel: " << this->StartLevel << "\n";
  os << indent << "NumberOfLevels: " << this->NumberOfLevels << "\n";
  os << indent << "LimitLevelsToImageSize: " << (this->LimitLevelsToImageSize ? "On" : "Off")
     << "\n";
  os << indent
     << "DownsampleKernel: " << named(this->DownsampleKernel, { "Jimenez13", "Box", "Binomial" })
     << "\n";
  os << indent << "KarisAverage: " << (this->KarisAverage ? "On" : "Off") << "\n";
  os << indent << "BlurKernel: " << (this->BlurKernel == BLUR_CUSTOM ? "Custom" : "Gaussian")
     << "\n";
  os << indent << "BlurStandardDeviation: " << this->BlurStandardDeviation << "\n";
  os << indent << "BlurRadius: " << this->BlurRadius << "\n";
  os << indent << "BlurGaussianKind: "
     << named(this->BlurGaussianKind, { "Sampled", "Integrated", "Discrete" }) << "\n";
  os << indent << "BlurHalfKernel: ";
  list(this->BlurHalfKernel);
  os << indent << "BlurTapSpacing: " << this->BlurTapSpacing << "\n";
  os << indent << "BlurIterations: " << this->BlurIterations << "\n";
  os << indent << "UpsampleKernel: " << (this->UpsampleKernel ? "Bilinear" : "Tent") << "\n";
  os << indent << "AccumulateMode: " << (this->AccumulateMode == DIRECT ? "Direct" : "Cascade")
     << "\n";
  os << indent << "LevelWeights: ";
  list(this->LevelWeights);
  os << indent << "CompositeMode: " << (this->CompositeMode == LERP ? "Lerp" : "Additive") << "\n";
  os << indent << "Strength: " << this->Strength << "\n";
  os << indent << "Tint: (" << this->Tint[0] << ", " << this->Tint[1] << ", " << this->Tint[2]
     << ")\n";
  os << indent << "ComputeStatistics: " << (this->ComputeStatistics ? "On" : "Off") << "\n";
  os << indent << "SanitizeNonFinite: " << (this->SanitizeNonFinite ? "On" : "Off") << "\n";
  os << indent << "ExecutionMode: " << (this->ExecutionMode == FAST ? "Fast" : "Reference") << "\n";
  os << indent << "SkipEmptyBloom: " << (this->SkipEmptyBloom ? "On" : "Off") << "\n";
  os << indent << "SkipDisabledEffects: " << (this->SkipDisabledEffects ? "On" : "Off") << "\n";
  os << indent << "TrimPyramid: " << (this->TrimPyramid ? "On" : "Off") << "\n";
  os << indent << "RestrictToBrightRegion: " << (this->RestrictToBrightRegion ? "On" : "Off")
     << "\n";
  os << indent << "UseAVX2: " << (this->UseAVX2 ? "On" : "Off") << "\n";
  os << indent
     << "ConvolutionMode: " << named(this->ConvolutionMode, { "Automatic", "Direct", "FFT" })
     << "\n";
  os << indent << "BloomMode: " << (this->BloomMode == BLOOM_PSF ? "PSF" : "Pyramid") << "\n";
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
  os << indent << "PSFBorderMode: " << named(this->PSFBorderMode, { "Clamp", "Reflect", "Zero" })
     << "\n";
  os << indent << "EnergyIn: " << this->EnergyIn << "\n";
  os << indent << "EnergyOut: " << this->EnergyOut << "\n";
  os << indent << "NumberOfBrightPixels: " << this->NumberOfBrightPixels << "\n";
  os << indent << "PeakLuminanceIn: " << this->PeakLuminanceIn << "\n";
  os << indent << "PeakLuminanceOut: " << this->PeakLuminanceOut << "\n";
  os << indent << "NumberOfLevelsUsed: " << this->NumberOfLevelsUsed << "\n";
  os << indent << "LastRunWasFast: " << (this->LastRunWasFast ? "On" : "Off") << "\n";
  os << indent << "LastBloomSkipped: " << (this->LastBloomSkipped ? "On" : "Off") << "\n";
  os << indent << "LastPassedThrough: " << (this->LastPassedThrough ? "On" : "Off") << "\n";
  os << indent << "LastLevelsBuilt: " << this->LastLevelsBuilt << "\n";
  os << indent << "LastWorkspaceBytes: " << this->LastWorkspaceBytes << "\n";
  os << indent << "LastFFTBlurs: " << this->LastFFTBlurs << "\n";
  os << indent << "ChainSize: (" << this->ChainSize[0] << ", " << this->ChainSize[1] << ")\n";
}
