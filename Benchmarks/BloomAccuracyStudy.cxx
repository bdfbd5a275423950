// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// The accuracy-versus-time study of issue 4 (docs/numerics.md).
//
//   BloomAccuracyStudy OUT_DIR [--quick]
//
// For every Gaussian method and sigma 0.5..64 it measures the impulse response against the
// float64 continuous Gaussian (the density sampled at the integers, untruncated, normalized)
// and the time per megapixel of a 2-D blur of a 1920x1080 float RGBA image; for the bloom
// pyramid variants (13-tap, box or binomial down; tent or bilinear up; 1..5 levels) it measures
// the point spread function of down^L up^L against the Gaussian of the same variance, and its
// time. Built with rendering (VTKBLOOM_ENABLE_RENDERING), it also runs every vtkImageBloom
// preset on the same frame through vtkBloomPass::ApplyToImage (the GPU chain) and through the
// CPU filter's FAST (float32) mode, each against the filter's REFERENCE (double) mode, with the
// time of all three. It writes OUT_DIR/accuracy.md (the Markdown tables) and
// OUT_DIR/accuracy.csv (for scripts/plot-accuracy.py). --quick uses a 480x270 image and fewer
// sigmas, for smoke runs.
#include <vtkDataArray.h>
#include <vtkImageBloom.h>
#include <vtkImageData.h>
#include <vtkImageGaussianSmooth.h>
#include <vtkImagePyramidDown.h>
#include <vtkImagePyramidUp.h>
#include <vtkImageSeparableGaussian.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>

#ifdef VTKBLOOM_ACCURACY_WITH_GPU
#include <vtkBloomPass.h>
#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkRenderWindow.h>
#endif

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
struct Row
{
  std::string Family;  ///< "gaussian", "chain", or "gpu" and "cpu" (see AddGpuRows)
  std::string Method;  ///< curve name in the plot
  double Sigma = 0.0;  ///< nominal sigma (Gaussians) or effective sigma (chains)
  double MaxAbs = 0.0; ///< max |h - g| / max g; gpu and cpu: max |out - ref| / max ref
  double Rms = 0.0;    ///< RMS of h - g over |x| <= 4 sigma, / max g; gpu and cpu: relative L2
  double VarianceRatio = 0.0;
  double MillisecondsPerMegapixel = 0.0;
  std::string Note;         ///< levels (chains) or the preset (gpu and cpu)
  double AbsoluteMax = 0.0; ///< gpu and cpu: max |out - ref|
  bool Reference = false;   ///< the double chain itself (its error is 0 by definition)
};

using Clock = std::chrono::steady_clock;

// Best time of up to five runs, repeated while under half a second in total.
double TimeIt(const std::function<void()>& run)
{
  double best = 1e300, total = 0.0;
  for (int k = 0; k < 5 && (k < 1 || total < 0.5); ++k)
  {
    const auto start = Clock::now();
    run();
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    best = std::min(best, seconds);
    total += seconds;
  }
  return best;
}

vtkSmartPointer<vtkImageData> MakeImage(int w, int h, int components, int type)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetExtent(0, w - 1, 0, h - 1, 0, 0);
  image->AllocateScalars(type, components);
  return image;
}

// A deterministic HDR-like test frame: smooth gradient plus bright discs.
vtkSmartPointer<vtkImageData> Frame(int w, int h)
{
  auto image = MakeImage(w, h, 4, VTK_FLOAT);
  float* p = static_cast<float*>(image->GetScalarPointer());
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i, p += 4)
    {
      const double g = 0.05 + 0.3 * i / w + 0.2 * j / h;
      const double d = std::hypot(std::fmod(i, 160.0) - 80.0, std::fmod(j, 120.0) - 60.0);
      const double e = d < 6.0 ? 50.0 : 0.0;
      p[0] = static_cast<float>(g + e);
      p[1] = static_cast<float>(g + 0.5 * e);
      p[2] = static_cast<float>(g + 0.25 * e);
      p[3] = 1.0f;
    }
  }
  return image;
}

std::vector<double> ContinuousGaussian(double sigma, int n, int centre)
{
  std::vector<double> g(static_cast<size_t>(n));
  long double total = 0.0L;
  for (int i = 0; i < n; ++i)
  {
    const double x = (i - centre) / sigma;
    g[static_cast<size_t>(i)] = std::exp(-0.5 * x * x);
    total += g[static_cast<size_t>(i)];
  }
  for (double& v : g)
  {
    v = static_cast<double>(v / total);
  }
  return g;
}

