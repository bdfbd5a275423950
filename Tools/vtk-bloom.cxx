// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// vtk-bloom: HDR bloom and Gaussian blur of OpenEXR images from the command line.
//
//   vtk-bloom image [--preset NAME] [options] IN.exr OUT.exr|OUT.png
//   vtk-bloom image [options] IN.exr... -o OUTDIR     (batch: one output per input)
//   vtk-bloom blur --radius R [--sigma S] [--border clamp|reflect|zero] IN.exr OUT.exr|OUT.png
//   vtk-bloom render [options] SCENE OUT.exr|OUT.png
//
// .exr output is float32 RGBA, linear, with no tone mapping. .png output is tone-mapped
// (exposure, ACES filmic fit, sRGB encoding) to opaque 8-bit RGB. Exit status: 0 on success, 1 when
// reading, processing or writing fails (in batch mode: when any file failed), 2 for a usage
// error. An input is never overwritten, and a batch never overwrites any existing file.
//
// The pieces: vtkBloomToolSupport (errors, arguments, progress), vtkBloomToolImageIO (read and
// write), vtkBloomToolOptions (the bloom options), vtkBloomToolBatch (planning a batch, per-file
// reports, --stats JSON), and this file (the commands).

#include "vtkBloomKernels.h"
#include "vtkBloomToolBatch.h"
#include "vtkBloomToolImageIO.h"
#include "vtkBloomToolOptions.h"
#include "vtkBloomToolSupport.h"
#include "vtkImageBloom.h"
#include "vtkImageBloomThreshold.h"
#include "vtkImagePyramidDown.h"
#include "vtkImagePyramidUp.h"
#include "vtkImageSeparableGaussian.h"

#include <vtkAlgorithm.h>
#include <vtkImageAlgorithm.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkVersion.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <map>
#include <string>
#include <unistd.h>
#include <utility>
#include <vector>

#ifdef VTKBLOOM_HAS_RENDERING
#include "vtkBloomExampleScenes.h"
#include "vtkBloomPass.h"
#include "vtkBloomToolRender.h"
#endif

namespace fs = std::filesystem;
using namespace vtkBloomTool;

