// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// End-to-end tests of `vtk-bloom`: the acceptance commands, exit codes, and that nothing is
// ever overwritten or left half-written.
#include "vtkBloomParameters.h"
#include "vtkBloomTestSupport.h"
#include "vtkBloomToolTestHelpers.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>

#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>
#include <vtkPointData.h>
#include <vtkRenderingOpenGLConfigure.h>
#include <vtkVersionMacros.h>

#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace vtkBloomToolTest;

// The calibration example in ../shared/data/presets: every preset and both blur settings.
class PresetExample : public ::testing::TestWithParam<std::pair<std::string, std::string>>
{
};

TEST_P(PresetExample, MatchesFloat64Reference)
{
  VTKBLOOM_REQUIRE_DATA(input, "presets/example_161x91.exr");
  const auto& [arguments, expectedName] = GetParam();
  VTKBLOOM_REQUIRE_DATA(expected, "presets/example_161x91__" + expectedName + ".exr");
  const std::string out = vtkBloomTest::OutputPath("cli-" + expectedName + ".exr");
  fs::remove(out);
  ASSERT_EQ(RunTool(arguments + " " + Quote(input) + " " + Quote(out)), 0);
  ASSERT_TRUE(IsFloatRGBA(out)) << ".exr output must be float32 RGBA";
  EXPECT_LE(RelativeL2(ReadEXR(out), ReadEXR(expected)), 1e-4);
}

INSTANTIATE_TEST_SUITE_P(CommandLine, PresetExample,
  ::testing::Values(std::make_pair("image --preset webgpu-market", "webgpu-market"),
    std::make_pair("image --preset mip-atlas", "mip-atlas"),
    std::make_pair("image --preset ping-pong", "ping-pong"),
    std::make_pair("image --preset crt-halfres", "crt-halfres"),
    std::make_pair("blur --radius 8", "blur_r8"),
    std::make_pair("blur --radius 3 --sigma 1", "blur_r3_s1")),
  [](const ::testing::TestParamInfo<PresetExample::ParamType>& info)
  {
    std::string name = info.param.second;
    std::replace(name.begin(), name.end(), '-', '_');
    return name;
  });

TEST(CommandLine, BlurRadiusZeroIsBitExactCopy)
{
  VTKBLOOM_REQUIRE_DATA(input, "presets/example_161x91.exr");
  const std::string out = vtkBloomTest::OutputPath("cli-r0.exr");
  ASSERT_EQ(RunTool("blur --radius 0 " + Quote(input) + " " + Quote(out)), 0);
  const Pixels a = ReadEXR(input), b = ReadEXR(out);
  ASSERT_EQ(a.Rgba.size(), b.Rgba.size());
  EXPECT_EQ(0, std::memcmp(a.Rgba.data(), b.Rgba.data(), a.Rgba.size() * sizeof(float)));
}

TEST(CommandLine, OptionsOverrideThePreset)
{
  VTKBLOOM_REQUIRE_DATA(input, "presets/example_161x91.exr");
  const std::string a = vtkBloomTest::OutputPath("cli-strength1.exr");
  const std::string b = vtkBloomTest::OutputPath("cli-strength0.exr");
  ASSERT_EQ(RunTool("image --preset webgpu-market " + Quote(input) + " " + Quote(a)), 0);
  ASSERT_EQ(
    RunTool("image --preset webgpu-market --strength 0 " + Quote(input) + " " + Quote(b)), 0);
  // Strength 0 leaves the input; strength 1 adds light.
  const Pixels in = ReadEXR(input), p1 = ReadEXR(a), p0 = ReadEXR(b);
  EXPECT_EQ(RelativeL2(p0, in), 0.0);
  EXPECT_GT(RelativeL2(p1, in), 1e-3);
}

