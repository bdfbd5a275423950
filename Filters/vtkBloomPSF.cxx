// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkBloomPSF.h"

#include "vtkBloomFFTConvolution.h"
#include "vtkBloomImageOps.h"
#include "vtkBloomLinearOperator.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>

namespace
{
// The real 2-D transforms of an ny x nx array (row-major) and back, threaded by FFTW.
struct Transform2D
{
  int NX = 0, NY = 0;
  float* Real = nullptr;
  fftwf_complex* Spectrum = nullptr;
  fftwf_plan Forward = nullptr;
  fftwf_plan Inverse = nullptr;

  Transform2D(int nx, int ny)
    : NX(nx)
    , NY(ny)
  {
    std::lock_guard<std::mutex> lock(vtkBloomFFTConvolution::PlannerMutex());
    static const bool threads = fftwf_init_threads() != 0;
    this->Real = fftwf_alloc_real(static_cast<size_t>(nx) * ny);
    this->Spectrum = fftwf_alloc_complex(static_cast<size_t>(nx / 2 + 1) * ny);
    if (threads)
    {
      fftwf_plan_with_nthreads(std::max(1, vtkSMPTools::GetEstimatedNumberOfThreads()));
    }
    this->Forward = fftwf_plan_dft_r2c_2d(ny, nx, this->Real, this->Spectrum, FFTW_ESTIMATE);
    this->Inverse = fftwf_plan_dft_c2r_2d(ny, nx, this->Spectrum, this->Real, FFTW_ESTIMATE);
    if (threads)
    {
      fftwf_plan_with_nthreads(1);
    }
  }
  ~Transform2D()
  {
    std::lock_guard<std::mutex> lock(vtkBloomFFTConvolution::PlannerMutex());
    fftwf_destroy_plan(this->Forward);
    fftwf_destroy_plan(this->Inverse);
    fftwf_free(this->Real);
    fftwf_free(this->Spectrum);
  }
  Transform2D(const Transform2D&) = delete;
  Transform2D& operator=(const Transform2D&) = delete;
  size_t SpectrumSize() const { return static_cast<size_t>(this->NX / 2 + 1) * this->NY; }
};

// J1(v) for v >= LargeArgument from Hankel's asymptotic expansion (DLMF 10.17.3):
// J1(v) = sqrt(2 / (pi v)) (P cos w - Q sin w), w = v - 3 pi / 4, with
// P = a0 - a2 / v^2 + a4 / v^4 - ..., Q = a1 / v - a3 / v^3 + ...,
// a_k = a_(k-1) (4 - (2k - 1)^2) / (8 k). The terms fall by about k / (2 v) each, so at v >= 25
// the sum reaches double precision (a term below 1e-17 of the first) long before they turn.
// cos w and sin w come from cos v and sin v, each reduced exactly by the library.
constexpr double LargeArgument = 25.0;
double BesselJ1Large(double v)
{
  double p = 0.0, q = 0.0, a = 1.0, power = 1.0;
  for (int k = 0; k < 60; ++k)
  {
    const double term = a * power; // a_k / v^k
    const double sign = (k / 2) % 2 == 0 ? 1.0 : -1.0;
    (k % 2 == 0 ? p : q) += sign * term;
    if (std::abs(term) < 1e-17)
    {
      break;
    }
    const double odd = 2.0 * (k + 1) - 1.0;
    a *= (4.0 - odd * odd) / (8.0 * (k + 1));
    power /= v;
  }
  const double c = std::cos(v), s = std::sin(v);
  const double root = 0.70710678118654752440; // cos(3 pi / 4) = -root, sin(3 pi / 4) = root
  const double cosw = root * (s - c), sinw = -root * (s + c);
  return std::sqrt(2.0 / (3.14159265358979323846 * v)) * (p * cosw - q * sinw);
}

// The Airy intensity (2 J1(v) / v)^2 at radius r for first dark ring r0.
double AiryIntensity(double r, double r0)
{
  const double v = 3.8317059702075125 * r / r0;
  if (v < 1e-8)
  {
    return 1.0;
  }
  // The library's J1 takes microseconds a call at large v, the expansion a tenth of one.
  const double j1 = v < LargeArgument ? std::cyl_bessel_j(1.0, v) : BesselJ1Large(v);
  const double j = 2.0 * j1 / v;
  return j * j;
}
}

//------------------------------------------------------------------------------
bool vtkBloomPSF::Normalize(vtkBloomPSFKernel& kernel)
{
  double sum = 0.0;
  for (double v : kernel.Values)
  {
    sum += v;
  }
  if (!(sum > 0.0) || !std::isfinite(sum))
  {
    return false;
  }
  for (double& v : kernel.Values)
  {
    v /= sum;
  }
  return true;
}

