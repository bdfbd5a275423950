// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkBloomToolOptions.h"

#include "vtkBloomParameters.h"
#include "vtkImageBloomThreshold.h"
#include "vtkImagePyramidDown.h"
#include "vtkImagePyramidUp.h"
#include "vtkOpenEXRReader.h"

#include <vtkImageData.h>
#include <vtkNew.h>

#include <algorithm>
#include <cfloat>
#include <cmath>

namespace vtkBloomTool
{
const std::vector<std::string> BloomOptionNames = { "--preset", "--threshold", "--knee", "--mode",
  "--clamp-luminance", "--strength", "--composite", "--tint", "--levels", "--start-level",
  "--reference-height", "--down", "--up", "--accumulate", "--blur-sigma", "--blur-radius",
  "--blur-spacing", "--blur-iterations", "--level-weights", "--convolution", "--psf",
  "--psf-radius", "--airy-radius", "--wavelengths", "--psf-gaussians", "--psf-border",
  "--psf-tail-scale", "--psf-core-radius" };

namespace
{
// The largest PSF file accepted: a radius of 2048 pixels (vtkBloomParameters' limit).
constexpr vtkTypeUInt64 MaximumPSFPixels = vtkTypeUInt64(4097) * 4097;

// The PSF read from a --psf FILE.exr.
vtkSmartPointer<vtkImageData> ReadPSF(const std::string& fileName)
{
  vtkNew<vtkOpenEXRReader> reader;
  reader->SetFileName(fileName.c_str());
  reader->SetMaximumImagePixels(MaximumPSFPixels);
  ErrorCollector errors;
  errors.Watch(reader);
  reader->Update();
  errors.ThrowIfAny("cannot read the PSF '" + fileName + "'");
  if (reader->GetOutput()->GetNumberOfPoints() == 0)
  {
    throw RunError{ "cannot read the PSF '" + fileName + "'" };
  }
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->DeepCopy(reader->GetOutput());
  return image;
}

// --psf-gaussians SIGMA:WEIGHT,SIGMA:WEIGHT,...
void ParsePSFGaussians(
  const std::string& v, std::vector<double>& sigmas, std::vector<double>& weights)
{
  size_t start = 0;
  while (start <= v.size())
  {
    const size_t comma = std::min(v.find(',', start), v.size());
    const std::string item = v.substr(start, comma - start);
    const size_t colon = item.find(':');
    if (colon == std::string::npos)
    {
      throw UsageError{ "--psf-gaussians expects SIGMA:WEIGHT,..., got '" + v + "'" };
    }
    const double s = ParseDouble("--psf-gaussians", item.substr(0, colon));
    const double w = ParseDouble("--psf-gaussians", item.substr(colon + 1));
    if (!(s > 0.0) || !(w >= 0.0) || !std::isfinite(s) || !std::isfinite(w))
    {
      throw UsageError{ "--psf-gaussians needs sigmas > 0 and weights >= 0" };
    }
    sigmas.push_back(s);
    weights.push_back(w);
    start = comma + 1;
  }
}
}

//------------------------------------------------------------------------------
// --psf airy|gaussians|FILE.exr and its parameters: PSF mode (vtkBloomParameters::BLOOM_PSF).
void BloomOptions::ParsePSF(Arguments& args)
{
  std::string v;
  if (args.Take("--psf", v))
  {
    this->PSF = true;
    this->Set(&vtkBloomParameters::SetBloomMode, int(vtkBloomParameters::BLOOM_PSF));
    if (v == "airy")
    {
      this->Set(&vtkBloomParameters::SetPSFType, int(vtkBloomParameters::PSF_AIRY));
    }
    else if (v == "gaussians")
    {
      this->Set(&vtkBloomParameters::SetPSFType, int(vtkBloomParameters::PSF_GAUSSIANS));
    }
    else if (Extension(v) == ".exr")
    {
      vtkSmartPointer<vtkImageData> image = ReadPSF(v);
      this->Set(&vtkBloomParameters::SetPSFType, int(vtkBloomParameters::PSF_IMAGE));
      this->Edits.emplace_back([image](vtkBloomParameters* p) { p->SetPSFImage(image); });
    }
    else
    {
      throw UsageError{ "--psf expects airy, gaussians or a FILE.exr, got '" + v + "'" };
    }
  }
  for (const char* option : { "--psf-radius", "--airy-radius", "--wavelengths", "--psf-gaussians",
         "--psf-border", "--psf-tail-scale", "--psf-core-radius" })
  {
    if (!this->PSF && args.Options.count(option))
    {
      throw UsageError{ std::string(option) + " applies with --psf only" };
    }
  }
  if (args.Take("--psf-radius", v))
  {
    this->Set(&vtkBloomParameters::SetPSFRadius, ParseInt("--psf-radius", v, 0, 2048));
  }
  if (args.Take("--psf-tail-scale", v))
  {
    const int scale = ParseInt("--psf-tail-scale", v, 1, 8);
    if (scale != 1 && scale != 2 && scale != 4 && scale != 8)
    {
      throw UsageError{ "--psf-tail-scale must be 1 (exact), 2, 4 or 8" };
    }
    this->Set(&vtkBloomParameters::SetPSFTailScale, scale);
  }
  if (args.Take("--psf-core-radius", v))
  {
    this->Set(&vtkBloomParameters::SetPSFCoreRadius, ParseInt("--psf-core-radius", v, 1, 2048));
  }
  if (args.Take("--airy-radius", v))
  {
    const double radius = ParseDouble("--airy-radius", v);
    if (!(radius >= 0.1 && radius <= 1000.0))
    {
      throw UsageError{ "--airy-radius must be in [0.1, 1000] pixels" };
    }
    this->Set(&vtkBloomParameters::SetAiryRadius, radius);
  }
  if (args.Take("--wavelengths", v))
  {
    const auto l = ParseList("--wavelengths", v);
    if (l.size() != 3 || !(l[0] > 0.0 && l[1] > 0.0 && l[2] > 0.0))
    {
      throw UsageError{ "--wavelengths expects three positive values R,G,B in nm" };
    }
    this->Edits.emplace_back([l](vtkBloomParameters* p) { p->SetWavelengths(l[0], l[1], l[2]); });
  }
  if (args.Take("--psf-gaussians", v))
  {
    std::vector<double> sigmas, weights;
    ParsePSFGaussians(v, sigmas, weights);
    this->Set(&vtkBloomParameters::SetPSFType, int(vtkBloomParameters::PSF_GAUSSIANS));
    this->Edits.emplace_back(
      [sigmas, weights](vtkBloomParameters* p) { p->SetPSFGaussians(sigmas, weights); });
  }
  if (args.Take("--psf-border", v))
  {
    this->Set(&vtkBloomParameters::SetPSFBorderMode,
      ParseChoice("--psf-border", v, { { "reflect", 1 }, { "zero", 2 } }));
  }
}

//------------------------------------------------------------------------------
BloomOptions::BloomOptions(Arguments& args)
{
  std::string v;
  if (args.Take("--preset", v))
  {
    // Checked here, so that the usage error is the only line (SetPreset would log its own).
    const std::string error = vtkBloomParameters::CheckPresetName(v.c_str());
    if (!error.empty())
    {
      throw UsageError{ "--preset: " + error };
    }
    this->Edits.emplace_back([v](vtkBloomParameters* p) { p->SetPreset(v.c_str()); });
  }
  if (args.Take("--threshold", v))
  {
    // Above FLT_MAX no float pixel can pass; below 0 every pixel would, black ones included.
    this->Set(&vtkBloomParameters::SetThreshold, ParseDoubleIn("--threshold", v, 0.0, FLT_MAX));
  }
  if (args.Take("--knee", v))
  {
    const double knee = ParseDouble("--knee", v);
    if (knee < 0.0 || knee > 1.0)
    {
      throw UsageError{ "--knee must be in [0, 1]" };
    }
    this->Set(&vtkBloomParameters::SetKnee, knee);
  }
  if (args.Take("--mode", v))
  {
    this->Set(&vtkBloomParameters::SetThresholdMode,
      ParseChoice("--mode", v,
        { { "smoothstep", vtkImageBloomThreshold::SMOOTHSTEP_KNEE },
          { "quadratic", vtkImageBloomThreshold::QUADRATIC_KNEE },
          { "hard", vtkImageBloomThreshold::HARD_LUMINANCE },
          { "per-channel", vtkImageBloomThreshold::PER_CHANNEL },
          { "none", vtkImageBloomThreshold::NONE },
          { "excess", vtkImageBloomThreshold::EXCESS_KNEE } }));
  }
  if (args.Take("--clamp-luminance", v))
  {
    const double clamp = ParseDouble("--clamp-luminance", v);
    if (clamp < 0.0)
    {
      throw UsageError{ "--clamp-luminance must be >= 0" };
    }
    this->Set(&vtkBloomParameters::SetClampLuminance, clamp);
  }
  if (args.Take("--strength", v))
  {
    // A negative strength subtracts light; far above 1000 the sum overflows float.
    this->Set(&vtkBloomParameters::SetStrength, ParseDoubleIn("--strength", v, 0.0, 1000.0));
  }
  if (args.Take("--composite", v))
  {
    this->Set(&vtkBloomParameters::SetCompositeMode,
      ParseChoice("--composite", v,
        { { "additive", vtkBloomParameters::ADDITIVE }, { "lerp", vtkBloomParameters::LERP } }));
  }
  if (args.Take("--tint", v))
  {
    const auto tint = ParseList("--tint", v);
    if (tint.size() != 3)
    {
      throw UsageError{ "--tint expects R,G,B" };
    }
    this->Edits.emplace_back(
      [tint](vtkBloomParameters* p) { p->SetTint(tint[0], tint[1], tint[2]); });
  }
  if (args.Take("--levels", v))
  {
    this->Set(&vtkBloomParameters::SetNumberOfLevels, ParseInt("--levels", v, 1, 32));
  }
  if (args.Take("--start-level", v))
  {
    this->Set(&vtkBloomParameters::SetStartLevel, ParseInt("--start-level", v, 0, 16));
  }
  if (args.Take("--reference-height", v))
  {
    this->Set(&vtkBloomParameters::SetReferenceHeight, ParseInt("--reference-height", v, 0, 65536));
  }
  if (args.Take("--down", v))
  {
    this->Set(&vtkBloomParameters::SetDownsampleKernel,
      ParseChoice("--down", v,
        { { "jimenez13", vtkImagePyramidDown::JIMENEZ13 }, { "box", vtkImagePyramidDown::BOX },
          { "binomial", vtkImagePyramidDown::BINOMIAL } }));
  }
  if (args.Take("--karis", v))
  {
    this->Set(&vtkBloomParameters::SetKarisAverage, true);
  }
  if (args.Take("--up", v))
  {
    this->Set(&vtkBloomParameters::SetUpsampleKernel,
      ParseChoice("--up", v,
        { { "tent", vtkImagePyramidUp::TENT }, { "bilinear", vtkImagePyramidUp::BILINEAR } }));
  }
  if (args.Take("--accumulate", v))
  {
    this->Set(&vtkBloomParameters::SetAccumulateMode,
      ParseChoice("--accumulate", v,
        { { "cascade", vtkBloomParameters::CASCADE }, { "direct", vtkBloomParameters::DIRECT } }));
  }
  if (args.Take("--blur-sigma", v))
  {
    const double sigma = ParseDouble("--blur-sigma", v);
    if (sigma < 0.0)
    {
      throw UsageError{ "--blur-sigma must be >= 0" };
    }
    this->Set(&vtkBloomParameters::SetBlurKernel, vtkBloomParameters::BLUR_GAUSSIAN);
    this->Set(&vtkBloomParameters::SetBlurStandardDeviation, sigma);
    this->Set(&vtkBloomParameters::SetBlurRadius, -1);
  }
  if (args.Take("--blur-radius", v))
  {
    this->Set(&vtkBloomParameters::SetBlurKernel, vtkBloomParameters::BLUR_GAUSSIAN);
    this->Set(&vtkBloomParameters::SetBlurRadius, ParseInt("--blur-radius", v, 0, 4096));
  }
  if (args.Take("--blur-spacing", v))
  {
    const double spacing = ParseDouble("--blur-spacing", v);
    if (spacing < 0.0)
    {
      throw UsageError{ "--blur-spacing must be >= 0" };
    }
    this->Set(&vtkBloomParameters::SetBlurTapSpacing, spacing);
  }
  if (args.Take("--blur-iterations", v))
  {
    this->Set(&vtkBloomParameters::SetBlurIterations, ParseInt("--blur-iterations", v, 0, 1024));
  }
  if (args.Take("--level-weights", v))
  {
    const std::vector<double> weights = ParseList("--level-weights", v);
    this->Edits.emplace_back([weights](vtkBloomParameters* p) { p->SetLevelWeights(weights); });
  }
  if (args.Take("--convolution", v))
  {
    this->Set(&vtkBloomParameters::SetConvolutionMode,
      ParseChoice("--convolution", v,
        { { "auto", vtkBloomParameters::CONVOLUTION_AUTOMATIC },
          { "direct", vtkBloomParameters::CONVOLUTION_DIRECT },
          { "fft", vtkBloomParameters::CONVOLUTION_FFT } }));
  }
  this->ParsePSF(args);
}

//------------------------------------------------------------------------------
void BloomOptions::Apply(vtkBloomParameters* parameters) const
{
  for (const auto& edit : this->Edits)
  {
    edit(parameters);
  }
}

}
