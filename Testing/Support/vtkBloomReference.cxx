// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// An independent float64 reference of the vtk-bloom filters; see vtkBloomReference.h.
// Deliberately written as GPU-style passes and direct convolutions, not as separable operators,
// so that it shares no structure (and no code) with the library it checks.
// It is long for that reason: every kernel, resampling step and preset of the specification is
// written out here a second time, in one place, rather than split across files a reader would
// have to assemble.
#include "vtkBloomReference.h"

#include <vtkDataArray.h>
#include <vtkPointData.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

namespace vtkBloomRef
{
namespace
{
Pixel Add(const Pixel& a, const Pixel& b)
{
  return { a[0] + b[0], a[1] + b[1], a[2] + b[2], a[3] + b[3] };
}

Pixel Scale(const Pixel& a, double s)
{
  return { a[0] * s, a[1] * s, a[2] * s, a[3] * s };
}

// sum_t w_t * in.Bilinear(u + dx_t / W, v + dy_t / H): a gather of bilinear taps whose offsets
// are given in texels of `in`.
struct Tap2D
{
  double Dx;
  double Dy;
  double Weight;
};

Pixel Gather(const Texture& in, double u, double v, const std::vector<Tap2D>& taps)
{
  Pixel sum = { 0.0, 0.0, 0.0, 0.0 };
  for (const Tap2D& tap : taps)
  {
    sum = Add(sum, Scale(in.Bilinear(u + tap.Dx / in.W, v + tap.Dy / in.H), tap.Weight));
  }
  return sum;
}

// A horizontal (or vertical) blur pass of a symmetric kernel: taps at k * spacing texels,
// k = -R..R, weights half[|k|].
Texture BlurPass(const Texture& in, const std::vector<double>& half, double spacing, bool vertical)
{
  std::vector<Tap2D> taps;
  const int r = static_cast<int>(half.size()) - 1;
  for (int k = -r; k <= r; ++k)
  {
    const double d = k * spacing;
    taps.push_back({ vertical ? 0.0 : d, vertical ? d : 0.0, half[std::abs(k)] });
  }
  return FullScreenPass(in.W, in.H, [&](double u, double v) { return Gather(in, u, v, taps); });
}

// Copy alpha from `from` into `to` (same size).
void CopyAlpha(const Texture& from, Texture& to)
{
  for (size_t t = 0; t < to.Texels.size(); ++t)
  {
    to.Texels[t][3] = from.Texels[t][3];
  }
}

// floor(log2(n)) for n >= 1.
int FloorLog2(int n)
{
  int k = 0;
  while (n > 1)
  {
    n /= 2;
    ++k;
  }
  return k;
}

// Length of [a, b] inside texel [i, i + 1].
double Overlap(double a, double b, int i)
{
  return std::max(0.0, std::min(b, i + 1.0) - std::max(a, static_cast<double>(i)));
}
}

//------------------------------------------------------------------------------
Texture::Texture(int w, int h)
  : W(w)
  , H(h)
  , Texels(static_cast<size_t>(w) * h, Pixel{ 0.0, 0.0, 0.0, 0.0 })
{
}

//------------------------------------------------------------------------------
Pixel Texture::Fetch(int i, int j) const
{
  i = std::min(std::max(i, 0), this->W - 1);
  j = std::min(std::max(j, 0), this->H - 1);
  return this->At(i, j);
}

//------------------------------------------------------------------------------
Pixel Texture::Bilinear(double u, double v) const
{
  // Texel coordinates with centres at integers.
  const double px = u * this->W - 0.5;
  const double py = v * this->H - 0.5;
  const double fx0 = std::floor(px);
  const double fy0 = std::floor(py);
  const double fx = px - fx0;
  const double fy = py - fy0;
  const int i = static_cast<int>(fx0);
  const int j = static_cast<int>(fy0);
  const Pixel a = this->Fetch(i, j);
  const Pixel b = this->Fetch(i + 1, j);
  const Pixel c = this->Fetch(i, j + 1);
  const Pixel d = this->Fetch(i + 1, j + 1);
  Pixel out;
  for (int ch = 0; ch < 4; ++ch)
  {
    out[ch] =
      (1.0 - fy) * ((1.0 - fx) * a[ch] + fx * b[ch]) + fy * ((1.0 - fx) * c[ch] + fx * d[ch]);
  }
  return out;
}

//------------------------------------------------------------------------------
int HalfSize(int n)
{
  return std::max(1, n / 2);
}

//------------------------------------------------------------------------------
int FoldIndex(int i, int n, Border border)
{
  if (i >= 0 && i < n)
  {
    return i;
  }
  switch (border)
  {
    case CLAMP:
      return i < 0 ? 0 : n - 1;
    case ZERO:
      return -1;
    case REFLECT:
    default:
    {
      // Mirror about -1/2 and n - 1/2 repeatedly: the extension has period 2n.
      int m = i % (2 * n);
      if (m < 0)
      {
        m += 2 * n;
      }
      return m < n ? m : 2 * n - 1 - m;
    }
  }
}

//------------------------------------------------------------------------------
double DiscreteGaussianWeight(int n, double t)
{
  n = std::abs(n);
  if (t <= 0.0)
  {
    return n == 0 ? 1.0 : 0.0;
  }
  // e^{-t} I_n(t) = sum_k e^{-t} (t/2)^{2k+n} / (k! (k+n)!).
  const double logHalf = std::log(0.5 * t);
  double sum = 0.0;
  for (int k = 0; k < 1000000; ++k)
  {
    const double term =
      std::exp((2.0 * k + n) * logHalf - std::lgamma(k + 1.0) - std::lgamma(k + n + 1.0) - t);
    sum += term;
    if (k > t && term < 1e-22 * sum)
    {
      break;
    }
  }
  return sum;
}

//------------------------------------------------------------------------------
std::vector<double> GaussianKernel(double sigma, int radius, GaussianKind kind)
{
  if (!(sigma > 0.0) || radius <= 0)
  {
    return { 1.0 };
  }
  std::vector<double> k(2 * static_cast<size_t>(radius) + 1);
  for (int i = -radius; i <= radius; ++i)
  {
    double w = 0.0;
    switch (kind)
    {
      case SAMPLED:
        w = std::exp(-0.5 * (i / sigma) * (i / sigma));
        break;
      case INTEGRATED:
      {
        const double s = sigma * std::sqrt(2.0);
        w = 0.5 * (std::erf((i + 0.5) / s) - std::erf((i - 0.5) / s));
        break;
      }
      case DISCRETE:
        w = DiscreteGaussianWeight(i, sigma * sigma);
        break;
    }
    k[i + radius] = w;
  }
  double total = 0.0;
  for (double w : k)
  {
    total += w;
  }
  for (double& w : k)
  {
    w /= total;
  }
  return k;
}

//------------------------------------------------------------------------------
Texture Convolve2D(
  const Texture& in, const std::vector<double>& kx, const std::vector<double>& ky, Border border)
{
  const int rx = static_cast<int>(kx.size()) / 2;
  const int ry = static_cast<int>(ky.size()) / 2;
  Texture out(in.W, in.H);
  for (int y = 0; y < in.H; ++y)
  {
    for (int x = 0; x < in.W; ++x)
    {
      Pixel sum = { 0.0, 0.0, 0.0, 0.0 };
      for (int b = -ry; b <= ry; ++b)
      {
        const int j = FoldIndex(y + b, in.H, border);
        if (j < 0)
        {
          continue;
        }
        for (int a = -rx; a <= rx; ++a)
        {
          const int i = FoldIndex(x + a, in.W, border);
          if (i < 0)
          {
            continue;
          }
          sum = Add(sum, Scale(in.At(i, j), kx[a + rx] * ky[b + ry]));
        }
      }
      out.At(x, y) = sum;
    }
  }
  return out;
}

//------------------------------------------------------------------------------
std::vector<double> Convolve3D(const std::vector<double>& in, int nx, int ny, int nz, int nc,
  const std::vector<double>& kx, const std::vector<double>& ky, const std::vector<double>& kz,
  Border border)
{
  const int r[3] = { static_cast<int>(kx.size()) / 2, static_cast<int>(ky.size()) / 2,
    static_cast<int>(kz.size()) / 2 };
  std::vector<double> out(in.size(), 0.0);
  auto index = [&](int i, int j, int k)
  { return ((static_cast<size_t>(k) * ny + j) * nx + i) * nc; };
  for (int z = 0; z < nz; ++z)
  {
    for (int y = 0; y < ny; ++y)
    {
      for (int x = 0; x < nx; ++x)
      {
        for (int c3 = -r[2]; c3 <= r[2]; ++c3)
        {
          const int k = FoldIndex(z + c3, nz, border);
          for (int b = -r[1]; b <= r[1] && k >= 0; ++b)
          {
            const int j = FoldIndex(y + b, ny, border);
            for (int a = -r[0]; a <= r[0] && j >= 0; ++a)
            {
              const int i = FoldIndex(x + a, nx, border);
              if (i < 0)
              {
                continue;
              }
              const double w = kx[a + r[0]] * ky[b + r[1]] * kz[c3 + r[2]];
              for (int c = 0; c < nc; ++c)
              {
                out[index(x, y, z) + c] += w * in[index(i, j, k) + c];
              }
            }
          }
        }
      }
    }
  }
  return out;
}

//------------------------------------------------------------------------------
Texture Blur(const Texture& in, int radius, double sigma, Border border)
{
  const std::vector<double> k = GaussianKernel(sigma, radius, SAMPLED);
  return Convolve2D(in, k, k, border);
}

//------------------------------------------------------------------------------
double Luminance(const Pixel& p)
{
  return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
}

//------------------------------------------------------------------------------
Pixel BrightPass(
  Pixel p, ThresholdMode mode, double threshold, double knee, double clampLuminance, int colours)
{
  if (mode == NONE)
  {
    return p;
  }
  const int n = colours == 1 ? 1 : 3;
  auto luminance = [&]() { return n == 1 ? p[0] : Luminance(p); };
  // Firefly guard first: scale the colour down to the clamp luminance.
  const double lum0 = luminance();
  if (lum0 > clampLuminance)
  {
    for (int c = 0; c < n; ++c)
    {
      p[c] *= clampLuminance / lum0;
    }
  }
  const double lum = luminance();
  const double k = threshold * knee;
  double factor = 1.0;
  if (mode == SMOOTHSTEP_KNEE)
  {
    if (k > 0.0)
    {
      // GLSL smoothstep(T - k, T + k, lum).
      double s = (lum - (threshold - k)) / (2.0 * k);
      s = std::min(1.0, std::max(0.0, s));
      factor = s * s * (3.0 - 2.0 * s);
    }
    else
    {
      factor = lum >= threshold ? 1.0 : 0.0;
    }
  }
  else if (mode == QUADRATIC_KNEE)
  {
    const double bright = n == 1 ? p[0] : std::max(p[0], std::max(p[1], p[2]));
    const double soft = std::min(std::max(bright - threshold + k, 0.0), 2.0 * k);
    const double q = soft * soft / (4.0 * k + 1e-5);
    factor = std::max(q, bright - threshold) / std::max(bright, 1e-5);
  }
  else if (mode == HARD_LUMINANCE)
  {
    factor = lum > threshold ? 1.0 : 0.0;
  }
  else if (mode == EXCESS_KNEE)
  {
    // e(B) as the documentation defines it, piece by piece: 0 up to T, the quadratic
    // (B - T)^2 / 4k up to T + 2k, the line B - T - k beyond; the colour is scaled to it.
    const double bright = n == 1 ? p[0] : std::max(p[0], std::max(p[1], p[2]));
    double excess = 0.0;
    if (bright >= threshold + 2.0 * k)
    {
      excess = bright - threshold - k;
    }
    else if (bright > threshold)
    {
      excess = (bright - threshold) * (bright - threshold) / (4.0 * k);
    }
    factor = bright > 0.0 ? excess / bright : 0.0;
  }
  else if (mode == PER_CHANNEL)
  {
    for (int c = 0; c < n; ++c)
    {
      p[c] = std::max(p[c] - threshold, 0.0);
    }
    return p;
  }
  // No mode but NONE ever emits negative light.
  for (int c = 0; c < n; ++c)
  {
    p[c] = std::max(p[c] * factor, 0.0);
  }
  return p;
}

//------------------------------------------------------------------------------
Texture Threshold(
  const Texture& in, ThresholdMode mode, double threshold, double knee, double clampLuminance)
{
  Texture out = in;
  for (Pixel& p : out.Texels)
  {
    p = BrightPass(p, mode, threshold, knee, clampLuminance);
  }
  return out;
}

//------------------------------------------------------------------------------
Texture Downsample13(const Texture& in, bool karis)
{
  // The 13 tap positions, in source texels: A..M of Jimenez 2014, slide 150.
  //   a . b . c
  //   . d . e .
  //   f . g . h
  //   . i . j .
  //   k . l . m
  const int w = HalfSize(in.W), h = HalfSize(in.H);
  return FullScreenPass(w, h,
    [&](double u, double v)
    {
      auto at = [&](double dx, double dy) { return in.Bilinear(u + dx / in.W, v + dy / in.H); };
      const Pixel a = at(-1, -1), b = at(0, -1), c = at(1, -1);
      const Pixel d = at(-0.5, -0.5), e = at(0.5, -0.5);
      const Pixel f = at(-1, 0), g = at(0, 0), hh = at(1, 0);
      const Pixel i = at(-0.5, 0.5), j = at(0.5, 0.5);
      const Pixel k = at(-1, 1), l = at(0, 1), m = at(1, 1);
      if (!karis)
      {
        Pixel out = { 0.0, 0.0, 0.0, 0.0 };
        const std::pair<const Pixel*, double> taps[13] = { { &g, 1.0 / 8 }, { &d, 1.0 / 8 },
          { &e, 1.0 / 8 }, { &i, 1.0 / 8 }, { &j, 1.0 / 8 }, { &b, 1.0 / 16 }, { &f, 1.0 / 16 },
          { &hh, 1.0 / 16 }, { &l, 1.0 / 16 }, { &a, 1.0 / 32 }, { &c, 1.0 / 32 }, { &k, 1.0 / 32 },
          { &m, 1.0 / 32 } };
        for (const auto& tap : taps)
        {
          out = Add(out, Scale(*tap.first, tap.second));
        }
        return out;
      }
      // Karis (2013): the five 2x2 boxes, each weighted by base / (1 + luma(box)).
      auto box = [](const Pixel& p, const Pixel& q, const Pixel& r, const Pixel& s)
      { return Scale(Add(Add(p, q), Add(r, s)), 0.25); };
      const Pixel boxes[5] = { box(d, e, i, j), box(a, b, f, g), box(b, c, g, hh), box(f, g, k, l),
        box(g, hh, l, m) };
      const double base[5] = { 0.5, 0.125, 0.125, 0.125, 0.125 };
      Pixel sum = { 0.0, 0.0, 0.0, 0.0 };
      double total = 0.0;
      for (int n = 0; n < 5; ++n)
      {
        const double weight = base[n] / (1.0 + Luminance(boxes[n]));
        sum = Add(sum, Scale(boxes[n], weight));
        total += weight;
      }
      return Scale(sum, 1.0 / total);
    });
}

//------------------------------------------------------------------------------
Texture AreaResample(const Texture& in, int w, int h)
{
  Texture out(w, h);
  for (int y = 0; y < h; ++y)
  {
    const double y0 = static_cast<double>(y) * in.H / h;
    const double y1 = static_cast<double>(y + 1) * in.H / h;
    for (int x = 0; x < w; ++x)
    {
      const double x0 = static_cast<double>(x) * in.W / w;
      const double x1 = static_cast<double>(x + 1) * in.W / w;
      // Integrate the piecewise-constant source over the output pixel's rectangle.
      Pixel sum = { 0.0, 0.0, 0.0, 0.0 };
      double area = 0.0;
      // Only texels within [floor(a), ceil(b)) can overlap [a, b].
      const int j0 = static_cast<int>(std::floor(y0)), j1 = static_cast<int>(std::ceil(y1));
      const int i0 = static_cast<int>(std::floor(x0)), i1 = static_cast<int>(std::ceil(x1));
      for (int j = std::max(j0, 0); j < std::min(j1, in.H); ++j)
      {
        const double oy = Overlap(y0, y1, j);
        if (oy <= 0.0)
        {
          continue;
        }
        for (int i = std::max(i0, 0); i < std::min(i1, in.W); ++i)
        {
          const double ox = Overlap(x0, x1, i);
          if (ox <= 0.0)
          {
            continue;
          }
          sum = Add(sum, Scale(in.At(i, j), ox * oy));
          area += ox * oy;
        }
      }
      out.At(x, y) = Scale(sum, 1.0 / area);
    }
  }
  return out;
}

//------------------------------------------------------------------------------
Texture DownsampleBinomial(const Texture& in)
{
  const double b[5] = { 1.0, 4.0, 6.0, 4.0, 1.0 };
  std::vector<Tap2D> taps;
  for (int dy = -2; dy <= 2; ++dy)
  {
    for (int dx = -2; dx <= 2; ++dx)
    {
      taps.push_back(
        { static_cast<double>(dx), static_cast<double>(dy), b[dx + 2] * b[dy + 2] / 256.0 });
    }
  }
  return FullScreenPass(
    HalfSize(in.W), HalfSize(in.H), [&](double u, double v) { return Gather(in, u, v, taps); });
}

//------------------------------------------------------------------------------
Texture PyramidDown(const Texture& in, DownKernel kernel, bool karis)
{
  switch (kernel)
  {
    case BOX:
      return AreaResample(in, HalfSize(in.W), HalfSize(in.H));
    case BINOMIAL:
      return DownsampleBinomial(in);
    case JIMENEZ13:
    default:
      return Downsample13(in, karis);
  }
}

//------------------------------------------------------------------------------
Texture PyramidUp(const Texture& coarse, int w, int h, UpKernel kernel)
{
  if (kernel == BILINEAR)
  {
    return BilinearResize(coarse, w, h);
  }
  std::vector<Tap2D> taps;
  const double t[3] = { 1.0, 2.0, 1.0 };
  for (int dy = -1; dy <= 1; ++dy)
  {
    for (int dx = -1; dx <= 1; ++dx)
    {
      taps.push_back(
        { static_cast<double>(dx), static_cast<double>(dy), t[dx + 1] * t[dy + 1] / 16.0 });
    }
  }
  return FullScreenPass(w, h, [&](double u, double v) { return Gather(coarse, u, v, taps); });
}

//------------------------------------------------------------------------------
Texture BilinearResize(const Texture& in, int w, int h)
{
  return FullScreenPass(w, h, [&](double u, double v) { return in.Bilinear(u, v); });
}

//------------------------------------------------------------------------------
Texture WebGPUMarket(const Texture& in)
{
  const double threshold = 0.8, softKnee = 0.5, radius = 0.5, strength = 1.0;
  const int levels = 5;
  // 1. mip0 = threshold(bilinear fetch at half-res uv).
  std::vector<Texture> mip(levels);
  mip[0] = FullScreenPass(HalfSize(in.W), HalfSize(in.H),
    [&](double u, double v)
    { return BrightPass(in.Bilinear(u, v), SMOOTHSTEP_KNEE, threshold, softKnee); });
  // 2. The 13-tap chain, from the unblurred levels.
  for (int i = 1; i < levels; ++i)
  {
    mip[i] = Downsample13(mip[i - 1]);
  }
  // 3. The 9-tap blur, taps k * radius texels apart, horizontal then vertical.
  const std::vector<double> weights = { 0.2270270270, 0.1945945946, 0.1216216216, 0.0540540541,
    0.0162162162 };
  std::vector<Texture> blurred(levels);
  for (int i = 0; i < levels; ++i)
  {
    blurred[i] = BlurPass(BlurPass(mip[i], weights, radius, false), weights, radius, true);
  }
  // 4. acc[4] = blurred[4]; acc[i] = tent(acc[i + 1]) + blurred[i].
  Texture acc = blurred[levels - 1];
  for (int i = levels - 2; i >= 0; --i)
  {
    Texture up = PyramidUp(acc, blurred[i].W, blurred[i].H, TENT);
    for (size_t t = 0; t < up.Texels.size(); ++t)
    {
      up.Texels[t] = Add(up.Texels[t], blurred[i].Texels[t]);
    }
    acc = std::move(up);
  }
  // 5. out = input + strength * bilinear(acc[0]) at full-res uv.
  Texture out = FullScreenPass(
    in.W, in.H, [&](double u, double v) { return Scale(acc.Bilinear(u, v), strength); });
  for (size_t t = 0; t < out.Texels.size(); ++t)
  {
    out.Texels[t] = Add(out.Texels[t], in.Texels[t]);
  }
  CopyAlpha(in, out);
  return out;
}

//------------------------------------------------------------------------------
Texture MipAtlas(const Texture& in)
{
  const int maxLevel = FloorLog2(std::max(in.W, in.H));
  std::vector<Texture> m(1, in);
  for (int k = 1; k <= maxLevel; ++k)
  {
    m.push_back(AreaResample(m[k - 1], HalfSize(m[k - 1].W), HalfSize(m[k - 1].H)));
  }
  const std::vector<double> binomial = { 1.0 / 64, 6.0 / 64, 15.0 / 64, 20.0 / 64, 15.0 / 64,
    6.0 / 64, 1.0 / 64 };
  const double lodWeight[7] = { 1.0, 1.0, 1.0, 0.8, 0.8, 0.6, 0.4 };
  Texture blur(in.W, in.H);
  for (int lod = 2; lod <= 8 && lod <= maxLevel; ++lod)
  {
    const Texture tile = Convolve2D(m[lod], binomial, binomial, CLAMP);
    const Texture full = BilinearResize(tile, in.W, in.H);
    for (size_t t = 0; t < blur.Texels.size(); ++t)
    {
      blur.Texels[t] = Add(blur.Texels[t], Scale(full.Texels[t], 0.14 * lodWeight[lod - 2]));
    }
  }
  Texture out(in.W, in.H);
  for (size_t t = 0; t < out.Texels.size(); ++t)
  {
    out.Texels[t] = Add(Scale(in.Texels[t], 0.48), Scale(blur.Texels[t], 0.52));
  }
  CopyAlpha(in, out);
  return out;
}

//------------------------------------------------------------------------------
Texture PingPong(const Texture& in)
{
  const std::vector<double> raw = { 0.227027, 0.1945946, 0.1216216, 0.054054, 0.016216, 0.007,
    0.002 };
  double sum = raw[0];
  for (size_t i = 1; i < raw.size(); ++i)
  {
    sum += 2.0 * raw[i];
  }
  std::vector<double> weights;
  for (double w : raw)
  {
    weights.push_back(w / sum);
  }
  Texture blur = Threshold(in, HARD_LUMINANCE, 1.0, 0.0);
  for (int pass = 0; pass < 32; ++pass)
  {
    blur = BlurPass(BlurPass(blur, weights, 1.0, false), weights, 1.0, true);
  }
  Texture out(in.W, in.H);
  for (size_t t = 0; t < out.Texels.size(); ++t)
  {
    out.Texels[t] = Add(in.Texels[t], blur.Texels[t]);
  }
  CopyAlpha(in, out);
  return out;
}

//------------------------------------------------------------------------------
Texture CrtHalfres(const Texture& in)
{
  const double threshold = 0.8, intensity = 1.5, sigma = 1.8;
  Texture half = FullScreenPass(HalfSize(in.W), HalfSize(in.H),
    [&](double u, double v)
    {
      Pixel p = in.Bilinear(u, v);
      for (int c = 0; c < 3; ++c)
      {
        p[c] = std::max(p[c] - threshold, 0.0);
      }
      return p;
    });
  std::vector<double> weights(5);
  double total = 0.0;
  for (int i = 0; i <= 4; ++i)
  {
    weights[i] = std::exp(-(i * i) / (2.0 * sigma * sigma));
    total += i == 0 ? weights[i] : 2.0 * weights[i];
  }
  for (double& w : weights)
  {
    w /= total;
  }
  const Texture blurred = BlurPass(BlurPass(half, weights, 1.0, false), weights, 1.0, true);
  Texture out = FullScreenPass(
    in.W, in.H, [&](double u, double v) { return Scale(blurred.Bilinear(u, v), intensity); });
  for (size_t t = 0; t < out.Texels.size(); ++t)
  {
    out.Texels[t] = Add(out.Texels[t], in.Texels[t]);
  }
  CopyAlpha(in, out);
  return out;
}

//------------------------------------------------------------------------------
Texture Bloom(const Texture& in, const BloomParameters& p)
{
  // Level sizes from level 0 (the input) down to the deepest level used.
  int deepest = p.StartLevel + p.NumberOfLevels - 1;
  if (p.LimitLevels)
  {
    deepest = std::min(deepest, FloorLog2(std::max(in.W, in.H)));
  }
  std::vector<std::pair<int, int>> sizes(1, { in.W, in.H });
  for (int k = 1; k <= deepest; ++k)
  {
    sizes.emplace_back(HalfSize(sizes.back().first), HalfSize(sizes.back().second));
  }
  if (deepest < p.StartLevel)
  {
    throw std::invalid_argument("no level fits");
  }
  auto weight = [&](size_t i) { return i < p.LevelWeights.size() ? p.LevelWeights[i] : 1.0; };

  // 1. Bright pass of the bilinear fetch at the start level.
  std::vector<Texture> levels;
  levels.push_back(FullScreenPass(sizes[p.StartLevel].first, sizes[p.StartLevel].second,
    [&](double u, double v)
    { return BrightPass(in.Bilinear(u, v), p.Mode, p.Threshold, p.Knee, p.ClampLuminance); }));
  // 2. The pyramid, from unblurred levels.
  for (int k = p.StartLevel + 1; k <= deepest; ++k)
  {
    levels.push_back(PyramidDown(levels.back(), p.Down, p.Karis && levels.size() == 1));
  }
  // 3. The blur.
  for (Texture& level : levels)
  {
    for (int it = 0; it < p.Iterations; ++it)
    {
      level = BlurPass(BlurPass(level, p.BlurHalfKernel, p.TapSpacing, false), p.BlurHalfKernel,
        p.TapSpacing, true);
    }
  }
  // 4. Accumulate.
  Texture bloom(in.W, in.H);
  if (p.Direct)
  {
    for (size_t i = 0; i < levels.size(); ++i)
    {
      const Texture full = BilinearResize(levels[i], in.W, in.H);
      for (size_t t = 0; t < bloom.Texels.size(); ++t)
      {
        bloom.Texels[t] = Add(bloom.Texels[t], Scale(full.Texels[t], weight(i)));
      }
    }
  }
  else
  {
    Texture acc = levels.back();
    for (Pixel& q : acc.Texels)
    {
      q = Scale(q, weight(levels.size() - 1));
    }
    for (size_t i = levels.size() - 1; i-- > 0;)
    {
      Texture up = PyramidUp(acc, levels[i].W, levels[i].H, p.Up);
      for (size_t t = 0; t < up.Texels.size(); ++t)
      {
        up.Texels[t] = Add(up.Texels[t], Scale(levels[i].Texels[t], weight(i)));
      }
      acc = std::move(up);
    }
    bloom = BilinearResize(acc, in.W, in.H);
  }
  // 5. Composite.
  Texture out(in.W, in.H);
  const double keep = p.Lerp ? 1.0 - p.Strength : 1.0;
  for (size_t t = 0; t < out.Texels.size(); ++t)
  {
    for (int c = 0; c < 3; ++c)
    {
      out.Texels[t][c] = keep * in.Texels[t][c] + p.Strength * p.Tint[c] * bloom.Texels[t][c];
    }
    out.Texels[t][3] = in.Texels[t][3];
  }
  return out;
}

//------------------------------------------------------------------------------
Texture Preset(const char* name, const Texture& in)
{
  const std::string preset = name;
  if (preset == "webgpu-market")
  {
    return WebGPUMarket(in);
  }
  if (preset == "mip-atlas")
  {
    return MipAtlas(in);
  }
  if (preset == "ping-pong")
  {
    return PingPong(in);
  }
  if (preset == "crt-halfres")
  {
    return CrtHalfres(in);
  }
  throw std::invalid_argument("unknown preset " + preset);
}

//------------------------------------------------------------------------------
double HashUniform(unsigned long long seed, unsigned long long index)
{
  // splitmix64 of a combination of seed and index.
  unsigned long long z = seed * 0x9E3779B97F4A7C15ULL + index + 0x632BE59BD9B4E019ULL;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) * (1.0 / 9007199254740992.0);
}

