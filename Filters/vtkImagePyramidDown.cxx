// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkImagePyramidDown.h"

#include "vtkBloomImageOps.h"
#include "vtkBloomKernels.h"
#include "vtkDataObject.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkImagePyramidDown);

//------------------------------------------------------------------------------
vtkImagePyramidDown::vtkImagePyramidDown()
{
  this->Kernel = JIMENEZ13;
  this->KarisAverage = false;
}

//------------------------------------------------------------------------------
vtkImagePyramidDown::~vtkImagePyramidDown() = default;

//------------------------------------------------------------------------------
void vtkImagePyramidDown::ComputeOutputGeometry(const int inExtent[6], const double inOrigin[3],
  const double inSpacing[3], int outExtent[6], double outOrigin[3], double outSpacing[3])
{
  for (int a = 0; a < 3; ++a)
  {
    const int lo = inExtent[2 * a];
    const int n = inExtent[2 * a + 1] - lo + 1;
    if (a == 2 || n <= 0)
    {
      outExtent[2 * a] = lo;
      outExtent[2 * a + 1] = inExtent[2 * a + 1];
      outOrigin[a] = inOrigin[a];
      outSpacing[a] = inSpacing[a];
      continue;
    }
    const int m = vtkImagePyramidDown::HalvedSize(n);
    const int outLo = static_cast<int>(std::floor(lo / 2.0));
    outExtent[2 * a] = outLo;
    outExtent[2 * a + 1] = outLo + m - 1;
    outSpacing[a] = inSpacing[a] * n / m;
    // The first output centre sits half an output pixel inside the input's footprint.
    const double footprintStart = inOrigin[a] + inSpacing[a] * (lo - 0.5);
    outOrigin[a] = footprintStart + outSpacing[a] * (0.5 - outLo);
  }
}

//------------------------------------------------------------------------------
int vtkImagePyramidDown::RequestInformation(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  int inExt[6], outExt[6];
  double inOrigin[3], inSpacing[3], outOrigin[3], outSpacing[3];
  inInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), inExt);
  inInfo->Get(vtkDataObject::ORIGIN(), inOrigin);
  inInfo->Get(vtkDataObject::SPACING(), inSpacing);
  vtkImagePyramidDown::ComputeOutputGeometry(
    inExt, inOrigin, inSpacing, outExt, outOrigin, outSpacing);
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), outExt, 6);
  outInfo->Set(vtkDataObject::ORIGIN(), outOrigin, 3);
  outInfo->Set(vtkDataObject::SPACING(), outSpacing, 3);
  return 1;
}

//------------------------------------------------------------------------------
bool vtkImagePyramidDown::BuildTerms(
  const int inWhole[6], const int outWhole[6], std::vector<Term>& terms)
{
  const int n[2] = { inWhole[1] - inWhole[0] + 1, inWhole[3] - inWhole[2] + 1 };
  const int m[2] = { outWhole[1] - outWhole[0] + 1, outWhole[3] - outWhole[2] + 1 };
  if (n[0] <= 0 || n[1] <= 0 || m[0] <= 0 || m[1] <= 0)
  {
    vtkErrorMacro(<< "Empty input extent.");
    return false;
  }
  for (auto& separable : vtkBloomDownsampleTerms(this->Kernel, this->KarisAverage, n, m))
  {
    Term term;
    term.Weight = separable.Weight;
    term.Operators[0] = std::move(separable.X);
    term.Operators[1] = std::move(separable.Y);
    term.Use[0] = term.Use[1] = true;
    terms.push_back(std::move(term));
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkImagePyramidDown::CombineTerms(
  const std::vector<vtkBloomBuffer>& results, vtkBloomBuffer& out)
{
  std::vector<double> weights;
  for (const Term& term : this->Terms)
  {
    weights.push_back(term.Weight);
  }
  vtkBloomCombineTerms(
    results, weights, this->Kernel == JIMENEZ13 && this->KarisAverage, out, false);
}

//------------------------------------------------------------------------------
const char* vtkImagePyramidDown::GetKernelAsString()
{
  switch (this->Kernel)
  {
    case BOX:
      return "Box";
    case BINOMIAL:
      return "Binomial";
    default:
      return "Jimenez13";
  }
}

//------------------------------------------------------------------------------
void vtkImagePyramidDown::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Kernel: " << this->GetKernelAsString() << "\n";
  os << indent << "KarisAverage: " << (this->KarisAverage ? "On" : "Off") << "\n";
}
