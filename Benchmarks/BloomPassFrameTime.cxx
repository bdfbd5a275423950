// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// Frame time of an example scene rendered with the plain render steps, into a float target
// copied to the window (the least any HDR post-process does) and with vtkBloomPass,
// interleaved frame by frame in one run so that machine noise hits them alike. Every frame is
// timed by the GPU (a GL_TIME_ELAPSED query around Render()). The table gives the bloom over
// the plain frame and over the cheapest float copy (a compute copy where the context has one)
// by the mean of the frames, and the bloom frame's median, mean, p99 and maximum.
//
//   BloomPassFrameTime [SCENE [WIDTH HEIGHT [FRAMES [PRESET]]]]
//   BloomPassFrameTime --profile [SCENE [WIDTH HEIGHT [FRAMES [PRESET]]]]
//   BloomPassFrameTime --info      the window class and the OpenGL vendor, renderer and version
//   BloomPassFrameTime --fragment ...  as above, every pass a fragment pass
//                                  (vtkBloomPass::UseComputeShadersOff)
//   BloomPassFrameTime --single-draw N ...  as above, vtkBloomPassTesting::SetSingleDrawSamples N
//   BloomPassFrameTime --pairs ...  as above, vtkBloomPassTesting::SetFuseSeparablePasses off (the
//                                  separable pairs as two passes, as before issue 37's fusion)
//   BloomPassFrameTime --unrestricted ...  as above, RestrictToBrightRegion off (the whole
//                                  chain every frame, no bright-region probes)
//   BloomPassFrameTime --no-read-back ...  as above, SkipEmptyBloom off too: the CPU never waits
//                                  for the GPU in the pass (no query or region read back)
//   BloomPassFrameTime --samples N ...  as above in a window of N samples (multisampling)
//   BloomPassFrameTime --depth-draw ...  as above, the scene's depth drawn after the composite
//                                  instead of rendered into the window's depth buffer
//                                  (vtkBloomPassTesting::SetShareWindowDepth off: the frame
//                                  before that sharing, for its cost)
//   BloomPassFrameTime --resolved ...  as above, vtkBloomPass::ThresholdSamplesOff (a
//                                  multisampled scene thresholded after its resolve)
//   BloomPassFrameTime --direct ... / --fft ...  as above, the level blurs by their taps or
//                                  through the FFT (vtkBloomParameters::ConvolutionMode; the
//                                  default is AUTOMATIC; with the options above)
//   BloomPassFrameTime --quality SCENE WIDTH HEIGHT FRAMES [CSV]
//   BloomPassFrameTime --sparse WIDTH HEIGHT FRAMES
//   BloomPassFrameTime --sync SCENE WIDTH HEIGHT FRAMES
//   BloomPassFrameTime --orbit SCENE WIDTH HEIGHT FRAMES
//   BloomPassFrameTime --renderers SCENE WIDTH HEIGHT FRAMES
//   BloomPassFrameTime --selective SCENE WIDTH HEIGHT FRAMES
//   BloomPassFrameTime --psf SCENE WIDTH HEIGHT FRAMES
//   BloomPassFrameTime --formats SCENE WIDTH HEIGHT FRAMES
//
// SCENE is a name of vtkBloomExampleSceneNames() or "all" (default lit-spheres); PRESET is
// "scene" (the scene's own parameters, the default), "default" (vtkBloomParameters' defaults),
// a name of vtkBloomParameters::GetPresetNames(), or "all" (default and every preset). A preset
// keeps the scene's bright pass, so the same pixels bloom. --profile prints, for each scene and
// preset, the bloom frame's passes (vtkBloomPassTesting::SetProfilePasses: GPU time from timestamp
// queries, size and compulsory memory traffic of each, medians over FRAMES frames).
//
// --quality: for vtkImageBloom's defaults, every preset, blurs by their taps and PSF bloom
// (exact and split), the pass's GPU time over the floor and its error on one frame against
// vtkImageBloom REFERENCE (double) on the same float render (relative L2 of the colour, and the
// largest absolute error over the reference's peak; a split PSF's rows against the unsplit
// PSF's REFERENCE). CSV also writes the rows to a file, for scripts/plot-gpu-quality.py.
// (The fast mode that these rows once compared, half floats and bilinear pairs of taps, was
// slower than the exact pass on an NVIDIA H200 and is gone: docs/gpu.md.)
//
// --sparse: the sparse scenes of vtkBloomFrameTimer::SetupSparse (one HDR disk over 0 %, 0.1 %,
// 1 % and 10 % of the window), vtkImageBloom's defaults, the full chain
// (RestrictToBrightRegion off) against the content-aware one (on) frame by frame; also checks
// on one frame that both give the same bits.
//
// --orbit: stutter. The bloom's own GPU time, frame by frame, over FRAMES frames of an orbiting
// camera: median, mean, p99, maximum, and the frames above 1.5 x the median.
//
// --selective: on a scene whose emitters alone bloom (scalar-field), the bloom of the whole
// scene against the emitters' bloom written in the scene's own render (with the content-aware
// chain and with the full chain) and in a second render of the emitters
// (vtkBloomPass::EmitInSceneRender off), interleaved frame by frame: the selective frames'
// median, mean, p99 and maximum, and their mean over the whole scene's.
//
// --psf: PSF bloom (vtkBloomParameters::BLOOM_PSF, the FFT convolution of vtkBloomPassFFT) on
// the scene's bright pass, an Airy pattern of PSF radius 16, 64 and 256, then as wide as the
// frame (radius max(WIDTH, HEIGHT) / 2; Gaussians there: an Airy pattern that wide takes
// minutes to make on the CPU, and the FFT's cost does not depend on the PSF's values), each
// interleaved frame by frame with the plain frame and the compute copy: the padded FFT grid,
// the bloom frame's median, mean, p99 and maximum, its mean over the compute copy's, and the
// wall time of the first bloom frame (the PSFs and their spectra made, the programs built).
// The Airy pattern of radius 256 and the wide Gaussians are also split (PSFTailScale: a
// full-resolution core and a coarse tail), each split row with its bloom's relative L2
// against the exact row's on the same frame.
//
// --formats: what the scene's colour target costs. The plain render steps into a target of each
// colour format (RGBA8, R11F_G11F_B10F, RGBA16F, RGBA32F) with a depth texture, blitted to the
// window (VTK's vtkFramebufferPass), interleaved with the plain frame, the compute copy and the
// bloom: the 8-bit row is what a target and a blit cost; each float row over it, its format.
//
// --sync: the cost of the pass's one wait for the GPU (the bright region's read-back, or
// SkipEmptyBloom's occlusion query): vtkImageBloom's defaults with the content-aware chain, with
// the occlusion query only, and with neither (no wait: the CPU submits the whole frame ahead
// of the GPU), GPU time and the CPU's time in Render().
//
// One executable for every GPU timing of scripts/gpu-run.sh (about 1350 lines): each mode is a
// function of its own (TimeFrames, ProfilePasses with its breakdown, QualityTable, SparseTable,
// SyncTable, OrbitTable, SelectiveTable, PSFTable, RenderersTable, FormatsTable), and they share
// the scene set-up and the options' flags (SetUp), the frame timing (vtkBloomFrameTimer.h) and the
// frame statistics, which separate files would have to export for one caller each.
#include "vtkBloomFrameTimer.h"
#include "vtkBloomParameters.h"
#include "vtkBloomPassTesting.h"
#include "vtkCallbackCommand.h"
#include "vtkCommand.h"

#include "vtkImageBloom.h"
#include "vtkImageData.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"

