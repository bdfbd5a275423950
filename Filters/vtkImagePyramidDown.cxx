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
  const int clamp = vtkBloomLinearOperator::BORDER_CLAMP;
  // A term whose x and y operators resample with the given taps on each axis.
  auto addTerm = [&](double weight, const std::vector<vtkBloomKernels::Tap>& tx,
                   const std::vector<vtkBloomKernels::Tap>& ty)
  {
    Term term;
    term.Weight = weight;
    term.Operators[0] = vtkBloomLinearOperator::Resample(n[0], m[0], tx, clamp);
    term.Operators[1] = vtkBloomLinearOperator::Resample(n[1], m[1], ty, clamp);
    term.Use[0] = term.Use[1] = true;
    terms.push_back(std::move(term));
  };

  switch (this->Kernel)
  {
    case BOX:
    {
      Term term;
      term.Operators[0] = vtkBloomLinearOperator::Area(n[0], m[0]);
      term.Operators[1] = vtkBloomLinearOperator::Area(n[1], m[1]);
      term.Use[0] = term.Use[1] = true;
      terms.push_back(std::move(term));
      break;
    }
    case BINOMIAL:
      addTerm(1.0, vtkBloomKernels::Binomial5Taps(), vtkBloomKernels::Binomial5Taps());
      break;
    case JIMENEZ13:
    default:
      if (this->KarisAverage)
      {
        // The five 2x2 boxes, combined non-linearly in CombineTerms.
        const auto inner = vtkBloomKernels::HalfTexelPairTaps();
        const auto left = vtkBloomKernels::LeftPairTaps();
        const auto right = vtkBloomKernels::RightPairTaps();
        addTerm(vtkBloomKernels::Jimenez13InnerWeight, inner, inner);
        addTerm(vtkBloomKernels::Jimenez13OuterWeight, left, left);
        addTerm(vtkBloomKernels::Jimenez13OuterWeight, right, left);
        addTerm(vtkBloomKernels::Jimenez13OuterWeight, left, right);
        addTerm(vtkBloomKernels::Jimenez13OuterWeight, right, right);
      }
      else
      {
        // 1/2 inner box + 4 x 1/8 outer boxes == 1/2 inner box + 1/2 tent (x) tent.
        addTerm(0.5, vtkBloomKernels::HalfTexelPairTaps(), vtkBloomKernels::HalfTexelPairTaps());
        addTerm(0.5, vtkBloomKernels::TentTaps(), vtkBloomKernels::TentTaps());
      }
      break;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkImagePyramidDown::CombineTerms(
  const std::vector<vtkBloomBuffer>& results, vtkBloomBuffer& out)
{
  if (!(this->Kernel == JIMENEZ13 && this->KarisAverage))
  {
    this->Superclass::CombineTerms(results, out);
    return;
  }
  // Karis average: each box weighted by base / (1 + luma(box)), then renormalized.
  out = results[0];
  const int nc = out.NumberOfComponents;
  const size_t samples = out.GetNumberOfSamples();
  for (size_t s = 0; s < samples; ++s)
  {
    double acc[4] = { 0.0, 0.0, 0.0, 0.0 };
    double total = 0.0;
    for (size_t t = 0; t < results.size(); ++t)
    {
      const double* box = results[t].Data.data() + s * nc;
      const double luma = nc >= 3 ? vtkBloomKernels::LuminanceR * box[0] +
          vtkBloomKernels::LuminanceG * box[1] + vtkBloomKernels::LuminanceB * box[2]
                                  : box[0];
      const double w = this->Terms[t].Weight / (1.0 + std::max(luma, 0.0));
      total += w;
      for (int c = 0; c < nc; ++c)
      {
        acc[c] += w * box[c];
      }
    }
    for (int c = 0; c < nc; ++c)
    {
      out.Data[s * nc + c] = acc[c] / total;
    }
  }
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