//------------------------------------------------------------------------------
vtkBloomPSFKernel vtkBloomPSF::Airy(double firstZero, int radius)
{
  vtkBloomPSFKernel k;
  k.Radius = std::max(radius, 0);
  const int r = k.Radius, n = 2 * r + 1;
  k.Values.assign(static_cast<size_t>(n) * n, 0.0);
  // 5 x 5 samples a pixel at offsets -0.4 .. 0.4, symmetric bit for bit, so the pattern is
  // exactly symmetric under x -> -x, y -> -y and x <-> y: each pixel (i, j), 0 <= j <= i, of
  // one eighth is averaged once and written to its (up to) eight images, the rows in parallel.
  const int sub = 5;
  double offsets[sub];
  for (int s = 0; s < sub; ++s)
  {
    offsets[s] = (2 * s - (sub - 1)) / (2.0 * sub);
  }
  vtkSMPTools::For(0, r + 1,
    [&](int begin, int end)
    {
      for (int i = begin; i < end; ++i)
      {
        for (int j = 0; j <= i; ++j)
        {
          double sum = 0.0;
          for (double oy : offsets)
          {
            for (double ox : offsets)
            {
              const double dx = i + ox, dy = j + oy;
              sum += AiryIntensity(std::sqrt(dx * dx + dy * dy), firstZero);
            }
          }
          const double value = sum / (sub * sub);
          for (int a : { i, -i })
          {
            for (int b : { j, -j })
            {
              k.Values[static_cast<size_t>(r + b) * n + (r + a)] = value;
              k.Values[static_cast<size_t>(r + a) * n + (r + b)] = value;
            }
          }
        }
      }
    });
  vtkBloomPSF::Normalize(k);
  return k;
}

//------------------------------------------------------------------------------
vtkBloomPSFKernel vtkBloomPSF::Gaussians(
  const std::vector<double>& sigmas, const std::vector<double>& weights, int radius)
{
  vtkBloomPSFKernel k;
  k.Radius = std::max(radius, 0);
  const int n = 2 * k.Radius + 1;
  k.Values.assign(static_cast<size_t>(n) * n, 0.0);
  for (size_t g = 0; g < std::min(sigmas.size(), weights.size()); ++g)
  {
    const double s = sigmas[g];
    const double norm = weights[g] / (2.0 * 3.14159265358979323846 * s * s);
    for (int y = 0; y < n; ++y)
    {
      for (int x = 0; x < n; ++x)
      {
        const double r2 = static_cast<double>(x - k.Radius) * (x - k.Radius) +
          static_cast<double>(y - k.Radius) * (y - k.Radius);
        k.Values[static_cast<size_t>(y) * n + x] += norm * std::exp(-0.5 * r2 / (s * s));
      }
    }
  }
  vtkBloomPSF::Normalize(k);
  return k;
}

//------------------------------------------------------------------------------
bool vtkBloomPSF::FromImage(
  vtkImageData* image, int component, int maxRadius, vtkBloomPSFKernel& kernel, std::string& error)
{
  vtkDataArray* scalars = image ? image->GetPointData()->GetScalars() : nullptr;
  if (!scalars || (scalars->GetDataType() != VTK_FLOAT && scalars->GetDataType() != VTK_DOUBLE))
  {
    error = "the PSF image needs float or double point scalars";
    return false;
  }
  int dims[3];
  image->GetDimensions(dims);
  if (dims[2] != 1 || dims[0] % 2 == 0 || dims[1] % 2 == 0 || dims[0] != dims[1])
  {
    error = "the PSF image must be square and 2-D with an odd size (its centre pixel is the "
            "centre); got " +
      std::to_string(dims[0]) + " x " + std::to_string(dims[1]) + " x " + std::to_string(dims[2]);
    return false;
  }
  if (dims[0] > 2 * maxRadius + 1)
  {
    error = "the PSF image is wider than " + std::to_string(2 * maxRadius + 1) + " pixels";
    return false;
  }
  const int nc = scalars->GetNumberOfComponents();
  const int c = std::min(std::max(component, 0), nc - 1);
  kernel.Radius = dims[0] / 2;
  kernel.Values.resize(static_cast<size_t>(dims[0]) * dims[1]);
  for (vtkIdType t = 0; t < scalars->GetNumberOfTuples(); ++t)
  {
    const double v = scalars->GetComponent(t, c);
    if (!std::isfinite(v) || v < 0.0)
    {
      error = "the PSF image holds a negative or non-finite value";
      return false;
    }
    kernel.Values[t] = v;
  }
  if (!vtkBloomPSF::Normalize(kernel))
  {
    error = "the PSF image sums to zero (or to more than the largest double)";
    return false;
  }
  return true;
}