namespace
{
const char* const Usage = R"(usage:
  vtk-bloom image [--preset NAME] [options] IN.exr OUT.exr|OUT.png
  vtk-bloom image [options] IN.exr... -o OUTDIR
  vtk-bloom blur --radius R [--sigma S] [--border clamp|reflect|zero] IN.exr OUT.exr|OUT.png
  vtk-bloom blur --radius R [options] IN.exr... -o OUTDIR
  vtk-bloom render [options] SCENE|FILE OUT.exr|OUT.png
  vtk-bloom render --list
  vtk-bloom view [options] SCENE|FILE
  vtk-bloom --help | --version

image: HDR bloom (vtkImageBloom). A preset is applied first; options then override it.
  --preset NAME          @PRESETS@ (default @DEFAULT_PRESET@)
  --exact                the double-precision REFERENCE chain, bit for bit PRESETS.md's
                         (default: the fused float32 FAST chain, within 1e-5 relative L2 of it)
  --threshold T          bright-pass threshold, >= 0
  --knee K               soft knee relative to the threshold, 0..1
  --mode M               excess | smoothstep | quadratic | hard | per-channel | none
                         (excess: only what exceeds the threshold glows, by its excess)
  --clamp-luminance L    firefly guard: largest luminance let through
  --strength S           bloom strength (additive) or blend factor (lerp), 0..1000
  --composite C          additive | lerp
  --tint R,G,B           bloom colour
  --levels N             number of pyramid levels (1..32)
  --start-level L        resolution of the bright pass: 0 full, 1 half, ...
  --reference-height H   sizes meant for a frame H pixels tall, scaled to the image's
                         (0: sizes in pixels, as a named preset's; default 1080, 540 for scenes)
  --down K               jimenez13 | box | binomial
  --karis                Karis average on the first downsample
  --up K                 tent | bilinear
  --accumulate A         cascade | direct
  --blur-sigma S         Gaussian blur per level, in level pixels
  --blur-radius R        taps each side of the per-level Gaussian
  --blur-spacing D       distance between blur taps, in level pixels
  --blur-iterations N    repeat the per-level blur N times
  --level-weights W,...  per-level weights, first level first
  --convolution C        auto (default) | direct | fft: how wide level blurs are applied
  --psf P                PSF bloom instead of the pyramid: airy | gaussians | FILE.exr (an odd,
                         square, centred PSF image; one channel, or one per colour)
  --psf-radius R         truncation radius in pixels (default: automatic)
  --airy-radius PX       airy: first dark ring radius at the green wavelength (default 3)
  --wavelengths R,G,B    airy: channel wavelengths in nm (default 610,550,465)
  --psf-gaussians S:W,.. gaussians: sigma:weight pairs (default 1.5:0.6,6:0.3,24:0.1)
  --psf-border B         reflect (default: conserves energy) | zero
  --psf-tail-scale F     1 (default: exact) | 2 | 4 | 8: the PSF's tail convolved on a grid F
                         times coarser, its core (within --psf-core-radius) at full resolution
  --psf-core-radius R    the split's core radius in pixels (default: 16)
  A frame with nothing above the threshold is written unchanged, without bloom work.

blur: separable Gaussian (vtkImageSeparableGaussian), seed 004 semantics.
  --radius R             integer taps each side, 0..32 (0 is an exact copy)
  --sigma S              standard deviation in pixels (default R/2; 0 is an exact copy)
  --border B             clamp (default) | reflect | zero
  --kernel K             sampled (default) | integrated | discrete
  --convolution C        auto (default) | direct | fft

batch (image and blur): many inputs, one output directory.
  -o OUTDIR              write OUTDIR/NAME.exr (or .png) for each input IN/NAME.exr; OUTDIR is
                         created when missing. An output that exists is never overwritten: that
                         file fails and the others go on. Exit status 1 when any file failed.
  --format F             exr (default) | png: the outputs' format in batch mode
  --stats FILE.json      write each file's outcome and bloom statistics (energy in and out,
                         bright pixels, peak luminance, levels, whether the bloom was skipped)

render: render an example scene or your dataset headless with the GPU pass (vtkBloomPass).
  SCENE is an example scene (--list). FILE is a dataset read by VTK's readers: .vti .vtu
  .vtp .vts .vtr .vtm .vtk, a .pvd time series, or a numbered pattern (step_%04d.vtu); a
  series writes one frame per step (OUT_0000.png, ..., or a %d pattern in OUT).
  --list                 print the scene names, one per line
  --size WxH             image size in pixels (default 960x540)
  --precision P          16 (default) or 32: float precision of the scene render target
  --no-bloom             write the float render without bloom (the "before" image)
  --color-by NAME[:C]    point or cell array to colour by (component C; default magnitude)
  --range LO:HI          colour range (default: the array's range in the first step)
  --colormap M           viridis (default) | inferno | coolwarm | grayscale
  --representation R     surface (default) | points | wireframe | volume (image data)
  --contour V1,V2,...    draw iso-contours of the coloured array
  --emit-range LO:HI     only the data in this range of the coloured array glows
  --emit-gain G          with --emit-range, the emitted light x G; without, the whole
                         scene's colours x G, so that what then exceeds 1 glows (default 1)
  --view V               iso (default) | +x | -x | +y | -y | +z | -z: the camera looks along V
  --azimuth A, --elevation E, --zoom Z    turn and zoom the camera after --view
  --background R,G,B     background colour (default 0.02,0.02,0.03)
  Scenes choose their bloom parameters; datasets start from vtkBloomParameters' defaults
  (only light above 1 glows, and what --emit-range marks, whatever its colour); the image
  options above override them. The background and the annotations never glow.

view: the same in an interactive X window: sliders for threshold, strength and levels; keys
  b bloom on/off, p next preset, s PNG screenshot, e EXR of the float frame, h help, q quit.
  --snapshot PREFIX      where s and e save (default vtk-bloom-view-NNN.png|exr)

common:
  --exposure E           exposure multiplier for .png output (default 1)
                         (.png is opaque RGB: premultiplied colour shown over black)
  --max-pixels N         refuse inputs larger than N pixels (default 268435456, 16384 x 16384;
                         suffixes K, M, G), before anything is allocated
  --quiet                no progress display
  --help                 this text

.exr output is float32 RGBA with no tone mapping; .png output is tone-mapped to 8-bit.
Exit status: 0 success, 1 failure, 2 usage error. An input file is never overwritten.
)";

// The options each command knows (CLI11 refuses any other); their values are parsed by the
// command (BloomOptions, TakeCommon, TakeRenderOptions).
const std::vector<std::string> CommonOptionNames = { "--exposure", "--max-pixels", "-o", "--format",
  "--stats" };
const std::vector<std::string> BlurOptionNames = { "--radius", "--sigma", "--border", "--kernel",
  "--convolution" };
const std::vector<std::string> RenderOptionNames = { "--size", "--precision", "--color-by",
  "--range", "--emit-range", "--contour", "--background", "--colormap", "--representation",
  "--view", "--emit-gain", "--azimuth", "--elevation", "--zoom", "--snapshot", "--play-events" };

std::vector<std::string> Join(std::initializer_list<std::vector<std::string>> lists)
{
  std::vector<std::string> all;
  for (const auto& list : lists)
  {
    all.insert(all.end(), list.begin(), list.end());
  }
  return all;
}

struct CommonOptions
{
  double Exposure = 1.0;
  bool Quiet = false;
  vtkTypeUInt64 MaximumPixels = DefaultMaximumPixels;
  std::string OutputDirectory; // batch mode when not empty
  std::string Format = ".exr";
  bool FormatGiven = false;
  std::string StatisticsFile;
};

void TakeCommon(Arguments& args, CommonOptions& common)
{
  std::string value;
  if (args.Take("--exposure", value))
  {
    common.Exposure = ParseDouble("--exposure", value);
    if (!(common.Exposure > 0.0))
    {
      throw UsageError{ "--exposure must be > 0" };
    }
  }
  common.Quiet = args.Take("--quiet", value);
  if (args.Take("--max-pixels", value))
  {
    common.MaximumPixels = ParseCount("--max-pixels", value);
  }
  if (args.Take("-o", value))
  {
    if (value.empty())
    {
      throw UsageError{ "-o expects an output directory" };
    }
    common.OutputDirectory = value;
  }
  if (args.Take("--format", value))
  {
    common.Format = "." +
      std::string(ParseChoice("--format", value, { { "exr", 0 }, { "png", 1 } }) ? "png" : "exr");
    common.FormatGiven = true;
  }
  if (args.Take("--stats", value))
  {
    if (Extension(value) != ".json")
    {
      throw UsageError{ "--stats expects a file name ending in .json, got '" + value + "'" };
    }
    common.StatisticsFile = value;
  }
}

// One file: read, filter, write, and the report. Throws RunError.
FileReport ProcessFile(const FileJob& job, const CommonOptions& common, vtkImageAlgorithm* filter,
  vtkImageBloom* bloom, bool rgba, ErrorCollector& errors, ProgressBar& progress, double start,
  double end)
{
  FileReport report;
  report.Input = job.Input;
  report.Output = job.Output;
  const auto begin = std::chrono::steady_clock::now();
  auto at = [start, end](double f) { return start + (end - start) * f; };

  progress.Begin("read", at(0.0), at(0.4));
  const InputImage input = ReadInput(job.Input, common.MaximumPixels, errors, progress);
  int dimensions[3];
  input.Image->GetDimensions(dimensions);

  progress.Begin(bloom ? "bloom" : "blur", at(0.4), at(0.6));
  // The filter reads the input in place when it is already what it needs (no copy).
  filter->SetInputData(rgba ? AsFloatRGBA(input.Image) : input.Image);
  filter->Update();
  errors.ThrowIfAny(
    (bloom ? std::string("bloom") : std::string("blur")) + " of " + job.Input + " failed:");
  vtkImageData* output = vtkImageData::SafeDownCast(filter->GetOutputDataObject(0));

  progress.Begin("write", at(0.6), at(1.0));
  WriteOutput(output, input.DisplayWindow, job.Output, common.Exposure, errors, progress);

  report.Succeeded = true;
  report.Width = dimensions[0];
  report.Height = dimensions[1];
  if (bloom)
  {
    report.Exact = bloom->GetExecutionMode() == vtkImageBloom::REFERENCE;
    report.BloomSkipped = bloom->GetLastBloomSkipped();
    report.HasBloomStatistics = bloom->GetComputeStatistics();
    report.EnergyIn = bloom->GetEnergyIn();
    report.EnergyOut = bloom->GetEnergyOut();
    report.NumberOfBrightPixels = bloom->GetNumberOfBrightPixels();
    report.PeakLuminanceIn = bloom->GetPeakLuminanceIn();
    report.PeakLuminanceOut = bloom->GetPeakLuminanceOut();
    report.NumberOfLevelsUsed = bloom->GetNumberOfLevelsUsed();
  }
  // Let go of this file's images before the next one is read.
  filter->SetInputData(nullptr);
  report.Seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  return report;
}

// The rest of every image command: the files from the positional arguments (IN OUT, or
// IN... -o OUTDIR), each read, filtered and written, and the --stats report.
int RunFiles(const Arguments& args, const CommonOptions& common, vtkImageAlgorithm* filter,
  vtkImageBloom* bloom, const std::string& command, bool rgba)
{
  args.CheckAllTaken();
  const bool batch = !common.OutputDirectory.empty();
  std::vector<FileJob> jobs;
  if (!batch)
  {
    if (common.FormatGiven)
    {
      throw UsageError{ "--format applies to batch mode (-o OUTDIR); the output's extension "
                        "chooses the format otherwise" };
    }
    if (args.Positional.size() != 2)
    {
      throw UsageError{ command + " needs exactly two files, IN and OUT (or IN... -o OUTDIR)" };
    }
    jobs.push_back(PlanSingle(args.Positional[0], args.Positional[1]));
  }
  else
  {
    if (args.Positional.empty())
    {
      throw UsageError{ command + " -o OUTDIR needs at least one input file" };
    }
    jobs = PlanBatch(args.Positional, common.OutputDirectory, common.Format);
  }
  if (!common.StatisticsFile.empty())
  {
    std::error_code ec;
    for (const FileJob& job : jobs)
    {
      if (fs::equivalent(job.Input, common.StatisticsFile, ec))
      {
        throw UsageError{ "refusing to overwrite the input " + job.Input + " with --stats" };
      }
    }
  }

  ProgressBar progress;
  progress.Enabled = !common.Quiet && ::isatty(STDERR_FILENO);
  ErrorCollector errors;
  errors.Watch(filter);
  progress.Watch(filter);
  std::vector<FileReport> reports;
  size_t failed = 0;
  const double count = static_cast<double>(jobs.size());
  for (size_t i = 0; i < jobs.size(); ++i)
  {
    const FileJob& job = jobs[i];
    try
    {
      if (!job.Problem.empty())
      {
        throw RunError{ job.Problem };
      }
      reports.push_back(ProcessFile(
        job, common, filter, bloom, rgba, errors, progress, i / count, (i + 1) / count));
    }
    catch (const RunError& e)
    {
      errors.Messages.clear();
      if (!batch && common.StatisticsFile.empty())
      {
        throw;
      }
      ++failed;
      FileReport report;
      report.Input = job.Input;
      report.Output = job.Output;
      report.Error = e.Message;
      reports.push_back(report);
      progress.Break();
      std::cerr << "vtk-bloom: error: " << e.Message << "\n";
    }
  }
  progress.Finish();
  if (!common.StatisticsFile.empty())
  {
    WriteStatistics(common.StatisticsFile, command, reports);
  }
  if (batch && !common.Quiet)
  {
    std::cerr << "vtk-bloom: " << command << ": " << (jobs.size() - failed) << " of " << jobs.size()
              << " file(s) written to " << common.OutputDirectory;
    std::cerr << (failed ? ", " + std::to_string(failed) + " failed\n" : "\n");
  }
  return failed ? 1 : 0;
}

int RunImage(int argc, char* argv[])
{
  Arguments args(argc, argv, 2, { "--karis", "--quiet", "--exact" },
    Join({ CommonOptionNames, BloomOptionNames }));
  CommonOptions common;
  TakeCommon(args, common);
  std::string value;
  vtkNew<vtkImageBloom> bloom;
  // FAST (the fused float32 chain) unless --exact asks for the double-precision REFERENCE
  // chain, which reproduces PRESETS.md bit for bit. Both skip the bloom work of a frame with
  // nothing above the threshold (SkipEmptyBloom), and FAST then writes the input unchanged.
  if (args.Take("--exact", value))
  {
    bloom->SetExecutionModeToReference();
  }
  // Statistics cost about twice the chain; measure them only when they are reported.
  bloom->SetComputeStatistics(!common.StatisticsFile.empty());
  bloom->SetPreset(vtkBloomParameters::GetDefaultPresetName().c_str());
  BloomOptions(args).Apply(bloom->GetParameters());
  return RunFiles(args, common, bloom, bloom, "image", false);
}

int RunBlur(int argc, char* argv[])
{
  Arguments args(argc, argv, 2, { "--quiet" }, Join({ CommonOptionNames, BlurOptionNames }));
  CommonOptions common;
  TakeCommon(args, common);
  std::string v;
  if (!args.Take("--radius", v))
  {
    throw UsageError{ "blur needs --radius R (an integer in [0, 32])" };
  }
  const int radius = ParseInt("--radius", v, 0, 32);
  double sigma = radius / 2.0;
  if (args.Take("--sigma", v))
  {
    sigma = ParseDouble("--sigma", v);
    if (sigma < 0.0)
    {
      throw UsageError{ "--sigma must be >= 0" };
    }
  }
  vtkNew<vtkImageSeparableGaussian> blur;
  if (args.Take("--border", v))
  {
    blur->SetBorderMode(ParseChoice("--border", v,
      { { "clamp", vtkImageSeparableGaussian::CLAMP },
        { "reflect", vtkImageSeparableGaussian::REFLECT },
        { "zero", vtkImageSeparableGaussian::ZERO } }));
  }
  if (args.Take("--kernel", v))
  {
    blur->SetKernelType(ParseChoice("--kernel", v,
      { { "sampled", vtkImageSeparableGaussian::SAMPLED },
        { "integrated", vtkImageSeparableGaussian::INTEGRATED },
        { "discrete", vtkImageSeparableGaussian::DISCRETE } }));
  }
  if (args.Take("--convolution", v))
  {
    blur->SetConvolutionMode(ParseChoice("--convolution", v,
      { { "auto", vtkImageSeparableGaussian::CONVOLUTION_AUTOMATIC },
        { "direct", vtkImageSeparableGaussian::CONVOLUTION_DIRECT },
        { "fft", vtkImageSeparableGaussian::CONVOLUTION_FFT } }));
  }
  blur->SetStandardDeviations(sigma, sigma, 0.0);
  blur->SetRadius(radius, radius, 0);
  // Blur all four channels, alpha included, as seed 004 does.
  return RunFiles(args, common, blur, nullptr, "blur", true);
}
}

