#include "vtkImageSeparableGaussian.h"

#include "vtkBloomKernels.h"
#include "vtkObjectFactory.h"

#include <cmath>

vtkStandardNewMacro(vtkImageSeparableGaussian);

//------------------------------------------------------------------------------
vtkImageSeparableGaussian::vtkImageSeparableGaussian()
{
  this->StandardDeviations[0] = 2.0;
  this->StandardDeviations[1] = 2.0;
  this->StandardDeviations[2] = 0.0;
  this->Radius[0] = this->Radius[1] = this->Radius[2] = -1;
  this->RadiusFactor = 4.0;
  this->KernelType = SAMPLED;
  this->BorderMode = CLAMP;
}

//------------------------------------------------------------------------------
vtkImageSeparableGaussian::~vtkImageSeparableGaussian() = default;

//------------------------------------------------------------------------------
std::vector<double> vtkImageSeparableGaussian::GetHalfKernel(int axis)
{
  if (axis < 0 || axis > 2)
  {
    return { 1.0 };
  }
  const double sigma = this->StandardDeviations[axis];
  const int radius = this->Radius[axis] >= 0
    ? this->Radius[axis]
    : vtkBloomKernels::RadiusForSigma(sigma, this->RadiusFactor);
  return vtkBloomKernels::GaussianHalfKernel(sigma, radius, this->KernelType);
}

//------------------------------------------------------------------------------
bool vtkImageSeparableGaussian::BuildTerms(
  const int inWhole[6], const int*, std::vector<Term>& terms)
{
  Term term;
  for (int a = 0; a < 3; ++a)
  {
    const double sigma = this->StandardDeviations[a];
    if (!(sigma >= 0.0) || !std::isfinite(sigma))
    {
      vtkErrorMacro(<< "StandardDeviations must be finite and >= 0; axis " << a << " has " << sigma
                    << ".");
      return false;
    }
    const std::vector<double> half = this->GetHalfKernel(a);
    const int n = inWhole[2 * a + 1] - inWhole[2 * a] + 1;
    if (half.size() > 1 && n > 0)
    {
      term.Operators[a] = vtkBloomLinearOperator::Convolve(
        n, vtkBloomKernels::SymmetricTaps(half, 1.0), this->BorderMode);
      term.Use[a] = !term.Operators[a].IsIdentity();
    }
  }
  terms.push_back(std::move(term));
  return true;
}

//------------------------------------------------------------------------------
const char* vtkImageSeparableGaussian::GetKernelTypeAsString()
{
  switch (this->KernelType)
  {
    case INTEGRATED:
      return "Integrated";
    case DISCRETE:
      return "Discrete";
    default:
      return "Sampled";
  }
}

//------------------------------------------------------------------------------
const char* vtkImageSeparableGaussian::GetBorderModeAsString()
{
  switch (this->BorderMode)
  {
    case REFLECT:
      return "Reflect";
    case ZERO:
      return "Zero";
    default:
      return "Clamp";
  }
}

//------------------------------------------------------------------------------
void vtkImageSeparableGaussian::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "StandardDeviations: (" << this->StandardDeviations[0] << ", "
     << this->StandardDeviations[1] << ", " << this->StandardDeviations[2] << ")\n";
  os << indent << "Radius: (" << this->Radius[0] << ", " << this->Radius[1] << ", "
     << this->Radius[2] << ")\n";
  os << indent << "RadiusFactor: " << this->RadiusFactor << "\n";
  os << indent << "KernelType: " << this->GetKernelTypeAsString() << "\n";
  os << indent << "BorderMode: " << this->GetBorderModeAsString() << "\n";
}