struct vtkBloomPSFConvolution::Internals
{
  // One 2-D transform (plans and buffers) per distinct kernel radius, and one spectrum per
  // distinct kernel; channel c uses Transforms[Transform[c]] and Spectra[Spectrum[c]].
  std::vector<std::unique_ptr<Transform2D>> Transforms;
  std::vector<int> Radii;
  std::vector<std::vector<float>> Spectra; ///< re, im interleaved, scaled by 1 / (nx ny)
  std::vector<int> Transform, Spectrum;
  int Size[2] = { 0, 0 };
};

//------------------------------------------------------------------------------
vtkBloomPSFConvolution::vtkBloomPSFConvolution()
  : Impl(new Internals)
{
}

//------------------------------------------------------------------------------
vtkBloomPSFConvolution::~vtkBloomPSFConvolution() = default;

//------------------------------------------------------------------------------
void vtkBloomPSFConvolution::Prepare(
  int width, int height, const std::vector<vtkBloomPSFKernel>& kernels)
{
  this->Impl.reset(new Internals);
  Internals& impl = *this->Impl;
  impl.Size[0] = width;
  impl.Size[1] = height;
  for (size_t c = 0; c < kernels.size(); ++c)
  {
    const vtkBloomPSFKernel& kernel = kernels[c];
    const int r = kernel.Radius;
    auto radius = std::find(impl.Radii.begin(), impl.Radii.end(), r);
    if (radius == impl.Radii.end())
    {
      impl.Radii.push_back(r);
      impl.Transforms.emplace_back(
        new Transform2D(vtkBloomFFTConvolution::GoodTransformSize(width + 2 * r),
          vtkBloomFFTConvolution::GoodTransformSize(height + 2 * r)));
      radius = impl.Radii.end() - 1;
    }
    impl.Transform.push_back(static_cast<int>(radius - impl.Radii.begin()));
    // A kernel equal to an earlier channel's shares its spectrum.
    size_t same = 0;
    while (same < c && kernels[same].Values != kernel.Values)
    {
      ++same;
    }
    if (same < c)
    {
      impl.Spectrum.push_back(impl.Spectrum[same]);
      continue;
    }
    Transform2D& fft = *impl.Transforms[impl.Transform.back()];
    const int kn = 2 * r + 1;
    const size_t total = static_cast<size_t>(fft.NX) * fft.NY;
    std::fill(fft.Real, fft.Real + total, 0.0f);
    for (int y = 0; y < kn; ++y)
    {
      for (int x = 0; x < kn; ++x)
      {
        fft.Real[static_cast<size_t>(y) * fft.NX + x] =
          static_cast<float>(kernel.Values[static_cast<size_t>(y) * kn + x]);
      }
    }
    fftwf_execute(fft.Forward);
    const float scale = 1.0f / static_cast<float>(total);
    std::vector<float> spectrum(2 * fft.SpectrumSize());
    for (size_t q = 0; q < fft.SpectrumSize(); ++q)
    {
      spectrum[2 * q] = fft.Spectrum[q][0] * scale;
      spectrum[2 * q + 1] = fft.Spectrum[q][1] * scale;
    }
    impl.Spectrum.push_back(static_cast<int>(impl.Spectra.size()));
    impl.Spectra.push_back(std::move(spectrum));
  }
}

//------------------------------------------------------------------------------
bool vtkBloomPSFConvolution::IsPreparedFor(int width, int height) const
{
  return !this->Impl->Transform.empty() && this->Impl->Size[0] == width &&
    this->Impl->Size[1] == height;
}

