// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// End-to-end tests of `vtk-bloom` on many files: hostile inputs refused fast with bounded
// memory and nothing written, the FAST default against --exact, frames with nothing to bloom,
// batch mode (-o OUTDIR) with failing files among good ones, --stats and --max-pixels.
#include "vtkBloomHostileEXR.h"
#include "vtkBloomTestSupport.h"
#include "vtkBloomToolTestHelpers.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace vtkBloomToolTest;

namespace
{
size_t Count(const std::string& text, const std::string& what)
{
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
  {
    ++n;
  }
  return n;
}

std::string FreshDirectory(const std::string& name)
{
  const std::string directory = vtkBloomTest::OutputPath(name);
  fs::remove_all(directory);
  fs::create_directories(directory);
  return directory;
}

bool SameBits(const Pixels& a, const Pixels& b)
{
  return a.Width == b.Width && a.Height == b.Height &&
    std::memcmp(a.Rgba.data(), b.Rgba.data(), a.Rgba.size() * sizeof(float)) == 0;
}
}

//------------------------------------------------------------------------------
// Every generated hostile file, through a copy (blur --radius 0) and a bloom: exit status 1
// with a message, within 10 s of CPU time and 256 MB of resident memory, and no output file.
// The bounds are on the work the tool does, not on the clock: a hang or a file that makes the
// reader work without bound exceeds them, a busy machine does not (on two cores shared with a
// ParaView build the slowest took 3.0 s of wall-clock time, and a 2 s deadline failed).
TEST(CommandLineFiles, HostileFilesAreRefusedFastWithNothingWritten)
{
  const std::string directory = FreshDirectory("cli-hostile");
  const auto paths = vtkBloomHostileEXR::WriteAll(directory);
  ASSERT_GE(paths.size(), 50u);
  const std::string out = vtkBloomTest::OutputPath("cli-hostile-out.exr");
  double slowest = 0.0;
  long largest = 0;
  for (const std::string& path : paths)
  {
    for (const std::vector<std::string>& command :
      { std::vector<std::string>{ "blur", "--radius", "0" }, std::vector<std::string>{ "image" } })
    {
      fs::remove(out);
      std::vector<std::string> arguments = command;
      arguments.insert(arguments.end(), { "--quiet", path, out });
      const MeasuredRun run = RunToolMeasured(arguments);
      EXPECT_EQ(run.Status, 1) << command[0] << " " << path << "\n" << run.Errors;
      EXPECT_NE(run.Errors.find("cannot read"), std::string::npos) << path << "\n" << run.Errors;
      EXPECT_LT(run.CPUSeconds, 10.0) << path;
      EXPECT_LT(run.PeakResidentKilobytes, 256 * 1024) << path;
      EXPECT_FALSE(fs::exists(out)) << path;
      slowest = std::max(slowest, run.CPUSeconds);
      largest = std::max(largest, run.PeakResidentKilobytes);
    }
  }
  std::cout << paths.size() << " hostile files x 2 commands: slowest " << slowest
            << " s of CPU time, largest resident " << largest / 1024 << " MB\n";
}

//------------------------------------------------------------------------------
// --exact runs the REFERENCE chain and reproduces PRESETS.md's float64 expectations exactly
// (as float32); the FAST default agrees within 1e-5.
TEST(CommandLineFiles, ExactIsBitForBitAndFastIsWithin1e5)
{
  VTKBLOOM_REQUIRE_DATA(input, "presets/example_161x91.exr");
  for (const std::string preset : { "webgpu-market", "mip-atlas", "ping-pong", "crt-halfres" })
  {
    VTKBLOOM_REQUIRE_DATA(expected, "presets/example_161x91__" + preset + ".exr");
    const std::string exact = vtkBloomTest::OutputPath("cli-exact-" + preset + ".exr");
    const std::string fast = vtkBloomTest::OutputPath("cli-fast-" + preset + ".exr");
    ASSERT_EQ(
      RunTool("image --exact --preset " + preset + " " + Quote(input) + " " + Quote(exact)), 0);
    ASSERT_EQ(RunTool("image --preset " + preset + " " + Quote(input) + " " + Quote(fast)), 0);
    const Pixels reference = ReadEXR(expected);
    EXPECT_EQ(RelativeL2(ReadEXR(exact), reference), 0.0) << preset;
    EXPECT_LE(RelativeL2(ReadEXR(fast), reference), 1e-5) << preset;
  }
}

