// vtk-bloom: HDR bloom and Gaussian blur of OpenEXR images from the command line.
//
//   vtk-bloom image [--preset NAME] [options] IN.exr OUT.exr|OUT.png
//   vtk-bloom blur --radius R [--sigma S] [--border clamp|reflect|zero] IN.exr OUT.exr|OUT.png
//
// .exr output is float32 RGBA, linear, with no tone mapping. .png output is tone-mapped
// (exposure, ACES filmic fit, sRGB encoding) to opaque 8-bit RGB. Exit status: 0 on success, 1 when
// reading, processing or writing fails, 2 for a usage error. An input is never overwritten.

#include "vtkBloomKernels.h"
#include "vtkImageBloom.h"
#include "vtkImageBloomThreshold.h"
#include "vtkImagePyramidDown.h"
#include "vtkImagePyramidUp.h"
#include "vtkImageSeparableGaussian.h"
#include "vtkOpenEXRReader.h"
#include "vtkOpenEXRWriter.h"

#include <vtkAlgorithm.h>
#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkImageAlgorithm.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <system_error>
#include <unistd.h>
#include <vector>

#ifdef VTKBLOOM_HAS_RENDERING
#include "vtkBloomExampleScenes.h"
#include "vtkBloomPass.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#endif

namespace fs = std::filesystem;

namespace
{
const char* const Usage = R"(usage:
  vtk-bloom image [--preset NAME] [options] IN.exr OUT.exr|OUT.png
  vtk-bloom blur --radius R [--sigma S] [--border clamp|reflect|zero] IN.exr OUT.exr|OUT.png
  vtk-bloom render [--size WxH] [--precision 16|32] [--no-bloom] [options] SCENE OUT.exr|OUT.png
  vtk-bloom render --list
  vtk-bloom --help

image: HDR bloom (vtkImageBloom). A preset is applied first; options then override it.
  --preset NAME          webgpu-market | mip-atlas | ping-pong | crt-halfres
  --threshold T          bright-pass threshold
  --knee K               soft knee relative to the threshold, 0..1
  --mode M               smoothstep | quadratic | hard | per-channel | none
  --clamp-luminance L    firefly guard: largest luminance let through
  --strength S           bloom strength (additive) or blend factor (lerp)
  --composite C          additive | lerp
  --tint R,G,B           bloom colour
  --levels N             number of pyramid levels (1..32)
  --start-level L        resolution of the bright pass: 0 full, 1 half, ...
  --down K               jimenez13 | box | binomial
  --karis                Karis average on the first downsample
  --up K                 tent | bilinear
  --accumulate A         cascade | direct
  --blur-sigma S         Gaussian blur per level, in level pixels
  --blur-radius R        taps each side of the per-level Gaussian
  --blur-spacing D       distance between blur taps, in level pixels
  --blur-iterations N    repeat the per-level blur N times
  --level-weights W,...  per-level weights, first level first

blur: separable Gaussian (vtkImageSeparableGaussian), seed 004 semantics.
  --radius R             integer taps each side, 0..32 (0 is an exact copy)
  --sigma S              standard deviation in pixels (default R/2; 0 is an exact copy)
  --border B             clamp (default) | reflect | zero
  --kernel K             sampled (default) | integrated | discrete

render: render an example emissive scene headless with the GPU pass (vtkBloomPass).
  --list                 print the scene names, one per line
  --size WxH             image size in pixels (default 960x540)
  --precision P          16 (default) or 32: float precision of the scene render target
  --no-bloom             write the float render without bloom (the "before" image)
  The scene chooses its bloom parameters; the image options above override them.

common:
  --exposure E           exposure multiplier for .png output (default 1)
                         (.png is opaque RGB: premultiplied colour shown over black)
  --quiet                no progress display
  --help                 this text

.exr output is float32 RGBA with no tone mapping; .png output is tone-mapped to 8-bit.
Exit status: 0 success, 1 failure, 2 usage error. An input file is never overwritten.
)";

// A usage error: message printed with the usage hint, exit status 2.
struct UsageError
{
  std::string Message;
};

// A processing error: message printed, exit status 1.
struct RunError
{
  std::string Message;
};

std::string Lower(std::string s)
{
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

std::string Extension(const std::string& path)
{
  return Lower(fs::path(path).extension().string());
}

double ParseDouble(const std::string& option, const std::string& text)
{
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || errno == ERANGE || !std::isfinite(value))
  {
    throw UsageError{ option + " expects a finite number, got '" + text + "'" };
  }
  return value;
}

