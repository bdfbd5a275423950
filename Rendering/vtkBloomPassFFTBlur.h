// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkBloomPassFFTBlur.h
 * @brief  (private to vtkBloomPass) a wide blur operator of the chain applied along the rows or
 *         the columns of a level through an FFT in compute shaders (OpenGL 4.3), as
 *         vtkBloomFFTConvolution applies it on the CPU.
 *
 * A same-size banded operator M (a level's blur, all its iterations folded: vtkBloomChain) is
 * applied to every line x of n samples as
 *
 *   M x = T x + D x,   T x = (k * E x) restricted to [PadLeft, PadLeft + n),
 *
 * with the kernel k, the extension E (the border mode, then zeros up to N), the low-rank
 * border blocks D = U V^T and the reach of each input sample all taken from a
 * vtkBloomFFTConvolution built on M (no maths is repeated here). N is the smallest product of
 * 2, 3 and 5 that holds the extended line; the kernel's spectrum for N is made once per
 * operator on the CPU in double (vtkBloomFFTConvolution::ComputeKernelSpectrum), completed to
 * N values by Hermitian symmetry and uploaded.
 *
 * Per axis, two dispatches (glsl/vtkBloomPassFFTBlurCS.glsl): one work group per line and pair
 * of channels convolves the line in shared memory with vtkBloomPassFFT's line transform and
 * computes D's coefficients V^T x; then one invocation per sample adds U (V^T x), scales by the
 * pass's weight and writes the target image. Outputs that no non-zero sample of their line
 * reaches are exactly zero, and an all-zero line is not transformed.
 *
 * Cost model (Choose, CONVOLUTION_AUTOMATIC): per line, the direct pass costs its taps per
 * output sample, DirectCost = nnz(M) tap-fetches; this path costs
 * FFTCostFactor * 2 N log2 N (two transforms per line) + 8 N (extension, product, crop,
 * finish) + rank x (rows + cols) for D, in the same units. FFTCostFactor was measured on an
 * NVIDIA H100 (see its comment).
 */

#ifndef vtkBloomPassFFTBlur_h
#define vtkBloomPassFFTBlur_h

#include <map>
#include <memory>
#include <string>
#include <vector>

class vtkBloomLinearOperator;
class vtkOpenGLRenderWindow;
class vtkTextureObject;
class vtkWindow;

class vtkBloomPassFFTBlur
{
public:
  vtkBloomPassFFTBlur();
  ~vtkBloomPassFFTBlur();
  vtkBloomPassFFTBlur(const vtkBloomPassFFTBlur&) = delete;
  vtkBloomPassFFTBlur& operator=(const vtkBloomPassFFTBlur&) = delete;

  /**
   * Tap-fetches of the direct pass that one N log2 N unit of a compute-shader transform costs.
   * 1.0 is an estimate for an NVIDIA H100, not yet a measurement: the direct ping-pong blur
   * (385 taps) costs 12 ms at 3840x2160 there, about 1.9 ps per tap-fetch, and the two
   * transforms per line of both axes (about 4.5e8 units) are bound by shared memory and its
   * barriers at an expected 1 ms or less, about 2 ps per unit. Measured on Mesa's llvmpipe
   * (BloomPassFrameTime --direct / --fft --profile lit-spheres 960 540 5 ping-pong: 672 ms
   * against 791 ms over the floor, 1.7 ns per tap-fetch, 19 ns per unit) it is about 11, so
   * there AUTOMATIC takes the FFT where the direct pass would be roughly ten times dearer than
   * modeled; the ping-pong preset still runs through the FFT at 1.2 times the direct cost.
   */
  static constexpr double FFTCostFactor = 1.0;

  /**
   * Whether `op` runs through the FFT with `mode` (vtkBloomParameters::CONVOLUTION_*): never
   * with DIRECT, whenever it can with FFT, and with AUTOMATIC when its modeled cost is below
   * the direct pass's. It cannot when the operator has no translation-invariant interior or
   * its extended line does not fit the shared memory of one work group. The operator's tables
   * are made on first use and kept until ReleaseOperators.
   */
  bool Choose(vtkOpenGLRenderWindow* context, const vtkBloomLinearOperator& op, int mode);

  ///@{
  /**
   * target = weight * M(source) along `axis` (0: rows, 1: columns) of `lines` lines of
   * n = op.InputSize samples: the source's [0, n) x [0, lines) for rows, [0, lines) x [0, n)
   * for columns, into the same samples of `target` (a texture of GL_RGBA32F or GL_RGBA16F
   * `format`), in two dispatches: Convolve (T x and V^T x of every line into buffers), then
   * Finish (plus U V^T x, times the weight, into the target). Choose must have returned true
   * for `op`. Convolve returns false, having dispatched nothing, when a program of the two does
   * not build.
   */
  bool Convolve(const vtkBloomLinearOperator& op, int axis, int lines, vtkTextureObject* source,
    unsigned int format);
  void Finish(const vtkBloomLinearOperator& op, int axis, int lines, unsigned int target,
    unsigned int format, double weight);
  ///@}

  /// The transform length N of `op` (after Choose; 0 when it has none), for tests.
  int GetTransformSize(const vtkBloomLinearOperator& op) const;

  /// Free the operators' tables (the chain is about to be rebuilt).
  void ReleaseOperators();

  /// Free everything.
  void ReleaseGraphicsResources(vtkWindow* w);

private:
  struct Operator;
  Operator* Prepare(vtkOpenGLRenderWindow* context, const vtkBloomLinearOperator& op);
  unsigned int Program(const std::string& defines, bool convolve);
  int Uniform(unsigned int program, const char* name);
  void Reserve(size_t signal, size_t coefficients, size_t ranges);

  vtkOpenGLRenderWindow* Context = nullptr;
  std::map<const vtkBloomLinearOperator*, std::unique_ptr<Operator>> Operators;
  std::map<std::string, unsigned int> Programs;
  std::map<std::pair<unsigned int, std::string>, int> Locations; // vtkBloomPassFFT::UniformCache
  unsigned int Buffers[3] = { 0, 0, 0 }; ///< signal, coefficients, line ranges
  size_t Capacity[3] = { 0, 0, 0 };      ///< their sizes in bytes
  int MaximumLength = 0;                 ///< the longest line shared memory holds; 0: not asked
};

#endif
// VTK-HeaderTest-Exclude: vtkBloomPassFFTBlur.h
