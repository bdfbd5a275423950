// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// BloomChainSpeed: vtkImageBloom against the same chain in OpenCV and in stock VTK filters, the
// memory-bandwidth bound, peak extra memory and sparse scenes, in one run (issue 5).
//
// Every row blooms the same float32 RGBA image. Times are wall-clock per frame (Google
// Benchmark, real time), with all threads the library uses (vtkSMPTools/TBB, OpenCV's pool).
// Peak extra memory is counted by interposing malloc/free (and so operator new) in this
// executable: the peak of live heap bytes during a first, cold run of the chain minus the bytes
// live before it, minus the one output frame. It counts every buffer the chain allocates,
// VTK arrays and OpenCV matrices included.
#include "vtkBloomFrameStatistics.h"
#include "vtkImageBloom.h"

#include "vtkImageData.h"
#include "vtkImageGaussianSmooth.h"
#include "vtkImageMathematics.h"
#include "vtkImageResize.h"
#include "vtkImageShrink3D.h"
#include "vtkImageThreshold.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkTrivialProducer.h"

#include <benchmark/benchmark.h>

#if VTKBLOOM_HAVE_OPENCV
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#endif

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <malloc.h>
#include <map>
#include <string>
#include <thread>
#include <vector>

//------------------------------------------------------------------------------
// Heap accounting: glibc's allocator under a counting front.
extern "C"
{
  void* __libc_malloc(size_t);
  void* __libc_calloc(size_t, size_t);
  void* __libc_realloc(void*, size_t);
  void* __libc_memalign(size_t, size_t);
  void __libc_free(void*);
}

namespace
{
std::atomic<long long> LiveBytes{ 0 };
std::atomic<long long> PeakBytes{ 0 };

void Count(void* p, long long sign)
{
  if (p)
  {
    const long long now =
      LiveBytes.fetch_add(sign * static_cast<long long>(malloc_usable_size(p))) +
      sign * static_cast<long long>(malloc_usable_size(p));
    long long peak = PeakBytes.load();
    while (now > peak && !PeakBytes.compare_exchange_weak(peak, now))
    {
    }
  }
}
}

extern "C"
{
  void* malloc(size_t n)
  {
    void* p = __libc_malloc(n);
    Count(p, 1);
    return p;
  }
  void free(void* p)
  {
    Count(p, -1);
    __libc_free(p);
  }
  void* calloc(size_t n, size_t s)
  {
    void* p = __libc_calloc(n, s);
    Count(p, 1);
    return p;
  }
  void* realloc(void* old, size_t n)
  {
    Count(old, -1);
    void* p = __libc_realloc(old, n);
    Count(p ? p : (n ? nullptr : nullptr), 1);
    if (!p && n && old)
    {
      Count(old, 1); // realloc failed: the old block is still live
    }
    return p;
  }
  void* memalign(size_t a, size_t n)
  {
    void* p = __libc_memalign(a, n);
    Count(p, 1);
    return p;
  }
  void* aligned_alloc(size_t a, size_t n)
  {
    return memalign(a, n);
  }
  int posix_memalign(void** out, size_t a, size_t n)
  {
    *out = memalign(a, n);
    return *out || !n ? 0 : 12; // ENOMEM
  }
}

namespace
{
//------------------------------------------------------------------------------
// Scenes. FULL: bright discs on a grid over the whole image (the bright region is the whole
// frame), on a dim background below every threshold and knee (<= 0.3). SPARSE p: one compact bright
// disc covering p of the pixels.
float Hash(int i, int j, int c)
{
  uint32_t h = static_cast<uint32_t>(i) * 73856093u ^ static_cast<uint32_t>(j) * 19349663u ^
    static_cast<uint32_t>(c) * 83492791u;
  h ^= h >> 13;
  h *= 0x5bd1e995u;
  h ^= h >> 15;
  return (h & 0xffffff) / 16777216.0f;
}

vtkSmartPointer<vtkImageData> MakeScene(int w, int h, double brightFraction)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(w, h, 1);
  image->AllocateScalars(VTK_FLOAT, 4);
  float* p = static_cast<float*>(image->GetScalarPointer());
  const bool full = brightFraction < 0.0;
  const double r2 = brightFraction * w * h / M_PI;
  const int cell = std::max(16, w / 24);
  vtkSMPTools::For(0, h,
    [&](int j0, int j1)
    {
      for (int j = j0; j < j1; ++j)
      {
        for (int i = 0; i < w; ++i)
        {
          bool bright;
          if (full)
          {
            const double dx = (i % cell) - cell / 2.0, dy = (j % cell) - cell / 2.0;
            bright = dx * dx + dy * dy < cell * cell / 16.0;
          }
          else
          {
            const double dx = i - 0.6 * w, dy = j - 0.4 * h;
            bright = dx * dx + dy * dy < r2;
          }
          float* v = p + (static_cast<size_t>(j) * w + i) * 4;
          for (int c = 0; c < 3; ++c)
          {
            v[c] = bright ? 2.0f + 6.0f * Hash(i, j, c) : 0.3f * Hash(i, j, c);
          }
          v[3] = 1.0f;
        }
      }
    });
  return image;
}