void Compare(const std::vector<double>& h, const std::vector<double>& g,
  const std::vector<double>& x2, double sigma, Row& row)
{
  double peak = 0.0;
  for (double v : g)
  {
    peak = std::max(peak, v);
  }
  long double squares = 0.0L, sum = 0.0L, moment = 0.0L;
  int inside = 0;
  for (size_t i = 0; i < h.size(); ++i)
  {
    const double d = h[i] - g[i];
    row.MaxAbs = std::max(row.MaxAbs, std::fabs(d));
    if (x2[i] <= std::max(16.0 * sigma * sigma, 1.0))
    {
      squares += static_cast<long double>(d) * d;
      ++inside;
    }
    sum += h[i];
    moment += h[i] * x2[i];
  }
  row.MaxAbs /= peak;
  row.Rms = std::sqrt(static_cast<double>(squares / std::max(inside, 1))) / peak;
  row.VarianceRatio = static_cast<double>(moment / sum) / (sigma * sigma);
}

// The Gaussian methods: a configured filter for sigma on the x axis (y too for timing).
struct GaussianMethod
{
  std::string Name;
  std::function<vtkSmartPointer<vtkAlgorithm>(double sx, double sy)> Make;
};

std::vector<GaussianMethod> GaussianMethods()
{
  std::vector<GaussianMethod> methods;
  auto separable = [](int method, int kind, int convolution = 0)
  {
    return [method, kind, convolution](double sx, double sy) -> vtkSmartPointer<vtkAlgorithm>
    {
      auto f = vtkSmartPointer<vtkImageSeparableGaussian>::New();
      f->SetMethod(method);
      f->SetKernelType(kind);
      f->SetConvolutionMode(convolution);
      f->SetStandardDeviations(sx, sy, 0.0);
      f->SetBorderMode(vtkImageSeparableGaussian::CLAMP);
      return f;
    };
  };
  methods.push_back({ "exact sampled 4 sigma, direct",
    separable(
      vtkImageSeparableGaussian::EXACT, 0, vtkImageSeparableGaussian::CONVOLUTION_DIRECT) });
  methods.push_back({ "exact sampled 4 sigma, FFT",
    separable(vtkImageSeparableGaussian::EXACT, 0, vtkImageSeparableGaussian::CONVOLUTION_FFT) });
  methods.push_back({ "exact discrete 4 sigma", separable(vtkImageSeparableGaussian::EXACT, 2) });
  methods.push_back({ "box x3", separable(vtkImageSeparableGaussian::BOX_CASCADE_3, 0) });
  methods.push_back({ "box x5", separable(vtkImageSeparableGaussian::BOX_CASCADE_5, 0) });
  methods.push_back({ "recursive (YvV)", separable(vtkImageSeparableGaussian::RECURSIVE, 0) });
  methods.push_back({ "vtkImageGaussianSmooth 1.5 sigma",
    [](double sx, double sy) -> vtkSmartPointer<vtkAlgorithm>
    {
      auto f = vtkSmartPointer<vtkImageGaussianSmooth>::New();
      f->SetDimensionality(sy > 0.0 ? 2 : 1);
      f->SetStandardDeviations(sx, sy > 0.0 ? sy : 1.0, 0.0);
      return f;
    } });
  return methods;
}

vtkSmartPointer<vtkImageData> Run(vtkAlgorithm* filter, vtkImageData* input)
{
  filter->SetInputDataObject(input);
  filter->Modified();
  filter->Update();
  return vtkImageData::SafeDownCast(filter->GetOutputDataObject(0));
}

