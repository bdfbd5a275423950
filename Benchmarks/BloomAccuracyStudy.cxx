// The accuracy-versus-time study of issue 4 (docs/numerics.md).
//
//   BloomAccuracyStudy OUT_DIR [--quick]
//
// For every Gaussian method and sigma 0.5..64 it measures the impulse response against the
// float64 continuous Gaussian (the density sampled at the integers, untruncated, normalized)
// and the time per megapixel of a 2-D blur of a 1920x1080 float RGBA image; for the bloom
// pyramid variants (13-tap, box or binomial down; tent or bilinear up; 1..5 levels) it measures
// the point spread function of down^L up^L against the Gaussian of the same variance, and its
// time. It writes OUT_DIR/accuracy.md (the Markdown tables) and OUT_DIR/accuracy.csv (for
// scripts/plot-accuracy.py). --quick uses a 480x270 image and fewer sigmas, for smoke runs.
#include <vtkImageData.h>
#include <vtkImageGaussianSmooth.h>
#include <vtkImagePyramidDown.h>
#include <vtkImagePyramidUp.h>
#include <vtkImageSeparableGaussian.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
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
  std::string Family;  ///< "gaussian" or "chain" (or "gpu", see AddGpuRows)
  std::string Method;  ///< curve name in the plot
  double Sigma = 0.0;  ///< nominal sigma (Gaussians) or effective sigma (chains)
  double MaxAbs = 0.0; ///< max |h - g| / max g
  double Rms = 0.0;    ///< RMS of h - g over |x| <= 4 sigma, / max g
  double VarianceRatio = 0.0;
  double MillisecondsPerMegapixel = 0.0;
  std::string Note;
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
  auto separable = [](int method, int kind)
  {
    return [method, kind](double sx, double sy) -> vtkSmartPointer<vtkAlgorithm>
    {
      auto f = vtkSmartPointer<vtkImageSeparableGaussian>::New();
      f->SetMethod(method);
      f->SetKernelType(kind);
      f->SetStandardDeviations(sx, sy, 0.0);
      f->SetBorderMode(vtkImageSeparableGaussian::CLAMP);
      return f;
    };
  };
  methods.push_back({ "exact sampled 4 sigma", separable(vtkImageSeparableGaussian::EXACT, 0) });
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

// Hook for the GPU rows (vtkBloomPass against these CPU filters), added by the render-pass
// work: append rows with Family "gpu", the same error measures (against ContinuousGaussian or
// the PSF's Gaussian as above) and the GPU time per megapixel on the same 1920x1080 RGBA frame.
void AddGpuRows(
  const std::vector<double>& /*sigmas*/, vtkImageData* /*frame*/, std::vector<Row>& /*rows*/)
{
}

std::string Format(double v, const char* format)
{
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), format, v);
  return buffer;
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
  AddGpuRows(sigmas, frame, rows);

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
    if (r.Family == "chain")
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
  return 0;
}