struct Size
{
  const char* Name;
  int W, H;
};
const Size Sizes[] = { { "1080p", 1920, 1080 }, { "2160p", 3840, 2160 } };

// The shared cache of scenes, built once per (size, fraction).
vtkImageData* Scene(int size, double fraction)
{
  static std::map<std::pair<int, double>, vtkSmartPointer<vtkImageData>> cache;
  auto& s = cache[{ size, fraction }];
  if (!s)
  {
    s = MakeScene(Sizes[size].W, Sizes[size].H, fraction);
  }
  return s;
}

double FrameBytes(int size)
{
  return 4.0 * sizeof(float) * Sizes[size].W * Sizes[size].H;
}

//------------------------------------------------------------------------------
// The configurations. "webgpu-market" is the default preset. "gaussian" is the issue's
// OpenCV-like chain as vtkImageBloom parameters: per-channel max(c - 1, 0), 6 levels below full
// resolution with the 5-tap binomial downsample (OpenCV's pyrDown kernel), a sigma-2 Gaussian
// per level (13 taps), tent upsample-and-add, additive composite with strength 0.5.
void Configure(vtkImageBloom* bloom, const std::string& config)
{
  if (config == "gaussian")
  {
    bloom->SetPreset("webgpu-market");
    bloom->SetThresholdMode(3);
    bloom->SetThreshold(1.0);
    bloom->SetStartLevel(1);
    bloom->SetNumberOfLevels(6);
    bloom->SetDownsampleKernel(2);
    bloom->SetBlurKernel(vtkBloomParameters::BLUR_GAUSSIAN);
    bloom->SetBlurStandardDeviation(2.0);
    bloom->SetBlurRadius(6);
    bloom->SetBlurTapSpacing(1.0);
    bloom->SetStrength(0.5);
  }
  else if (config == "ping-pong.direct")
  {
    // The ping-pong preset with its 385-tap blur summed tap by tap (before the FFT path).
    bloom->SetPreset("ping-pong");
    bloom->SetConvolutionModeToDirect();
  }
  else if (config == "ping-pong.noblur")
  {
    // The ping-pong chain without its blur: the full-resolution bright pass, accumulation and
    // composite that any blur of this preset comes on top of.
    bloom->SetPreset("ping-pong");
    bloom->SetBlurIterations(0);
  }
  else if (config == "psf.airy" || config == "psf.gaussians")
  {
    // PSF mode with the default Airy pattern or sum of Gaussians, at the default threshold.
    bloom->SetPreset("webgpu-market");
    bloom->SetBloomModeToPSF();
    bloom->SetPSFType(
      config == "psf.airy" ? vtkBloomParameters::PSF_AIRY : vtkBloomParameters::PSF_GAUSSIANS);
  }
  else if (config.rfind("psf.wide", 0) == 0)
  {
    // A wide sum of Gaussians (radius 512, the widest sigma 170 px), exact ("psf.wide") or split
    // ("psf.wide.tail4", "psf.wide.tail8": PSFTailScale 4 or 8, the automatic core).
    bloom->SetPreset("webgpu-market");
    bloom->SetBloomModeToPSF();
    bloom->SetPSFType(vtkBloomParameters::PSF_GAUSSIANS);
    bloom->SetPSFRadius(512);
    bloom->GetParameters()->SetPSFGaussians({ 2.0, 16.0, 512.0 / 3.0 }, { 1.0, 0.3, 0.1 });
    const size_t tail = config.find(".tail");
    bloom->SetPSFTailScale(tail == std::string::npos ? 1 : std::stoi(config.substr(tail + 5)));
  }
  else
  {
    bloom->SetPreset(config.c_str());
  }
}

struct Row
{
  std::vector<double> Ms; ///< one time per repetition
  double ExtraFrames = -1.0;