void GaussianRows(const std::vector<double>& sigmas, vtkImageData* frame, std::vector<Row>& rows)
{
  const double megapixels = static_cast<double>(frame->GetNumberOfPoints()) / 1e6;
  for (const GaussianMethod& method : GaussianMethods())
  {
    for (double sigma : sigmas)
    {
      Row row;
      row.Family = "gaussian";
      row.Method = method.Name;
      row.Sigma = sigma;
      // Error: the 1-D impulse response on a line of +/- (12 sigma + 32), in double.
      const int half = static_cast<int>(std::ceil(12.0 * sigma)) + 32;
      const int n = 2 * half + 1;
      auto line = MakeImage(n, 1, 1, VTK_DOUBLE);
      double* p = static_cast<double*>(line->GetScalarPointer());
      std::fill(p, p + n, 0.0);
      p[half] = 1.0;
      auto filter = method.Make(sigma, 0.0);
      auto out = Run(filter, line);
      std::vector<double> h(static_cast<size_t>(n)), x2(static_cast<size_t>(n));
      for (int i = 0; i < n; ++i)
      {
        h[static_cast<size_t>(i)] = out->GetScalarComponentAsDouble(i, 0, 0, 0);
        x2[static_cast<size_t>(i)] = static_cast<double>(i - half) * (i - half);
      }
      Compare(h, ContinuousGaussian(sigma, n, half), x2, sigma, row);
      // Time: the 2-D blur of the frame.
      auto blur = method.Make(sigma, sigma);
      row.MillisecondsPerMegapixel = 1e3 * TimeIt([&] { Run(blur, frame); }) / megapixels;
      std::cerr << row.Method << " sigma " << sigma << ": " << row.MaxAbs << ", "
                << row.MillisecondsPerMegapixel << " ms/MP\n";
      rows.push_back(row);
    }
  }
}

// down^L then up^L with the pyramid filters.
vtkSmartPointer<vtkImageData> Chain(vtkImageData* input, int down, int up, int levels)
{
  std::vector<vtkSmartPointer<vtkImageData>> pyramid{ input };
  for (int l = 0; l < levels; ++l)
  {
    vtkNew<vtkImagePyramidDown> filter;
    filter->SetKernel(down);
    auto next = vtkSmartPointer<vtkImageData>::New();
    next->ShallowCopy(Run(filter, pyramid.back()));
    pyramid.push_back(next);
  }
  vtkSmartPointer<vtkImageData> current = pyramid.back();
  for (int l = levels - 1; l >= 0; --l)
  {
    vtkNew<vtkImagePyramidUp> filter;
    filter->SetKernel(up);
    filter->SetFineInputData(pyramid[static_cast<size_t>(l)]);
    auto next = vtkSmartPointer<vtkImageData>::New();
    next->ShallowCopy(Run(filter, current));
    current = next;
  }
  return current;
}

void ChainRows(int maxLevels, vtkImageData* frame, std::vector<Row>& rows)
{
  const double megapixels = static_cast<double>(frame->GetNumberOfPoints()) / 1e6;
  const char* downNames[] = { "13-tap", "box", "binomial" };
  const char* upNames[] = { "tent", "bilinear" };
  for (int down = 0; down < 3; ++down)
  {
    for (int up = 0; up < 2; ++up)
    {
      for (int levels = 1; levels <= maxLevels; ++levels)
      {
        // The PSF of a centred impulse on a 2-D image wide enough for the deepest level.
        const int n = 64 << levels;
        auto impulse = MakeImage(n, n, 1, VTK_DOUBLE);
        double* p = static_cast<double*>(impulse->GetScalarPointer());
        std::fill(p, p + static_cast<size_t>(n) * n, 0.0);
        const int c = n / 2;
        p[static_cast<size_t>(c) * n + c] = 1.0;
        auto psf = Chain(impulse, down, up, levels);
        const double* q = static_cast<const double*>(psf->GetScalarPointer());
        // Centroid and variance of the PSF, then the 2-D Gaussian of that variance there.
        long double s = 0, mx = 0, my = 0;
        for (int j = 0; j < n; ++j)
        {
          for (int i = 0; i < n; ++i)
          {
            const double v = q[static_cast<size_t>(j) * n + i];
            s += v;
            mx += v * i;
            my += v * j;
          }
        }
        const double cx = static_cast<double>(mx / s), cy = static_cast<double>(my / s);
        long double vx = 0;
        for (int j = 0; j < n; ++j)
        {
          for (int i = 0; i < n; ++i)
          {
            const double v = q[static_cast<size_t>(j) * n + i];
            vx += v * ((i - cx) * (i - cx) + (j - cy) * (j - cy));
          }
        }
        const double sigma = std::sqrt(static_cast<double>(vx / s) / 2.0);
        std::vector<double> h(static_cast<size_t>(n) * n), g(h.size()), x2(h.size());
        long double total = 0;
        for (int j = 0; j < n; ++j)
        {
          for (int i = 0; i < n; ++i)
          {
            const size_t k = static_cast<size_t>(j) * n + i;
            const double r2 = (i - cx) * (i - cx) + (j - cy) * (j - cy);
            h[k] = q[k];
            x2[k] = r2 / 2.0; // so that the variance ratio is per axis
            g[k] = std::exp(-r2 / (2 * sigma * sigma));
            total += g[k];
          }
        }
        for (double& v : g)
        {
          v = static_cast<double>(v / total);
        }
        Row row;
        row.Family = "chain";
        row.Method = std::string("pyramid ") + downNames[down] + " + " + upNames[up];
        row.Sigma = sigma;
        Compare(h, g, x2, sigma, row);
        row.Note = std::to_string(levels) + (levels == 1 ? " level" : " levels");
        row.MillisecondsPerMegapixel =
          1e3 * TimeIt([&] { Chain(frame, down, up, levels); }) / megapixels;
        std::cerr << row.Method << " " << row.Note << ": sigma " << sigma << ", " << row.MaxAbs
                  << ", " << row.MillisecondsPerMegapixel << " ms/MP\n";
        rows.push_back(row);
      }
    }
  }
}

