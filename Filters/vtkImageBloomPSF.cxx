// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// vtkImageBloom's PSF mode (its parameters are vtkBloomParameters'): the point-spread function of
// each colour channel and the execution (bright pass, convolution with the PSF, composite). The
// convolution itself is vtkBloomPSF's; the pyramid chain is in vtkImageBloom.cxx and
// vtkImageBloomReferenceChain.cxx.
#include "vtkImageBloom.h"

#include "vtkBloomImageOps.h"
#include "vtkBloomPSF.h"
#include "vtkImageData.h"
#include "vtkInformation.h"

#include <algorithm>
#include <cmath>

namespace
{
// The largest PSF radius an automatic choice or an image may have.
constexpr int MaximumPSFRadius = 2048;
}

//------------------------------------------------------------------------------
vtkMTimeType vtkImageBloom::GetMTime()
{
  return std::max(this->Superclass::GetMTime(), this->Parameters->GetMTime());
}

//------------------------------------------------------------------------------
std::vector<double> vtkImageBloom::ComputePSF(int channel, int& radius)
{
  radius = 0;
  const int c = std::min(std::max(channel, 0), 2);
  vtkBloomPSFKernel kernel;
  switch (this->Parameters->GetPSFType())
  {
    case PSF_GAUSSIANS:
    {
      const auto& s = this->Parameters->GetPSFGaussianSigmas();
      const auto& w = this->Parameters->GetPSFGaussianWeights();
      double widest = 0.0, total = 0.0;
      bool valid = !s.empty() && s.size() == w.size();
      for (size_t g = 0; valid && g < s.size(); ++g)
      {
        valid = std::isfinite(s[g]) && s[g] > 0.0 && std::isfinite(w[g]) && w[g] >= 0.0;
        widest = std::max(widest, s[g]);
        total += w[g];
      }
      if (!valid || !(total > 0.0))
      {
        vtkErrorMacro(<< "PSF Gaussians need as many weights as sigmas, sigmas > 0 and finite, "
                         "weights >= 0 and finite with a positive sum.");
        return {};
      }
      const int r = this->Parameters->GetPSFRadius() >= 0
        ? this->Parameters->GetPSFRadius()
        : static_cast<int>(std::min<double>(MaximumPSFRadius, std::ceil(4.0 * widest)));
      kernel = vtkBloomPSF::Gaussians(s, w, r);
      break;
    }
    case PSF_IMAGE:
    {
      std::string error;
      const int limit =
        this->Parameters->GetPSFRadius() >= 0 ? this->Parameters->GetPSFRadius() : MaximumPSFRadius;
      if (!this->Parameters->GetPSFImage())
      {
        vtkErrorMacro(<< "PSF mode with PSF_IMAGE needs SetPSFImage.");
        return {};
      }
      if (!vtkBloomPSF::FromImage(this->Parameters->GetPSFImage(), c, limit, kernel, error))
      {
        vtkErrorMacro(<< "Invalid PSF image: " << error << ".");
        return {};
      }
      break;
    }
    case PSF_AIRY:
    default:
    {
      const double* l = this->Parameters->GetWavelengths();
      if (!(l[0] > 0.0 && l[1] > 0.0 && l[2] > 0.0) ||
        !(std::isfinite(l[0]) && std::isfinite(l[1]) && std::isfinite(l[2])))
      {
        vtkErrorMacro(<< "Wavelengths must be finite and > 0; got (" << l[0] << ", " << l[1] << ", "
                      << l[2] << ").");
        return {};
      }
      const double longest = std::max(std::max(l[0], l[1]), l[2]);
      const int r = this->Parameters->GetPSFRadius() >= 0
        ? this->Parameters->GetPSFRadius()
        : static_cast<int>(std::min<double>(MaximumPSFRadius,
            std::ceil(12.0 * this->Parameters->GetAiryRadius() * longest / l[1])));
      kernel = vtkBloomPSF::Airy(this->Parameters->GetAiryRadius() * l[c] / l[1], r);
      break;
    }
  }
  radius = kernel.Radius;
  return kernel.Values;
}

//------------------------------------------------------------------------------
int vtkImageBloom::ExecutePSF(vtkImageData* input, vtkInformation* outInfo, vtkImageData* output)
{
  int inExt[6];
  input->GetExtent(inExt);
  if (inExt[4] != inExt[5])
  {
    vtkErrorMacro(<< "PSF mode needs a 2-D image; the input has " << inExt[5] - inExt[4] + 1
                  << " slices.");
    output->Initialize();
    return 0;
  }
  const int colours = input->GetNumberOfScalarComponents() >= 3 ? 3 : 1;
  // One PSF per colour channel (a single-colour image uses the green one) and their prepared
  // convolution (plans, buffers, the kernels' spectra), built again only when a parameter, the
  // PSF image or the image size changed: an Airy pattern takes longer than its FFT.
  vtkBloomPSFKernels& cache = *this->PSFKernels;
  const vtkMTimeType time = this->GetMTime();
  const int width = inExt[1] - inExt[0] + 1, height = inExt[3] - inExt[2] + 1;
  const bool rebuild = cache.Time != time || cache.Colours != colours;
  if (rebuild)
  {
    cache.Kernels.assign(colours, vtkBloomPSFKernel());
    cache.Time = 0;
    for (int c = 0; c < colours; ++c)
    {
      vtkBloomPSFKernel& kernel = cache.Kernels[c];
      kernel.Values = this->ComputePSF(colours == 3 ? c : 1, kernel.Radius);
      if (kernel.Values.empty())
      {
        output->Initialize();
        return 0;
      }
    }
    cache.Time = time;
    cache.Colours = colours;
  }
  if (rebuild || !cache.Convolution.IsPreparedFor(width, height))
  {
    cache.Prepare(width, height, this->Parameters->GetPSFTailScale(),
      this->Parameters->GetEffectivePSFCoreRadius());
  }
  this->AllocateOutputData(output, outInfo);
  vtkBloomBuffer bright;
  this->ImportColours(input, bright);
  // Strength and tint only: PSF mode has no level weights.
  bool skip =
    this->Parameters->GetSkipDisabledEffects() && this->Parameters->IsBloomDisabled(colours, 0);
  if (!skip)
  {
    this->BrightPassInPlace(bright);
    skip = this->Parameters->GetSkipEmptyBloom() &&
      std::all_of(bright.Data.begin(), bright.Data.end(), [](double v) { return v == 0.0; });
  }
  this->LastBloomSkipped = skip;
  this->UpdateProgress(0.2);
  vtkBloomBuffer bloom;
  if (!skip)
  {
    cache.Convolve(bright, this->Parameters->GetPSFBorderMode() == 1, bloom);
  }
  this->UpdateProgress(0.8);
  this->Composite(input, skip ? nullptr : &bloom, output);
  this->ComputeOutputStatistics(input, output, 0, false);
  this->UpdateProgress(1.0);
  return 1;
}
