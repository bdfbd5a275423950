// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
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
  this->Parameters = vtkSmartPointer<vtkBloomParameters>::New();
  this->ComputeStatistics = true;
  this->ExecutionMode = FAST;
  this->UseAVX2 = true;
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
void vtkImageBloom::SetParameters(vtkBloomParameters* parameters)
{
  if (parameters && parameters != this->Parameters)
  {
    this->Parameters = parameters;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
bool vtkImageBloom::SetPreset(const char* name)
{
  const std::string error = vtkBloomParameters::CheckPresetName(name);
  if (!error.empty())
  {
    vtkErrorMacro(<< error);
    return false;
  }
  return this->Parameters->SetPreset(name);
}

//------------------------------------------------------------------------------
void vtkImageBloom::CopyParameters(vtkImageBloom* source)
{
  if (!source || source == this)
  {
    return;
  }
  this->Parameters->DeepCopy(source->Parameters);
  this->SetExecutionMode(source->ExecutionMode);
  this->SetUseAVX2(source->UseAVX2);
  this->SetComputeStatistics(source->ComputeStatistics);
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
  if (this->Parameters->GetBloomMode() == BLOOM_PSF)
  {
    return this->ExecutePSF(input, outInfo, output);
  }
  int inExt[6];
  input->GetExtent(inExt);
  const int width = inExt[1] - inExt[0] + 1;
  const int height = inExt[3] - inExt[2] + 1;
  this->UpdateChain(width, height);
  int levelsUsed = 0;
  bool measured = false;
  if (this->ExecutionMode == FAST &&
    this->ExecuteFast(input, outInfo, output, levelsUsed, measured))
  {
    this->ComputeOutputStatistics(input, output, levelsUsed, measured);
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
  this->Composite(input, bright ? &bloom : nullptr, output);       // 5. composite
  this->ComputeOutputStatistics(input, output, levelsUsed, false); // 6. statistics
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
  const std::string invalid = this->Parameters->Validate();
  if (!invalid.empty())
  {
    vtkErrorMacro(<< invalid);
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
  // only when a parameter (this filter's MTime includes its parameters') or the size changed.
  if (this->GetMTime() > this->ChainTime || width != this->ChainSize[0] ||
    height != this->ChainSize[1])
  {
    this->Chain->Build(this->Parameters, width, height);
    this->ChainTime.Modified();
    this->ChainSize[0] = width;
    this->ChainSize[1] = height;
  }
}

//------------------------------------------------------------------------------
bool vtkImageBloom::ExecuteFast(vtkImageData* input, vtkInformation* outInfo, vtkImageData* output,
  int& levelsUsed, bool& measured)
{
  int inExt[6];
  input->GetExtent(inExt);
  const int width = inExt[1] - inExt[0] + 1;
  const int height = inExt[3] - inExt[2] + 1;
  vtkBloomFastChainParameters p;
  p.Set(this->Parameters, this->Chain, width, height);
  p.UseAVX2 = this->UseAVX2;
  p.ChainTime = this->ChainTime.GetMTime();
  p.MeasureStatistics = this->ComputeStatistics;
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
  measured = report.StatisticsMeasured;
  if (measured)
  {
    this->EnergyIn = report.StatisticsIn.Energy;
    this->EnergyOut = report.StatisticsOut.Energy;
    this->PeakLuminanceIn = report.StatisticsIn.Peak;
    this->PeakLuminanceOut = report.StatisticsOut.Peak;
    this->NumberOfBrightPixels = report.BrightPixels;
  }
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
  vtkImageData* input, vtkImageData* output, int levelsUsed, bool measured)
{
  // The executive initializes the output (field data included) before every execution, so
  // with statistics off there is nothing stale to remove.
  if (!this->ComputeStatistics)
  {
    return;
  }
  if (!measured)
  {
    // Over the output extent: the input there is what the output piece was composited from.
    // An output that shares the input's scalars (the pass-through) is measured once.
    int ext[6];
    output->GetExtent(ext);
    const vtkBloomLuminanceStatistics in = vtkBloomMeasureLuminance(input, ext);
    const bool shared =
      output->GetPointData()->GetScalars() == input->GetPointData()->GetScalars() &&
      std::equal(ext, ext + 6, input->GetExtent());
    const vtkBloomLuminanceStatistics out = shared ? in : vtkBloomMeasureLuminance(output, ext);
    this->EnergyIn = in.Energy;
    this->EnergyOut = out.Energy;
    this->PeakLuminanceIn = in.Peak;
    this->PeakLuminanceOut = out.Peak;
    this->NumberOfBrightPixels = vtkBloomCountBrightPixels(input, ext,
      this->Parameters->GetThresholdMode(), this->Parameters->GetThreshold(),
      this->Parameters->GetKnee(), this->Parameters->GetClampLuminance());
  }
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
  os << indent << "Parameters:\n";
  this->Parameters->PrintSelf(os, indent.GetNextIndent());
  os << indent << "ComputeStatistics: " << (this->ComputeStatistics ? "On" : "Off") << "\n";
  os << indent << "ExecutionMode: " << (this->ExecutionMode == FAST ? "Fast" : "Reference") << "\n";
  os << indent << "UseAVX2: " << (this->UseAVX2 ? "On" : "Off") << "\n";
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
  os << indent << "LastRunUsedAVX2: " << (this->LastRunUsedAVX2 ? "On" : "Off") << "\n";
  os << indent << "LastFFTBlurs: " << this->LastFFTBlurs << "\n";
  os << indent << "ChainSize: (" << this->ChainSize[0] << ", " << this->ChainSize[1] << ")\n";
}