// max |a - b| and the relative L2 ||a - b|| / ||b|| over the colour channels of two RGBA
// images of the same size, and the largest colour value of b.
struct Difference
{
  double MaxAbs = 0.0;
  double RelativeL2 = 0.0;
  double Peak = 0.0;
};

Difference Compare(vtkImageData* a, vtkImageData* b)
{
  Difference d;
  vtkDataArray* x = a->GetPointData()->GetScalars();
  vtkDataArray* y = b->GetPointData()->GetScalars();
  long double num = 0.0L, den = 0.0L;
  for (vtkIdType p = 0; p < b->GetNumberOfPoints(); ++p)
  {
    for (int c = 0; c < 3; ++c)
    {
      const double u = x->GetComponent(p, c), v = y->GetComponent(p, c);
      d.MaxAbs = std::max(d.MaxAbs, std::fabs(u - v));
      d.Peak = std::max(d.Peak, std::fabs(v));
      num += static_cast<long double>(u - v) * (u - v);
      den += static_cast<long double>(v) * v;
    }
  }
  d.RelativeL2 = std::sqrt(static_cast<double>(num / den));
  return d;
}

Row ChainRow(const char* family, const std::string& method, const std::string& preset,
  const Difference& d, double millisecondsPerMegapixel)
{
  Row row;
  row.Family = family;
  row.Method = method;
  row.Note = preset;
  row.MaxAbs = d.MaxAbs / d.Peak;
  row.Rms = d.RelativeL2;
  row.AbsoluteMax = d.MaxAbs;
  row.MillisecondsPerMegapixel = millisecondsPerMegapixel;
  return row;
}

std::string Format(double v, const char* format)
{
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), format, v);
  return buffer;
}

// The FFT rows: the exact Gaussian through the FFT against the same kernel summed directly, a
// 2-D blur of the frame for sigma 8 to 64 (clamp border), and the ping-pong preset's FAST chain
// with its 385-tap blur through the FFT against the same chain summing it directly and against
// the REFERENCE chain (double); relative L2 and max abs over the peak, and the time per
// megapixel of the FFT path (its Note holds the direct path's).
void AddFFTRows(vtkImageData* frame, const std::vector<double>& sigmas, std::vector<Row>& rows)
{
  const double megapixels = static_cast<double>(frame->GetNumberOfPoints()) / 1e6;
  for (double sigma : sigmas)
  {
    if (sigma < 8.0)
    {
      continue;
    }
    vtkNew<vtkImageSeparableGaussian> direct, fft;
    for (vtkImageSeparableGaussian* f : { direct.Get(), fft.Get() })
    {
      f->SetStandardDeviations(sigma, sigma, 0.0);
      f->SetBorderModeToClamp();
    }
    direct->SetConvolutionModeToDirect();
    fft->SetConvolutionModeToFFT();
    vtkNew<vtkImageData> a, b;
    const double directMs = 1e3 * TimeIt([&] { Run(direct, frame); }) / megapixels;
    a->DeepCopy(direct->GetOutput());
    const double fftMs = 1e3 * TimeIt([&] { Run(fft, frame); }) / megapixels;
    b->DeepCopy(fft->GetOutput());
    Row row = ChainRow("fft", "Gaussian FFT vs direct", "", Compare(b, a), fftMs);
    row.Sigma = sigma;
    row.Note = Format(directMs, "%.1f");
    std::cerr << "FFT sigma " << sigma << ": " << row.Rms << ", " << fftMs << " ms/MP (direct "
              << directMs << ")\n";
    rows.push_back(row);
  }
  auto bloom = [&](int execution, int convolution, vtkImageData* out)
  {
    vtkNew<vtkImageBloom> f;
    f->SetPreset("ping-pong");
    f->SetExecutionMode(execution);
    f->SetConvolutionMode(convolution);
    f->ComputeStatisticsOff();
    f->SetInputData(frame);
    f->Update(); // the chain's operators and FFT plans are built once, as for a video
    const double ms = 1e3 *
      TimeIt(
        [&]
        {
          frame->Modified();
          f->Update();
        }) /
      megapixels;
    out->DeepCopy(f->GetOutput());
    return ms;
  };
  vtkNew<vtkImageData> reference, direct, fft;
  bloom(vtkImageBloom::REFERENCE, vtkBloomParameters::CONVOLUTION_DIRECT, reference);
  const double directMs =
    bloom(vtkImageBloom::FAST, vtkBloomParameters::CONVOLUTION_DIRECT, direct);
  const double fftMs = bloom(vtkImageBloom::FAST, vtkBloomParameters::CONVOLUTION_FFT, fft);
  Row row = ChainRow("fft", "ping-pong FFT vs direct", "", Compare(fft, direct), fftMs);
  row.Note = Format(directMs, "%.1f");
  row.VarianceRatio = Compare(fft, reference).RelativeL2; // against the double chain
  rows.push_back(row);
}