// --mode excess: nothing at or below the threshold glows (the input is written unchanged when
// no channel exceeds it), and what exceeds it does.
TEST(CommandLine, ExcessModeBloomsOnlyWhatExceedsTheThreshold)
{
  VTKBLOOM_REQUIRE_DATA(input, "presets/example_161x91.exr");
  const Pixels in = ReadEXR(input);
  float brightest = 0.0f;
  for (size_t i = 0; i < in.Rgba.size(); ++i)
  {
    brightest = i % 4 == 3 ? brightest : std::max(brightest, in.Rgba[i]);
  }
  auto threshold = [](float t)
  {
    std::ostringstream os;
    os << std::setprecision(9) << t; // the float exactly
    return os.str();
  };
  const std::string above = vtkBloomTest::OutputPath("cli-excess-above.exr");
  const std::string below = vtkBloomTest::OutputPath("cli-excess-below.exr");
  ASSERT_EQ(RunTool("image --mode excess --threshold " + threshold(brightest) + " " + Quote(input) +
              " " + Quote(above)),
    0);
  ASSERT_EQ(RunTool("image --mode excess --threshold " + threshold(0.5f * brightest) + " " +
              Quote(input) + " " + Quote(below)),
    0);
  EXPECT_EQ(RelativeL2(ReadEXR(above), in), 0.0);
  EXPECT_GT(RelativeL2(ReadEXR(below), in), 1e-4);
}

// Sum of colour channel c of an image.
double ChannelSum(const Pixels& p, int c)
{
  double sum = 0.0;
  for (size_t i = c; i < p.Rgba.size(); i += 4)
  {
    sum += p.Rgba[i];
  }
  return sum;
}

TEST(CommandLine, PSFBloomConservesEnergy)
{
  VTKBLOOM_REQUIRE_DATA(input, "presets/example_161x91.exr");
  const Pixels in = ReadEXR(input);
  // With no threshold the bright pass is the image, so reflect borders make the output's sum
  // (1 + strength) times the input's, per channel, whatever the PSF.
  const std::string psfFile = vtkBloomTest::OutputPath("cli-psf-5x5.exr");
  {
    // An asymmetric measured PSF, written as float RGBA.
    std::vector<float> rgba(5 * 5 * 4);
    for (int i = 0; i < 25; ++i)
    {
      for (int c = 0; c < 3; ++c)
      {
        rgba[4 * i + c] = 0.1f + 0.05f * static_cast<float>((i * (c + 2)) % 7);
      }
      rgba[4 * i + 3] = 1.0f;
    }
    Imf::Header header(5, 5);
    Imf::FrameBuffer fb;
    const char* names[4] = { "R", "G", "B", "A" };
    for (int c = 0; c < 4; ++c)
    {
      header.channels().insert(names[c], Imf::Channel(Imf::FLOAT));
      fb.insert(
        names[c], Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(rgba.data() + c), 16, 16 * 5));
    }
    fs::remove(psfFile);
    Imf::OutputFile file(psfFile.c_str(), header);
    file.setFrameBuffer(fb);
    file.writePixels(5);
  }
  for (const std::string& psf : std::vector<std::string>{ "airy", "gaussians", Quote(psfFile) })
  {
    const std::string out = vtkBloomTest::OutputPath("cli-psf.exr");
    fs::remove(out);
    ASSERT_EQ(RunTool("image --psf " + psf + " --mode none --strength 0.5 " + Quote(input) + " " +
                Quote(out)),
      0)
      << psf;
    const Pixels bloomed = ReadEXR(out);
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_NEAR(ChannelSum(bloomed, c) / ChannelSum(in, c), 1.5, 1e-5) << psf << " " << c;
    }
    EXPECT_GT(RelativeL2(bloomed, in), 1e-3) << psf;
  }
  {
    // A split PSF: the tail on a grid 4 times coarser keeps the light to within its edges' share.
    const std::string out = vtkBloomTest::OutputPath("cli-psf-split.exr");
    fs::remove(out);
    ASSERT_EQ(RunTool("image --psf gaussians --psf-tail-scale 4 --psf-core-radius 6 --mode none "
                      "--strength 0.5 " +
                Quote(input) + " " + Quote(out)),
      0);
    const Pixels bloomed = ReadEXR(out);
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_NEAR(ChannelSum(bloomed, c) / ChannelSum(in, c), 1.5, 1e-2) << c;
    }
  }
  const std::string out = Quote(vtkBloomTest::OutputPath("cli-psf-bad.exr"));
  std::string errors;
  EXPECT_EQ(RunTool("image --psf airy --psf-tail-scale 3 " + Quote(input) + " " + out, &errors), 2);
  EXPECT_NE(errors.find("--psf-tail-scale"), std::string::npos) << errors;
  EXPECT_EQ(RunTool("image --psf airy --psf-core-radius 0 " + Quote(input) + " " + out), 2);
  EXPECT_EQ(RunTool("image --psf-tail-scale 2 " + Quote(input) + " " + out), 2);
  EXPECT_EQ(RunTool("image --psf bessel " + Quote(input) + " " + out), 2);
  EXPECT_EQ(RunTool("image --psf-radius 4 " + Quote(input) + " " + out, &errors), 2);
  EXPECT_NE(errors.find("--psf"), std::string::npos) << errors;
  EXPECT_EQ(
    RunTool("image --psf gaussians --psf-gaussians 2:1,0:1 " + Quote(input) + " " + out), 2);
  EXPECT_EQ(RunTool("image --psf airy --wavelengths 600,500 " + Quote(input) + " " + out), 2);
  EXPECT_EQ(RunTool("image --psf missing-psf.exr " + Quote(input) + " " + out), 1);
  // An even-sized PSF image: the filter refuses it and the tool fails cleanly.
  EXPECT_EQ(RunTool("image --psf " + Quote(input) + " " + Quote(input) + " " + out, &errors), 1);
  EXPECT_NE(errors.find("odd"), std::string::npos) << errors;
  EXPECT_FALSE(fs::exists(vtkBloomTest::OutputPath("cli-psf-bad.exr")));