  /// The median over the repetitions (0 when the row did not run): with repetitions
  /// interleaved across rows, a burst of load on a shared machine moves one sample of a row,
  /// not the row.
  double Median() const { return vtkBloomMedian(this->Ms); }
};
std::map<std::string, Row> Results;

// Peak extra heap of one cold run, in frames (beyond the input and one output frame).
template <typename F>
double PeakExtraFrames(F&& run, double frame)
{
  const long long before = LiveBytes.load();
  PeakBytes.store(before);
  run();
  return (PeakBytes.load() - before - frame) / frame;
}

//------------------------------------------------------------------------------
// vtkImageBloom.
void BM_Bloom(benchmark::State& state, std::string config, int size, double fraction, bool adaptive,
  bool statistics, int mode, bool avx2, std::string row)
{
  vtkImageData* input = Scene(size, fraction);
  auto make = [&]()
  {
    auto bloom = vtkSmartPointer<vtkImageBloom>::New();
    Configure(bloom, config);
    bloom->SetExecutionMode(mode);
    bloom->SetComputeStatistics(statistics);
    bloom->SetSkipEmptyBloom(adaptive);
    bloom->SetSkipDisabledEffects(adaptive);
    bloom->SetTrimPyramid(adaptive);
    bloom->SetRestrictToBrightRegion(adaptive);
    bloom->SetUseAVX2(avx2);
    bloom->SetInputData(input);
    return bloom;
  };
  double extra;
  {
    auto cold = make();
    extra = PeakExtraFrames([&] { cold->Update(); }, FrameBytes(size));
  }
  auto bloom = make();
  for (auto _ : state)
  {
    input->Modified(); // a new frame, as for the stock-VTK chain
    bloom->Update();
    benchmark::DoNotOptimize(bloom->GetOutput()->GetScalarPointer());
  }
  state.counters["extra_frames"] = extra;
  state.counters["fast"] = bloom->GetLastRunWasFast();
  state.counters["statistics"] = statistics;
  state.counters["avx2"] = bloom->GetLastRunUsedAVX2();
  state.counters["workspace_MB"] = bloom->GetLastWorkspaceBytes() / 1048576.0;
  Results[row].ExtraFrames = extra;
}

//------------------------------------------------------------------------------
// The same gaussian chain from stock VTK 9.1 filters: vtkImageMathematics + vtkImageThreshold
// (bright pass), vtkImageShrink3D (2x2 mean), vtkImageGaussianSmooth (sigma 2, radius 3
// sigma), vtkImageResize (upsample), vtkImageMathematics (add, scale, composite).
struct StockChain
{
  vtkNew<vtkTrivialProducer> Source;
  std::vector<vtkSmartPointer<vtkAlgorithm>> Keep;
  vtkAlgorithm* Last = nullptr;

  template <typename T>
  T* Add()
  {
    auto a = vtkSmartPointer<T>::New();
    this->Keep.push_back(a);
    return a;
  }