// The GPU rows: every vtkImageBloom preset on the frame through vtkBloomPass::ApplyToImage
// (32-bit storage; the pass's chain always runs on 32-bit float targets) and through the CPU
// filter's FAST mode (its float32 default), both against its REFERENCE mode (the chain in
// double), and the time of all three, measured as the other rows are. The GPU time is the whole
// ApplyToImage call: upload, chain and read back. The CPU times are with statistics off (the
// pass computes none). Without a GPU context (or when built without rendering) a note says so
// and no row is added. `device` receives the OpenGL renderer and window class.
void AddGpuRows(vtkImageData* frame, std::vector<Row>& rows, std::string& device)
{
#ifndef VTKBLOOM_ACCURACY_WITH_GPU
  (void)frame;
  (void)rows;
  (void)device;
  std::cerr << "note: built without rendering (VTKBLOOM_ENABLE_RENDERING off): no GPU rows\n";
#else
  const double megapixels = static_cast<double>(frame->GetNumberOfPoints()) / 1e6;
  vtkNew<vtkRenderWindow> window;
  vtkOpenGLRenderWindow* gl = vtkOpenGLRenderWindow::SafeDownCast(window);
  if (!gl)
  {
    std::cerr << "note: no OpenGL render window in this VTK: no GPU rows\n";
    return;
  }
  // VTK 9.1's X window aborts the process when it cannot open its display, so look first: set,
  // and for a local display (":N", ":N.S") its socket present.
  if (gl->IsA("vtkXOpenGLRenderWindow"))
  {
    const char* variable = std::getenv("DISPLAY");
    const std::string display = variable ? variable : "";
    bool present = !display.empty();
    if (present && display[0] == ':')
    {
      const std::string number = display.substr(1, display.find('.') - 1);
      present = std::filesystem::exists("/tmp/.X11-unix/X" + number);
    }
    if (!present)
    {
      std::cerr << "note: " << gl->GetClassName() << " needs an X display and DISPLAY='" << display
                << "' names none (run under scripts/lib/with-xvfb.sh): no GPU rows\n";
      return;
    }
  }
  gl->SetOffScreenRendering(1);
  gl->SetMultiSamples(0);
  gl->SetSize(16, 16);
  if (!gl->SupportsOpenGL())
  {
    std::cerr << "note: no usable OpenGL context (" << gl->GetOpenGLSupportMessage()
              << "): no GPU rows\n";
    return;
  }
  // Any VTK error during the GPU rows (context, shaders, ApplyToImage) is printed and drops
  // them.
  bool failed = false;
  vtkNew<vtkCallbackCommand> onError;
  onError->SetClientData(&failed);
  onError->SetCallback(
    [](vtkObject*, unsigned long, void* flag, void* message)
    {
      std::cerr << "error: " << (message ? static_cast<const char*>(message) : "") << "\n";
      *static_cast<bool*>(flag) = true;
    });
  gl->AddObserver(vtkCommand::ErrorEvent, onError);
  gl->Initialize();
  std::string renderer = "unknown renderer";
  std::istringstream capabilities(gl->ReportCapabilities());
  for (std::string line; std::getline(capabilities, line);)
  {
    const std::string key = "OpenGL renderer string:";
    if (line.compare(0, key.size(), key) == 0)
    {
      renderer = line.substr(line.find_first_not_of(' ', key.size()));
    }
  }
  device = renderer + " (" + gl->GetClassName() + ")";
  std::cerr << "GPU rows on " << device << "\n";

  vtkNew<vtkBloomPass> pass;
  pass->AddObserver(vtkCommand::ErrorEvent, onError);
  pass->SetFloatPrecisionTo32Bit();
  std::vector<Row> added;
  for (const std::string& preset : vtkImageBloom::GetPresetNames())
  {
    pass->SetPreset(preset.c_str());
    vtkNew<vtkImageBloom> cpu;
    cpu->AddObserver(vtkCommand::ErrorEvent, onError);
    cpu->SetPreset(preset.c_str());
    cpu->SetComputeStatistics(false);
    cpu->SetExecutionModeToReference();
    auto reference = vtkSmartPointer<vtkImageData>::New();
    reference->DeepCopy(Run(cpu, frame));
    const double referenceTime = 1e3 * TimeIt([&] { Run(cpu, frame); }) / megapixels;
    cpu->SetExecutionModeToFast();
    auto fast = vtkSmartPointer<vtkImageData>::New();
    fast->DeepCopy(Run(cpu, frame));
    const double fastTime = 1e3 * TimeIt([&] { Run(cpu, frame); }) / megapixels;
    vtkNew<vtkImageData> gpu;
    failed = !pass->ApplyToImage(gl, frame, gpu) || failed; // also builds shaders and targets
    if (failed)
    {
      break;
    }
    const double gpuTime =
      1e3 * TimeIt([&] { failed = !pass->ApplyToImage(gl, frame, gpu) || failed; }) / megapixels;
    if (failed)
    {
      break;
    }
    const Difference g = Compare(gpu, reference), f = Compare(fast, reference);
    added.push_back(ChainRow("gpu", "vtkBloomPass (GPU) vs double chain", preset, g, gpuTime));
    added.push_back(ChainRow("cpu", "vtkImageBloom FAST vs double chain", preset, f, fastTime));
    Difference none;
    none.Peak = 1.0;
    added.push_back(ChainRow("cpu", "vtkImageBloom REFERENCE", preset, none, referenceTime));
    added.back().Reference = true;
    std::cerr << "preset " << preset << ": GPU relative L2 " << g.RelativeL2 << ", " << gpuTime
              << " ms/MP; FAST " << f.RelativeL2 << ", " << fastTime << " ms/MP; REFERENCE "
              << referenceTime << " ms/MP\n";
  }
  pass->ReleaseGraphicsResources(gl);
  if (failed)
  {
    std::cerr << "note: the GPU pass reported an error: no GPU rows\n";
    device.clear();
    return;
  }
  rows.insert(rows.end(), added.begin(), added.end());
#endif
}

}