#include <algorithm>
#include <fstream>
#include <map>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace
{
bool Fragment = false;     // --fragment
int Convolution = -1;      // --direct, --fft: vtkBloomParameters::ConvolutionMode
int SingleDraw = -1;       // --single-draw N: vtkBloomPassTesting::SetSingleDrawSamples
bool Pairs = false;        // --pairs: vtkBloomPassTesting::SetFuseSeparablePasses off
bool Unrestricted = false; // --unrestricted: vtkBloomParameters::RestrictToBrightRegionOff
bool NoReadBack = false;   // --no-read-back: SkipEmptyBloomOff too (the CPU never waits)
int Samples = 0;           // --samples N: a multisampled window
bool Resolved = false;     // --resolved: vtkBloomPass::ThresholdSamplesOff
bool DepthDraw = false;    // --depth-draw: the depth drawn after the composite, never shared

// The timer on `scene` with `preset`, in the shader stage the options ask for; false,
// with a message, for an unknown scene or preset.
bool SetUp(vtkBloomFrameTimer& timer, const std::string& scene, const std::string& preset,
  int width, int height)
{
  timer.Samples = Samples;
  if (!timer.Setup(scene, width, height) || !timer.UsePreset(preset))
  {
    std::fprintf(stderr, "unknown scene %s or preset %s\n", scene.c_str(), preset.c_str());
    return false;
  }
  timer.Bloom->SetUseComputeShaders(!Fragment);
  if (SingleDraw >= 0)
  {
    vtkBloomPassTesting::SetSingleDrawSamples(timer.Bloom, SingleDraw);
  }
  vtkBloomPassTesting::SetFuseSeparablePasses(timer.Bloom, !Pairs);
  if (Unrestricted || NoReadBack)
  {
    timer.Bloom->GetParameters()->SetRestrictToBrightRegion(false);
  }
  if (NoReadBack)
  {
    timer.Bloom->GetParameters()->SetSkipEmptyBloom(false);
  }
  timer.Bloom->SetThresholdSamples(!Resolved);
  vtkBloomPassTesting::SetShareWindowDepth(timer.Bloom, !DepthDraw);
  vtkBloomPassTesting::SetShareWindowDepth(timer.ComputeCopy, !DepthDraw);
  if (Convolution >= 0)
  {
    timer.Bloom->GetParameters()->SetConvolutionMode(Convolution);
  }
  return true;
}

std::vector<std::string> Expand(const std::string& name, const std::vector<std::string>& all)
{
  return name == "all" ? all : std::vector<std::string>{ name };
}

// One row of the frame-time table; false for an unknown scene or preset. Four kinds of frame,
// interleaved: the plain render, the cheapest float copy (COMPUTE_COPY), VTK's float copy
// (vtkFramebufferPass, a blit: the floor of earlier tables) and the bloom. The bloom's cost is
// given over the plain frame and over the cheapest float copy, by the mean of the frames (a
// median hides the frames that stutter), with the bloom frame's median, p99 and maximum.
bool TimeFrames(const std::string& scene, const std::string& preset, int width, int height,
  int frames, bool header)
{
  vtkBloomFrameTimer timer;
  if (!SetUp(timer, scene, preset, width, height))
  {
    return false;
  }
  // Selective scenes also render their emitters; measure the plain scene pass for all.
  const vtkBloomFrameTimer::Kind kinds[] = { vtkBloomFrameTimer::PLAIN,
    vtkBloomFrameTimer::COMPUTE_COPY, vtkBloomFrameTimer::FLOAT_COPY, vtkBloomFrameTimer::BLOOM };
  std::vector<double> gpu[4], cpu[4];
  for (int f = -2; f < frames; ++f) // two warm-up frames of each
  {
    for (int k = 0; k < 4; ++k)
    {
      timer.Frame(kinds[k]);
      if (f >= 0)
      {
        gpu[k].push_back(1e3 * timer.LastGPUSeconds);
        cpu[k].push_back(1e3 * timer.LastSubmitSeconds);
      }
    }
  }
  const vtkBloomFrameStatistics plain(gpu[0]), copy(gpu[1]), blit(gpu[2]), bloom(gpu[3]);
  // The CPU's time in Render() (the wall clock before the wait for the GPU): the pass's own is
  // the bloom frame's over the plain frame's, which submits the same scene; the chain's own,
  // over the compute copy's (the same pass with no chain: its float target and composite).
  const vtkBloomFrameStatistics plainCPU(cpu[0]), copyCPU(cpu[1]), bloomCPU(cpu[3]);
  if (header)
  {
    std::printf("GPU time per frame (GL_TIME_ELAPSED), ms; %d frames of each kind, interleaved; "
                "CPU: the wall clock in Render(), before the wait for the GPU\n"
                "| scene | preset | size | plain, mean | float + compute copy, mean | float + "
                "VTK blit, mean | bloom: median | mean | p99 | max | bloom over plain, mean | "
                "bloom over compute copy, mean | by the medians | passes | CPU: plain, mean | "
                "CPU: compute copy, mean | CPU: bloom, mean / p99 | CPU: bloom over plain, mean | "
                "CPU: bloom over the copy, mean |\n"
                "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n",
      frames);
  }
  // Over the copy by the medians too: a stall of the card that lands on a few frames of one
  // kind moves the means (see p99) but not the medians.
  std::printf("| %s | %s | %dx%d | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %+.3f | "
              "%+.3f | %+.3f | %d | %.3f | %.3f | %.3f / %.3f | %+.3f | %+.3f |\n",
    scene.c_str(), preset.c_str(), width, height, plain.Mean, copy.Mean, blit.Mean, bloom.Median,
    bloom.Mean, bloom.P99, bloom.Max, bloom.Mean - plain.Mean, bloom.Mean - copy.Mean,
    bloom.Median - copy.Median, timer.Bloom->GetLastFrame()->GetNumberOfPasses(), plainCPU.Mean,
    copyCPU.Mean, bloomCPU.Mean, bloomCPU.P99, bloomCPU.Mean - plainCPU.Mean,
    bloomCPU.Mean - copyCPU.Mean);
  std::fflush(stdout);
  return true;
}

// One entry of the profile over several frames: its name, the median of its GPU times, and its
// size and traffic, in how many of the frames it ran.
struct ProfiledMedian
{
  std::string Name;
  double Milliseconds = 0.0;
  int Size[2] = { 0, 0 };
  double Bytes = 0.0;
  int Frames = 0;
};

// The median GPU time of each profiled entry of `pass` over `frames` frames of `kind`, in the
// order they first ran. Entries are matched by name and by which of that name's entries of the
// frame they are (the blurs of a level repeat a name), not by their place in the frame: a
// frame that measures the bright region has a reduction that the others have not.
std::vector<ProfiledMedian> ProfiledMedians(
  vtkBloomFrameTimer& timer, vtkBloomPass* pass, vtkBloomFrameTimer::Kind kind, int frames)
{
  vtkBloomPassTesting::SetProfilePasses(pass, true);
  std::vector<ProfiledMedian> entries;
  std::vector<std::vector<double>> ms;
  std::map<std::string, std::size_t> index;
  for (int f = -1; f < frames; ++f)
  {
    timer.Frame(kind);
    std::map<std::string, int> seen;
    for (const auto& entry : vtkBloomPassTesting::GetProfile(pass))
    {
      const std::string key = entry.Name + "#" + std::to_string(seen[entry.Name]++);
      auto found = index.find(key);
      if (found == index.end())
      {
        found = index.emplace(key, entries.size()).first;
        entries.emplace_back();
        entries.back().Name = entry.Name;
        ms.emplace_back();
      }
      ProfiledMedian& out = entries[found->second];
      std::copy(entry.Size, entry.Size + 2, out.Size);
      out.Bytes = entry.Bytes;
      if (f >= 0)
      {
        ms[found->second].push_back(entry.Milliseconds);
        ++out.Frames;
      }
    }
  }
  for (std::size_t i = 0; i < entries.size(); ++i)
  {
    entries[i].Milliseconds = vtkBloomMedian(ms[i]);
  }
  vtkBloomPassTesting::SetProfilePasses(pass, false);
  return entries;
}

// GPU timestamps at the window's and the renderer's StartEvent and EndEvent: where in the
// window's Render() a frame's GPU time goes (before the renderer, in it, after it: the
// window's own copy to its display framebuffer).
struct FrameSegments
{
  std::vector<GLuint> Queries;
  size_t Next = 0;
  static void Stamp(vtkObject*, unsigned long, void* data, void*)
  {
    auto* self = static_cast<FrameSegments*>(data);
    if (self->Next < self->Queries.size())
    {
      glQueryCounter(self->Queries[self->Next++], GL_TIMESTAMP);
    }
  }
  // The medians over `frames` frames of `kind`: window start to renderer start, renderer
  // start to end, renderer end to window end.
  std::vector<double> Measure(vtkBloomFrameTimer& timer, vtkBloomFrameTimer::Kind kind, int frames)
  {
    timer.Frame(kind);
    this->Queries.assign(4, 0);
    glGenQueries(4, this->Queries.data());
    vtkNew<vtkCallbackCommand> stamp;
    stamp->SetCallback(&FrameSegments::Stamp);
    stamp->SetClientData(this);
    const unsigned long tags[4] = { timer.Window->AddObserver(vtkCommand::StartEvent, stamp),
      timer.Renderer->AddObserver(vtkCommand::StartEvent, stamp),
      timer.Renderer->AddObserver(vtkCommand::EndEvent, stamp),
      timer.Window->AddObserver(vtkCommand::EndEvent, stamp) };
    std::vector<double> ms[3];
    for (int f = 0; f < frames; ++f)
    {
      this->Next = 0;
      timer.Frame(kind);
      GLuint64 t[4] = { 0, 0, 0, 0 };
      for (size_t i = 0; i < this->Next; ++i)
      {
        glGetQueryObjectui64v(this->Queries[i], GL_QUERY_RESULT, &t[i]);
      }
      for (int k = 0; this->Next == 4 && k < 3; ++k)
      {
        ms[k].push_back(1e-6 * static_cast<double>(t[k + 1] - t[k]));
      }
    }
    timer.Window->RemoveObserver(tags[0]);
    timer.Renderer->RemoveObserver(tags[1]);
    timer.Renderer->RemoveObserver(tags[2]);
    timer.Window->RemoveObserver(tags[3]);
    glDeleteQueries(4, this->Queries.data());
    return { vtkBloomMedian(ms[0]), vtkBloomMedian(ms[1]), vtkBloomMedian(ms[2]) };
  }
};

// What the user pays for the bloom frame over the plain frame, then its parts: the plain,
// compute-copy and bloom frames interleaved unprofiled (the GPU timer around Render()), then
// the profile of the bloom frame and of the compute copy (the same pass with no chain: its
// composite is the copy back).
void PrintBreakdown(vtkBloomFrameTimer& timer, const std::vector<ProfiledMedian>& bloom, int width,
  int height, int frames)
{
  std::vector<double> gpu[3];
  const vtkBloomFrameTimer::Kind kinds[3] = { vtkBloomFrameTimer::PLAIN,
    vtkBloomFrameTimer::COMPUTE_COPY, vtkBloomFrameTimer::BLOOM };
  for (int f = -2; f < frames; ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      timer.Frame(kinds[k]);
      if (f >= 0)
      {
        gpu[k].push_back(1e3 * timer.LastGPUSeconds);
      }
    }
  }
  const vtkBloomFrameStatistics plain(gpu[0]), copy(gpu[1]), frame(gpu[2]);
  const auto copyParts = ProfiledMedians(
    timer, timer.ComputeCopy, vtkBloomFrameTimer::COMPUTE_COPY, std::min(frames, 50));
  double scene = 0.0, depth = 0.0, fxaa = 0.0, chain = 0.0, composite = 0.0, copyBack = 0.0;
  for (const ProfiledMedian& part : bloom)
  {
    const std::string& name = part.Name;
    double& sum = name == "scene" || name == "emitters" ? scene
      : name == "depth"                                 ? depth
      : name == "fxaa"                                  ? fxaa
      : name.rfind("composite", 0) == 0                 ? composite
                                                        : chain;
    sum += part.Milliseconds;
  }
  for (const ProfiledMedian& part : copyParts)
  {
    copyBack += part.Name.rfind("composite", 0) == 0 ? part.Milliseconds : 0.0;
  }
  std::printf("\n**What the user pays**, %dx%d, %d frames of each kind interleaved (GPU timer): "
              "plain frame %.3f mean; bloom frame %.3f mean, %.3f median, %.3f p99; **bloom over "
              "plain %+.3f ms by the means** (%+.3f by the medians); over the compute copy "
              "(%.3f mean) %+.3f\n\n",
    width, height, frames, plain.Mean, frame.Mean, frame.Median, frame.P99, frame.Mean - plain.Mean,
    frame.Median - plain.Median, copy.Mean, frame.Mean - copy.Mean);
  std::printf("| part (medians of the profiled frames) | GPU ms |\n|---|---:|\n");
  std::printf(
    "| the scene into the float target (scene span; the plain frame is %.3f in all) | %.4f |\n",
    plain.Median, scene);
  std::printf(
    "| the depth's draw (where the scene could not render into the window's depth) | %.4f |\n",
    depth);
  std::printf("| the copy back (the compute copy's composite) | %.4f |\n", copyBack);
  std::printf("| the chain (bright pass to last upsample) | %.4f |\n", chain);
  std::printf("| the composite | %.4f |\n", composite);
  std::printf("| the renderer's FXAA | %.4f |\n", fxaa);
  std::printf("| the bloom frame outside these spans (its median less their sum) | %.4f |\n",
    frame.Median - (scene + depth + fxaa + chain + composite));
  FrameSegments segments;
  const std::vector<double> p = segments.Measure(timer, vtkBloomFrameTimer::PLAIN, 50);
  const std::vector<double> b = segments.Measure(timer, vtkBloomFrameTimer::BLOOM, 50);
  std::printf("\n| segment of the window's Render() (GPU timestamps, medians of 50) | plain | "
              "bloom |\n|---|---:|---:|\n| the window's start to the renderer's | %.4f | %.4f "
              "|\n| the renderer | %.4f | %.4f |\n| the renderer's end to the window's (its "
              "copy to the display framebuffer) | %.4f | %.4f |\n",
    p[0], b[0], p[1], b[1], p[2], b[2]);
  std::fflush(stdout);
}