//------------------------------------------------------------------------------
void vtkBloomPSFConvolution::Convolve(const vtkBloomBuffer& in, bool reflect, vtkBloomBuffer& out)
{
  const Internals& impl = *this->Impl;
  const int w = in.Size[0], h = in.Size[1], nc = in.NumberOfComponents;
  out.Allocate(in.Lo, in.Size, nc);
  std::fill(out.Data.begin(), out.Data.end(), 0.0);
  const int border =
    reflect ? vtkBloomLinearOperator::BORDER_REFLECT : vtkBloomLinearOperator::BORDER_ZERO;
  for (int c = 0; c < nc; ++c)
  {
    const size_t k = std::min<size_t>(c, impl.Transform.size() - 1);
    Transform2D& fft = *impl.Transforms[impl.Transform[k]];
    const std::vector<float>& kernelSpectrum = impl.Spectra[impl.Spectrum[k]];
    const int r = impl.Radii[impl.Transform[k]];
    const int nx = fft.NX;
    const size_t total = static_cast<size_t>(nx) * fft.NY;
    float* real = fft.Real;
    // The channel, scaled by a power of two so that its largest magnitude is below 1.
    double largest = 0.0;
    for (size_t i = c; i < in.Data.size(); i += nc)
    {
      largest = std::max(largest, std::abs(in.Data[i]));
    }
    if (largest == 0.0)
    {
      continue;
    }
    int exponent = 0;
    std::frexp(largest, &exponent);
    const double scale = std::ldexp(1.0, -exponent);
    std::fill(real, real + total, 0.0f);
    for (int y = 0; y < h; ++y)
    {
      for (int x = 0; x < w; ++x)
      {
        real[static_cast<size_t>(y) * nx + x] =
          static_cast<float>(in.Data[(static_cast<size_t>(y) * w + x) * nc + c] * scale);
      }
    }
    fftwf_execute(fft.Forward);
    fftwf_complex* s = fft.Spectrum;
    for (size_t q = 0; q < fft.SpectrumSize(); ++q)
    {
      const float kr = kernelSpectrum[2 * q], ki = kernelSpectrum[2 * q + 1];
      const float re = s[q][0] * kr - s[q][1] * ki;
      const float im = s[q][0] * ki + s[q][1] * kr;
      s[q][0] = re;
      s[q][1] = im;
    }
    fftwf_execute(fft.Inverse);
    // The full convolution, centred (index x - r), folded back into the image.
    const double unscale = std::ldexp(1.0, exponent);
    std::vector<int> foldX(w + 2 * r), foldY(h + 2 * r);
    for (int x = 0; x < w + 2 * r; ++x)
    {
      foldX[x] = vtkBloomLinearOperator::FoldIndex(x - r, w, border);
    }
    for (int y = 0; y < h + 2 * r; ++y)
    {
      foldY[y] = vtkBloomLinearOperator::FoldIndex(y - r, h, border);
    }
    for (int y = 0; y < h + 2 * r; ++y)
    {
      if (foldY[y] < 0)
      {
        continue;
      }
      const float* row = real + static_cast<size_t>(y) * nx;
      double* target = out.Data.data() + static_cast<size_t>(foldY[y]) * w * nc + c;
      for (int x = 0; x < w + 2 * r; ++x)
      {
        if (foldX[x] >= 0)
        {
          target[static_cast<size_t>(foldX[x]) * nc] += static_cast<double>(row[x]) * unscale;
        }
      }
    }
  }
}

//------------------------------------------------------------------------------
void vtkBloomPSFKernels::Prepare(int width, int height, int scale, int coreRadius)
{
  this->TailScale = 1;
  if (scale <= 1)
  {
    this->Convolution.Prepare(width, height, this->Kernels);
    return;
  }
  std::vector<vtkBloomPSFKernel> cores, tails;
  for (const vtkBloomPSFKernel& kernel : this->Kernels)
  {
    const vtkBloomPSFSplit split = vtkBloomPSFSplit::Make(kernel, scale, coreRadius);
    cores.push_back(split.Core);
    tails.push_back(split.GridKernel());
    this->TailScale = split.HasTail() ? scale : this->TailScale;
  }
  this->Convolution.Prepare(width, height, cores);
  if (this->TailScale > 1)
  {
    this->TailConvolution.Prepare(vtkBloomPSFSplit::CoarseSize(width, scale),
      vtkBloomPSFSplit::CoarseSize(height, scale), tails);
  }
}

//------------------------------------------------------------------------------
void vtkBloomPSFKernels::Convolve(const vtkBloomBuffer& bright, bool reflect, vtkBloomBuffer& bloom)
{
  this->Convolution.Convolve(bright, reflect, bloom);
  const int f = this->TailScale;
  if (f <= 1)
  {
    return;
  }
  const int w = bright.Size[0], h = bright.Size[1], nc = bright.NumberOfComponents;
  const int lo[3] = { 0, 0, 0 };
  const int size[3] = { vtkBloomPSFSplit::CoarseSize(w, f), vtkBloomPSFSplit::CoarseSize(h, f), 1 };
  vtkBloomBuffer coarse, tail;
  coarse.Allocate(lo, size, nc);
  vtkBloomPSFSplit::Down(bright.Data.data(), w, h, nc, f, coarse.Data.data());
  this->TailConvolution.Convolve(coarse, reflect, tail);
  vtkBloomPSFSplit::AddUp(tail.Data.data(), w, h, nc, f, bloom.Data.data());
}