//------------------------------------------------------------------------------
Texture SyntheticScene(int w, int h, unsigned seed)
{
  unsigned long long counter = 0;
  auto rnd = [&]() { return HashUniform(seed, counter++); };
  struct Disc
  {
    double X, Y, R;
    Pixel Colour;
  };
  std::vector<Disc> discs;
  const int n = 3 + static_cast<int>(rnd() * 5);
  const double extent = std::max(w, h);
  for (int d = 0; d < n; ++d)
  {
    Disc disc;
    // Centres up to 10 % outside the image, so that some discs cross the border.
    disc.X = (rnd() * 1.2 - 0.1) * w;
    disc.Y = (rnd() * 1.2 - 0.1) * h;
    disc.R = 0.5 + rnd() * 0.2 * extent;
    const double value = 2.0 * std::pow(100.0, rnd()); // 2..200
    disc.Colour = { value * (0.3 + 0.7 * rnd()), value * (0.3 + 0.7 * rnd()),
      value * (0.3 + 0.7 * rnd()), 0.0 };
    discs.push_back(disc);
  }
  Texture t(w, h);
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      const double gx = w > 1 ? static_cast<double>(i) / (w - 1) : 0.5;
      const double gy = h > 1 ? static_cast<double>(j) / (h - 1) : 0.5;
      Pixel p = { 0.02 + 0.3 * gx + 0.08 * gy, 0.05 + 0.2 * gy, 0.4 - 0.3 * gx, 0.0 };
      for (const Disc& disc : discs)
      {
        const double dx = i + 0.5 - disc.X, dy = j + 0.5 - disc.Y;
        if (dx * dx + dy * dy <= disc.R * disc.R)
        {
          p = disc.Colour;
        }
      }
      p[3] = 0.25 + 0.75 * (0.5 + 0.5 * std::sin(0.7 * i + 1.3 * j));
      for (double& v : p)
      {
        v = static_cast<float>(v);
      }
      t.At(i, j) = p;
    }
  }
  return t;
}