// The per-pass profile of the bloom frame, then what the user pays and its parts
// (PrintBreakdown); false for an unknown scene or preset.
bool ProfilePasses(
  const std::string& scene, const std::string& preset, int width, int height, int frames)
{
  vtkBloomFrameTimer timer;
  if (!SetUp(timer, scene, preset, width, height))
  {
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
  const auto medians = ProfiledMedians(timer, timer.Bloom, vtkBloomFrameTimer::BLOOM, frames);
  vtkBloomPass* bloom = timer.Bloom;
  std::printf("\n%s, preset %s%s, %dx%d, %s precision: %d GPU passes of the chain and the "
              "composite (the profile also lists the scene render)\n\n",
    scene.c_str(), preset.c_str(), Fragment ? " (fragment passes)" : "", width, height,
    bloom->GetFloatPrecision() == vtkBloomPass::FLOAT32 ? "float32" : "float16",
    bloom->GetLastFrame()->GetNumberOfPasses());
  std::printf("| # | pass | size | GPU time | MB | GB/s |\n|---|---|---|---|---|---|\n");
  double total = 0.0, chain = 0.0, bytes = 0.0, chainBytes = 0.0;
  for (std::size_t i = 0; i < medians.size(); ++i)
  {
    const ProfiledMedian& entry = medians[i];
    const double t = entry.Milliseconds;
    const double b = entry.Bytes;
    const std::string& name = entry.Name;
    const std::string ran =
      entry.Frames < frames ? " (" + std::to_string(entry.Frames) + " frames)" : "";
    std::printf("| %d | %s%s | %dx%d | %.4f ms | %.2f | %.0f |\n", static_cast<int>(i),
      name.c_str(), ran.c_str(), entry.Size[0], entry.Size[1], t, 1e-6 * b,
      t > 0.0 ? 1e-6 * b / t : 0.0);
    total += t;
    bytes += b;
    if (name != "scene" && name != "emitters" && name != "depth" && name != "fxaa")
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
  PrintBreakdown(timer, medians, width, height, frames);
  return true;
}

// Colour errors of `a` against `reference`: relative L2, and the largest absolute error over
// the reference's largest absolute value.
void Errors(vtkImageData* a, vtkImageData* reference, double& relativeL2, double& maxOverPeak)
{
  vtkDataArray* x = a->GetPointData()->GetScalars();
  vtkDataArray* y = reference->GetPointData()->GetScalars();
  double num = 0.0, den = 0.0, worst = 0.0, peak = 0.0;
  for (vtkIdType p = 0; p < a->GetNumberOfPoints(); ++p)
  {
    for (int c = 0; c < 3; ++c)
    {
      const double u = x->GetComponent(p, c), v = y->GetComponent(p, c);
      num += (u - v) * (u - v);
      den += v * v;
      worst = std::max(worst, std::abs(u - v));
      peak = std::max(peak, std::abs(v));
    }
  }
  relativeL2 = std::sqrt(num / std::max(den, 1e-300));
  maxOverPeak = worst / std::max(peak, 1e-300);
}

// Medians of the GPU time of the floor, the bloom pass and (the first `count` of the three) the
// alternative pass, interleaved.
void TimeTwo(vtkBloomFrameTimer& timer, int frames, double ms[3], int count = 3)
{
  const vtkBloomFrameTimer::Kind kinds[] = { vtkBloomFrameTimer::FLOAT_COPY,
    vtkBloomFrameTimer::BLOOM, vtkBloomFrameTimer::ALTERNATIVE };
  std::vector<double> gpu[3];
  for (int f = -2; f < frames; ++f)
  {
    for (int k = 0; k < count; ++k)
    {
      timer.Frame(kinds[k]);
      if (f >= 0)
      {
        gpu[k].push_back(1e3 * timer.LastGPUSeconds);
      }
    }
  }
  for (int k = 0; k < 3; ++k)
  {
    ms[k] = k < count ? vtkBloomMedian(gpu[k]) : 0.0;
  }
}

// One frame of the bloom pass and (where `b` is given) of the alternative pass, with the same
// camera: the scene and the results.
void Capture(
  vtkBloomFrameTimer& timer, vtkImageData* scene, vtkImageData* a, vtkImageData* b = nullptr)
{
  timer.Bloom->CaptureResultOn();
  timer.Renderer->SetPass(timer.Bloom);
  timer.Window->Render();
  timer.Bloom->ReadSceneImage(scene);
  timer.Bloom->ReadResultImage(a);
  timer.Bloom->CaptureResultOff();
  if (b)
  {
    timer.Alternative->CaptureResultOn();
    timer.Renderer->SetPass(timer.Alternative);
    timer.Window->Render();
    timer.Alternative->ReadResultImage(b);
    timer.Alternative->CaptureResultOff();
  }
}

// The quality row of one setting on `timer`: the pass's GPU time over the floor and its error
// against vtkImageBloom REFERENCE.
void QualityRow(vtkBloomFrameTimer& timer, const std::string& label, int frames, std::ofstream& out)
{
  // Over black: over a coloured background the pass puts the background behind the glow
  // (docs/rendering.md) where vtkImageBloom adds the glow to every pixel, a difference of the
  // composite's design (1.8e-3 relative L2 on lit-spheres), not of the chain's numerics.
  timer.Renderer->SetBackground(0.0, 0.0, 0.0);
  timer.Renderer->GradientBackgroundOff();
  timer.Renderer->TexturedBackgroundOff();
  timer.Frame(vtkBloomFrameTimer::PLAIN); // a context for the GPU timer
  vtkNew<vtkImageData> sceneImage, result;
  Capture(timer, sceneImage, result);
  // The reference runs the exact operators: a split PSF's row is measured against the whole
  // PSF's convolution (what the split costs in accuracy).
  vtkNew<vtkBloomParameters> reference;
  reference->DeepCopy(timer.Bloom->GetParameters());
  reference->SetPSFTailScale(1);
  vtkNew<vtkImageBloom> cpu;
  cpu->SetParameters(reference);
  cpu->SetExecutionModeToReference();
  cpu->SetInputData(sceneImage);
  cpu->Update();
  double l2 = 0.0, peak = 0.0;
  Errors(result, cpu->GetOutput(), l2, peak);
  double ms[3];
  TimeTwo(timer, frames, ms, 2);
  const int passes = timer.Bloom->GetLastFrame()->GetNumberOfPasses();
  std::printf(
    "| %s | %+.3f ms | %d | %.2e | %.2e |\n", label.c_str(), ms[1] - ms[0], passes, l2, peak);
  if (out.is_open())
  {
    out << "\"" << label << "\"," << ms[1] - ms[0] << "," << passes << "," << l2 << "," << peak
        << "\n";
  }
  std::fflush(stdout);
}

bool QualityTable(const std::string& scene, int width, int height, int frames, const char* csv)
{
  std::vector<std::string> presets = vtkBloomParameters::GetPresetNames();
  presets.insert(presets.begin(), "default");
  std::ofstream out;
  if (csv)
  {
    out.open(csv);
    out << "preset,gpu_ms_over_floor,passes,rel_l2_vs_reference,max_abs_over_peak_vs_reference\n";
  }
  std::printf(
    "%s over black, %dx%d, vtkImageBloom REFERENCE (double) on the same float render "
    "as the reference\n\n| preset | bloom over the floor GPU | passes | relative L2 against "
    "REFERENCE | max abs / peak against REFERENCE |\n|---|---|---|---|---|\n",
    scene.c_str(), width, height);
  for (const std::string& preset : presets)
  {
    vtkBloomFrameTimer timer;
    if (!timer.Setup(scene, width, height) || !timer.UsePreset(preset))
    {
      return false;
    }
    QualityRow(timer, preset, frames, out);
  }
  // The compute FFT's rows: ping-pong's blurs summed tap by tap (through the FFT is its
  // default, above), and PSF bloom with the filter's default Airy pattern and Gaussians, exact
  // and split (the tail on a grid 4 or 8 times coarser, PSFTailScale).
  const std::string taps = "ping-pong, blurs tap by tap";
  for (const char* name : { "ping-pong, blurs tap by tap", "psf airy", "psf gaussians",
         "psf airy, tail 1/4", "psf gaussians, tail 1/4", "psf gaussians, tail 1/8" })
  {
    const std::string extra = name;
    const size_t tail = extra.find("tail 1/");
    vtkBloomFrameTimer timer;
    if (!timer.Setup(scene, width, height) ||
      !timer.UsePreset(extra == taps ? "ping-pong" : "default"))
    {
      return false;
    }
    vtkBloomParameters* parameters = timer.Bloom->GetParameters();
    if (extra == taps)
    {
      parameters->SetConvolutionModeToDirect();
    }
    else
    {
      parameters->SetBloomModeToPSF();
      parameters->SetPSFType(extra.find("airy") != std::string::npos
          ? vtkBloomParameters::PSF_AIRY
          : vtkBloomParameters::PSF_GAUSSIANS);
      parameters->SetPSFTailScale(
        tail == std::string::npos ? 1 : std::stoi(extra.substr(tail + 7)));
    }
    QualityRow(timer, extra, frames, out);
  }
  return true;
}

bool SyncTable(const std::string& scene, int width, int height, int frames)
{
  std::printf("%s, vtkImageBloom defaults, %dx%d: the pass's wait for the GPU\n\n| chain | "
              "bloom over the floor GPU | Render() on the CPU | passes |\n|---|---|---|---|\n",
    scene.c_str(), width, height);
  const char* names[] = { "content-aware (reduction read back)",
    "full, SkipEmptyBloom "
    "(occlusion query read back)",
    "full, no read-back (SkipEmptyBloom and RestrictToBrightRegion off)" };
  std::string costs;
  for (int mode = 0; mode < 3; ++mode)
  {
    vtkBloomFrameTimer timer;
    if (!timer.Setup(scene, width, height) || !timer.UsePreset("default"))
    {
      return false;
    }
    vtkBloomParameters* p = timer.Bloom->GetParameters();
    p->SetRestrictToBrightRegion(mode == 0);
    p->SetSkipEmptyBloom(mode < 2);
    std::vector<double> floorGPU, floorSubmit, gpu, submit;
    int measured = 0;
    for (int f = -2; f < frames; ++f)
    {
      timer.Frame(vtkBloomFrameTimer::FLOAT_COPY);
      const double floorMs = 1e3 * timer.LastGPUSeconds;
      const double floorSubmitMs = 1e3 * timer.LastSubmitSeconds;
      timer.Frame(vtkBloomFrameTimer::BLOOM);
      measured += f >= 0 && timer.Bloom->GetLastFrame()->GetChainCoverage() < 1.0 ? 1 : 0;
      if (f >= 0)
      {
        floorGPU.push_back(floorMs);
        floorSubmit.push_back(floorSubmitMs);
        gpu.push_back(1e3 * timer.LastGPUSeconds);
        submit.push_back(1e3 * timer.LastSubmitSeconds);
      }
    }
    if (mode == 0)
    {
      std::printf("| the floor itself (float target + copy): GPU %.3f ms | | %.3f ms | |\n",
        vtkBloomMedian(floorGPU), vtkBloomMedian(floorSubmit));
    }
    std::printf("| %s | %+.3f ms | %.3f ms | %d |\n", names[mode],
      vtkBloomMedian(gpu) - vtkBloomMedian(floorGPU), vtkBloomMedian(submit),
      timer.Bloom->GetLastFrame()->GetNumberOfPasses());
    if (mode == 0)
    {
      costs = "content-aware: " + std::to_string(measured) + " of " + std::to_string(frames) +
        " frames restricted; measured cost " +
        std::to_string(timer.Bloom->GetLastFrame()->GetRegionCost()) + " ms with the region, " +
        std::to_string(timer.Bloom->GetLastFrame()->GetFullCost()) +
        " ms with the full chain (GPU, the chain's start to the composite's end)\n";
    }
    std::fflush(stdout);
  }
  std::printf("\n%s", costs.c_str());
  return true;
}

bool SparseTable(int width, int height, int frames)
{
  std::printf("sparse scenes, vtkImageBloom defaults, %dx%d: the full chain "
              "(RestrictToBrightRegion off) against the content-aware chain (on)\n\n| bright "
              "| float target + copy GPU | full: bloom over the floor | content-aware: bloom "
              "over the floor | saving | bright region (level 0) | chain coverage | passes | "
              "same bits |\n|---|---|---|---|---|---|---|---|---|\n",
    width, height);
  for (const double fraction : { 0.0, 0.001, 0.01, 0.1 })
  {
    vtkBloomFrameTimer timer;
    timer.SetupSparse(fraction, width, height);
    timer.Bloom->GetParameters()->SetRestrictToBrightRegion(false);
    timer.Alternative->GetParameters()->SetRestrictToBrightRegion(true);
    timer.Frame(vtkBloomFrameTimer::PLAIN);
    vtkNew<vtkImageData> scene, full, restricted;
    Capture(timer, scene, full, restricted);
    const bool same = full->GetNumberOfPoints() == restricted->GetNumberOfPoints() &&
      std::equal(static_cast<float*>(full->GetScalarPointer()),
        static_cast<float*>(full->GetScalarPointer()) + 4 * full->GetNumberOfPoints(),
        static_cast<float*>(restricted->GetScalarPointer()),
        [](float u, float v) { return std::memcmp(&u, &v, sizeof(float)) == 0; });
    double ms[3];
    TimeTwo(timer, frames, ms);
    int region[4];
    timer.Alternative->GetLastFrame()->GetBrightRegion(region);
    std::printf(
      "| %g %% | %.3f ms | %+.3f ms | %+.3f ms | %.3f ms | %dx%d | %.3f | %d / %d | %s |\n",
      100.0 * fraction, ms[0], ms[1] - ms[0], ms[2] - ms[0], ms[1] - ms[2], region[1] - region[0],
      region[3] - region[2], timer.Alternative->GetLastFrame()->GetChainCoverage(),
      timer.Bloom->GetLastFrame()->GetNumberOfPasses(),
      timer.Alternative->GetLastFrame()->GetNumberOfPasses(), same ? "yes" : "NO");
    std::fflush(stdout);
  }
  return true;
}

// Stutter: FRAMES frames of an orbiting camera (half a degree a frame), after 16 of warm-up
// (the first frames compile programs and learn what the bright region costs). The bloom's cost
// per frame is the pass's own GPU time, from the bright pass to the end of the composite
// (vtkBloomFrameReport::GetChainMilliseconds), so the scene's own variation is not in it; its
// median, mean, p99 and maximum, and how many frames cost more than 1.5 times the median.
bool OrbitTable(const std::string& scene, int width, int height, int frames)
{
  vtkBloomFrameTimer timer;
  if (!SetUp(timer, scene, "scene", width, height))
  {
    return false;
  }
  vtkBloomPassTesting::SetTimeChains(timer.Bloom, true);
  std::vector<double> cost;
  for (int f = -16; f < frames; ++f)
  {
    timer.Frame(vtkBloomFrameTimer::BLOOM); // waits for the frame to complete
    const double ms = timer.Bloom->GetLastFrame()->GetChainMilliseconds();
    if (f >= 0 && ms >= 0.0)
    {
      cost.push_back(ms);
    }
  }
  const vtkBloomFrameStatistics stats(cost);
  const long over = std::count_if(
    cost.begin(), cost.end(), [&stats](double ms) { return ms > 1.5 * stats.Median; });
  std::printf("The bloom's own GPU time per frame (bright pass to composite), %zu frames of an "
              "orbiting camera after 16 of warm-up\n"
              "| scene | size | median | mean | p99 | max | max / median | frames over 1.5 x "
              "median |\n|---|---|---|---|---|---|---|---|\n"
              "| %s | %dx%d | %.3f ms | %.3f ms | %.3f ms | %.3f ms | %.2f | %ld |\n",
    cost.size(), scene.c_str(), width, height, stats.Median, stats.Mean, stats.P99, stats.Max,
    stats.Median > 0.0 ? stats.Max / stats.Median : 0.0, over);
  // Which frames: a period points at the pass's own schedule, isolated ones at the machine.
  if (over > 0)
  {
    std::printf("\nframes over 1.5 x the median (index: ms):");
    int shown = 0;
    for (size_t f = 0; f < cost.size() && shown < 12; ++f)
    {
      if (cost[f] > 1.5 * stats.Median)
      {
        std::printf(" %zu: %.3f", f, cost[f]);
        ++shown;
      }
    }
    std::printf("\n");
  }
  std::fflush(stdout);
  return true;
}
}

// PSF bloom's frame time on `scene` for a few PSF radii (see --psf above); false for an unknown
// scene.
// One row of PSF bloom's per-stage profile: the medians of 5 profiled bloom frames.
std::string PSFStages(vtkBloomFrameTimer& timer, const std::string& label)
{
  vtkBloomPass* bloom = timer.Bloom;
  vtkBloomPassTesting::SetProfilePasses(bloom, true);
  std::map<std::string, std::vector<double>> ms;
  std::vector<std::string> order;
  for (int f = -1; f < 5; ++f)
  {
    timer.Frame(vtkBloomFrameTimer::BLOOM);
    if (f < 0)
    {
      continue; // a first frame, untimed
    }
    for (const auto& pass : vtkBloomPassTesting::GetProfile(bloom))
    {
      if (ms.find(pass.Name) == ms.end())
      {
        order.push_back(pass.Name);
      }
      ms[pass.Name].push_back(pass.Milliseconds);
    }
  }
  vtkBloomPassTesting::SetProfilePasses(bloom, false);
  std::string row = "| " + label + " |";
  for (const std::string& name : order)
  {
    if (name != "scene")
    {
      char cell[32];
      std::snprintf(cell, sizeof(cell), " %.3f |", vtkBloomMedian(ms[name]));
      row += cell;
    }
  }
  return row + "\n";
}

// One PSF bloom setting of the --psf table.
struct PSFSetting
{
  bool Airy;
  int Radius;
  int TailScale;  ///< 1: exact
  int CoreRadius; ///< -1: automatic
};

// The bloom term (result - scene) of one captured bloom frame, RGB.
std::vector<double> CapturedBloom(vtkBloomFrameTimer& timer)
{
  timer.Bloom->CaptureResultOn();
  timer.Frame(vtkBloomFrameTimer::BLOOM);
  vtkNew<vtkImageData> scene, result;
  timer.Bloom->ReadSceneImage(scene);
  timer.Bloom->ReadResultImage(result);
  timer.Bloom->CaptureResultOff();
  vtkDataArray* s = scene->GetPointData()->GetScalars();
  vtkDataArray* r = result->GetPointData()->GetScalars();
  std::vector<double> bloom;
  for (vtkIdType t = 0; t < r->GetNumberOfTuples(); ++t)
  {
    for (int c = 0; c < 3; ++c)
    {
      bloom.push_back(r->GetComponent(t, c) - s->GetComponent(t, c));
    }
  }
  return bloom;
}

// One row of the --psf table (and its stages' row in `stages`); `exact` holds the exact bloom
// of the setting's PSF (made by its exact row, compared with by its split rows).
bool PSFRow(const std::string& scene, int width, int height, int frames, const PSFSetting& row,
  std::vector<double>& exact, std::string& stages)
{
  vtkBloomFrameTimer timer;
  if (!SetUp(timer, scene, "scene", width, height))
  {
    return false;
  }
  vtkBloomParameters* parameters = timer.Bloom->GetParameters();
  parameters->SetBloomModeToPSF();
  parameters->SetPSFRadius(row.Radius);
  parameters->SetPSFTailScale(row.TailScale);
  parameters->SetPSFCoreRadius(row.CoreRadius);
  if (row.Airy)
  {
    parameters->SetPSFType(vtkBloomParameters::PSF_AIRY);
  }
  else
  {
    parameters->SetPSFType(vtkBloomParameters::PSF_GAUSSIANS);
    parameters->SetPSFGaussians({ 2.0, 16.0, row.Radius / 3.0 }, { 1.0, 0.3, 0.1 });
  }
  const vtkBloomFrameTimer::Kind kinds[] = { vtkBloomFrameTimer::PLAIN,
    vtkBloomFrameTimer::COMPUTE_COPY, vtkBloomFrameTimer::BLOOM };
  std::vector<double> gpu[3];
  double first = 0.0;
  for (int f = -2; f < frames; ++f) // two warm-up frames of each
  {
    for (int k = 0; k < 3; ++k)
    {
      const double wall = timer.Frame(kinds[k]);
      first = f == -2 && k == 2 ? wall : first;
      if (f >= 0)
      {
        gpu[k].push_back(1e3 * timer.LastGPUSeconds);
      }
    }
  }
  const int* grid = timer.Bloom->GetLastFrame()->GetPSFGrid();
  const vtkBloomFrameStatistics plain(gpu[0]), copy(gpu[1]), bloom(gpu[2]);
  const std::string gridText = grid[0] > 0 ? std::to_string(grid[0]) + "x" + std::to_string(grid[1])
                                           : std::string("refused: no bloom");
  const std::string split = row.TailScale == 1 ? std::string("exact")
                                               : std::to_string(row.TailScale) + ", core " +
      std::to_string(parameters->GetEffectivePSFCoreRadius());
  // The split's error: the relative L2 of its bloom term against the exact row's.
  const std::vector<double> term = CapturedBloom(timer);
  double num = 0.0, den = 0.0;
  for (size_t i = 0; row.TailScale > 1 && i < term.size() && i < exact.size(); ++i)
  {
    num += (term[i] - exact[i]) * (term[i] - exact[i]);
    den += exact[i] * exact[i];
  }
  exact = row.TailScale == 1 ? term : exact;
  char error[32] = "-";
  if (den > 0.0)
  {
    std::snprintf(error, sizeof(error), "%.1e", std::sqrt(num / den));
  }
  std::printf("| %s | %d | %s | %s | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %+.3f | %s | "
              "%.2f s |\n",
    row.Airy ? "Airy" : "Gaussians", row.Radius, split.c_str(), gridText.c_str(), plain.Mean,
    copy.Mean, bloom.Median, bloom.Mean, bloom.P99, bloom.Max, bloom.Mean - copy.Mean, error,
    first);
  std::fflush(stdout);
  stages += PSFStages(timer,
    std::string(row.Airy ? "Airy" : "Gaussians") + ", " + std::to_string(row.Radius) + ", " +
      split + ", " + gridText);
  return true;
}

bool PSFTable(const std::string& scene, int width, int height, int frames)
{
  std::printf("PSF bloom (FFT convolution), %s at %dx%d: GPU time per frame (GL_TIME_ELAPSED), "
              "ms, %d frames of each kind, interleaved\n"
              "| PSF | radius | split: tail scale, core radius | FFT grid | plain, mean | "
              "compute copy, mean | bloom: median | mean | p99 | max | bloom over compute copy, "
              "mean | bloom's relative L2 against exact | first bloom frame (wall) |\n"
              "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n",
    scene.c_str(), width, height, frames);
  // Airy patterns, then Gaussians as wide as the frame, each exact and then split.
  const int wide = std::max(width, height) / 2;
  const PSFSetting rows[] = { { true, 16, 1, -1 }, { true, 64, 1, -1 }, { true, 256, 1, -1 },
    { true, 256, 4, -1 }, { true, 256, 8, -1 }, { false, wide, 1, -1 }, { false, wide, 2, -1 },
    { false, wide, 4, -1 }, { false, wide, 8, -1 }, { false, wide, 4, 8 }, { false, wide, 8, 8 } };
  std::string stages;
  std::vector<double> exact;
  for (const PSFSetting& row : rows)
  {
    if (!PSFRow(scene, width, height, frames, row, exact, stages))
    {
      return false;
    }
  }
  std::printf("\nThe bloom frame's passes (the pass's profile), medians of 5 frames, ms "
              "(a split PSF: the spread onto the grid, the tail's FFT there, then the core with "
              "the tail added)\n"
              "| PSF, radius, split, grid | bright pass | rows | columns | multiply | inverse "
              "columns | inverse rows | fold | composite |\n|---|---|---|---|---|---|---|---|---|\n"
              "%s",
    stages.c_str());
  std::fflush(stdout);
  return true;
}

// Selective bloom's cost over the whole scene's on `scene`, with the emission in the scene's
// render and in a second render; false for an unknown scene or one without emitters. The
// one-render frames have a window of their own: a mapper drawn alternately with and without
// the pass's shader replacement would rebuild its shaders every frame, which no application
// showing one view does.
bool SelectiveTable(const std::string& scene, int width, int height, int frames)
{
  vtkBloomFrameTimer timer, oneRender, oneRenderFull;
  for (vtkBloomFrameTimer* t : { &timer, &oneRender, &oneRenderFull })
  {
    if (!SetUp(*t, scene, "scene", width, height) ||
      t->Bloom->GetEmissionSource() != vtkBloomPass::EMISSION_EMITTERS)
    {
      std::fprintf(stderr, "scene %s has no emitters\n", scene.c_str());
      return false;
    }
  }
  // The alternative pass shares the parameters and blooms the whole scene; the timer's own
  // bloom pass renders the emitters again. The third window runs the full chain, with no
  // bright region (and so no read-back).
  timer.Alternative->SetEmissionSourceToScene();
  timer.Bloom->SetEmitInSceneRender(false);
  oneRenderFull.Bloom->GetParameters()->SetRestrictToBrightRegion(false);
  struct Row
  {
    const char* Name;
    vtkBloomFrameTimer* Timer;
    vtkBloomFrameTimer::Kind Kind;
    std::vector<double> GPU;
  };
  Row rows[] = { { "plain", &timer, vtkBloomFrameTimer::PLAIN, {} },
    { "whole scene", &timer, vtkBloomFrameTimer::ALTERNATIVE, {} },
    { "in the scene's render", &oneRender, vtkBloomFrameTimer::BLOOM, {} },
    { "in the scene's render, full chain", &oneRenderFull, vtkBloomFrameTimer::BLOOM, {} },
    { "emitters rendered again", &timer, vtkBloomFrameTimer::BLOOM, {} } };
  for (int f = -2; f < frames; ++f)
  {
    for (Row& row : rows)
    {
      row.Timer->Frame(row.Kind);
      if (f >= 0)
      {
        row.GPU.push_back(1e3 * row.Timer->LastGPUSeconds);
      }
    }
  }
  const vtkBloomFrameStatistics plain(rows[0].GPU), whole(rows[1].GPU);
  std::printf("GPU time per frame (GL_TIME_ELAPSED), ms, %s at %dx%d; %d frames of each kind, "
              "interleaved; plain %.3f (mean). The profile's medians over %d more frames: the "
              "scene's render, the emitters' second render, the chain and composite\n"
              "| bloom | renders | median | mean | p99 | max | over the whole scene's bloom, mean "
              "| scene | emitters | chain |\n"
              "|---|---|---|---|---|---|---|---|---|---|\n",
    scene.c_str(), width, height, frames, plain.Mean, std::min(frames, 20));
  for (Row& row : rows)
  {
    if (row.Kind == vtkBloomFrameTimer::PLAIN)
    {
      continue;
    }
    vtkBloomPass* pass =
      row.Kind == vtkBloomFrameTimer::ALTERNATIVE ? row.Timer->Alternative : row.Timer->Bloom;
    const vtkBloomFrameStatistics bloom(row.GPU);
    // Then the profile of the same frame, run alone.
    std::vector<double> spans[3]; // scene, emitters, chain
    vtkBloomPassTesting::SetProfilePasses(pass, true);
    for (int f = -1; f < std::min(frames, 20); ++f)
    {
      row.Timer->Frame(row.Kind);
      double sum[3] = { 0.0, 0.0, 0.0 };
      for (const auto& entry : vtkBloomPassTesting::GetProfile(pass))
      {
        const std::string& name = entry.Name;
        if (name == "depth" || name == "fxaa")
        {
          continue; // after the chain, outside this table's three spans
        }
        sum[name == "scene" ? 0 : name == "emitters" ? 1 : 2] += entry.Milliseconds;
      }
      for (int k = 0; f >= 0 && k < 3; ++k)
      {
        spans[k].push_back(sum[k]);
      }
    }
    vtkBloomPassTesting::SetProfilePasses(pass, false);
    std::printf("| %s | %d | %.3f | %.3f | %.3f | %.3f | %+.3f | %.3f | %.3f | %.3f |\n", row.Name,
      pass->GetLastFrame()->GetEmissionInSceneRender() ||
          row.Kind == vtkBloomFrameTimer::ALTERNATIVE
        ? 1
        : 2,
      bloom.Median, bloom.Mean, bloom.P99, bloom.Max, bloom.Mean - whole.Mean,
      vtkBloomMedian(spans[0]), vtkBloomMedian(spans[1]), vtkBloomMedian(spans[2]));
  }
  std::fflush(stdout);
  return true;
}

// Several bloomed renderers: a window of WIDTH x HEIGHT split into 2 x 2 viewports, each its
// own renderer of the scene with its own vtkBloomPass (vtkImageBloom's defaults), against the
// same four renderers with the plain render steps, frame by frame. The CPU's time in Render()
// (before the wait for the GPU) and the GPU's, per frame; the pass's CPU cost per renderer is
// the difference over four.
bool RenderersTable(const std::string& scene, int width, int height, int frames)
{
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(width, height);
  vtkNew<vtkRenderStepsPass> steps;
  std::vector<vtkSmartPointer<vtkRenderer>> renderers;
  std::vector<vtkSmartPointer<vtkBloomPass>> passes;
  for (int i = 0; i < 4; ++i)
  {
    auto renderer = vtkSmartPointer<vtkRenderer>::New();
    auto pass = vtkSmartPointer<vtkBloomPass>::New();
    renderer->SetViewport(0.5 * (i % 2), 0.5 * (i / 2), 0.5 * (i % 2) + 0.5, 0.5 * (i / 2) + 0.5);
    window->AddRenderer(renderer);
    if (!vtkBloomBuildExampleScene(scene, renderer, pass))
    {
      std::fprintf(stderr, "unknown scene %s\n", scene.c_str());
      return false;
    }
    // vtkImageBloom's defaults with the scene's bright pass, as UsePreset("default") does.
    vtkNew<vtkBloomParameters> defaults;
    vtkBloomParameters* own = pass->GetParameters();
    defaults->SetThresholdMode(own->GetThresholdMode());
    defaults->SetThreshold(own->GetThreshold());
    defaults->SetKnee(own->GetKnee());
    defaults->SetRestrictToBrightRegion(!Unrestricted && !NoReadBack);
    defaults->SetSkipEmptyBloom(!NoReadBack);
    pass->SetParameters(defaults);
    pass->SetDelegatePass(steps);
    pass->SetUseComputeShaders(!Fragment);
    vtkBloomPassTesting::SetFuseSeparablePasses(pass, !Pairs);
    if (SingleDraw >= 0)
    {
      vtkBloomPassTesting::SetSingleDrawSamples(pass, SingleDraw);
    }
    renderers.push_back(renderer);
    passes.push_back(pass);
  }
  vtkBloomRenderTiming timing;
  std::vector<double> cpu[2], gpu[2];
  for (int f = -3; f < frames; ++f)
  {
    for (int bloom = 0; bloom < 2; ++bloom)
    {
      for (int i = 0; i < 4; ++i)
      {
        renderers[i]->SetPass(bloom ? static_cast<vtkRenderPass*>(passes[i]) : steps.Get());
        renderers[i]->GetActiveCamera()->Azimuth(0.5);
      }
      timing.Render(window);
      if (f >= 0)
      {
        cpu[bloom].push_back(1e3 * timing.LastSubmitSeconds);
        gpu[bloom].push_back(1e3 * timing.LastGPUSeconds);
      }
    }
  }
  timing.Release(window);
  const vtkBloomFrameStatistics plainCPU(cpu[0]), bloomCPU(cpu[1]), plainGPU(gpu[0]),
    bloomGPU(gpu[1]);
  std::printf("Four bloomed renderers (2 x 2 viewports of %s, vtkImageBloom's defaults) in one "
              "%dx%d window, %d frames of each kind, interleaved, ms\n"
              "| frame | CPU in Render(): median | mean | p99 | GPU: mean | p99 |\n"
              "|---|---|---|---|---|---|\n"
              "| plain | %.3f | %.3f | %.3f | %.3f | %.3f |\n"
              "| bloom | %.3f | %.3f | %.3f | %.3f | %.3f |\n"
              "The pass's CPU time per renderer (bloom over plain, mean, over 4): %.3f ms; GPU: "
              "%.3f ms\n",
    scene.c_str(), width, height, frames, plainCPU.Median, plainCPU.Mean, plainCPU.P99,
    plainGPU.Mean, plainGPU.P99, bloomCPU.Median, bloomCPU.Mean, bloomCPU.P99, bloomGPU.Mean,
    bloomGPU.P99, (bloomCPU.Mean - plainCPU.Mean) / 4.0, (bloomGPU.Mean - plainGPU.Mean) / 4.0);
  for (auto& pass : passes)
  {
    pass->ReleaseGraphicsResources(window);
  }
  return true;
}

//------------------------------------------------------------------------------
// VTK's vtkFramebufferPass with a colour target of any internal format: it makes its texture
// with the format set on it, where no texture was made before.
class vtkBloomFormatCopyPass : public vtkFramebufferPass
{
public:
  static vtkBloomFormatCopyPass* New();
  vtkTypeMacro(vtkBloomFormatCopyPass, vtkFramebufferPass);
  unsigned int InternalFormat = GL_RGBA8;

  void Render(const vtkRenderState* s) override
  {
    if (!this->ColorTexture->GetHandle())
    {
      this->ColorTexture->SetInternalFormat(this->InternalFormat);
      this->ColorTexture->SetDataType(
        this->InternalFormat == GL_RGBA8 ? GL_UNSIGNED_BYTE : GL_FLOAT);
    }
    this->Superclass::Render(s);
  }
};
vtkStandardNewMacro(vtkBloomFormatCopyPass);

// The --formats table (see above); false for an unknown scene.
bool FormatsTable(const std::string& scene, int width, int height, int frames)
{
  vtkBloomFrameTimer timer;
  if (!SetUp(timer, scene, "default", width, height))
  {
    return false;
  }
  const std::pair<const char*, unsigned int> formats[] = { { "RGBA8", GL_RGBA8 },
    { "R11F_G11F_B10F", GL_R11F_G11F_B10F }, { "RGBA16F", GL_RGBA16F }, { "RGBA32F", GL_RGBA32F } };
  std::vector<vtkSmartPointer<vtkBloomFormatCopyPass>> copies;
  std::vector<std::pair<std::string, vtkRenderPass*>> kinds = { { "plain", timer.Steps } };
  for (const auto& format : formats)
  {
    auto copy = vtkSmartPointer<vtkBloomFormatCopyPass>::New();
    copy->InternalFormat = format.second;
    copy->SetDelegatePass(timer.Steps);
    copies.push_back(copy);
    kinds.emplace_back(std::string(format.first) + " target + VTK blit", copy);
  }
  kinds.emplace_back("the bloom pass, no chain (compute copy)", timer.ComputeCopy);
  kinds.emplace_back("the bloom pass", timer.Bloom);
  std::vector<std::vector<double>> gpu(kinds.size());
  for (int f = -2; f < frames; ++f) // two warm-up frames of each
  {
    for (size_t k = 0; k < kinds.size(); ++k)
    {
      timer.FrameWith(kinds[k].second);
      if (f >= 0)
      {
        gpu[k].push_back(1e3 * timer.LastGPUSeconds);
      }
    }
  }
  const vtkBloomFrameStatistics plain(gpu[0]), target8(gpu[1]);
  std::printf("The scene's colour target, %s at %dx%d: GPU time per frame (GL_TIME_ELAPSED), ms, "
              "%d frames of each kind, interleaved\n"
              "| frame | median | mean | p99 | over plain, mean | over the RGBA8 target, mean |\n"
              "|---|---:|---:|---:|---:|---:|\n",
    scene.c_str(), width, height, frames);
  for (size_t k = 0; k < kinds.size(); ++k)
  {
    const vtkBloomFrameStatistics t(gpu[k]);
    std::printf("| %s | %.3f | %.3f | %.3f | %+.3f | %+.3f |\n", kinds[k].first.c_str(), t.Median,
      t.Mean, t.P99, t.Mean - plain.Mean, t.Mean - target8.Mean);
  }
  std::fflush(stdout);
  for (auto& copy : copies)
  {
    copy->ReleaseGraphicsResources(timer.Window);
  }
  return true;
}

int main(int argc, char* argv[])
{
  // Options first; they apply to every table that renders the bloom view.
  while (argc > 1 &&
    (std::strcmp(argv[1], "--fragment") == 0 || std::strcmp(argv[1], "--direct") == 0 ||
      std::strcmp(argv[1], "--fft") == 0 || std::strcmp(argv[1], "--pairs") == 0 ||
      std::strcmp(argv[1], "--resolved") == 0 || std::strcmp(argv[1], "--unrestricted") == 0 ||
      std::strcmp(argv[1], "--no-read-back") == 0 || std::strcmp(argv[1], "--depth-draw") == 0 ||
      (argc > 2 && std::strcmp(argv[1], "--single-draw") == 0) ||
      (argc > 2 && std::strcmp(argv[1], "--samples") == 0)))
  {
    if (std::strcmp(argv[1], "--single-draw") == 0 || std::strcmp(argv[1], "--samples") == 0)
    {
      (std::strcmp(argv[1], "--samples") == 0 ? Samples : SingleDraw) = std::atoi(argv[2]);
      --argc;
      ++argv;
    }
    else if (std::strcmp(argv[1], "--resolved") == 0)
    {
      Resolved = true;
    }
    else if (std::strcmp(argv[1], "--depth-draw") == 0)
    {
      DepthDraw = true;
    }
    else if (std::strcmp(argv[1], "--direct") == 0 || std::strcmp(argv[1], "--fft") == 0)
    {
      Convolution = std::strcmp(argv[1], "--fft") == 0 ? vtkBloomParameters::CONVOLUTION_FFT
                                                       : vtkBloomParameters::CONVOLUTION_DIRECT;
    }
    else if (std::strcmp(argv[1], "--pairs") == 0)
    {
      Pairs = true;
    }
    else if (std::strcmp(argv[1], "--unrestricted") == 0)
    {
      Unrestricted = true;
    }
    else if (std::strcmp(argv[1], "--no-read-back") == 0)
    {
      NoReadBack = true;
    }
    else
    {
      Fragment = true;
    }
    --argc;
    ++argv;
  }
  if (argc > 5 && std::strcmp(argv[1], "--selective") == 0)
  {
    return SelectiveTable(argv[2], std::atoi(argv[3]), std::atoi(argv[4]), std::atoi(argv[5])) ? 0
                                                                                               : 1;
  }
  if (argc > 5 && std::strcmp(argv[1], "--formats") == 0)
  {
    return FormatsTable(argv[2], std::atoi(argv[3]), std::atoi(argv[4]), std::atoi(argv[5])) ? 0
                                                                                             : 1;
  }
  if (argc > 5 && std::strcmp(argv[1], "--psf") == 0)
  {
    return PSFTable(argv[2], std::atoi(argv[3]), std::atoi(argv[4]), std::atoi(argv[5])) ? 0 : 1;
  }
  if (argc > 5 && std::strcmp(argv[1], "--renderers") == 0)
  {
    return RenderersTable(argv[2], std::atoi(argv[3]), std::atoi(argv[4]), std::atoi(argv[5])) ? 0
                                                                                               : 1;
  }
  if (argc > 5 && std::strcmp(argv[1], "--orbit") == 0)
  {
    return OrbitTable(argv[2], std::atoi(argv[3]), std::atoi(argv[4]), std::atoi(argv[5])) ? 0 : 1;
  }
  if (argc > 5 && std::strcmp(argv[1], "--quality") == 0)
  {
    return QualityTable(argv[2], std::atoi(argv[3]), std::atoi(argv[4]), std::atoi(argv[5]),
             argc > 6 ? argv[6] : nullptr)
      ? 0
      : 1;
  }
  if (argc > 5 && std::strcmp(argv[1], "--sync") == 0)
  {
    return SyncTable(argv[2], std::atoi(argv[3]), std::atoi(argv[4]), std::atoi(argv[5])) ? 0 : 1;
  }
  if (argc > 4 && std::strcmp(argv[1], "--sparse") == 0)
  {
    return SparseTable(std::atoi(argv[2]), std::atoi(argv[3]), std::atoi(argv[4])) ? 0 : 1;
  }
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
  std::vector<std::string> presets = vtkBloomParameters::GetPresetNames();
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