  explicit StockChain(vtkImageData* input)
  {
    this->Source->SetOutput(input);
    auto* minus = this->Add<vtkImageMathematics>();
    minus->SetOperationToAddConstant();
    minus->SetConstantC(-1.0);
    minus->SetInputConnection(this->Source->GetOutputPort());
    auto* clamp = this->Add<vtkImageThreshold>();
    clamp->ThresholdByUpper(0.0);
    clamp->SetOutValue(0.0);
    clamp->ReplaceOutOn();
    clamp->SetInputConnection(minus->GetOutputPort());
    std::vector<vtkAlgorithm*> levels{ clamp };
    for (int i = 0; i < 6; ++i)
    {
      auto* shrink = this->Add<vtkImageShrink3D>();
      shrink->SetShrinkFactors(2, 2, 1);
      shrink->AveragingOn();
      shrink->SetInputConnection(levels.back()->GetOutputPort());
      levels.push_back(shrink);
    }
    std::vector<vtkAlgorithm*> blurred(levels.size(), nullptr);
    for (size_t i = 1; i < levels.size(); ++i)
    {
      auto* blur = this->Add<vtkImageGaussianSmooth>();
      blur->SetDimensionality(2);
      blur->SetStandardDeviations(2.0, 2.0, 0.0);
      blur->SetRadiusFactors(3.0, 3.0, 0.0);
      blur->SetInputConnection(levels[i]->GetOutputPort());
      blurred[i] = blur;
    }
    vtkAlgorithm* acc = blurred.back();
    for (size_t i = levels.size() - 2; i >= 1; --i)
    {
      auto* up = this->Add<vtkImageResize>();
      up->SetResizeMethodToOutputDimensions();
      up->SetInputConnection(acc->GetOutputPort());
      this->Sizes.push_back({ up, static_cast<int>(i) });
      auto* add = this->Add<vtkImageMathematics>();
      add->SetOperationToAdd();
      add->SetInputConnection(0, up->GetOutputPort());
      add->SetInputConnection(1, blurred[i]->GetOutputPort());
      acc = add;
    }
    auto* full = this->Add<vtkImageResize>();
    full->SetResizeMethodToOutputDimensions();
    full->SetInputConnection(acc->GetOutputPort());
    this->Sizes.push_back({ full, 0 });
    auto* scale = this->Add<vtkImageMathematics>();
    scale->SetOperationToMultiplyByK();
    scale->SetConstantK(0.5);
    scale->SetInputConnection(full->GetOutputPort());
    auto* composite = this->Add<vtkImageMathematics>();
    composite->SetOperationToAdd();
    composite->SetInputConnection(0, this->Source->GetOutputPort());
    composite->SetInputConnection(1, scale->GetOutputPort());
    this->Last = composite;
    int dims[3];
    input->GetDimensions(dims);
    for (auto& s : this->Sizes)
    {
      int w = dims[0], h = dims[1];
      for (int k = 0; k < s.second; ++k)
      {
        w = std::max(1, w / 2);
        h = std::max(1, h / 2);
      }
      s.first->SetOutputDimensions(w, h, 1);
    }
  }
  std::vector<std::pair<vtkImageResize*, int>> Sizes;

  void Run()
  {
    this->Source->Modified();
    this->Last->Update();
  }
};

void BM_StockVTK(benchmark::State& state, int size, std::string row)
{
  vtkImageData* input = Scene(size, -1.0);
  double extra;
  {
    StockChain cold(input);
    extra = PeakExtraFrames([&] { cold.Run(); }, FrameBytes(size));
  }
  StockChain chain(input);
  for (auto _ : state)
  {
    chain.Run();
  }
  state.counters["extra_frames"] = extra;
  Results[row].ExtraFrames = extra;
}

#if VTKBLOOM_HAVE_OPENCV
//------------------------------------------------------------------------------
// The same gaussian chain in OpenCV: threshold (max(c - 1, 0)), 6 x pyrDown, GaussianBlur
// sigma 2 per level, pyrUp + add, pyrUp to full size, composite in + 0.5 bloom. Matrices are
// reused across frames, as an application would.
struct OpenCVChain
{
  cv::Mat Input, Bright, Out;
  std::vector<cv::Mat> Levels, Blurred, Acc;
  explicit OpenCVChain(vtkImageData* image)
  {
    int d[3];
    image->GetDimensions(d);
    this->Input = cv::Mat(d[1], d[0], CV_32FC4, image->GetScalarPointer());
    this->Levels.resize(7);
    this->Blurred.resize(7);
    this->Acc.resize(7);
  }
  void Run()
  {
    cv::subtract(this->Input, cv::Scalar(1.0, 1.0, 1.0, 1.0), this->Bright);
    cv::max(this->Bright, 0.0, this->Levels[0]);
    for (int i = 1; i <= 6; ++i)
    {
      cv::pyrDown(this->Levels[i - 1], this->Levels[i]);
      cv::GaussianBlur(
        this->Levels[i], this->Blurred[i], cv::Size(13, 13), 2.0, 2.0, cv::BORDER_REPLICATE);
    }
    this->Acc[6] = this->Blurred[6];
    for (int i = 5; i >= 1; --i)
    {
      cv::pyrUp(this->Acc[i + 1], this->Acc[i], this->Levels[i].size());
      this->Acc[i] += this->Blurred[i];
    }
    cv::pyrUp(this->Acc[1], this->Acc[0], this->Input.size());
    cv::scaleAdd(this->Acc[0], 0.5, this->Input, this->Out);
  }
};

void BM_OpenCV(benchmark::State& state, int size, int threads, std::string row)
{
  vtkImageData* input = Scene(size, -1.0);
  cv::setNumThreads(threads);
  double extra;
  {
    OpenCVChain cold(input);
    extra = PeakExtraFrames([&] { cold.Run(); }, FrameBytes(size));
  }
  OpenCVChain chain(input);
  for (auto _ : state)
  {
    chain.Run();
    benchmark::DoNotOptimize(chain.Out.data);
  }
  state.counters["extra_frames"] = extra;
  Results[row].ExtraFrames = extra;
}
#endif