namespace
{
#ifdef VTKBLOOM_HAS_RENDERING
// The options of render and view: size, precision, the data scene's, and the bloom's.
RenderOptions TakeRenderOptions(Arguments& args, const CommonOptions& common)
{
  if (!common.OutputDirectory.empty() || common.FormatGiven || !common.StatisticsFile.empty())
  {
    throw UsageError{ "-o, --format and --stats apply to image and blur, not render or view" };
  }
  RenderOptions options;
  options.Exposure = common.Exposure;
  options.Quiet = common.Quiet;
  std::string value;
  if (args.Take("--size", value))
  {
    const auto x = value.find('x');
    if (x == std::string::npos)
    {
      throw UsageError{ "--size expects WxH, got '" + value + "'" };
    }
    options.Size[0] = ParseInt("--size", value.substr(0, x), 1, 8192);
    options.Size[1] = ParseInt("--size", value.substr(x + 1), 1, 8192);
  }
  if (args.Take("--precision", value))
  {
    options.Precision = ParseInt("--precision", value, 16, 32);
    if (options.Precision != 16 && options.Precision != 32)
    {
      throw UsageError{ "--precision expects 16 or 32, got '" + value + "'" };
    }
  }
  options.Bloom = !args.Take("--no-bloom", value);
  DataSceneOptions& data = options.Data;
  for (const char* option :
    { "--color-by", "--range", "--emit-range", "--contour", "--background" })
  {
    if (args.Take(option, value))
    {
      ParseDataOption(option, value, data);
    }
  }
  if (args.Take("--colormap", value))
  {
    const int map = ParseChoice("--colormap", value,
      { { "viridis", 0 }, { "inferno", 1 }, { "coolwarm", 2 }, { "grayscale", 3 } });
    data.Colormap = std::vector<std::string>{ "viridis", "inferno", "coolwarm", "grayscale" }[map];
  }
  if (args.Take("--representation", value))
  {
    const int r = ParseChoice("--representation", value,
      { { "surface", 0 }, { "points", 1 }, { "wireframe", 2 }, { "volume", 3 } });
    data.Representation = std::vector<std::string>{ "surface", "points", "wireframe", "volume" }[r];
  }
  if (args.Take("--view", value))
  {
    const int v = ParseChoice("--view", value,
      { { "iso", 0 }, { "+x", 1 }, { "-x", 2 }, { "+y", 3 }, { "-y", 4 }, { "+z", 5 },
        { "-z", 6 } });
    data.View = std::vector<std::string>{ "iso", "+x", "-x", "+y", "-y", "+z", "-z" }[v];
  }
  if (args.Take("--emit-gain", value))
  {
    data.EmitGain = ParseDouble("--emit-gain", value);
    if (data.EmitGain < 0.0)
    {
      throw UsageError{ "--emit-gain must be >= 0" };
    }
  }
  if (args.Take("--azimuth", value))
  {
    data.Azimuth = ParseDouble("--azimuth", value);
  }
  if (args.Take("--elevation", value))
  {
    data.Elevation = ParseDouble("--elevation", value);
  }
  if (args.Take("--zoom", value))
  {
    data.Zoom = ParseDouble("--zoom", value);
    if (!(data.Zoom > 0.0))
    {
      throw UsageError{ "--zoom must be > 0" };
    }
  }
  if (args.Take("--snapshot", value))
  {
    options.SnapshotPrefix = value;
  }
  // The bloom options are parsed now (usage errors before any rendering) and applied to the
  // pass after the scene has set its own parameters.
  const BloomOptions bloom(args);
  // With --emit-range the emitters' light blooms as it is (no threshold) through a chain that
  // is linear in it, so the emitted light times G blooms to the glow times G: the strength.
  const double emissionGain = data.HasEmitRange && data.EmitGain >= 0.0 ? data.EmitGain : 1.0;
  options.ConfigureBloom = [bloom, emissionGain](vtkBloomPass* pass)
  {
    vtkBloomParameters* parameters = pass->GetParameters();
    bloom.Apply(parameters);
    parameters->SetStrength(parameters->GetStrength() * emissionGain);
  };
  return options;
}
#endif

int RunRender(int argc, char* argv[], bool interactive)
{
  Arguments args(argc, argv, 2, { "--list", "--no-bloom", "--karis", "--quiet" },
    Join({ CommonOptionNames, BloomOptionNames, RenderOptionNames }));
  std::string value;
  if (!interactive && args.Take("--list", value))
  {
    args.CheckAllTaken();
    if (!args.Positional.empty())
    {
      throw UsageError{ "render --list takes no other argument" };
    }
#ifdef VTKBLOOM_HAS_RENDERING
    for (const auto& name : vtkBloomExampleSceneNames())
    {
      std::cout << name << "\n";
    }
#endif
    return 0;
  }
#ifndef VTKBLOOM_HAS_RENDERING
  throw RunError{ "this vtk-bloom was built without the render pass (VTKBLOOM_ENABLE_RENDERING)" };
#else
  CommonOptions common;
  TakeCommon(args, common);
  std::string events;
  if (interactive)
  {
    args.Take("--play-events", events);
  }
  const RenderOptions options = TakeRenderOptions(args, common);
  args.CheckAllTaken();
  if (interactive)
  {
    if (args.Positional.size() != 1)
    {
      throw UsageError{ "view needs one dataset file or scene name" };
    }
#ifdef VTKBLOOM_HAS_INTERACTIVE
    return View(args.Positional[0], options, events);
#else
    throw RunError{ "this vtk-bloom renders headless only (its VTK has no X window or widgets); "
                    "use 'vtk-bloom render " +
      args.Positional[0] + " OUT.png'" };
#endif
  }
  if (args.Positional.size() != 2)
  {
    throw UsageError{ "render needs a scene name or dataset file and an output file (see render "
                      "--list)" };
  }
  const std::string input = args.Positional[0], out = args.Positional[1];
  return IsDatasetPath(input) ? RenderData(input, out, options) : RenderScene(input, out, options);
#endif
}
}