#ifdef VTKBLOOM_HAS_RENDERING
  // The render pass runs PSF mode too (OpenGL 4.3 compute shaders).
  const std::string rendered = vtkBloomTest::OutputPath("cli-psf-render.exr");
  fs::remove(rendered);
  EXPECT_EQ(RunTool("render --psf airy lit-spheres " + Quote(rendered)), 0);
  EXPECT_TRUE(fs::exists(rendered));
#endif
}

TEST(CommandLine, PngOutputIsToneMapped8Bit)
{
  VTKBLOOM_REQUIRE_DATA(input, "presets/example_161x91.exr");
  const std::string out = vtkBloomTest::OutputPath("cli-bloom.png");
  fs::remove(out);
  ASSERT_EQ(RunTool("image --preset crt-halfres " + Quote(input) + " " + Quote(out)), 0);
  vtkNew<vtkPNGReader> reader;
  reader->SetFileName(out.c_str());
  reader->Update();
  int dims[3];
  reader->GetOutput()->GetDimensions(dims);
  EXPECT_EQ(dims[0], 161);
  EXPECT_EQ(dims[1], 91);
  EXPECT_EQ(reader->GetOutput()->GetScalarType(), VTK_UNSIGNED_CHAR);
  // The emissive discs (values up to 200) are white after tone mapping, the dim corner is not.
  double range[2];
  reader->GetOutput()->GetPointData()->GetScalars()->GetRange(range, 0);
  EXPECT_EQ(range[1], 255.0);
  EXPECT_LT(range[0], 128.0);
}

