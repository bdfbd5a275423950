// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkBloomPassFFT.h
 * @brief  (private to vtkBloomPass) PSF bloom's convolution on the GPU: a float RGBA texture
 *         convolved with one point-spread function per colour channel through a 2-D FFT in
 *         compute shaders (OpenGL 4.3), as vtkBloomPSFConvolution::Convolve does on the CPU.
 *
 * For a W x H image and kernels k_c of radius R (the largest of the three; a smaller kernel is
 * centred in the larger window), out_c = fold(b_c * k_c): the full linear convolution
 * (W + 2R) x (H + 2R) of the zero-padded grid NX x NY (NX >= W + 2R, NY >= H + 2R, products
 * of 2, 3 and 5, so nothing wraps around), then what falls outside the image folded back by
 * half-sample reflection (REFLECT: energy conserved) or dropped (ZERO). Alpha is 0.
 *
 * The real channels are transformed two at a time as one complex signal: z = R + i G and
 * B + i 0 (two complex 2-D transforms for three real channels). After the forward transform
 * the multiply separates the spectra of R and G by Hermitian symmetry,
 * R^[k] = (Z[k] + conj Z[-k]) / 2, G^[k] = (Z[k] - conj Z[-k]) / (2 i), multiplies each by its
 * kernel's spectrum and recombines them as Y = R^ KR + i G^ KG, whose inverse is
 * (r * kR) + i (g * kG), both parts real. The kernels' spectra are made the same way, once per
 * kernel set and grid (SetKernels / Prepare), scaled by 1 / (NX NY).
 *
 * Per convolution: the row transforms (reading the texture), the column transforms, the
 * multiply, the inverse columns, the inverse rows and the fold, each line in shared memory,
 * several adjacent lines (or sub-sequences) to a work group (LayoutOf). The zero padding is
 * not transformed: the forward rows run only on the image's rows and the forward columns read
 * only those; the inverse rows run only on the rows the fold reads. Storage is float32: two
 * shader storage buffers of 2 NX NY vec2 (the signals) and 3 NX (NY / 2 + 1) vec2 (the
 * kernels' spectra: real kernels have Hermitian spectra, so only the frequencies 0 to NY / 2
 * along y are kept), and one twiddle table per axis, cos and sin of 2 pi m / N computed in
 * double.
 *
 * A row of N <= 4096 samples (MaximumLength: 4096 vec2 fill the 32 KiB of shared memory every
 * OpenGL 4.3 context has), or a column of N <= 2048, is transformed by one dispatch. A longer
 * one (up to MaximumGridLength) takes two, the four-step transform of Bailey (1990, "FFTs in
 * external or hierarchical memory"): N = N1 N2 (Split: both at most 4096, as close as they can be),
 * with n = N2 n1 + n2 and k = k1 + N1 k2,
 *
 *   X[k1 + N1 k2] = sum_n2 W_N2^(n2 k2) [ W_N^(n2 k1) sum_n1 W_N1^(n1 k1) x[N2 n1 + n2] ],
 *
 * W_M = exp(-2 pi i / M). The first dispatch transforms the N2 sub-sequences of stride N2
 * (length N1) in place and multiplies output k1 of sub-sequence n2 by the twiddle W_N^(n2 k1)
 * (entry n2 k1 of the axis's table); the second transforms the N1 contiguous runs of N2 samples
 * in place. No transpose: the spectrum stays in that order, position N2 k1 + k2 holding
 * frequency k1 + N1 k2. The multiply (and the kernels' spectra, made by the same transform)
 * only needs where -k is, which its shader works out from N2. The inverse runs the two
 * dispatches backwards with conjugate roots: the runs of N2 (then the twiddle W_N^(-n2 k1)),
 * then the strided sub-sequences, which leaves the signal in natural order for the fold.
 *
 * Limits: a grid line longer than MaximumGridLength, a buffer larger than MaximumBufferBytes
 * (2 GiB; the signals, 16 NX NY bytes, are the largest) or than the context's shader storage
 * block, or a kernel window wider than its largest texture is refused. A 3840 x 2160 frame with
 * a PSF of radius 1920 (grid 7680 x 6000) needs 0.74 GB of signals and 0.55 GB of spectra.
 * Dispatches of more than 65535 work groups are laid out in 2-D.
 *
 * The programs are plain OpenGL (VTK 9.1's shader classes have no compute stage), from
 * glsl/vtkBloomPassFFTCS.glsl and a #define preamble, made on first use.
 */

#ifndef vtkBloomPassFFT_h
#define vtkBloomPassFFT_h

#include "vtkBloomPSFSplit.h" // For the kernel type
#include "vtkSmartPointer.h"  // For the kernel texture
#include "vtkType.h"          // For vtkMTimeType

#include <map>
#include <string>
#include <vector>

class vtkBloomPassProfiler;
class vtkOpenGLRenderWindow;
class vtkTextureObject;
class vtkWindow;

class vtkBloomPassFFT
{
public:
  vtkBloomPassFFT();
  ~vtkBloomPassFFT();
  vtkBloomPassFFT(const vtkBloomPassFFT&) = delete;
  vtkBloomPassFFT& operator=(const vtkBloomPassFFT&) = delete;

  /// One colour channel's kernel: (2 Radius + 1)^2 values, row-major, centred on (R, R).
  using Kernel = vtkBloomPSFSplit::Kernel;

  /// The longest line one dispatch transforms: 4096 vec2 fill 32 KiB of shared memory.
  static constexpr int MaximumLength = 4096;

  /// The longest grid line: longer than MaximumLength, it is transformed in four steps.
  static constexpr int MaximumGridLength = 65536;

  /// The largest shader storage buffer Prepare makes (the signals, 16 NX NY bytes).
  static constexpr long long MaximumBufferBytes = 1LL << 31;

  /**
   * N = n1 n2 for the four-step transform of a line of n samples (a product of 2, 3 and 5):
   * n1 = n, n2 = 1 for n <= longest (one dispatch); else both at most MaximumLength,
   * n1 the smallest such divisor that is at least sqrt(n). False if there is none.
   */
  static bool Split(int n, int& n1, int& n2, int longest = MaximumLength);
  /// The longest line transformed in one dispatch along `axis`: MaximumLength for rows, half
  /// that for columns (a longer column is transformed in four steps, `longest` in Split).
  static int LongestOnePass(int axis);

  /// A program's uniform locations, looked up once each (here and in vtkBloomPassFFTBlur).
  using UniformCache = std::map<std::pair<unsigned int, std::string>, int>;
  static int CachedUniform(UniformCache& cache, unsigned int program, const char* name);

  /// The smallest n' >= n whose prime factors are 2, 3 and 5.
  static int GoodSize(int n);

  /// The radices of n (a product of 2, 3 and 5) in the order the stages run: 4s, a 2, 3s, 5s.
  static std::vector<int> Radices(int n);

  /**
   * Use `kernels` (red, green, blue) from now on, identified by `version` (not 0): the spectra are
   * made again only when the version, or the grid, changes.
   */
  void SetKernels(const Kernel kernels[3], vtkMTimeType version);
  vtkMTimeType GetKernelsVersion() const { return this->KernelsVersion; }

  /**
   * Make the grid, the buffers, the programs and (where stale) the kernels' spectra for
   * width x height images in `context`. False, with the reason in `why`, when the context has
   * no compute shaders, a program does not build, the grid has a line longer than
   * MaximumGridLength, a buffer would exceed MaximumBufferBytes or the context's largest shader
   * storage block, or the kernels' window its largest texture.
   */
  bool Prepare(vtkOpenGLRenderWindow* context, int width, int height, std::string& why);

  /**
   * target = `source` (width x height, RGBA float, the prepared size) convolved with the
   * kernels, REFLECT or ZERO borders; `target` an RGBA32F texture of the same size. Its six
   * stages: the forward rows and columns, the multiply, the inverse columns and rows, the fold,
   * each a span of `profiler` sized as the grid.
   */
  void Convolve(vtkTextureObject* source, vtkTextureObject* target, bool reflect,
    vtkBloomPassProfiler& profiler);

  /// The padded grid (NX, NY) of the last Prepare.
  const int* GetGridSize() const { return this->Grid; }

  void ReleaseGraphicsResources(vtkWindow* w);

  ///@{
  /**
   * For other programs that run the line transform on a line of their own (vtkBloomPassFFTBlur):
   * the #defines of glsl/vtkBloomPassFFTCS.glsl's transform of n samples (FFT_TRANSFORM) with
   * FFT_LIBRARY, which leaves out its main() and adds TransformLine(), the in-place DFT of the
   * shared `line`; and its twiddle table, cos and sin of 2 pi m / n for m < n, computed in double
   * and rounded once to float.
   */
  static std::string LineTransformDefines(int n);
  static std::vector<float> TwiddleTable(int n);
  ///@}

private:
  /// One dispatch of a transform: the DFT of Count sub-sequences of Length samples per line,
  /// sub-sequence j at line samples j Offset + i Spacing, then the four-step twiddle or not.
  struct Pass
  {
    int Length;
    int Count;
    int Offset;
    int Spacing;
    bool Twiddle;
  };
  /// The dispatches of a forward (direction -1) or inverse (+1) transform of lines of n samples.
  static std::vector<Pass> Passes(int n, int axis, float direction);

  /// The lines a transform runs on, and where its input is zero.
  struct Lines
  {
    int First;                ///< the first line transformed
    int Count;                ///< lines transformed, from First; the others are left alone
    int SampleLimit;          ///< samples at or past it along a line are zero (not read)
    vtkTextureObject* Source; ///< rows forward: read from this texture, not the buffer
    const int* SourceSize;    ///< its size (zero beyond)
  };
  /// The forward (direction -1) or inverse (+1) transform of `lines` along `axis` (0: rows,
  /// 1: columns) of both signals.
  void Transform(int axis, float direction, const Lines& lines);
  /// The forward transform of `source` (its size, zero padded to the grid): its rows, then
  /// every column, reading only the source's rows.
  void Forward(vtkTextureObject* source, const int sourceSize[2]);
  void ForwardRows(vtkTextureObject* source, const int sourceSize[2]);
  void ForwardColumns(int rows);
  /// The image's spectrum times the kernels' (FFT_MULTIPLY), in place.
  void Multiply();
  /// The inverse transform's full convolution folded into `target` (FFT_FOLD).
  void Fold(vtkTextureObject* target, bool reflect);
  /// The compute program of `defines`, made on first use; 0 when it does not build (the
  /// compiler's log in `log`, when given).
  unsigned int Program(const std::string& defines, std::string* log = nullptr);
  /**
   * How a work group of `pass` along `axis` is laid out: Threads invocations per unit (a line's
   * sub-sequence), Butterflies each per stage, Lines units to a group, Stride samples apart in
   * shared memory. Units adjacent in memory come several to a group (columns, and the
   * sub-sequences of a row's four-step transform), so that a group reads and writes runs of
   * them rather than one sample a row; a row of one pass is a group of its own.
   */
  struct Layout
  {
    int Threads;
    int Butterflies;
    int Lines;
    int Stride;
    bool BlockSubs;      ///< the units are sub-sequences of one line (else lines of one)
    bool SamplesFastest; ///< consecutive invocations load consecutive samples of a unit
  };
  static Layout LayoutOf(const Pass& pass, int axis);
  /// The defines of `pass` along a line of n samples laid out as `layout`.
  static std::string TransformDefines(
    const Pass& pass, int n, bool fromTexture, const Layout& layout);
  /// One dispatch of a transform as BuildPrograms planned it for the grid.
  struct PlannedPass
  {
    Pass Run;
    Layout Shape;
    unsigned int Program;
  };
  void RunPass(const PlannedPass& planned, int axis, float direction, const Lines& lines);
  /// The padded grid of width x height images in `grid`, and why this context cannot use it
  /// (empty when it can).
  std::string MakeGrid(int width, int height, int grid[2]) const;
  /// Build (or find) every program of the grid's transforms and plan their dispatches
  /// (Planned); false, with the reason in `why`.
  bool BuildPrograms(const int grid[2], std::string& why);
  /// Upload the kernels and compute their spectra into SpectraBuffer.
  void MakeSpectra();
  int Uniform(unsigned int program, const char* name);
  /// The `split` uniform of the separate and multiply stages: N2 of each axis (1: one pass).
  void SetSplit(unsigned int program);
  void AllocateBuffers();
  /// The bytes of the signals (two complex NX x NY grids) and of the kernels' spectra (three,
  /// Hermitian: NX (NY / 2 + 1) samples each).
  static long long SignalBytes(const int grid[2]);
  static long long SpectraBytes(const int grid[2]);

  vtkOpenGLRenderWindow* Context = nullptr;
  Kernel Kernels[3];
  int Radius = 0;
  vtkMTimeType KernelsVersion = 0;
  vtkMTimeType SpectraVersion = 0; ///< the kernels' version the spectra were made for; 0: none
  int Size[2] = { 0, 0 };          ///< the image
  int Grid[2] = { 0, 0 };          ///< NX, NY
  bool ProgramsBuilt = false;      ///< BuildPrograms succeeded for Grid
  std::vector<PlannedPass> Planned[2][2]; ///< [axis][0: forward, 1: inverse], by BuildPrograms
  unsigned int SignalBuffer = 0;
  unsigned int SpectraBuffer = 0;
  unsigned int TwiddleBuffers[2] = { 0, 0 }; ///< per axis
  vtkSmartPointer<vtkTextureObject> KernelTexture;
  std::map<std::string, unsigned int> Programs;
  UniformCache Locations;
};

#endif
// VTK-HeaderTest-Exclude: vtkBloomPassFFT.h
