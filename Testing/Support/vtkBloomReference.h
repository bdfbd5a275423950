// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file    vtkBloomReference.h
 * @brief   An independent float64 reference of the vtk-bloom filters, for the test suites.
 *
 * Written from ../shared/seeds/PRESETS.md and the filters' class documentation, on purpose
 * without any code of the library under test (no vtkBloomLinearOperator, no vtkBloomKernels):
 * where the filters build separable banded operators, this reference does what a GPU does. A
 * Texture is a W x H RGBA grid of doubles (row 0 first), read with fetch() (index clamp) or
 * bilinear() (uv in [0, 1], texel centres at (i + 0.5) / W, clamp-to-edge, exact weights). A
 * full-screen pass loops over the target's pixels, computes uv = ((x + 0.5) / W', (y + 0.5) /
 * H') and gathers its taps in two dimensions. Convolutions are direct 2-D (or 3-D) loops over
 * the outer-product kernel, and the area resample integrates the overlaps explicitly.
 *
 * It only needs to be right, not fast: keep images small.
 */

#ifndef vtkBloomReference_h
#define vtkBloomReference_h

#include <vtkImageData.h>
#include <vtkSmartPointer.h>

#include <array>
#include <vector>

namespace vtkBloomRef
{
using Pixel = std::array<double, 4>;

/// A W x H grid of RGBA doubles, row 0 first, x fastest.
struct Texture
{
  int W = 0;
  int H = 0;
  std::vector<Pixel> Texels;

  Texture() = default;
  Texture(int w, int h);

  Pixel& At(int i, int j) { return this->Texels[static_cast<size_t>(j) * this->W + i]; }
  const Pixel& At(int i, int j) const { return this->Texels[static_cast<size_t>(j) * this->W + i]; }

  /// Texel (i, j) with both indices clamped into the texture.
  Pixel Fetch(int i, int j) const;

  /// GPU bilinear sample at normalized uv: clamp-to-edge, texel centres at (i + 0.5) / W.
  Pixel Bilinear(double u, double v) const;
};

/// The size of one axis of the next mip level: max(1, floor(n / 2)).
int HalfSize(int n);

/// A full-screen pass of size w x h: out(x, y) = shader(u, v) at the pixel centre's uv.
template <typename Shader>
Texture FullScreenPass(int w, int h, Shader shader)
{
  Texture out(w, h);
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      out.At(x, y) = shader((x + 0.5) / w, (y + 0.5) / h);
    }
  }
  return out;
}

///@{
/// Border of a direct convolution.
enum Border
{
  CLAMP = 0,
  REFLECT = 1, ///< half-sample symmetric, d c b a | a b c d | d c b a, periodic with period 2n
  ZERO = 2
};
/// Index i folded into [0, n) for the border; -1 means "outside, reads zero".
int FoldIndex(int i, int n, Border border);
///@}

///@{
/**
 * Full (2R + 1)-tap Gaussian kernels, index R is the centre, normalized over the taps.
 * sigma <= 0 or radius <= 0 give the single tap {1}.
 */
enum GaussianKind
{
  SAMPLED = 0,    ///< exp(-i^2 / (2 sigma^2))
  INTEGRATED = 1, ///< Phi((i + 1/2) / sigma) - Phi((i - 1/2) / sigma), via erf
  DISCRETE = 2    ///< Lindeberg: e^{-t} I_i(t), t = sigma^2 (power series of I_i)
};
std::vector<double> GaussianKernel(double sigma, int radius, GaussianKind kind);
/// e^{-t} I_n(t) by its power series (all terms positive; accurate, not fast).
double DiscreteGaussianWeight(int n, double t);
///@}

/// Direct 2-D convolution with the outer product kx (x) ky (full kernels, odd lengths), all
/// four channels.
Texture Convolve2D(
  const Texture& in, const std::vector<double>& kx, const std::vector<double>& ky, Border border);

/**
 * Direct 3-D convolution of a volume (nx * ny * nz samples of nc interleaved components, x
 * fastest) with kx (x) ky (x) kz.
 */
std::vector<double> Convolve3D(const std::vector<double>& in, int nx, int ny, int nz, int nc,
  const std::vector<double>& kx, const std::vector<double>& ky, const std::vector<double>& kz,
  Border border);

/// `blur` of seed 004 / PRESETS.md: sampled kernel of the given radius and sigma, separable in
/// meaning, computed here as one direct 2-D convolution; alpha is blurred too. sigma <= 0 or
/// radius 0 is the identity.
Texture Blur(const Texture& in, int radius, double sigma, Border border = CLAMP);

///@{
/// Threshold modes, as numbered by vtkImageBloomThreshold.
enum ThresholdMode
{
  SMOOTHSTEP_KNEE = 0,
  QUADRATIC_KNEE = 1,
  HARD_LUMINANCE = 2,
  PER_CHANNEL = 3,
  NONE = 4,
  EXCESS_KNEE = 5
};
/// Rec. 709 luminance of RGB.
double Luminance(const Pixel& p);
/**
 * The bright pass of one colour, literally from the vtkImageBloomThreshold documentation
 * (finite input only). With `colours` 3 it acts on RGB; with 1 on channel 0 alone, whose value
 * is then its own luminance and brightness. The other channels are left alone.
 */