//------------------------------------------------------------------------------
Texture RandomImage(int w, int h, unsigned seed, double lo, double hi)
{
  Texture t(w, h);
  unsigned long long counter = 0;
  for (Pixel& p : t.Texels)
  {
    for (double& v : p)
    {
      v = static_cast<float>(lo + (hi - lo) * HashUniform(seed + 7919ULL, counter++));
    }
  }
  return t;
}

//------------------------------------------------------------------------------
double RelativeL2(const Texture& a, const Texture& b, int channels)
{
  if (a.W != b.W || a.H != b.H)
  {
    return std::nan("");
  }
  double num = 0.0, den = 0.0;
  for (size_t t = 0; t < a.Texels.size(); ++t)
  {
    for (int c = 0; c < channels; ++c)
    {
      const double d = a.Texels[t][c] - b.Texels[t][c];
      num += d * d;
      den += b.Texels[t][c] * b.Texels[t][c];
    }
  }
  return den > 0.0 ? std::sqrt(num / den) : std::sqrt(num);
}

//------------------------------------------------------------------------------
Texture FromImage(vtkImageData* image, int k)
{
  int ext[6];
  image->GetExtent(ext);
  const int nc = image->GetNumberOfScalarComponents();
  Texture t(ext[1] - ext[0] + 1, ext[3] - ext[2] + 1);
  for (int j = 0; j < t.H; ++j)
  {
    for (int i = 0; i < t.W; ++i)
    {
      auto value = [&](int c)
      { return image->GetScalarComponentAsDouble(ext[0] + i, ext[2] + j, ext[4] + k, c); };
      Pixel& p = t.At(i, j);
      if (nc >= 3)
      {
        p = { value(0), value(1), value(2), nc == 4 ? value(3) : 1.0 };
      }
      else
      {
        const double v = value(0);
        p = { v, v, v, nc == 2 ? value(1) : 1.0 };
      }
    }
  }
  return t;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkImageData> ToImage(
  const Texture& texture, int components, int scalarType, const int extentLo[2])
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  const int x0 = extentLo ? extentLo[0] : 0;
  const int y0 = extentLo ? extentLo[1] : 0;
  image->SetExtent(x0, x0 + texture.W - 1, y0, y0 + texture.H - 1, 0, 0);
  image->AllocateScalars(scalarType, components);
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  for (int j = 0; j < texture.H; ++j)
  {
    for (int i = 0; i < texture.W; ++i)
    {
      const Pixel& p = texture.At(i, j);
      const vtkIdType id = static_cast<vtkIdType>(j) * texture.W + i;
      switch (components)
      {
        case 1:
          scalars->SetComponent(id, 0, p[0]);
          break;
        case 2:
          scalars->SetComponent(id, 0, p[0]);
          scalars->SetComponent(id, 1, p[3]);
          break;
        default:
          for (int c = 0; c < components; ++c)
          {
            scalars->SetComponent(id, c, p[c]);
          }
          break;
      }
    }
  }
  return image;
}
}
