// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkImagePyramidUp.h"

#include "vtkBloomPieces.h"

#include "vtkBloomImageOps.h"
#include "vtkBloomKernels.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

vtkStandardNewMacro(vtkImagePyramidUp);

//------------------------------------------------------------------------------
vtkImagePyramidUp::vtkImagePyramidUp()
{
  this->SetNumberOfInputPorts(2);
  this->Kernel = TENT;
  this->CoarseWeight = 1.0;
  this->FineWeight = 0.0;
}

//------------------------------------------------------------------------------
vtkImagePyramidUp::~vtkImagePyramidUp() = default;

//------------------------------------------------------------------------------
int vtkImagePyramidUp::FillInputPortInformation(int port, vtkInformation* info)
{
  this->Superclass::FillInputPortInformation(port, info);
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
  return 1;
}

//------------------------------------------------------------------------------
int vtkImagePyramidUp::RequestInformation(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInformation* fineInfo = inputVector[1]->GetInformationObject(0);
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  if (!fineInfo)
  {
    vtkErrorMacro(<< "The finer level (input 1) is required: it defines the output geometry.");
    return 0;
  }
  int ext[6];
  double origin[3], spacing[3];
  fineInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), ext);
  fineInfo->Get(vtkDataObject::ORIGIN(), origin);
  fineInfo->Get(vtkDataObject::SPACING(), spacing);
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), ext, 6);
  outInfo->Set(vtkDataObject::ORIGIN(), origin, 3);
  outInfo->Set(vtkDataObject::SPACING(), spacing, 3);
  return 1;
}

//------------------------------------------------------------------------------
int vtkImagePyramidUp::RequestUpdateExtent(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  this->Superclass::RequestUpdateExtent(request, inputVector, outputVector);
  // The finer level is read pixel for pixel where it is added.
  int outExt[6];
  vtkBloomExecutionExtent(outputVector->GetInformationObject(0), outExt);
  if (vtkInformation* fineInfo = inputVector[1]->GetInformationObject(0))
  {
    vtkBloomRequestExactExtent(fineInfo, outExt);
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkImagePyramidUp::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkImageData* coarse = vtkImageData::GetData(inputVector[0]);
  vtkImageData* fine = vtkImageData::GetData(inputVector[1]);
  if (this->FineWeight != 0.0 && coarse && fine)
  {
    if (!fine->GetPointData()->GetScalars() ||
      !vtkImageSeparableAlgorithm::IsSupportedInput(
        fine->GetScalarType(), fine->GetNumberOfScalarComponents()) ||
      fine->GetNumberOfScalarComponents() != coarse->GetNumberOfScalarComponents())
    {
      vtkErrorMacro(<< "The finer level must be float or double with as many components as the "
                       "coarse input to be added.");
      vtkImageData::GetData(outputVector)->Initialize();
      return 0;
    }
  }
  return this->Superclass::RequestData(request, inputVector, outputVector);
}

//------------------------------------------------------------------------------
bool vtkImagePyramidUp::BuildTerms(
  const int inWhole[6], const int outWhole[6], std::vector<Term>& terms)
{
  const int n[3] = { inWhole[1] - inWhole[0] + 1, inWhole[3] - inWhole[2] + 1,
    inWhole[5] - inWhole[4] + 1 };
  const int m[3] = { outWhole[1] - outWhole[0] + 1, outWhole[3] - outWhole[2] + 1,
    outWhole[5] - outWhole[4] + 1 };
  if (n[0] <= 0 || n[1] <= 0 || m[0] <= 0 || m[1] <= 0)
  {
    vtkErrorMacro(<< "Empty input extent.");
    return false;
  }
  if (n[2] != m[2])
  {
    vtkErrorMacro(<< "The coarse and fine inputs must have the same number of Z slices (" << n[2]
                  << " vs " << m[2] << ").");
    return false;
  }
  const auto taps =
    this->Kernel == BILINEAR ? vtkBloomKernels::BilinearTaps() : vtkBloomKernels::TentTaps();
  Term term;
  term.Weight = this->CoarseWeight;
  for (int a = 0; a < 2; ++a)
  {
    term.Operators[a] =
      vtkBloomLinearOperator::Resample(n[a], m[a], taps, vtkBloomLinearOperator::BORDER_CLAMP);
    term.Use[a] = true;
  }
  terms.push_back(std::move(term));
  return true;
}

//------------------------------------------------------------------------------
void vtkImagePyramidUp::ThreadedRequestData(vtkInformation* request,
  vtkInformationVector** inputVector, vtkInformationVector* outputVector, vtkImageData*** inData,
  vtkImageData** outData, int outExt[6], int threadId)
{
  this->Superclass::ThreadedRequestData(
    request, inputVector, outputVector, inData, outData, outExt, threadId);
  vtkImageData* fine = inData[1] ? inData[1][0] : nullptr;
  if (this->FineWeight == 0.0 || !fine || outExt[0] > outExt[1] || outExt[2] > outExt[3] ||
    outExt[4] > outExt[5])
  {
    return;
  }
  // out += FineWeight * fine over this piece.
  const int origin[3] = { 0, 0, 0 };
  const int nc = fine->GetNumberOfScalarComponents();
  vtkBloomBuffer sum, addend;
  vtkBloomImport(outData[0], outExt, origin, 0, nc, sum);
  vtkBloomImport(fine, outExt, origin, 0, nc, addend);
  vtkBloomAddScaled(addend, this->FineWeight, sum);
  vtkBloomExport(sum, origin, outData[0], outExt, 0);
}

//------------------------------------------------------------------------------
const char* vtkImagePyramidUp::GetKernelAsString()
{
  return this->Kernel == BILINEAR ? "Bilinear" : "Tent";
}

//------------------------------------------------------------------------------
void vtkImagePyramidUp::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Kernel: " << this->GetKernelAsString() << "\n";
  os << indent << "CoarseWeight: " << this->CoarseWeight << "\n";
  os << indent << "FineWeight: " << this->FineWeight << "\n";
}