Pixel BrightPass(Pixel p, ThresholdMode mode, double threshold, double knee,
  double clampLuminance = 3.4028234663852886e38, int colours = 3);
Texture Threshold(const Texture& in, ThresholdMode mode, double threshold, double knee,
  double clampLuminance = 3.4028234663852886e38);
///@}

///@{
/// One level down: size HalfSize(W) x HalfSize(H), all four channels filtered.
enum DownKernel
{
  JIMENEZ13 = 0,
  BOX = 1,
  BINOMIAL = 2
};
/// The 13 bilinear taps of Jimenez (2014), optionally with the Karis average of its 5 boxes.
Texture Downsample13(const Texture& in, bool karis = false);
/// The exact area-weighted resample to `w` x `h` (explicit overlap integrals).
Texture AreaResample(const Texture& in, int w, int h);
/// The 5 x 5 binomial 1 4 6 4 1 / 16 taps at integer offsets from the mapped position.
Texture DownsampleBinomial(const Texture& in);
Texture PyramidDown(const Texture& in, DownKernel kernel, bool karis = false);
///@}

///@{
/// Upsample onto a finer w x h grid: the 3 x 3 tent (1 2 1 / 2 4 2 / 1 2 1 over 16, taps one
/// coarse texel apart) or a single bilinear fetch.
enum UpKernel
{
  TENT = 0,
  BILINEAR = 1
};
Texture PyramidUp(const Texture& coarse, int w, int h, UpKernel kernel);
///@}

/// A bilinear fetch of `in` at every pixel of a w x h target.
Texture BilinearResize(const Texture& in, int w, int h);

///@{
/// The presets of PRESETS.md; each returns the full-resolution RGBA output with the input's
/// alpha.
Texture WebGPUMarket(const Texture& in);
Texture MipAtlas(const Texture& in);
Texture PingPong(const Texture& in);
Texture CrtHalfres(const Texture& in);
/// By name ("webgpu-market", "mip-atlas", "ping-pong", "crt-halfres").
Texture Preset(const char* name, const Texture& in);
///@}

///@{
/**
 * The general vtkImageBloom chain, step by step as its class documentation states it: bright
 * pass of the bilinear fetch at the start level; the pyramid (Karis on the first downsample
 * only; levels deeper than floor(log2(max(W, H))) dropped when LimitLevels); each level blurred
 * Iterations times, horizontally then vertically, with taps TapSpacing level pixels apart
 * (bilinear, clamp); CASCADE (A_last = w Bb_last, A_i = up(A_{i+1}) + w_i Bb_i, bilinear of A_0
 * at full size) or DIRECT (sum_i w_i bilinear(Bb_i)); ADDITIVE (I + S t bloom) or LERP
 * ((1 - S) I + S t bloom); alpha copied.
 */
struct BloomParameters
{
  ThresholdMode Mode = SMOOTHSTEP_KNEE;
  double Threshold = 1.0;
  double Knee = 0.5;
  double ClampLuminance = 3.4028234663852886e38;
  int StartLevel = 1;
  int NumberOfLevels = 5;
  bool LimitLevels = false;
  DownKernel Down = JIMENEZ13;
  bool Karis = false;
  std::vector<double> BlurHalfKernel = { 1.0 }; ///< centre first, used as given
  double TapSpacing = 1.0;
  int Iterations = 1;
  UpKernel Up = TENT;
  bool Direct = false;
  std::vector<double> LevelWeights; ///< missing weights are 1
  bool Lerp = false;
  double Strength = 1.0;
  double Tint[3] = { 1.0, 1.0, 1.0 };
};
Texture Bloom(const Texture& in, const BloomParameters& p);
///@}

///@{
/**
 * Test images, deterministic for a seed on every platform, with every value exactly
 * representable as a float (so float and double inputs hold the same numbers).
 * - SyntheticScene: a dim gradient (0.02..0.4) with emissive discs of value 2..200 and random
 *   hue, several crossing the border; alpha varies in [0.25, 1].
 * - RandomImage: independent uniform values in [lo, hi] in all four channels.
 */
Texture SyntheticScene(int w, int h, unsigned seed);
Texture RandomImage(int w, int h, unsigned seed, double lo = 0.0, double hi = 4.0);
/// A uniform random number in [0, 1) from a 64-bit hash of (seed, index); portable.
double HashUniform(unsigned long long seed, unsigned long long index);
///@}

/// ||a - b||_2 / ||b||_2 over the first `channels` channels; NaN if the sizes differ.
double RelativeL2(const Texture& a, const Texture& b, int channels = 4);

///@{
/**
 * Conversions to and from vtkImageData (slice k of a 2-D image). Components map as: 1 = (v, v,
 * v, 1), 2 = (v, v, v, a), 3 = (r, g, b, 1), 4 = (r, g, b, a); ToImage writes back the same
 * layout (component 0 of a 1-2 component image is R).
 */
Texture FromImage(vtkImageData* image, int k = 0);
vtkSmartPointer<vtkImageData> ToImage(
  const Texture& texture, int components, int scalarType, const int extentLo[2] = nullptr);
///@}
}

#endif
// VTK-HeaderTest-Exclude: vtkBloomReference.h