int ParseInt(const std::string& option, const std::string& text, int lo, int hi)
{
  char* end = nullptr;
  errno = 0;
  const long value = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || errno == ERANGE || value < lo || value > hi)
  {
    throw UsageError{ option + " expects an integer in [" + std::to_string(lo) + ", " +
      std::to_string(hi) + "], got '" + text + "'" };
  }
  return static_cast<int>(value);
}

std::vector<double> ParseList(const std::string& option, const std::string& text)
{
  std::vector<double> values;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ','))
  {
    values.push_back(ParseDouble(option, item));
  }
  if (values.empty())
  {
    throw UsageError{ option + " expects a comma-separated list of numbers" };
  }
  return values;
}

int ParseChoice(
  const std::string& option, const std::string& text, const std::map<std::string, int>& choices)
{
  const auto it = choices.find(Lower(text));
  if (it == choices.end())
  {
    std::string valid;
    for (const auto& choice : choices)
    {
      valid += (valid.empty() ? "" : " | ") + choice.first;
    }
    throw UsageError{ option + " expects one of " + valid + ", got '" + text + "'" };
  }
  return it->second;
}

// Command-line arguments: options with values, flags, and positional arguments.
class Arguments
{
public:
  Arguments(int argc, char* argv[], int first, const std::vector<std::string>& flags)
  {
    for (int i = first; i < argc; ++i)
    {
      const std::string arg = argv[i];
      if (arg.size() > 2 && arg.compare(0, 2, "--") == 0)
      {
        if (std::find(flags.begin(), flags.end(), arg) != flags.end())
        {
          this->Options[arg] = "";
          continue;
        }
        if (i + 1 >= argc)
        {
          throw UsageError{ arg + " needs a value" };
        }
        this->Options[arg] = argv[++i];
      }
      else
      {
        this->Positional.push_back(arg);
      }
    }
  }

  // Visit a known option; everything not visited is reported as unknown.
  bool Take(const std::string& name, std::string& value)
  {
    const auto it = this->Options.find(name);
    if (it == this->Options.end())
    {
      return false;
    }
    value = it->second;
    this->Options.erase(it);
    return true;
  }

  void CheckAllTaken() const
  {
    if (!this->Options.empty())
    {
      throw UsageError{ "unknown option " + this->Options.begin()->first };
    }
  }

  std::map<std::string, std::string> Options;
  std::vector<std::string> Positional;
};

// Errors from VTK objects are collected here instead of going to the output window.
struct ErrorCollector
{
  std::vector<std::string> Messages;

  static void OnError(vtkObject*, unsigned long, void* clientData, void* callData)
  {
    auto* self = static_cast<ErrorCollector*>(clientData);
    std::string text = callData ? static_cast<const char*>(callData) : "unknown error";
    // Keep the message and drop VTK's "ERROR: In file, line N / Class (0x...): " prefix.
    const auto pos = text.find("): ");
    if (pos != std::string::npos)
    {
      text = text.substr(pos + 3);
    }
    while (!text.empty() && (text.back() == '\n' || text.back() == ' '))
    {
      text.pop_back();
    }
    self->Messages.push_back(text);
  }

  void Watch(vtkObject* object)
  {
    vtkNew<vtkCallbackCommand> command;
    command->SetCallback(&ErrorCollector::OnError);
    command->SetClientData(this);
    object->AddObserver(vtkCommand::ErrorEvent, command);
  }

  void ThrowIfAny(const std::string& context)
  {
    if (!this->Messages.empty())
    {
      std::string all = context;
      for (const auto& m : this->Messages)
      {
        all += "\n  " + m;
      }
      this->Messages.clear();
      throw RunError{ all };
    }
  }
};

// A progress bar on stderr, shown only when stderr is a terminal.
struct ProgressBar
{
  bool Enabled = false;
  std::string Label;
  int LastPercent = -1;

  static void OnProgress(vtkObject*, unsigned long, void* clientData, void* callData)
  {
    auto* self = static_cast<ProgressBar*>(clientData);
    const double fraction = callData ? *static_cast<double*>(callData) : 0.0;
    self->Show(fraction);
  }

  void Watch(vtkAlgorithm* algorithm, const std::string& label)
  {
    if (!this->Enabled)
    {
      return;
    }
    vtkNew<vtkCallbackCommand> command;
    command->SetCallback(&ProgressBar::OnProgress);
    command->SetClientData(this);
    algorithm->AddObserver(vtkCommand::ProgressEvent, command);
    this->Label = label;
    this->LastPercent = -1;
  }

