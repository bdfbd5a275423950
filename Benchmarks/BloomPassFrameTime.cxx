// Frame time of an example scene rendered with the plain render steps, into a float target
// copied to the window (the least any HDR post-process does) and with vtkBloomPass,
// interleaved frame by frame in one run so that machine noise hits them alike. Every frame is
// timed by the GPU (a GL_TIME_ELAPSED query around Render()) and by the wall clock (Render()
// then glFinish); the table gives the medians of both.
//
//   BloomPassFrameTime [SCENE [WIDTH HEIGHT [FRAMES [PRESET]]]]
//   BloomPassFrameTime --profile [SCENE [WIDTH HEIGHT [FRAMES [PRESET]]]]
//   BloomPassFrameTime --info      the window class and the OpenGL vendor, renderer and version
//
// SCENE is a name of vtkBloomExampleSceneNames() or "all" (default lit-spheres); PRESET is
// "scene" (the scene's own parameters, the default), "default" (vtkImageBloom's defaults), a
// name of vtkImageBloom::GetPresetNames(), or "all" (default and every preset). A preset keeps
// the scene's bright pass, so the same pixels bloom. --profile prints, for each scene and
// preset, the bloom frame's passes (vtkBloomPass::ProfilePasses: GPU time from timestamp
// queries, size and compulsory memory traffic of each, medians over FRAMES frames).
#include "vtkBloomFrameTimer.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace
{
std::vector<std::string> Expand(const std::string& name, const std::vector<std::string>& all)
{
  return name == "all" ? all : std::vector<std::string>{ name };
}

// One row of the frame-time table; false for an unknown scene or preset.
bool TimeFrames(const std::string& scene, const std::string& preset, int width, int height,
  int frames, bool header)
{
  vtkBloomFrameTimer timer;
  if (!timer.Setup(scene, width, height) || !timer.UsePreset(preset))
  {
    std::fprintf(stderr, "unknown scene %s or preset %s\n", scene.c_str(), preset.c_str());
    return false;
  }
  // Selective scenes also render their emitters; measure the plain scene pass for all.
  const vtkBloomFrameTimer::Kind kinds[] = { vtkBloomFrameTimer::PLAIN,
    vtkBloomFrameTimer::FLOAT_COPY, vtkBloomFrameTimer::BLOOM };
  std::vector<double> wall[3], gpu[3];
  for (int f = -2; f < frames; ++f) // two warm-up frames of each
  {
    for (int k = 0; k < 3; ++k)
    {
      const double ms = 1e3 * timer.Frame(kinds[k]);
      if (f >= 0)
      {
        wall[k].push_back(ms);
        gpu[k].push_back(1e3 * timer.LastGPUSeconds);
      }
    }
  }
  double w[3], g[3];
  for (int k = 0; k < 3; ++k)
  {
    w[k] = vtkBloomMedian(wall[k]);
    g[k] = vtkBloomMedian(gpu[k]);
  }
  if (header)
  {
    std::printf("| scene | preset | size | plain GPU | plain wall | float target + copy GPU "
                "| float target + copy wall | with bloom GPU | with bloom wall | bloom over "
                "the floor GPU | bloom over the floor wall | passes |\n"
                "|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  }
  std::printf("| %s | %s | %dx%d | %.3f ms | %.3f ms | %.3f ms | %.3f ms | %.3f ms | %.3f ms | "
              "%+.3f ms | %+.3f ms | %d |\n",
    scene.c_str(), preset.c_str(), width, height, g[0], w[0], g[1], w[1], g[2], w[2], g[2] - g[1],
    w[2] - w[1], timer.Bloom->GetNumberOfPasses());
  std::fflush(stdout);
  return true;
}

// The per-pass profile of the bloom frame; false for an unknown scene or preset.
bool ProfilePasses(
  const std::string& scene, const std::string& preset, int width, int height, int frames)
{
  vtkBloomFrameTimer timer;
  if (!timer.Setup(scene, width, height) || !timer.UsePreset(preset))
  {
    std::fprintf(stderr, "unknown scene %s or preset %s\n", scene.c_str(), preset.c_str());
    return false;
  }
  // Unprofiled frames first: the whole bloom frame and the floor, for the totals.
  std::vector<double> floorGPU, frameGPU;
  for (int f = -2; f < frames; ++f)
  {
    timer.Frame(vtkBloomFrameTimer::FLOAT_COPY);
    const double floorMs = 1e3 * timer.LastGPUSeconds;
    timer.Frame(vtkBloomFrameTimer::BLOOM);
    if (f >= 0)
    {
      floorGPU.push_back(floorMs);
      frameGPU.push_back(1e3 * timer.LastGPUSeconds);
    }
  }
  timer.Bloom->ProfilePassesOn();
  std::vector<std::vector<double>> ms;
  for (int f = -1; f < frames; ++f)
  {
    timer.Frame(vtkBloomFrameTimer::BLOOM);
    const int n = timer.Bloom->GetNumberOfProfiledPasses();
    ms.resize(n);
    for (int i = 0; f >= 0 && i < n; ++i)
    {
      ms[i].push_back(timer.Bloom->GetProfiledPassMilliseconds(i));
    }
  }
  vtkBloomPass* bloom = timer.Bloom;
  std::printf("\n%s, preset %s, %dx%d, %s precision: %d GPU passes of the chain and the "
              "composite (the profile also lists the scene render)\n\n",
    scene.c_str(), preset.c_str(), width, height,
    bloom->GetFloatPrecision() == vtkBloomPass::FLOAT32 ? "float32" : "float16",
    bloom->GetNumberOfPasses());
  std::printf("| # | pass | size | GPU time | MB | GB/s |\n|---|---|---|---|---|---|\n");
  double total = 0.0, chain = 0.0, bytes = 0.0, chainBytes = 0.0;
  for (int i = 0; i < static_cast<int>(ms.size()); ++i)
  {
    int size[2];
    bloom->GetProfiledPassSize(i, size);
    const double t = vtkBloomMedian(ms[i]);
    const double b = bloom->GetProfiledPassBytes(i);
    const std::string name = bloom->GetProfiledPassName(i);
    std::printf("| %d | %s | %dx%d | %.4f ms | %.2f | %.0f |\n", i, name.c_str(), size[0], size[1],
      t, 1e-6 * b, t > 0.0 ? 1e-6 * b / t : 0.0);
    total += t;
    bytes += b;
    if (name != "scene" && name != "emitters")
    {
      chain += t;
      chainBytes += b;
    }
  }
  const double frameMs = vtkBloomMedian(frameGPU), floorMs = vtkBloomMedian(floorGPU);
  std::printf("\nsum of the passes %.3f ms (%.1f MB); the chain and composite alone %.3f ms "
              "(%.1f MB, %.0f GB/s)\nunprofiled frames (GPU timer): with bloom %.3f ms, float "
              "target + copy %.3f ms, bloom over the floor %+.3f ms\n",
    total, 1e-6 * bytes, chain, 1e-6 * chainBytes, chain > 0.0 ? 1e-6 * chainBytes / chain : 0.0,
    frameMs, floorMs, frameMs - floorMs);
  std::fflush(stdout);
  return true;
}
}

int main(int argc, char* argv[])
{
  if (argc > 1 && std::strcmp(argv[1], "--info") == 0)
  {
    vtkBloomFrameTimer timer;
    timer.Setup("lit-spheres", 64, 64);
    timer.Frame(vtkBloomFrameTimer::PLAIN);
    std::printf("window: %s\n", timer.Window->GetClassName());
    const std::string caps = timer.Window->ReportCapabilities();
    for (const char* key :
      { "OpenGL vendor string:", "OpenGL renderer string:", "OpenGL version string:" })
    {
      const size_t at = caps.find(key);
      if (at != std::string::npos)
      {
        std::printf("%s\n", caps.substr(at, caps.find('\n', at) - at).c_str());
      }
    }
    return 0;
  }
  const bool profile = argc > 1 && std::strcmp(argv[1], "--profile") == 0;
  if (profile)
  {
    --argc;
    ++argv;
  }
  const std::string scene = argc > 1 ? argv[1] : "lit-spheres";
  const int width = argc > 3 ? std::atoi(argv[2]) : 1920;
  const int height = argc > 3 ? std::atoi(argv[3]) : 1080;
  const int frames = argc > 4 ? std::atoi(argv[4]) : 15;
  const std::string preset = argc > 5 ? argv[5] : "scene";
  if (width <= 0 || height <= 0 || frames <= 0)
  {
    std::fprintf(
      stderr, "usage: BloomPassFrameTime [--profile] [SCENE [WIDTH HEIGHT [FRAMES [PRESET]]]]\n");
    return 2;
  }
  std::vector<std::string> presets = vtkImageBloom::GetPresetNames();
  presets.insert(presets.begin(), "default");
  bool header = true;
  for (const std::string& s : Expand(scene, vtkBloomExampleSceneNames()))
  {
    for (const std::string& p : Expand(preset, presets))
    {
      const bool ok = profile ? ProfilePasses(s, p, width, height, frames)
                              : TimeFrames(s, p, width, height, frames, header);
      if (!ok)
      {
        return 1;
      }
      header = false;
    }
  }
  return 0;
}
