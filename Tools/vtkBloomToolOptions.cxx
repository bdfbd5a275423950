#include "vtkBloomToolOptions.h"

#include "vtkImageBloom.h"
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
  "--clamp-luminance", "--strength", "--composite", "--tint", "--levels", "--start-level", "--down",
  "--up", "--accumulate", "--blur-sigma", "--blur-radius", "--blur-spacing", "--blur-iterations",
  "--level-weights", "--convolution", "--psf", "--psf-radius", "--airy-radius", "--wavelengths",
  "--psf-gaussians", "--psf-border" };

namespace
{
// The largest PSF file accepted: a radius of 2048 pixels (vtkImageBloom's limit).
constexpr vtkTypeUInt64 MaximumPSFPixels = vtkTypeUInt64(4097) * 4097;

// --psf airy|gaussians|FILE.exr and its parameters: PSF mode (vtkImageBloom::BLOOM_PSF).
void ApplyPSFOptions(Arguments& args, vtkImageBloom* bloom)
{
  std::string v;
  if (args.Take("--psf", v))
  {
    bloom->SetBloomModeToPSF();
    if (v == "airy")
    {
      bloom->SetPSFType(vtkImageBloom::PSF_AIRY);
    }
    else if (v == "gaussians")
    {
      bloom->SetPSFType(vtkImageBloom::PSF_GAUSSIANS);
    }
    else if (Extension(v) == ".exr")
    {
      vtkNew<vtkOpenEXRReader> reader;
      reader->SetFileName(v.c_str());
      reader->SetMaximumImagePixels(MaximumPSFPixels);
      ErrorCollector errors;
      errors.Watch(reader);
      reader->Update();
      errors.ThrowIfAny("cannot read the PSF '" + v + "'");
      if (reader->GetOutput()->GetNumberOfPoints() == 0)
      {
        throw RunError{ "cannot read the PSF '" + v + "'" };
      }
      auto image = vtkSmartPointer<vtkImageData>::New();
      image->DeepCopy(reader->GetOutput());
      bloom->SetPSFType(vtkImageBloom::PSF_IMAGE);
      bloom->SetPSFImage(image);
    }
    else
    {
      throw UsageError{ "--psf expects airy, gaussians or a FILE.exr, got '" + v + "'" };
    }
  }
  const bool psf = bloom->GetBloomMode() == vtkImageBloom::BLOOM_PSF;
  for (const char* option :
    { "--psf-radius", "--airy-radius", "--wavelengths", "--psf-gaussians", "--psf-border" })
  {
    if (!psf && args.Options.count(option))
    {
      throw UsageError{ std::string(option) + " applies with --psf only" };
    }
  }
  if (args.Take("--psf-radius", v))
  {
    bloom->SetPSFRadius(ParseInt("--psf-radius", v, 0, 2048));
  }
  if (args.Take("--airy-radius", v))
  {
    const double radius = ParseDouble("--airy-radius", v);
    if (!(radius >= 0.1 && radius <= 1000.0))
    {
      throw UsageError{ "--airy-radius must be in [0.1, 1000] pixels" };
    }
    bloom->SetAiryRadius(radius);
  }
  if (args.Take("--wavelengths", v))
  {
    const auto l = ParseList("--wavelengths", v);
    if (l.size() != 3 || !(l[0] > 0.0 && l[1] > 0.0 && l[2] > 0.0))
    {
      throw UsageError{ "--wavelengths expects three positive values R,G,B in nm" };
    }
    bloom->SetWavelengths(l[0], l[1], l[2]);
  }
  if (args.Take("--psf-gaussians", v))
  {
    // SIGMA:WEIGHT,SIGMA:WEIGHT,...
    std::vector<double> sigmas, weights;
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
    bloom->SetPSFType(vtkImageBloom::PSF_GAUSSIANS);
    bloom->SetPSFGaussians(sigmas, weights);
  }
  if (args.Take("--psf-border", v))
  {
    bloom->SetPSFBorderMode(ParseChoice("--psf-border", v, { { "reflect", 1 }, { "zero", 2 } }));
  }
}
}

