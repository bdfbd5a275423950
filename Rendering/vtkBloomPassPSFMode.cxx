// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// vtkBloomPass's PSF mode (vtkBloomParameters::BLOOM_PSF): the PSFs made from the parameters
// (only when what they depend on changed), the choice between the exact convolution
// (vtkBloomPassFFT) and the split one (vtkBloomPassPSFSplit), the bright pass and the
// convolution itself.
#include "vtkBloomPassInternals.h"

#include "vtkBloomPSFSplit.h"
#include "vtkImageBloom.h"
#include "vtkImageSeparableGaussian.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkTextureObject.h"

#include <algorithm>
#include <vector>

//------------------------------------------------------------------------------
bool vtkBloomPass::vtkInternals::UpdateKernels(vtkBloomParameters* parameters)
{
  // Only the parameters the PSFs depend on: a strength or threshold slider must not remake an
  // Airy pattern (seconds for a wide one) and its spectra every frame.
  vtkImageData* image = parameters->GetPSFImage();
  const double* wavelengths = parameters->GetWavelengths();
  std::vector<double> signature = { static_cast<double>(parameters->GetPSFType()),
    static_cast<double>(parameters->GetPSFRadius()), parameters->GetAiryRadius(), wavelengths[0],
    wavelengths[1], wavelengths[2], image ? static_cast<double>(image->GetMTime()) : -1.0,
    static_cast<double>(parameters->GetPSFTailScale()),
    static_cast<double>(parameters->GetEffectivePSFCoreRadius()) };
  for (const auto* values :
    { &parameters->GetPSFGaussianSigmas(), &parameters->GetPSFGaussianWeights() })
  {
    signature.push_back(static_cast<double>(values->size()));
    signature.insert(signature.end(), values->begin(), values->end());
  }
  if (signature == this->KernelsSignature && this->KernelsVersion != 0)
  {
    return !this->KernelsFailed;
  }
  this->KernelsSignature = signature;
  // The CPU filter's own PSFs (vtkImageBloom::ComputePSF), which report invalid parameters.
  vtkNew<vtkImageBloom> filter;
  filter->SetParameters(parameters);
  vtkBloomPassFFT::Kernel kernels[3];
  ++this->KernelsVersion;
  this->KernelsFailed = false;
  this->KernelsRadius = 0;
  for (int c = 0; c < 3; ++c)
  {
    kernels[c].Values = filter->ComputePSF(c, kernels[c].Radius);
    if (kernels[c].Values.empty())
    {
      this->KernelsFailed = true;
      return false;
    }
    this->KernelsRadius = std::max(this->KernelsRadius, kernels[c].Radius);
  }
  // Split (as the CPU filter splits them) where a tail is left; else the exact convolution.
  this->UsePSFSplit = false;
  if (parameters->GetPSFTailScale() > 1)
  {
    vtkBloomPSFSplit splits[3];
    for (int c = 0; c < 3; ++c)
    {
      splits[c] = vtkBloomPSFSplit::Make(
        kernels[c], parameters->GetPSFTailScale(), parameters->GetEffectivePSFCoreRadius());
      this->UsePSFSplit = this->UsePSFSplit || splits[c].HasTail();
    }
    if (this->UsePSFSplit)
    {
      this->PSFSplit.SetKernels(splits, this->KernelsVersion);
      return true;
    }
  }
  this->FFT.SetKernels(kernels, this->KernelsVersion);
  return true;
}

//------------------------------------------------------------------------------
bool vtkBloomPass::vtkInternals::RunPSF(vtkBloomPass* self)
{
  // Where PSF mode cannot run (no compute shaders, a grid too large, invalid PSFs) the scene
  // renders without bloom, and the reason is reported once.
  vtkBloomPassResources& res = this->Resources;
  if (!this->UpdateKernels(self->Parameters))
  {
    return false;
  }
  std::string why;
  if (this->Switches.SimulateComputeShaderFailure)
  {
    why = "PSF bloom's compute programs did not build (simulated for a test).";
  }
  // The other convolution's buffers go (a frame-wide PSF's exact grid holds 1.3 GB).
  if (this->UsePSFSplit && this->FFT.GetGridSize()[0] != 0)
  {
    this->FFT.ReleaseGraphicsResources(res.Context);
  }
  else if (!this->UsePSFSplit && this->PSFSplit.GetGridSize()[0] != 0)
  {
    this->PSFSplit.ReleaseGraphicsResources(res.Context);
  }
  const int* size = res.PSFBright.Size;
  if (!why.empty() ||
    !(this->UsePSFSplit ? this->PSFSplit.Prepare(res.Context, size[0], size[1], why)
                        : this->FFT.Prepare(res.Context, size[0], size[1], why)))
  {
    if (why != this->PSFError)
    {
      vtkErrorWithObjectMacro(self, << why << " The scene renders without bloom.");
      this->PSFError = why;
    }
    return false;
  }
  this->PSFError.clear();
  const int* grid = this->UsePSFSplit ? this->PSFSplit.GetGridSize() : this->FFT.GetGridSize();
  std::copy(grid, grid + 2, this->Report->PSFGrid);
  if (!this->Runner.BrightPassPSF(this->Light, res.PSFBright))
  {
    return false;
  }
  // Profiled (vtkBloomPassTesting::SetProfilePasses), each stage of the convolution is a profiled
  // span, sized as the grid.
  const bool reflect = self->Parameters->GetPSFBorderMode() == vtkImageSeparableGaussian::REFLECT;
  if (this->UsePSFSplit)
  {
    this->PSFSplit.Convolve(res.PSFBright.Color, res.PSFBloom.Color, reflect, this->Profiler);
  }
  else
  {
    this->FFT.Convolve(res.PSFBright.Color, res.PSFBloom.Color, reflect, this->Profiler);
  }
  return true;
}