int main(int argc, char* argv[])
{
  if (argc < 2)
  {
    std::cerr << "usage: BloomAccuracyStudy OUT_DIR [--quick]\n";
    return 2;
  }
  const std::string dir = argv[1];
  const bool quick = argc > 2 && std::string(argv[2]) == "--quick";
  const int w = quick ? 480 : 1920, h = quick ? 270 : 1080;
  const std::vector<double> sigmas =
    quick ? std::vector<double>{ 1.0, 8.0 } : std::vector<double>{ 0.5, 1, 2, 4, 8, 16, 32, 64 };
  auto frame = Frame(w, h);
  std::vector<Row> rows;
  GaussianRows(sigmas, frame, rows);
  ChainRows(quick ? 2 : 5, frame, rows);
  AddFFTRows(frame, sigmas, rows);
  std::string device;
  AddGpuRows(frame, rows, device);

  std::ofstream csv(dir + "/accuracy.csv");
  csv << "family,method,sigma,max_abs,rms,variance_ratio,ms_per_mp,note\n";
  for (const Row& r : rows)
  {
    csv << r.Family << ",\"" << r.Method << "\"," << r.Sigma << "," << r.MaxAbs << "," << r.Rms
        << "," << r.VarianceRatio << "," << r.MillisecondsPerMegapixel << "," << r.Note << "\n";
  }
  std::ofstream md(dir + "/accuracy.md");
  md << "Gaussian methods: error of the 1-D impulse response against the float64 continuous "
        "Gaussian (max abs and RMS over ±4σ, both over the peak; variance ratio σ²_eff/σ²), "
        "time of a 2-D blur of a "
     << w << "×" << h << " float RGBA image (clamp border).\n\n";
  md << "| method | σ | max abs | RMS | variance ratio | ms / MP "
        "|\n|---|---:|---:|---:|---:|---:|\n";
  for (const Row& r : rows)
  {
    if (r.Family != "gaussian")
    {
      continue;
    }
    md << "| " << r.Method << " | " << Format(r.Sigma, "%g") << " | " << Format(r.MaxAbs, "%.2e")
       << " | " << Format(r.Rms, "%.2e") << " | " << Format(r.VarianceRatio, "%.5f") << " | "
       << Format(r.MillisecondsPerMegapixel, "%.1f") << " |\n";
  }
  md << "\nBloom pyramid (down^L then up^L) as a wide Gaussian: its 2-D point spread function "
        "against the Gaussian of the same variance (σ_eff), and the time of the chain on the "
        "same image.\n\n";
  md << "| chain | levels | σ_eff | max abs | RMS | ms / MP |\n|---|---:|---:|---:|---:|---:|\n";
  for (const Row& r : rows)
  {
    if (r.Family != "chain")
    {
      continue;
    }
    md << "| " << r.Method << " | " << r.Note.substr(0, r.Note.find(' ')) << " | "
       << Format(r.Sigma, "%.2f") << " | " << Format(r.MaxAbs, "%.2e") << " | "
       << Format(r.Rms, "%.2e") << " | " << Format(r.MillisecondsPerMegapixel, "%.1f") << " |\n";
  }
  md << "\nFFT against the direct exact path (vtkBloomFFTConvolution, single precision): the "
        "exact Gaussian's 2-D blur of the same image, and the ping-pong preset's FAST chain "
        "(its 385-tap blur), each against the same computation summing the taps; the ping-pong "
        "row also against the REFERENCE chain (double).\n\n";
  md << "| operator | σ | relative L2 vs direct | max abs / peak | vs REFERENCE | FFT ms / MP | "
        "direct ms / MP |\n|---|---:|---:|---:|---:|---:|---:|\n";
  for (const Row& r : rows)
  {
    if (r.Family != "fft")
    {
      continue;
    }
    const bool gaussian = r.Method.rfind("Gaussian", 0) == 0;
    md << "| " << (gaussian ? "Gaussian" : "ping-pong preset") << " | "
       << (gaussian ? Format(r.Sigma, "%g") : std::string("385 taps")) << " | "
       << Format(r.Rms, "%.2e") << " | " << Format(r.MaxAbs, "%.2e") << " | "
       << (gaussian ? std::string("") : Format(r.VarianceRatio, "%.2e")) << " | "
       << Format(r.MillisecondsPerMegapixel, "%.1f") << " | " << r.Note << " |\n";
  }
  if (!device.empty())
  {
    md << "\nThe GPU pass against the CPU filter: every preset of `vtkImageBloom` on the same "
          "image, through `vtkBloomPass::ApplyToImage` (GPU: "
       << device
       << "; the time is the whole call, upload and read-back included) and through the "
          "filter's float32 FAST mode, against its REFERENCE mode (the chain in double): "
          "relative L2 and max abs over the colour channels, and max abs over the largest "
          "colour value of the reference. CPU times with statistics off.\n\n";
    md << "| preset | implementation | relative L2 | max abs | max abs / peak | ms / MP "
          "|\n|---|---|---:|---:|---:|---:|\n";
    for (const Row& r : rows)
    {
      if (r.Family != "gpu" && r.Family != "cpu")
      {
        continue;
      }
      const bool reference = r.Reference;
      md << "| " << r.Note << " | " << r.Method.substr(0, r.Method.find(" vs ")) << " | "
         << (reference ? "(reference)" : Format(r.Rms, "%.2e")) << " | "
         << (reference ? "" : Format(r.AbsoluteMax, "%.2e")) << " | "
         << (reference ? "" : Format(r.MaxAbs, "%.2e")) << " | "
         << Format(r.MillisecondsPerMegapixel, "%.1f") << " |\n";
    }
  }
  return 0;
}
