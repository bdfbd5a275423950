// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// Helpers of the vtk-bloom end-to-end tests: running the tool, measuring a run, and reading its
// EXR output with OpenEXR directly (independently of vtkOpenEXRReader).
#ifndef vtkBloomToolTestHelpers_h
#define vtkBloomToolTestHelpers_h

#include "vtkBloomTestSupport.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>

#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fcntl.h>
#include <fstream>
#include <iterator>
#include <string>
#include <unistd.h>
#include <vector>

extern char** environ;

namespace vtkBloomToolTest
{
// Run the tool with the given arguments; returns its exit status, stderr in `errors`.
inline int RunTool(const std::string& arguments, std::string* errors = nullptr)
{
  const std::string log = vtkBloomTest::OutputPath("cli-stderr.txt");
  const std::string command = std::string(VTKBLOOM_TOOL) + " " + arguments + " >/dev/null 2>" + log;
  const int status = std::system(command.c_str());
  if (errors)
  {
    std::ifstream in(log);
    errors->assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// An EXR file as float RGBA (missing channels: 0, alpha 1), read with OpenEXR directly.
struct Pixels
{
  int Width = 0, Height = 0;
  std::vector<float> Rgba;
};

inline Pixels ReadEXR(const std::string& path)
{
  Imf::InputFile file(path.c_str());
  const Imath::Box2i dw = file.header().dataWindow();
  Pixels p;
  p.Width = dw.max.x - dw.min.x + 1;
  p.Height = dw.max.y - dw.min.y + 1;
  p.Rgba.assign(static_cast<size_t>(p.Width) * p.Height * 4, 0.0f);
  char* base = reinterpret_cast<char*>(p.Rgba.data()) -
    (static_cast<ptrdiff_t>(dw.min.x) + static_cast<ptrdiff_t>(dw.min.y) * p.Width) * 16;
  Imf::FrameBuffer fb;
  const char* names[4] = { "R", "G", "B", "A" };
  for (int c = 0; c < 4; ++c)
  {
    fb.insert(names[c],
      Imf::Slice(
        Imf::FLOAT, base + 4 * c, 16, 16 * static_cast<size_t>(p.Width), 1, 1, c == 3 ? 1.0 : 0.0));
  }
  file.setFrameBuffer(fb);
  file.readPixels(dw.min.y, dw.max.y);
  return p;
}

inline bool IsFloatRGBA(const std::string& path)
{
  Imf::InputFile file(path.c_str());
  const Imf::ChannelList& channels = file.header().channels();
  int count = 0;
  for (auto it = channels.begin(); it != channels.end(); ++it, ++count)
  {
    if (it.channel().type != Imf::FLOAT)
    {
      return false;
    }
  }
  return count == 4 && channels.findChannel("R") && channels.findChannel("A");
}

inline double RelativeL2(const Pixels& out, const Pixels& expected)
{
  if (out.Width != expected.Width || out.Height != expected.Height)
  {
    return INFINITY;
  }
  double num = 0.0, den = 0.0;
  for (size_t i = 0; i < out.Rgba.size(); ++i)
  {
    const double d = static_cast<double>(out.Rgba[i]) - expected.Rgba[i];
    num += d * d;
    den += static_cast<double>(expected.Rgba[i]) * expected.Rgba[i];
  }
  return std::sqrt(num / den);
}

inline std::string Slurp(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

inline std::string Quote(const std::string& path)
{
  return "'" + path + "'";
}

/// One run of the tool, measured: exit status, wall time, the child's peak resident memory.
struct MeasuredRun
{
  int Status = -1;
  double Seconds = 0.0;    ///< wall-clock: reported, never bounded (a busy machine stretches it)
  double CPUSeconds = 0.0; ///< the work the run did: user and system time of the child
  long PeakResidentKilobytes = 0;
  std::string Errors;
};

/// Run the tool directly (no shell) with `arguments`, stdout discarded and stderr kept, and
/// measure it with wait4().
inline MeasuredRun RunToolMeasured(const std::vector<std::string>& arguments)
{
  MeasuredRun run;
  const std::string log = vtkBloomTest::OutputPath("cli-measured-stderr.txt");
  std::vector<std::string> words = { VTKBLOOM_TOOL };
  words.insert(words.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (std::string& word : words)
  {
    argv.push_back(&word[0]);
  }
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  const auto start = std::chrono::steady_clock::now();
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0)
  {
    return run;
  }
  int status = 0;
  rusage usage{};
  wait4(pid, &status, 0, &usage);
  run.Seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  run.Status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.PeakResidentKilobytes = usage.ru_maxrss;
  run.CPUSeconds = static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
    1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
  run.Errors = Slurp(log);
  return run;
}
}

#endif