TEST(CommandLine, UsageErrorsExitWithTwo)
{
  VTKBLOOM_REQUIRE_DATA(input, "presets/example_161x91.exr");
  const std::string out = Quote(vtkBloomTest::OutputPath("cli-usage.exr"));
  const std::string in = Quote(input);
  std::string errors;
  EXPECT_EQ(RunTool("", &errors), 2);
  EXPECT_EQ(RunTool("frobnicate " + in + " " + out), 2);
  EXPECT_EQ(RunTool("image --preset nope " + in + " " + out, &errors), 2);
  EXPECT_NE(errors.find("--preset: Unknown bloom preset 'nope'"), std::string::npos) << errors;
  EXPECT_NE(errors.find(vtkBloomParameters::GetPresetNamesList()), std::string::npos) << errors;
  EXPECT_EQ(errors.find("ERR|"), std::string::npos)
    << "VTK's own log before the message: " << errors;
  // Values the filter would take but misuse: each refused with the option and its range.
  for (const std::string bad : { "--strength -1", "--strength 1e40", "--threshold -1" })
  {
    EXPECT_EQ(RunTool("image " + bad + " " + in + " " + out, &errors), 2) << bad;
    const std::string option = bad.substr(0, bad.find(' '));
    EXPECT_NE(errors.find(option + " must be in ["), std::string::npos) << errors;
  }
  EXPECT_EQ(RunTool("image --threshold abc " + in + " " + out), 2);
  EXPECT_EQ(RunTool("image --knee 2 " + in + " " + out), 2);
  EXPECT_EQ(RunTool("image --levels 0 " + in + " " + out), 2);
  for (const std::string bad : { "-1", "65537", "tall" })
  {
    EXPECT_EQ(RunTool("image --reference-height " + bad + " " + in + " " + out, &errors), 2);
    EXPECT_NE(errors.find("--reference-height expects an integer in [0, 65536]"), std::string::npos)
      << errors;
  }
  EXPECT_EQ(RunTool("image --bogus 1 " + in + " " + out), 2);
  EXPECT_EQ(RunTool("image " + in), 2);
  EXPECT_EQ(RunTool("blur " + in + " " + out, &errors), 2);
  EXPECT_NE(errors.find("--radius"), std::string::npos) << errors;
  EXPECT_EQ(RunTool("blur --radius 33 " + in + " " + out), 2);
  EXPECT_EQ(RunTool("blur --radius -1 " + in + " " + out), 2);
  EXPECT_EQ(RunTool("blur --radius 4 --sigma -1 " + in + " " + out), 2);
  EXPECT_EQ(RunTool("blur --radius 4 --border wrap " + in + " " + out), 2);
  EXPECT_EQ(RunTool("blur --radius 4 " + in + " out.tiff"), 2);
  EXPECT_EQ(RunTool("--help"), 0);
  EXPECT_EQ(RunTool("image --help"), 0);
  EXPECT_EQ(RunTool("--version"), 0);
  // The help's presets and default are vtkBloomParameters' own.
  const std::string help = vtkBloomTest::OutputPath("cli-help.txt");
  ASSERT_EQ(std::system((std::string(VTKBLOOM_TOOL) + " --help >" + Quote(help)).c_str()), 0);
  EXPECT_NE(Slurp(help).find("--preset NAME          " + vtkBloomParameters::GetPresetNamesList() +
              " (default " + vtkBloomParameters::GetDefaultPresetName() + ")"),
    std::string::npos)
    << Slurp(help);
}

TEST(CommandLine, NeverOverwritesTheInput)
{
  VTKBLOOM_REQUIRE_DATA(source, "presets/example_161x91.exr");
  const std::string copy = vtkBloomTest::OutputPath("cli-input-copy.exr");
  fs::copy_file(source, copy, fs::copy_options::overwrite_existing);
  const std::string before = Slurp(copy);
  std::string errors;
  EXPECT_EQ(RunTool("image " + Quote(copy) + " " + Quote(copy), &errors), 2);
  EXPECT_NE(errors.find("refusing to overwrite"), std::string::npos) << errors;
  // Through another spelling of the same path, too.
  const std::string other = vtkBloomTest::OutputPath("./cli-input-copy.exr");
  EXPECT_EQ(RunTool("blur --radius 2 " + Quote(copy) + " " + Quote(other)), 2);
  EXPECT_EQ(Slurp(copy), before);
}

TEST(CommandLine, FailuresLeaveExistingOutputUntouched)
{
  VTKBLOOM_REQUIRE_DATA(damaged, "exr/Damaged/NULL_pointer");
  const std::string out = vtkBloomTest::OutputPath("cli-keep.exr");
  {
    std::ofstream keep(out, std::ios::binary);
    keep << "precious";
  }
  std::string errors;
  EXPECT_EQ(RunTool("image " + Quote(damaged) + " " + Quote(out), &errors), 1);
  EXPECT_NE(errors.find("cannot read"), std::string::npos) << errors;
  EXPECT_EQ(Slurp(out), "precious");
  EXPECT_EQ(RunTool("image /nonexistent/file.exr " + Quote(out)), 1);
  EXPECT_EQ(Slurp(out), "precious");
  // An unwritable destination fails cleanly.
  VTKBLOOM_REQUIRE_DATA(input, "presets/example_161x91.exr");
  EXPECT_EQ(RunTool("image " + Quote(input) + " /nonexistent-dir/out.exr"), 1);
  EXPECT_EQ(RunTool("image " + Quote(input) + " /nonexistent-dir/out.png"), 1);
}

TEST(CommandLine, EveryDamagedFileFailsCleanly)
{
  VTKBLOOM_REQUIRE_DATA(readme, "exr/Damaged/README.rst");
  const fs::path folder = fs::path(readme).parent_path();
  const std::string out = vtkBloomTest::OutputPath("cli-damaged.exr");
  int files = 0;
  for (const auto& entry : fs::directory_iterator(folder))
  {
    if (entry.path().filename() == "README.rst")
    {
      continue;
    }
    ++files;
    fs::remove(out);
    EXPECT_EQ(
      RunTool("blur --radius 1 --quiet " + Quote(entry.path().string()) + " " + Quote(out)), 1)
      << entry.path();
    EXPECT_FALSE(fs::exists(out)) << entry.path();
  }
  EXPECT_EQ(files, 145);
}

