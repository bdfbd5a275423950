// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkImageSeparableAlgorithm.h"

#include "vtkBloomPieces.h"

#include "vtkBloomImageOps.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>

//------------------------------------------------------------------------------
vtkImageSeparableAlgorithm::vtkImageSeparableAlgorithm()
{
  std::fill(this->InputWholeExtent, this->InputWholeExtent + 6, 0);
  std::fill(this->OutputWholeExtent, this->OutputWholeExtent + 6, 0);
}

//------------------------------------------------------------------------------
vtkImageSeparableAlgorithm::~vtkImageSeparableAlgorithm() = default;

//------------------------------------------------------------------------------
bool vtkImageSeparableAlgorithm::IsSupportedInput(int scalarType, int numberOfComponents)
{
  return (scalarType == VTK_FLOAT || scalarType == VTK_DOUBLE) && numberOfComponents >= 1 &&
    numberOfComponents <= 4;
}

//------------------------------------------------------------------------------
void vtkImageSeparableAlgorithm::ComputeInputExtent(const std::vector<Term>& terms,
  const int inWhole[6], const int outWhole[6], const int outExt[6], int inExt[6])
{
  // The union over the terms of what each operator reads, in whole-extent-relative indices.
  for (int a = 0; a < 3; ++a)
  {
    const int outMin = outExt[2 * a] - outWhole[2 * a];
    const int outMax = outExt[2 * a + 1] - outWhole[2 * a];
    int lo = VTK_INT_MAX, hi = VTK_INT_MIN;
    for (const Term& term : terms)
    {
      int tmin = outMin, tmax = outMax;
      if (term.Use[a])
      {
        term.Operators[a].GetInputRange(outMin, outMax, tmin, tmax);
      }
      lo = std::min(lo, tmin);
      hi = std::max(hi, tmax);
    }
    inExt[2 * a] = std::max(inWhole[2 * a], inWhole[2 * a] + lo);
    inExt[2 * a + 1] = std::min(inWhole[2 * a + 1], inWhole[2 * a] + hi);
  }
}

//------------------------------------------------------------------------------
int vtkImageSeparableAlgorithm::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  int inWhole[6], outWhole[6], outExt[6];
  inInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), inWhole);
  outInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), outWhole);
  // The extent this filter will compute (one rank's piece under MPI), grown by the support.
  vtkBloomExecutionExtent(outInfo, outExt);

  std::vector<Term> terms;
  if (!this->BuildTerms(inWhole, outWhole, terms) || outExt[0] > outExt[1] ||
    outExt[2] > outExt[3] || outExt[4] > outExt[5])
  {
    vtkBloomRequestExactExtent(inInfo, inWhole);
    return 1;
  }

  int inExt[6];
  vtkImageSeparableAlgorithm::ComputeInputExtent(terms, inWhole, outWhole, outExt, inExt);
  vtkBloomRequestExactExtent(inInfo, inExt);
  return 1;
}

//------------------------------------------------------------------------------
int vtkImageSeparableAlgorithm::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkImageData* input = vtkImageData::GetData(inInfo);
  vtkImageData* output = vtkImageData::GetData(outInfo);
  if (!input || !input->GetPointData()->GetScalars())
  {
    vtkErrorMacro(<< "Input has no point scalars.");
    output->Initialize();
    return 0;
  }
  if (!vtkImageSeparableAlgorithm::IsSupportedInput(
        input->GetScalarType(), input->GetNumberOfScalarComponents()))
  {
    vtkErrorMacro(<< "Input scalars must be float or double with 1 to 4 components; got "
                  << input->GetScalarTypeAsString() << " with "
                  << input->GetNumberOfScalarComponents() << " components.");
    output->Initialize();
    return 0;
  }
  vtkBloomMatchOutputScalars(outInfo, input);
  inInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), this->InputWholeExtent);
  outInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), this->OutputWholeExtent);
  this->Terms.clear();
  if (!this->BuildTerms(this->InputWholeExtent, this->OutputWholeExtent, this->Terms))
  {
    output->Initialize();
    return 0;
  }
  const int result = this->Superclass::RequestData(request, inputVector, outputVector);
  this->Terms.clear();
  return result;
}

//------------------------------------------------------------------------------
void vtkImageSeparableAlgorithm::CombineTerms(
  const std::vector<vtkBloomBuffer>& results, vtkBloomBuffer& out)
{
  std::vector<double> weights;
  for (const Term& term : this->Terms)
  {
    weights.push_back(term.Weight);
  }
  vtkBloomCombineTerms(results, weights, false, out, false);
}

//------------------------------------------------------------------------------
void vtkImageSeparableAlgorithm::ThreadedRequestData(vtkInformation*, vtkInformationVector**,
  vtkInformationVector*, vtkImageData*** inData, vtkImageData** outData, int outExt[6],
  int threadId)
{
  vtkImageData* input = inData[0][0];
  vtkImageData* output = outData[0];
  if (outExt[0] > outExt[1] || outExt[2] > outExt[3] || outExt[4] > outExt[5] ||
    this->Terms.empty())
  {
    return;
  }
  const int* inWhole = this->InputWholeExtent;
  const int* outWhole = this->OutputWholeExtent;
  const int inLo[3] = { inWhole[0], inWhole[2], inWhole[4] };
  const int outWholeLo[3] = { outWhole[0], outWhole[2], outWhole[4] };

  // Import only the part of the input this piece reads.
  int inExt[6], available[6];
  vtkImageSeparableAlgorithm::ComputeInputExtent(this->Terms, inWhole, outWhole, outExt, inExt);
  input->GetExtent(available);
  for (int a = 0; a < 3; ++a)
  {
    inExt[2 * a] = std::max(inExt[2 * a], available[2 * a]);
    inExt[2 * a + 1] = std::min(inExt[2 * a + 1], available[2 * a + 1]);
  }
  const int nc = input->GetNumberOfScalarComponents();
  vtkBloomBuffer source;
  vtkBloomImport(input, inExt, inLo, 0, nc, source);

  const int lo[3] = { outExt[0] - outWhole[0], outExt[2] - outWhole[2], outExt[4] - outWhole[4] };
  const int size[3] = { outExt[1] - outExt[0] + 1, outExt[3] - outExt[2] + 1,
    outExt[5] - outExt[4] + 1 };
  std::vector<vtkBloomBuffer> results(this->Terms.size());
  for (size_t t = 0; t < this->Terms.size(); ++t)
  {
    if (this->AbortExecute)
    {
      return;
    }
    const Term& term = this->Terms[t];
    const vtkBloomLinearOperator* ops[3];
    for (int a = 0; a < 3; ++a)
    {
      ops[a] = term.Use[a] ? &term.Operators[a] : nullptr;
    }
    vtkBloomApplySeparable(source, ops, lo, size, results[t], false);
    if (threadId == 0)
    {
      this->UpdateProgress(0.9 * static_cast<double>(t + 1) / this->Terms.size());
    }
  }
  vtkBloomBuffer combined;
  this->CombineTerms(results, combined);
  vtkBloomExport(combined, outWholeLo, output, outExt, 0);
  if (threadId == 0)
  {
    this->UpdateProgress(1.0);
  }
}

//------------------------------------------------------------------------------
void vtkImageSeparableAlgorithm::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
