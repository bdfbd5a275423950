// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// The GPU rows of BloomChainSpeed (issue 5): frame time of the example scenes at 1920x1080 with
// the plain render steps and with vtkBloomPass, interleaved frame by frame in one benchmark so
// that machine noise hits both alike. Linked into BloomChainSpeed by Benchmarks/Speed.cmake;
// ChainSpeed.cxx calls vtkBloomRegisterGPUBenchmarks() before running and
// vtkBloomPrintGPUSummary() after its own table.
//
// Each iteration renders one frame without the pass, one into a float target copied to the window
// (vtkFramebufferPass: the least any HDR post-process does, the floor of the ratio) and one with
// the pass (the camera moves a little every frame, so nothing is cached), and waits for each to
// finish; the benchmark's time is the frame with bloom, its counters the medians and ratios. The
// rows are registered when the VTK build renders offscreen without a display (OSMesa) or a display
// is set.
#include "vtkBloomFrameTimer.h"

#include "vtkAutoInit.h"
#include "vtkImageBloom.h"
#include "vtkOpenGLRenderWindow.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <string>
#include <vector>

VTK_MODULE_INIT(vtkRenderingOpenGL2);

namespace
{
const int Width = 1920;
const int Height = 1080;

struct GPURow
{
  std::vector<double> Times[3]; ///< seconds per frame of each vtkBloomFrameTimer::Kind
  int Passes = 0;

  /// Median frame time of a kind over every repetition of the row, in ms.
  double Ms(int kind) const { return 1e3 * vtkBloomMedian(this->Times[kind]); }
};
std::map<std::string, GPURow> GPURows; // by row name
std::string Backend;

// `empty`: a threshold nothing reaches, so the pass stops after its bright pass.
void BM_GPUFrame(
  benchmark::State& state, const std::string& scene, bool empty, const std::string& row)
{
  vtkBloomFrameTimer timer;
  if (!timer.Setup(scene, Width, Height))
  {
    state.SkipWithError("unknown scene");
    return;
  }
  vtkRenderWindow* window = timer.Window;
  if (empty)
  {
    timer.Bloom->GetParameters()->SetThreshold(1e30);
  }
  GPURow& result = GPURows[row];
  const vtkBloomFrameTimer::Kind kinds[] = { vtkBloomFrameTimer::PLAIN,
    vtkBloomFrameTimer::FLOAT_COPY, vtkBloomFrameTimer::BLOOM };
  for (int warmUp = 0; warmUp < 2; ++warmUp) // shaders, targets and the chain are made here
  {
    for (auto kind : kinds)
    {
      timer.Frame(kind);
    }
  }
  // The backend: the window class and the OpenGL renderer (llvmpipe for OSMesa).
  Backend = window->GetClassName();
  if (auto* gl = vtkOpenGLRenderWindow::SafeDownCast(window))
  {
    const std::string caps = gl->ReportCapabilities();
    const std::string key = "OpenGL renderer string:";
    const size_t at = caps.find(key);
    if (at != std::string::npos)
    {
      const size_t begin = caps.find_first_not_of(' ', at + key.size());
      Backend += ", " + caps.substr(begin, caps.find('\n', begin) - begin);
    }
  }
  for (auto _ : state)
  {
    for (int k = 0; k < 3; ++k)
    {
      result.Times[k].push_back(timer.Frame(kinds[k]));
    }
    state.SetIterationTime(result.Times[2].back());
  }
  result.Passes = timer.Bloom->GetLastFrame()->GetNumberOfPasses();
  const double plain = result.Ms(0);
  state.counters["without_ms"] = plain;
  state.counters["float_copy_ms"] = result.Ms(1);
  state.counters["with_ms"] = result.Ms(2);
  state.counters["ratio"] = plain > 0.0 ? result.Ms(2) / plain : 0.0;
  state.counters["passes"] = result.Passes;
}
}

//------------------------------------------------------------------------------
extern "C" void vtkBloomRegisterGPUBenchmarks()
{
  vtkNew<vtkRenderWindow> probe;
  const bool headless = std::strcmp(probe->GetClassName(), "vtkOSOpenGLRenderWindow") == 0 ||
    std::strcmp(probe->GetClassName(), "vtkEGLRenderWindow") == 0;
  if (!headless && !std::getenv("DISPLAY"))
  {
    std::printf("GPU rows skipped: %s needs a display (build against the OSMesa VTK, or run "
                "under scripts/lib/with-xvfb.sh)\n",
      probe->GetClassName());
    return;
  }
  const char* size = "1080p";
  for (const std::string scene : { "lit-spheres", "field-lines", "scalar-field" })
  {
    const std::string row = "gpu." + scene + "/" + size;
    benchmark::RegisterBenchmark(row.c_str(), BM_GPUFrame, scene, false, row)
      ->Unit(benchmark::kMillisecond)
      ->UseManualTime()
      ->Iterations(12);
  }
  const std::string empty = std::string("gpu.lit-spheres.empty/") + size;
  benchmark::RegisterBenchmark(empty.c_str(), BM_GPUFrame, std::string("lit-spheres"), true, empty)
    ->Unit(benchmark::kMillisecond)
    ->UseManualTime()
    ->Iterations(12);
}

//------------------------------------------------------------------------------
extern "C" void vtkBloomPrintGPUSummary()
{
  if (GPURows.empty())
  {
    return;
  }
  std::printf("\nGPU pass (%s), %dx%d, frames without bloom, into a float target copied to "
              "the window (vtkFramebufferPass) and with vtkBloomPass interleaved; medians over 12 "
              "frames of each kind per repetition, all repetitions\n\n",
    Backend.c_str(), Width, Height);
  std::printf("| scene | without bloom (ms) | float target + copy (ms) | with bloom (ms) | float "
              "target + copy / without | with / without | passes |\n");
  std::printf("|---|---|---|---|---|---|---|\n");
  for (const auto& r : GPURows)
  {
    const std::string scene = r.first.substr(4, r.first.find('/') - 4);
    const double plain = r.second.Ms(0) > 0.0 ? r.second.Ms(0) : 1.0;
    std::printf("| %s | %.1f | %.1f | %.1f | %.2fx | %.2fx | %d |\n", scene.c_str(), r.second.Ms(0),
      r.second.Ms(1), r.second.Ms(2), r.second.Ms(1) / plain, r.second.Ms(2) / plain,
      r.second.Passes);
  }
}