#ifdef VTKBLOOM_HAS_RENDERING
//------------------------------------------------------------------------------
// `render`: the scene list, usage errors, and a headless render whose bloom adds light.
TEST(CommandLine, RenderListsAndRendersTheExampleScenes)
{
  const std::string list = vtkBloomTest::OutputPath("render-list.txt");
  ASSERT_EQ(std::system((std::string(VTKBLOOM_TOOL) + " render --list >" + list).c_str()), 0);
  std::ifstream in(list);
  std::vector<std::string> names;
  for (std::string line; std::getline(in, line);)
  {
    names.push_back(line);
  }
  ASSERT_EQ(names.size(), 3u);
  EXPECT_EQ(names[0], "scalar-field");

  const std::string before = vtkBloomTest::OutputPath("render-before.exr");
  const std::string after = vtkBloomTest::OutputPath("render-after.exr");
  fs::remove(before);
  fs::remove(after);
  EXPECT_EQ(RunTool("render nope " + Quote(after)), 2);
  EXPECT_EQ(RunTool("render --size 0x10 lit-spheres " + Quote(after)), 2);
  EXPECT_EQ(RunTool("render lit-spheres out.tiff"), 2);
  EXPECT_FALSE(fs::exists(after));
  ASSERT_EQ(RunTool("render --quiet --size 96x64 --no-bloom lit-spheres " + Quote(before)), 0);
  ASSERT_EQ(RunTool("render --quiet --size 96x64 lit-spheres " + Quote(after)), 0);
  const Pixels a = ReadEXR(before), b = ReadEXR(after);
  ASSERT_EQ(a.Width, 96);
  ASSERT_EQ(b.Height, 64);
  double sumBefore = 0.0, sumAfter = 0.0, peak = 0.0;
  for (size_t i = 0; i < a.Rgba.size(); ++i)
  {
    ASSERT_TRUE(std::isfinite(b.Rgba[i]));
    if (i % 4 != 3)
    {
      sumBefore += a.Rgba[i];
      sumAfter += b.Rgba[i];
      peak = std::max(peak, static_cast<double>(a.Rgba[i]));
    }
  }
  EXPECT_GT(peak, 1.5) << "the render is not HDR";
  EXPECT_GT(sumAfter, sumBefore * 1.01) << "the bloom added no light";
}

// --azimuth, --elevation and --zoom turn the camera of the built-in scenes as of datasets.
TEST(CommandLine, CameraOptionsTurnTheExampleScenes)
{
  const std::string plain = vtkBloomTest::OutputPath("render-camera-plain.exr");
  const std::string turned = vtkBloomTest::OutputPath("render-camera-turned.exr");
  for (const auto& run : { std::make_pair(plain, std::string()),
         std::make_pair(turned, std::string("--azimuth 60 --elevation 20 --zoom 1.5 ")) })
  {
    fs::remove(run.first);
    ASSERT_EQ(RunTool("render --quiet --no-bloom --size 64x48 " + run.second + "lit-spheres " +
                Quote(run.first)),
      0);
  }
  const Pixels a = ReadEXR(plain), b = ReadEXR(turned);
  ASSERT_EQ(a.Rgba.size(), b.Rgba.size());
  double difference = 0.0, energy = 0.0;
  for (size_t i = 0; i < a.Rgba.size(); ++i)
  {
    difference += std::abs(static_cast<double>(a.Rgba[i]) - b.Rgba[i]);
    energy += std::abs(static_cast<double>(a.Rgba[i]));
  }
  EXPECT_GT(difference, 0.1 * energy) << "the camera options changed nothing";
}