  void Show(double fraction)
  {
    const int percent =
      static_cast<int>(std::round(100.0 * std::min(std::max(fraction, 0.0), 1.0)));
    if (percent == this->LastPercent)
    {
      return;
    }
    this->LastPercent = percent;
    const int filled = percent * 30 / 100;
    std::fprintf(stderr, "\r%-8s [%s%s] %3d%%", this->Label.c_str(),
      std::string(filled, '#').c_str(), std::string(30 - filled, ' ').c_str(), percent);
    if (percent == 100)
    {
      std::fprintf(stderr, "\n");
    }
    std::fflush(stderr);
  }
};

struct CommonOptions
{
  double Exposure = 1.0;
  bool Quiet = false;
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
}

// Refuse anything that would overwrite the input or write a format we do not know.
void CheckPaths(const std::string& in, const std::string& out)
{
  const std::string ext = Extension(out);
  if (ext != ".exr" && ext != ".png")
  {
    throw UsageError{ "output must end in .exr or .png: " + out };
  }
  std::error_code ec;
  if (!fs::exists(in, ec))
  {
    throw RunError{ "cannot read " + in + ": no such file" };
  }
  if (fs::exists(out, ec) && fs::equivalent(in, out, ec))
  {
    throw UsageError{ "refusing to overwrite the input " + in + " with the output" };
  }
  if (fs::is_directory(out, ec))
  {
    throw RunError{ "output " + out + " is a directory" };
  }
}

// The image and the display window it came with, which the EXR output keeps.
struct InputImage
{
  vtkSmartPointer<vtkImageData> Image;
  int DisplayWindow[4] = { 0, -1, 0, -1 };
};

InputImage ReadInput(const std::string& path, ErrorCollector& errors, ProgressBar& progress)
{
  vtkNew<vtkOpenEXRReader> reader;
  errors.Watch(reader);
  progress.Watch(reader, "read");
  reader->SetFileName(path.c_str());
  reader->Update();
  errors.ThrowIfAny("cannot read " + path + ":");
  vtkImageData* image = reader->GetOutput();
  if (!image || image->GetNumberOfPoints() == 0 || !image->GetPointData()->GetScalars())
  {
    throw RunError{ "cannot read " + path + ": no image data" };
  }
  InputImage result;
  result.Image = vtkSmartPointer<vtkImageData>::New();
  result.Image->ShallowCopy(image);
  reader->GetDisplayWindow(result.DisplayWindow);
  return result;
}

// Float RGBA copy of an image with 1-4 components (alpha 1 when absent).
vtkSmartPointer<vtkImageData> ToFloatRGBA(vtkImageData* image)
{
  const int nc = image->GetNumberOfScalarComponents();
  auto rgba = vtkSmartPointer<vtkImageData>::New();
  rgba->CopyStructure(image);
  rgba->AllocateScalars(VTK_FLOAT, 4);
  vtkDataArray* in = image->GetPointData()->GetScalars();
  float* out = static_cast<float*>(rgba->GetScalarPointer());
  const vtkIdType n = image->GetNumberOfPoints();
  for (vtkIdType p = 0; p < n; ++p, out += 4)
  {
    const double v0 = in->GetComponent(p, 0);
    out[0] = static_cast<float>(v0);
    out[1] = static_cast<float>(nc >= 3 ? in->GetComponent(p, 1) : v0);
    out[2] = static_cast<float>(nc >= 3 ? in->GetComponent(p, 2) : v0);
    out[3] = nc == 4 ? static_cast<float>(in->GetComponent(p, 3))
                     : (nc == 2 ? static_cast<float>(in->GetComponent(p, 1)) : 1.0f);
  }
  return rgba;
}

// Display encoding for PNG: exposure, the ACES filmic fit of Narkowicz (2015), sRGB OETF.
unsigned char ToneMap(double linear, double exposure)
{
  double x = std::isnan(linear) ? 0.0 : std::max(linear * exposure, 0.0);
  x = std::min(x, 1e6);
  double y = (x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14);
  y = std::min(std::max(y, 0.0), 1.0);
  const double s = y <= 0.0031308 ? 12.92 * y : 1.055 * std::pow(y, 1.0 / 2.4) - 0.055;
  return static_cast<unsigned char>(std::lround(255.0 * std::min(std::max(s, 0.0), 1.0)));
}