namespace
{
// Usage with the preset names and the default filled in from vtkBloomParameters.
std::string UsageText()
{
  std::string text = Usage;
  const std::pair<const char*, std::string> fields[] = {
    { "@PRESETS@", vtkBloomParameters::GetPresetNamesList() },
    { "@DEFAULT_PRESET@", vtkBloomParameters::GetDefaultPresetName() },
  };
  for (const auto& field : fields)
  {
    const size_t at = text.find(field.first);
    if (at != std::string::npos)
    {
      text.replace(at, std::strlen(field.first), field.second);
    }
  }
  return text;
}
}

int main(int argc, char* argv[])
{
  const std::string command = argc > 1 ? argv[1] : "";
  if (command == "--version")
  {
    std::cout << "vtk-bloom " << VTKBLOOM_VERSION << " (VTK " << vtkVersion::GetVTKVersion()
              << ")\n";
    return 0;
  }
  if (command == "--help" || command == "-h" || command == "help")
  {
    std::cout << UsageText();
    return 0;
  }
  for (int i = 2; i < argc; ++i)
  {
    if (std::strcmp(argv[i], "--help") == 0 || std::strcmp(argv[i], "-h") == 0)
    {
      std::cout << UsageText();
      return 0;
    }
  }
  try
  {
    if (command == "image")
    {
      return RunImage(argc, argv);
    }
    if (command == "blur")
    {
      return RunBlur(argc, argv);
    }
    if (command == "render" || command == "view")
    {
      return RunRender(argc, argv, command == "view");
    }
    throw UsageError{ command.empty() ? "no command given" : "unknown command '" + command + "'" };
  }
  catch (const UsageError& e)
  {
    std::cerr << "vtk-bloom: " << e.Message << "\nTry 'vtk-bloom --help'.\n";
    return 2;
  }
  catch (const RunError& e)
  {
    std::cerr << "vtk-bloom: error: " << e.Message << "\n";
    return 1;
  }
  catch (const std::exception& e)
  {
    std::cerr << "vtk-bloom: error: " << e.what() << "\n";
    return 1;
  }
}