//------------------------------------------------------------------------------
void ApplyImageOptions(Arguments& args, vtkImageBloom* bloom)
{
  std::string v;
  if (args.Take("--preset", v))
  {
    // Checked here, so that the usage error is the only line (SetPreset would log its own).
    const std::vector<std::string> presets = vtkImageBloom::GetPresetNames();
    if (std::find(presets.begin(), presets.end(), v) == presets.end())
    {
      std::string names;
      for (const std::string& name : presets)
      {
        names += (names.empty() ? "" : ", ") + name;
      }
      throw UsageError{ "--preset: unknown preset '" + v + "', expected one of " + names };
    }
    bloom->SetPreset(v.c_str());
  }
  if (args.Take("--threshold", v))
  {
    // Above FLT_MAX no float pixel can pass; below 0 every pixel would, black ones included.
    bloom->SetThreshold(ParseDoubleIn("--threshold", v, 0.0, FLT_MAX));
  }
  if (args.Take("--knee", v))
  {
    const double knee = ParseDouble("--knee", v);
    if (knee < 0.0 || knee > 1.0)
    {
      throw UsageError{ "--knee must be in [0, 1]" };
    }
    bloom->SetKnee(knee);
  }
  if (args.Take("--mode", v))
  {
    bloom->SetThresholdMode(ParseChoice("--mode", v,
      { { "smoothstep", vtkImageBloomThreshold::SMOOTHSTEP_KNEE },
        { "quadratic", vtkImageBloomThreshold::QUADRATIC_KNEE },
        { "hard", vtkImageBloomThreshold::HARD_LUMINANCE },
        { "per-channel", vtkImageBloomThreshold::PER_CHANNEL },
        { "none", vtkImageBloomThreshold::NONE } }));
  }
  if (args.Take("--clamp-luminance", v))
  {
    const double clamp = ParseDouble("--clamp-luminance", v);
    if (clamp < 0.0)
    {
      throw UsageError{ "--clamp-luminance must be >= 0" };
    }
    bloom->SetClampLuminance(clamp);
  }
  if (args.Take("--strength", v))
  {
    // A negative strength subtracts light; far above 1000 the sum overflows float.
    bloom->SetStrength(ParseDoubleIn("--strength", v, 0.0, 1000.0));
  }
  if (args.Take("--composite", v))
  {
    bloom->SetCompositeMode(ParseChoice("--composite", v,
      { { "additive", vtkImageBloom::ADDITIVE }, { "lerp", vtkImageBloom::LERP } }));
  }
  if (args.Take("--tint", v))
  {
    const auto tint = ParseList("--tint", v);
    if (tint.size() != 3)
    {
      throw UsageError{ "--tint expects R,G,B" };
    }
    bloom->SetTint(tint[0], tint[1], tint[2]);
  }
  if (args.Take("--levels", v))
  {
    bloom->SetNumberOfLevels(ParseInt("--levels", v, 1, 32));
  }
  if (args.Take("--start-level", v))
  {
    bloom->SetStartLevel(ParseInt("--start-level", v, 0, 16));
  }
  if (args.Take("--down", v))
  {
    bloom->SetDownsampleKernel(ParseChoice("--down", v,
      { { "jimenez13", vtkImagePyramidDown::JIMENEZ13 }, { "box", vtkImagePyramidDown::BOX },
        { "binomial", vtkImagePyramidDown::BINOMIAL } }));
  }
  if (args.Take("--karis", v))
  {
    bloom->KarisAverageOn();
  }
  if (args.Take("--up", v))
  {
    bloom->SetUpsampleKernel(ParseChoice("--up", v,
      { { "tent", vtkImagePyramidUp::TENT }, { "bilinear", vtkImagePyramidUp::BILINEAR } }));
  }
  if (args.Take("--accumulate", v))
  {
    bloom->SetAccumulateMode(ParseChoice("--accumulate", v,
      { { "cascade", vtkImageBloom::CASCADE }, { "direct", vtkImageBloom::DIRECT } }));
  }
  if (args.Take("--blur-sigma", v))
  {
    const double sigma = ParseDouble("--blur-sigma", v);
    if (sigma < 0.0)
    {
      throw UsageError{ "--blur-sigma must be >= 0" };
    }
    bloom->SetBlurKernel(vtkImageBloom::BLUR_GAUSSIAN);
    bloom->SetBlurStandardDeviation(sigma);
    bloom->SetBlurRadius(-1);
  }
  if (args.Take("--blur-radius", v))
  {
    bloom->SetBlurKernel(vtkImageBloom::BLUR_GAUSSIAN);
    bloom->SetBlurRadius(ParseInt("--blur-radius", v, 0, 4096));
  }
  if (args.Take("--blur-spacing", v))
  {
    const double spacing = ParseDouble("--blur-spacing", v);
    if (spacing < 0.0)
    {
      throw UsageError{ "--blur-spacing must be >= 0" };
    }
    bloom->SetBlurTapSpacing(spacing);
  }
  if (args.Take("--blur-iterations", v))
  {
    bloom->SetBlurIterations(ParseInt("--blur-iterations", v, 0, 1024));
  }
  if (args.Take("--level-weights", v))
  {
    bloom->SetLevelWeights(ParseList("--level-weights", v));
  }
  if (args.Take("--convolution", v))
  {
    bloom->SetConvolutionMode(ParseChoice("--convolution", v,
      { { "auto", vtkImageBloom::CONVOLUTION_AUTOMATIC },
        { "direct", vtkImageBloom::CONVOLUTION_DIRECT },
        { "fft", vtkImageBloom::CONVOLUTION_FFT } }));
  }
  ApplyPSFOptions(args, bloom);
}

}