// Write bytes to a temporary file beside `path`, then rename it over `path`, so a failure
// never leaves a partial file and never clobbers an existing one.
void WriteFileAtomically(const std::string& path, const unsigned char* data, size_t size)
{
  const std::string temporary = path + ".tmp-" + std::to_string(::getpid());
  std::error_code ec;
  {
    std::ofstream file(temporary, std::ios::binary | std::ios::trunc);
    if (file)
    {
      file.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
      file.close();
    }
    if (!file)
    {
      fs::remove(temporary, ec);
      throw RunError{ "cannot write " + path + ": " + std::strerror(errno) };
    }
  }
  fs::rename(temporary, path, ec);
  if (ec)
  {
    fs::remove(temporary, ec);
    throw RunError{ "cannot write " + path + ": " + ec.message() };
  }
}

// Tone-map to 8-bit and write through WriteFileAtomically. The PNG is opaque RGB: OpenEXR
// colour is premultiplied by alpha, so showing it as is composites it over black, which keeps
// the glow that bloom spreads into transparent pixels.
void WritePNG(vtkImageData* rgba, const std::string& path, double exposure, ErrorCollector& errors)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  int ext[6];
  rgba->GetExtent(ext);
  const int w = ext[1] - ext[0] + 1, h = ext[3] - ext[2] + 1;
  image->SetDimensions(w, h, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  const float* in = static_cast<const float*>(rgba->GetScalarPointer());
  unsigned char* out = static_cast<unsigned char*>(image->GetScalarPointer());
  for (int j = 0; j < h; ++j)
  {
    // Row 0 is the top of the picture; VTK's PNG writer puts the last row on top.
    const float* src = in + static_cast<size_t>(j) * w * 4;
    unsigned char* dst = out + static_cast<size_t>(h - 1 - j) * w * 3;
    for (int i = 0; i < w; ++i)
    {
      for (int c = 0; c < 3; ++c)
      {
        dst[3 * i + c] = ToneMap(src[4 * i + c], exposure);
      }
    }
  }
  // Encode in memory: VTK 9.1's vtkPNGWriter leaks libpng state when it cannot open its file.
  vtkNew<vtkPNGWriter> writer;
  errors.Watch(writer);
  writer->WriteToMemoryOn();
  writer->SetInputData(image);
  writer->Write();
  vtkUnsignedCharArray* bytes = writer->GetResult();
  if (!errors.Messages.empty() || !bytes || bytes->GetNumberOfValues() == 0)
  {
    errors.Messages.push_back("PNG encoding failed");
    errors.ThrowIfAny("cannot write " + path + ":");
  }
  WriteFileAtomically(path, bytes->GetPointer(0), static_cast<size_t>(bytes->GetNumberOfValues()));
}

void WriteOutput(vtkImageData* image, const int displayWindow[4], const std::string& path,
  const CommonOptions& common, ErrorCollector& errors)
{
  auto rgba = ToFloatRGBA(image);
  if (Extension(path) == ".png")
  {
    WritePNG(rgba, path, common.Exposure, errors);
    return;
  }
  vtkNew<vtkOpenEXRWriter> writer;
  errors.Watch(writer);
  writer->SetFileName(path.c_str());
  writer->SetInputData(rgba);
  writer->SetPixelTypeToFloat();
  writer->SetDisplayWindow(const_cast<int*>(displayWindow));
  writer->Write();
  errors.ThrowIfAny("cannot write " + path + ":");
}

void ApplyImageOptions(Arguments& args, vtkImageBloom* bloom)
{
  std::string v;
  if (args.Take("--preset", v) && !bloom->SetPreset(v.c_str()))
  {
    throw UsageError{ "unknown preset '" + v +
      "'; expected webgpu-market, mip-atlas, ping-pong or crt-halfres" };
  }
  if (args.Take("--threshold", v))
  {
    bloom->SetThreshold(ParseDouble("--threshold", v));
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
    bloom->SetStrength(ParseDouble("--strength", v));
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
}

// The rest of every command: IN and OUT from the positional arguments, read, filter, write.
// With `rgba` the filter sees the image as float RGBA (alpha 1 when absent).
int RunFilter(const Arguments& args, const CommonOptions& common, vtkImageAlgorithm* filter,
  const std::string& command, bool rgba)
{
  args.CheckAllTaken();
  if (args.Positional.size() != 2)
  {
    throw UsageError{ command + " needs exactly two files, IN and OUT" };
  }
  const std::string in = args.Positional[0], out = args.Positional[1];
  CheckPaths(in, out);

  ErrorCollector errors;
  ProgressBar progress;
  progress.Enabled = !common.Quiet && ::isatty(STDERR_FILENO);
  const InputImage input = ReadInput(in, errors, progress);
  errors.Watch(filter);
  progress.Watch(filter, command);
  filter->SetInputData(rgba ? ToFloatRGBA(input.Image) : input.Image);
  filter->Update();
  errors.ThrowIfAny(command + " failed:");
  WriteOutput(vtkImageData::SafeDownCast(filter->GetOutputDataObject(0)), input.DisplayWindow, out,
    common, errors);
  return 0;
}

int RunImage(int argc, char* argv[])
{
  Arguments args(argc, argv, 2, { "--karis", "--quiet" });
  CommonOptions common;
  TakeCommon(args, common);
  vtkNew<vtkImageBloom> bloom;
  // Files are processed once: the exact double-precision chain, bit for bit PRESETS.md's.
  bloom->SetExecutionModeToReference();
  bloom->SetPreset("webgpu-market");
  ApplyImageOptions(args, bloom);
  return RunFilter(args, common, bloom, "image", false);
}

int RunBlur(int argc, char* argv[])
{
  Arguments args(argc, argv, 2, { "--quiet" });
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
  blur->SetStandardDeviations(sigma, sigma, 0.0);
  blur->SetRadius(radius, radius, 0);
  // Blur all four channels, alpha included, as seed 004 does.
  return RunFilter(args, common, blur, "blur", true);
}
}