//------------------------------------------------------------------------------
// Nothing above the threshold: the bloom work is skipped and the frame is written unchanged.
TEST(CommandLineFiles, FrameWithNothingToBloomIsWrittenUnchanged)
{
  VTKBLOOM_REQUIRE_DATA(input, "presets/example_161x91.exr");
  const std::string out = vtkBloomTest::OutputPath("cli-dark.exr");
  const std::string stats = vtkBloomTest::OutputPath("cli-dark.json");
  ASSERT_EQ(RunTool("image --threshold 1e6 --stats " + Quote(stats) + " " + Quote(input) + " " +
              Quote(out)),
    0);
  EXPECT_TRUE(SameBits(ReadEXR(out), ReadEXR(input)));
  const std::string json = Slurp(stats);
  EXPECT_NE(json.find("\"bloom_skipped\": true"), std::string::npos) << json;
  EXPECT_NE(json.find("\"bright_pixels\": 0,"), std::string::npos) << json;
}

//------------------------------------------------------------------------------
TEST(CommandLineFiles, BatchProcessesGoodFilesAndReportsEachFailure)
{
  VTKBLOOM_REQUIRE_DATA(input, "presets/example_161x91.exr");
  VTKBLOOM_REQUIRE_DATA(damaged, "exr/Damaged/NULL_pointer");
  const std::string in = FreshDirectory("cli-batch-in");
  const std::string outdir = vtkBloomTest::OutputPath("cli-batch-out");
  fs::remove_all(outdir);
  fs::copy_file(input, in + "/a.exr");
  fs::copy_file(input, in + "/c.exr");
  fs::create_directories(in + "/again");
  fs::copy_file(input, in + "/again/a.exr");
  fs::copy_file(damaged, in + "/bad.exr");
  fs::create_directories(outdir);
  {
    std::ofstream keep(outdir + "/c.exr", std::ios::binary);
    keep << "precious";
  }
  const std::string stats = vtkBloomTest::OutputPath("cli-batch.json");
  fs::remove(stats);
  std::string errors;
  const int status = RunTool("image --preset crt-halfres --quiet " + Quote(in + "/a.exr") + " " +
      Quote(in + "/bad.exr") + " " + Quote(in + "/c.exr") + " " + Quote(in + "/missing.exr") + " " +
      Quote(in + "/again/a.exr") + " -o " + Quote(outdir) + " --stats " + Quote(stats),
    &errors);
  EXPECT_EQ(status, 1) << errors;

  // The good file is written, and equals the single-file command's output bit for bit.
  const std::string single = vtkBloomTest::OutputPath("cli-batch-single.exr");
  ASSERT_EQ(RunTool("image --preset crt-halfres " + Quote(input) + " " + Quote(single)), 0);
  ASSERT_TRUE(fs::exists(outdir + "/a.exr"));
  EXPECT_TRUE(SameBits(ReadEXR(outdir + "/a.exr"), ReadEXR(single)));
  // Nothing else is written, and the existing file is untouched.
  EXPECT_FALSE(fs::exists(outdir + "/bad.exr"));
  EXPECT_FALSE(fs::exists(outdir + "/missing.exr"));
  EXPECT_EQ(Slurp(outdir + "/c.exr"), "precious");
  EXPECT_EQ(std::distance(fs::directory_iterator(outdir), fs::directory_iterator()), 2);
  // Each failure is reported with its file.
  EXPECT_NE(errors.find("bad.exr"), std::string::npos) << errors;
  EXPECT_NE(errors.find("missing.exr: no such file"), std::string::npos) << errors;
  EXPECT_NE(errors.find("already exists"), std::string::npos) << errors;
  EXPECT_NE(errors.find("an earlier input of the same name"), std::string::npos) << errors;
  // And the report has one entry per input, in order.
  const std::string json = Slurp(stats);
  EXPECT_EQ(Count(json, "\"input\": "), 5u) << json;
  EXPECT_EQ(Count(json, "\"status\": \"ok\""), 1u) << json;
  EXPECT_EQ(Count(json, "\"status\": \"error\""), 4u) << json;
  EXPECT_LT(json.find("a.exr"), json.find("bad.exr"));
  EXPECT_NE(json.find("\"energy_in\": "), std::string::npos) << json;

  // Only good files: exit status 0; PNG outputs with --format png.
  const std::string pngs = vtkBloomTest::OutputPath("cli-batch-png");
  fs::remove_all(pngs);
  EXPECT_EQ(RunTool("blur --radius 2 --quiet --format png " + Quote(in + "/a.exr") + " " +
              Quote(in + "/c.exr") + " -o " + Quote(pngs)),
    0);
  EXPECT_TRUE(fs::exists(pngs + "/a.png"));
  EXPECT_TRUE(fs::exists(pngs + "/c.png"));
  // Running it again refuses to overwrite either.
  EXPECT_EQ(
    RunTool("blur --radius 2 --quiet --format png " + Quote(in + "/a.exr") + " -o " + Quote(pngs)),
    1);
  // Usage errors of batch mode.
  EXPECT_EQ(RunTool("image -o " + Quote(pngs)), 2);
  EXPECT_EQ(RunTool("image --format png " + Quote(input) + " " + Quote(single)), 2);
  EXPECT_EQ(RunTool("image --format tiff " + Quote(input) + " -o " + Quote(pngs)), 2);
  EXPECT_EQ(RunTool("image --stats out.txt " + Quote(input) + " -o " + Quote(pngs)), 2);
}