//------------------------------------------------------------------------------
// STREAM triad a = b + s c on 3 x 128 MiB arrays with the given threads; returns GB/s.
double TriadBandwidth(int threads)
{
  const size_t n = (128u << 20) / sizeof(double);
  std::vector<double> a(n, 0.0), b(n, 1.0), c(n, 2.0);
  double best = 0.0;
  for (int rep = 0; rep < 5; ++rep)
  {
    const auto t0 = std::chrono::steady_clock::now();
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t)
    {
      pool.emplace_back(
        [&, t]
        {
          const size_t lo = n * t / threads, hi = n * (t + 1) / threads;
          for (size_t i = lo; i < hi; ++i)
          {
            a[i] = b[i] + 3.0 * c[i];
          }
        });
    }
    for (auto& th : pool)
    {
      th.join();
    }
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    best = std::max(best, 3.0 * n * sizeof(double) / s / 1e9);
  }
  benchmark::DoNotOptimize(a.data());
  return best;
}

// Whether a run failed or was skipped. Google Benchmark 1.8 replaced Run::error_occurred by
// Run::skipped; the overload on int is taken where the member `skipped` exists.
template <typename R>
auto RunDidNotComplete(const R& r, int) -> decltype(static_cast<bool>(r.skipped))
{
  return static_cast<bool>(r.skipped);
}
template <typename R>
bool RunDidNotComplete(const R& r, long)
{
  return r.error_occurred;
}

// Records every run's real time in ms (each repetition), then prints the summary table.
class Recorder : public benchmark::ConsoleReporter
{
public:
  void ReportRuns(const std::vector<Run>& runs) override
  {
    for (const auto& r : runs)
    {
      if (!RunDidNotComplete(r, 0) && r.run_type == Run::RT_Iteration)
      {
        std::string name = r.benchmark_name();
        const std::string suffix = "/real_time";
        if (name.size() > suffix.size() &&
          name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0)
        {
          name.resize(name.size() - suffix.size());
        }
        Results[name].Ms.push_back(r.GetAdjustedRealTime());
      }
    }
    ConsoleReporter::ReportRuns(runs);
  }
};

double Ms(const std::string& name)
{
  auto it = Results.find(name);
  return it == Results.end() ? 0.0 : it->second.Median();
}
}

//------------------------------------------------------------------------------
// The lead's GPU row registers itself here when Speed/ChainSpeedGPU.cxx is linked in.
extern "C" void vtkBloomRegisterGPUBenchmarks() __attribute__((weak));
// ... and prints its own table (frame times with and without the pass) after ours.
extern "C" void vtkBloomPrintGPUSummary() __attribute__((weak));