// VTK 9.4 and later choose the render window at run time. Asked for an OSMesa window where
// there is no libOSMesa (Mesa 25.1 removed it), or given an empty name, VTK 9.6 crashes; the
// tool refuses instead, with one line that names the variable, and writes nothing.
//------------------------------------------------------------------------------
// VTK 9.1 built for X aborts with no word where no display opens. The tool must say, in one
// line, what is missing and what to run instead, exit 1 and write nothing. Headless builds
// (OSMesa, EGL, VTK 9.4 and later) must render with no display at all.
TEST(CommandLine, RenderWithoutADisplaySaysWhatToRun)
{
#if VTK_VERSION_NUMBER < VTK_VERSION_CHECK(9, 4, 0) && defined(VTK_USE_X) &&                       \
  !defined(VTK_OPENGL_HAS_OSMESA) && !defined(VTK_OPENGL_HAS_EGL)
  const bool needsX = true;
#else
  const bool needsX = false;
#endif
  const std::string out = vtkBloomTest::OutputPath("render-no-display.png");
  const std::string log = vtkBloomTest::OutputPath("render-no-display.txt");
  for (const std::string& display :
    { std::string("env -u DISPLAY"), std::string("env DISPLAY=:9871") })
  {
    for (const std::string& verb : { std::string("render"), std::string("view") })
    {
      fs::remove(out);
      const std::string command = display + " " + std::string(VTKBLOOM_TOOL) + " " + verb +
        " --size 32x24 lit-spheres" + (verb == "render" ? " " + Quote(out) : "") +
        " >/dev/null 2>" + Quote(log);
      const int status = std::system(command.c_str());
      ASSERT_TRUE(WIFEXITED(status)) << command << ": the tool did not exit by itself";
      std::ifstream in(log);
      const std::string errors{ std::istreambuf_iterator<char>(in),
        std::istreambuf_iterator<char>() };
      if (verb == "render" && !needsX)
      {
        EXPECT_EQ(WEXITSTATUS(status), 0) << command << ": " << errors;
        EXPECT_TRUE(fs::exists(out)) << command;
        continue;
      }
      // view always needs a display; render does where VTK renders through X.
      EXPECT_EQ(WEXITSTATUS(status), 1) << command << ": " << errors;
      EXPECT_EQ(std::count(errors.begin(), errors.end(), '\n'), 1) << command << ": " << errors;
      if (verb == "render")
      {
        EXPECT_NE(errors.find("DISPLAY"), std::string::npos) << command << ": " << errors;
        EXPECT_NE(errors.find("xvfb-run"), std::string::npos) << errors;
        EXPECT_FALSE(fs::exists(out)) << command;
      }
      else
      {
        // No display, or (headless builds) no window at all: it says to render instead.
        EXPECT_NE(errors.find("vtk-bloom render"), std::string::npos) << command << ": " << errors;
      }
    }
  }
}

TEST(CommandLine, RenderRefusesAWindowVTKCannotMake)
{
#if VTK_VERSION_NUMBER < VTK_VERSION_CHECK(9, 4, 0)
  GTEST_SKIP() << "VTK " << VTK_VERSION << " fixes its render window when it is built";
#else
  const std::string out = vtkBloomTest::OutputPath("render-no-window.exr");
  const std::string log = vtkBloomTest::OutputPath("render-no-window.txt");
  const bool hasOSMesa = std::system("ldconfig -p | grep -q 'libOSMesa\\.so'") == 0;
  for (const std::string& window : { std::string(), std::string("vtkOSOpenGLRenderWindow") })
  {
    const bool makeable = !window.empty() && hasOSMesa;
    fs::remove(out);
    const std::string command = "env VTK_DEFAULT_OPENGL_WINDOW=" + window + " " +
      std::string(VTKBLOOM_TOOL) + " render --quiet --size 32x24 lit-spheres " + Quote(out) +
      " >/dev/null 2>" + Quote(log);
    const int status = std::system(command.c_str());
    ASSERT_TRUE(WIFEXITED(status)) << "'" << window << "': the tool did not exit by itself";
    std::ifstream in(log);
    const std::string errors{ std::istreambuf_iterator<char>(in),
      std::istreambuf_iterator<char>() };
    if (makeable)
    {
      EXPECT_EQ(WEXITSTATUS(status), 0) << errors;
      continue;
    }
    EXPECT_EQ(WEXITSTATUS(status), 1) << "'" << window << "': " << errors;
    EXPECT_NE(errors.find("VTK_DEFAULT_OPENGL_WINDOW"), std::string::npos) << errors;
    EXPECT_EQ(std::count(errors.begin(), errors.end(), '\n'), 1) << errors;
    EXPECT_FALSE(fs::exists(out));
  }
#endif
}
#endif