//------------------------------------------------------------------------------
TEST(CommandLineFiles, StatisticsDescribeTheBloom)
{
  VTKBLOOM_REQUIRE_DATA(input, "presets/example_161x91.exr");
  const std::string out = vtkBloomTest::OutputPath("cli-stats.exr");
  const std::string stats = vtkBloomTest::OutputPath("cli-stats.json");
  ASSERT_EQ(RunTool("image --stats " + Quote(stats) + " " + Quote(input) + " " + Quote(out)), 0);
  const std::string json = Slurp(stats);
  EXPECT_NE(json.find("\"command\": \"image\""), std::string::npos) << json;
  EXPECT_NE(json.find("\"width\": 161, \"height\": 91"), std::string::npos) << json;
  EXPECT_NE(json.find("\"bloom_skipped\": false"), std::string::npos) << json;
  EXPECT_NE(json.find("\"exact\": false"), std::string::npos) << json;
  EXPECT_EQ(json.find("\"bright_pixels\": 0,"), std::string::npos) << json;
  EXPECT_NE(json.find("\"levels_used\": "), std::string::npos) << json;
}

//------------------------------------------------------------------------------
TEST(CommandLineFiles, MaxPixelsRefusesLargerInputsAndCanBeRaised)
{
  VTKBLOOM_REQUIRE_DATA(input, "presets/example_161x91.exr");
  const std::string out = vtkBloomTest::OutputPath("cli-limit.exr");
  fs::remove(out);
  std::string errors;
  EXPECT_EQ(
    RunTool("blur --radius 1 --max-pixels 14650 " + Quote(input) + " " + Quote(out), &errors), 1);
  EXPECT_NE(errors.find("--max-pixels"), std::string::npos) << errors;
  EXPECT_FALSE(fs::exists(out));
  EXPECT_EQ(RunTool("blur --radius 1 --max-pixels 14651 " + Quote(input) + " " + Quote(out)), 0);
  EXPECT_EQ(RunTool("blur --radius 1 --max-pixels 1G " + Quote(input) + " " + Quote(out)), 0);
  EXPECT_EQ(RunTool("blur --radius 1 --max-pixels 0 " + Quote(input) + " " + Quote(out)), 2);
  EXPECT_EQ(RunTool("blur --radius 1 --max-pixels -5 " + Quote(input) + " " + Quote(out)), 2);
  EXPECT_EQ(RunTool("blur --radius 1 --max-pixels 3X " + Quote(input) + " " + Quote(out)), 2);
}