int main(int argc, char** argv)
{
  const int threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  for (int s = 0; s < 2; ++s)
  {
    const std::string size = Sizes[s].Name;
    auto reg = [&](const std::string& name, auto&&... args)
    {
      const std::string row = name + "/" + size;
      return benchmark::RegisterBenchmark(row.c_str(), args..., row)
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
    };
    reg("bloom.webgpu-market", BM_Bloom, std::string("webgpu-market"), s, -1.0, true, false,
      vtkImageBloom::FAST, true);
    if (vtkImageBloom::IsAVX2Available())
    {
      reg("bloom.webgpu-market.baseline", BM_Bloom, std::string("webgpu-market"), s, -1.0, true,
        false, vtkImageBloom::FAST, false);
    }
    reg("bloom.gaussian", BM_Bloom, std::string("gaussian"), s, -1.0, true, false,
      vtkImageBloom::FAST, true);
    // Wide blurs at full resolution: the preset that found the ring's recomputed support rows.
    reg("bloom.ping-pong", BM_Bloom, std::string("ping-pong"), s, -1.0, true, false,
      vtkImageBloom::FAST, true);
    reg("bloom.ping-pong.direct", BM_Bloom, std::string("ping-pong.direct"), s, -1.0, true, false,
      vtkImageBloom::FAST, true);
    reg("bloom.ping-pong.noblur", BM_Bloom, std::string("ping-pong.noblur"), s, -1.0, true, false,
      vtkImageBloom::FAST, true);
    reg("bloom.psf.airy", BM_Bloom, std::string("psf.airy"), s, -1.0, true, false,
      vtkImageBloom::FAST, true);
    reg("bloom.psf.gaussians", BM_Bloom, std::string("psf.gaussians"), s, -1.0, true, false,
      vtkImageBloom::FAST, true);
    for (const char* wide : { "psf.wide", "psf.wide.tail4", "psf.wide.tail8" })
    {
      reg(std::string("bloom.") + wide, BM_Bloom, std::string(wide), s, -1.0, true, false,
        vtkImageBloom::FAST, true);
    }
    reg("bloom.webgpu-market.statistics", BM_Bloom, std::string("webgpu-market"), s, -1.0, true,
      true, vtkImageBloom::FAST, true);
    reg("stockvtk.gaussian", BM_StockVTK, s);
#if VTKBLOOM_HAVE_OPENCV
    reg("opencv.gaussian.threads1", BM_OpenCV, s, 1);
    reg("opencv.gaussian.threads" + std::to_string(threads), BM_OpenCV, s, threads);
#endif
    for (double f : { 0.0, 0.001, 0.01, 0.1 })
    {
      char name[64];
      std::snprintf(name, sizeof(name), "bloom.webgpu-market.sparse%g", f * 100.0);
      reg(
        name, BM_Bloom, std::string("webgpu-market"), s, f, true, false, vtkImageBloom::FAST, true);
      std::snprintf(name, sizeof(name), "bloom.webgpu-market.sparse%g.adaptiveoff", f * 100.0);
      reg(name, BM_Bloom, std::string("webgpu-market"), s, f, false, false, vtkImageBloom::FAST,
        true);
    }
  }
  if (vtkBloomRegisterGPUBenchmarks)
  {
    vtkBloomRegisterGPUBenchmarks();
  }
  benchmark::Initialize(&argc, argv);
  const double bw1 = TriadBandwidth(1), bw = TriadBandwidth(threads);
  Recorder recorder;
  benchmark::RunSpecifiedBenchmarks(&recorder);

  std::printf("\nSTREAM triad: %.1f GB/s (1 thread), %.1f GB/s (%d threads)\n", bw1, bw, threads);
  std::printf("Bandwidth bound: 4.7 frames of traffic (fused two-pass design) / triad bandwidth\n"
              "Each time is the median over the row's repetitions (--benchmark_repetitions)\n\n");
  std::printf(
    "| size | row | ms | vs OpenCV | vs stock VTK | bound / time | extra memory (frames) |\n");
  std::printf("|---|---|---|---|---|---|---|\n");
  for (int s = 0; s < 2; ++s)
  {
    const std::string size = std::string("/") + Sizes[s].Name;
    double cv = 0.0;
    for (const auto& r : Results)
    {
      const double ms = r.second.Median();
      if (r.first.rfind("opencv.", 0) == 0 && r.first.find(size) != std::string::npos && ms > 0.0)
      {
        cv = cv > 0.0 ? std::min(cv, ms) : ms;
      }
    }
    const double stock = Ms("stockvtk.gaussian" + size);
    const double full = Ms("bloom.webgpu-market" + size);
    const double bound = 4.7 * FrameBytes(s) / (bw * 1e9) * 1e3;
    for (const auto& r : Results)
    {
      const double ms = r.second.Median();
      if (r.first.find(size) == std::string::npos || ms <= 0.0 || r.first.rfind("gpu.", 0) == 0)
      {
        continue;
      }
      auto ratio = [&](double other)
      {
        static char buf[32];
        std::snprintf(buf, sizeof(buf), other > 0.0 ? "%.2fx" : "-", other / ms);
        return std::string(buf);
      };
      std::printf("| %s | %s | %.2f | %s | %s | %.2f | %.2f |\n", Sizes[s].Name,
        r.first.substr(0, r.first.size() - size.size()).c_str(), ms, ratio(cv).c_str(),
        ratio(stock).c_str(), bound / ms, r.second.ExtraFrames);
    }
    std::printf("| %s | bandwidth bound | %.2f | | | 1.00 | |\n", Sizes[s].Name, bound);
    if (full > 0.0)
    {
      for (double f : { 0.0, 0.001, 0.01, 0.1 })
      {
        char name[64];
        std::snprintf(name, sizeof(name), "bloom.webgpu-market.sparse%g", f * 100.0);
        std::printf("%s sparse %g %%: %.3f of the full chain\n", Sizes[s].Name, f * 100.0,
          Ms(name + size) / full);
      }
    }
  }
  if (vtkBloomPrintGPUSummary)
  {
    vtkBloomPrintGPUSummary();
  }
  benchmark::Shutdown();
  return 0;
}