int RunRender(int argc, char* argv[])
{
  Arguments args(argc, argv, 2, { "--list", "--no-bloom", "--karis", "--quiet" });
  std::string value;
  if (args.Take("--list", value))
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
  int size[2] = { 960, 540 };
  if (args.Take("--size", value))
  {
    const auto x = value.find('x');
    if (x == std::string::npos)
    {
      throw UsageError{ "--size expects WxH, got '" + value + "'" };
    }
    size[0] = ParseInt("--size", value.substr(0, x), 1, 8192);
    size[1] = ParseInt("--size", value.substr(x + 1), 1, 8192);
  }
  int precision = vtkBloomPass::FLOAT16;
  if (args.Take("--precision", value))
  {
    precision = ParseInt("--precision", value, 16, 32);
    if (precision != 16 && precision != 32)
    {
      throw UsageError{ "--precision expects 16 or 32, got '" + value + "'" };
    }
  }
  const bool bloom = !args.Take("--no-bloom", value);
  if (args.Positional.size() != 2)
  {
    throw UsageError{ "render needs a scene name and an output file (see render --list)" };
  }
  const std::string scene = args.Positional[0], out = args.Positional[1];
  const auto names = vtkBloomExampleSceneNames();
  if (std::find(names.begin(), names.end(), scene) == names.end())
  {
    throw UsageError{ "unknown scene '" + scene + "' (see render --list)" };
  }
  const std::string ext = Extension(out);
  if (ext != ".exr" && ext != ".png")
  {
    throw UsageError{ "output must be .exr or .png: " + out };
  }

  ErrorCollector errors;
  vtkNew<vtkRenderWindow> window;
  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkBloomPass> pass;
  vtkNew<vtkRenderStepsPass> steps;
  errors.Watch(window);
  errors.Watch(pass);
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(size[0], size[1]);
  window->AddRenderer(renderer);
  pass->SetDelegatePass(steps);
  renderer->SetPass(pass);
  vtkBloomBuildExampleScene(scene, renderer, pass);
  ApplyImageOptions(args, pass->GetParameters());
  args.CheckAllTaken();
  pass->SetFloatPrecision(precision);
  pass->CaptureResultOn();
  window->Render();
  vtkNew<vtkImageData> image;
  if (bloom)
  {
    pass->ReadResultImage(image);
  }
  else
  {
    pass->ReadSceneImage(image);
  }
  window->ReleaseGraphicsResources(window);
  errors.ThrowIfAny("render " + scene + " failed:");
  const int displayWindow[4] = { 0, 0, size[0] - 1, size[1] - 1 };
  WriteOutput(image, displayWindow, out, common, errors);
  if (!common.Quiet)
  {
    std::cerr << "vtk-bloom: rendered " << scene << " (" << size[0] << "x" << size[1] << ", "
              << pass->GetNumberOfPasses() << " GPU passes) to " << out << "\n";
  }
  return 0;
#endif
}

int main(int argc, char* argv[])
{
  const std::string command = argc > 1 ? argv[1] : "";
  if (command == "--help" || command == "-h" || command == "help")
  {
    std::cout << Usage;
    return 0;
  }
  for (int i = 2; i < argc; ++i)
  {
    if (std::strcmp(argv[i], "--help") == 0 || std::strcmp(argv[i], "-h") == 0)
    {
      std::cout << Usage;
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
    if (command == "render")
    {
      return RunRender(argc, argv);
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
