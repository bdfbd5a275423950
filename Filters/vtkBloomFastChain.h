// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file    vtkBloomFastChain.h
 * @brief   Internal: the fused, content-aware float32 bloom chain vtkImageBloom runs by default.
 *
 * Not installed and not part of the public API. It computes the chain vtkImageBloom documents
 * (same operators, taken from vtkBloomLinearOperator, vtkBloomKernels and
 * vtkBloomDownsampleTerms) in float32 arithmetic, in few passes over the full-resolution data:
 *
 * 1. Bright pass: one read of the input. Per level-0 row, the input rows are first bounded
 *    (per-channel extremes, NaN/Inf): rows whose every fetched sample is certainly below the
 *    threshold's zero edge are not fetched at all. Otherwise the y fetch combines whole rows
 *    (flat), the x fetch gathers the colours, and the bright pass (vtkBloomBrightPass in float)
 *    runs its full formula only where vtkBloomBrightPassIsZero cannot decide. The pass also finds
 *    the bounding box of the non-zero bright samples and whether the input holds -0, NaN or Inf.
 * 2. Pyramid: each level from the level above, over the region its support can reach.
 * 3. Blur fused with the upsample-accumulate: acc_i = up(acc_{i+1}) + w_i blur(level_i), one
 *    output row at a time (CASCADE), into a plane of its own; DIRECT blurs each level into its
 *    own plane. Separable passes stream: blurs and downsamples run y first (the y operator
 *    combines source rows into one line, the x operator runs on it); upsamples keep the
 *    x-passed source rows they need in a ring of a few rows.
 * 4. Composite fused with the last upsample: each output row interpolates its bloom row from
 *    acc_0 (CASCADE) or from every weighted level (DIRECT) and writes
 *    keep * in + (S t bloom + 0). Adding +0 makes every zero bloom term +0, so the result does
 *    not depend on the sign of a zero bloom and the content-aware skips are exact. For an input
 *    without -0, NaN and Inf and keep = 1, rows take an exact short form (in + (S t bloom + 0),
 *    or a copy where there is no bloom).
 * RGB levels hold four float lanes per sample (the fourth is zero), so per-pixel work is one
 * 4-wide vector operation; level samples saturate at +-FLT_MAX (a float32 sum that overflows
 * stays finite instead of turning into Inf and then NaN at a zero band weight).
 * The passes are compiled twice where the compiler allows it: for the baseline instruction set
 * and for AVX2 (without FMA); Execute runs the AVX2 copy when the CPU has it and UseAVX2 is
 * set. Both copies compute each sample with the same operations in the same order.
 * Rows are threaded with vtkSMPTools; every output sample is computed by the same expression
 * whatever the threading and the regions, so the output is deterministic.
 *
 * Content-aware work (each can be switched off; the output is bit-identical either way):
 * - SkipEmpty: nothing non-zero after the bright pass means a zero bloom: no pyramid, and the
 *   input scalars are passed through (shared, not copied) when keep = 1 and the input has no
 *   -0, NaN or (with sanitizing) Inf, which are the only samples "in + 0" would change.
 * - TrimPyramid: trailing levels of weight 0 are not built (they only add zeros).
 * - RestrictToBrightRegion: every step computes only the region its operators can reach from
 *   the bounding box of the bright samples; outside, samples are zero and the composite is
 *   keep * in + 0.
 * - SkipDisabled: Strength 0, a black tint or all weights 0 skip the whole chain.
 * Wide level blurs (the ping-pong preset folds 32 passes into one operator 385 taps wide) can
 * run through the FFT instead (vtkBloomFFTConvolution, single precision): per level and axis,
 * when ConvolutionMode asks for it or, in AUTOMATIC, when the FFT's modeled cost is below the
 * direct cost divided by DirectSpeedup (the fused direct passes are that many times faster per
 * tap than the cost model's unit). The level is then blurred in place on those axes before the
 * fused pass, whose blur on them becomes the identity. The FFT leaves exact zeros wherever no
 * bright sample reaches, so the content-aware skips stay exact.
 * Double input, Karis averaging and 3-D (multi-slice) inputs are not handled (Supports()
 * returns false) and vtkImageBloom runs its double-precision reference for them.
 */

#ifndef vtkBloomFastChain_h
#define vtkBloomFastChain_h

#include "vtkBloomStatistics.h" // For the statistics measured in the composite
#include "vtkSmartPointer.h"    // For the recycled output array
#include "vtkType.h"            // For vtkMTimeType

class vtkBloomChain;
class vtkBloomParameters;

#include <cstddef>
#include <utility>
#include <vector>

class vtkAlgorithm;
class vtkDataArray;
class vtkImageData;

/**
 * Everything the chain needs for one update: the bloom's values copied once from its
 * vtkBloomParameters (Set) into plain fields, which the fused per-sample loops read without a
 * virtual getter call, and the execution options of the filter (UseAVX2, ChainTime).
 */
struct vtkBloomFastChainParameters
{
  /// Copy the values of `bloom`, with the chain built for width x height and its level sizes.
  void Set(vtkBloomParameters* bloom, const vtkBloomChain* chain, int width, int height);

  int ThresholdMode = 0;
  double Threshold = 1.0;
  double Knee = 0.5;
  double ClampLuminance = 0.0;
  /// The operators of every step (vtkBloomChain::Build for the input's size); not owned.
  const vtkBloomChain* Chain = nullptr;
  std::vector<std::pair<int, int>> LevelSizes; ///< vtkImageBloom::ComputeLevelSizes
  std::vector<double> LevelWeights;            ///< one per level
  int DownsampleKernel = 0;
  bool KarisAverage = false;
  int BlurIterations = 1;
  int AccumulateMode = 0; ///< vtkBloomParameters::CASCADE or DIRECT
  int CompositeMode = 0;  ///< vtkBloomParameters::ADDITIVE or LERP
  double Strength = 1.0;
  double Tint[3] = { 1.0, 1.0, 1.0 };
  bool SanitizeNonFinite = true;
  bool SkipEmpty = true;
  bool TrimPyramid = true;
  bool RestrictToBrightRegion = true;
  bool SkipDisabled = true;
  /// Run the passes compiled for AVX2 when the CPU has it (same bits as the baseline build).
  bool UseAVX2 = true;
  /// How the level blurs run: vtkBloomParameters::CONVOLUTION_AUTOMATIC, _DIRECT or _FFT.
  int ConvolutionMode = 0;
  /// When Chain was built: the FFT convolutions of its blurs are kept until it changes.
  vtkMTimeType ChainTime = 0;
  /// Measure vtkImageBloom's statistics in the composite (vtkBloomStatisticsRows.h).
  bool MeasureStatistics = false;
};

/// What the last Execute did (for tests and the benchmark).
struct vtkBloomFastChainReport
{
  bool ChainSkipped = false;      ///< zero bloom: no pyramid was built
  bool PassedThrough = false;     ///< the output shares the input scalars
  int LevelsBuilt = 0;            ///< pyramid levels computed
  long long SamplesProcessed = 0; ///< level samples computed (all levels, all steps)
  size_t WorkspaceBytes = 0;      ///< bytes of intermediate buffers held
  bool UsedAVX2 = false;          ///< the passes compiled for AVX2 ran
  int FFTBlurs = 0;               ///< level blur axes run through the FFT
  /// The statistics below were measured (MeasureStatistics, and the composite ran).
  bool StatisticsMeasured = false;
  vtkBloomLuminanceStatistics StatisticsIn, StatisticsOut;
  vtkIdType BrightPixels = 0;
};

class vtkBloomFastChain
{
public:
  /**
   * How many times less a tap of the fused direct blur costs than the unit of
   * vtkBloomFFTConvolution's cost model. Measured at 1080p (scripts/benchmark.sh,
   * docs/numerics.md): the ping-pong blur takes 760 ms direct (0.24 ns per tap and sample on
   * each axis) and about 40 ms through the FFT (about 10 ns per sample and axis, which the model
   * puts at 44 units), so a direct tap costs about one unit.
   */
  static constexpr double DirectSpeedup = 1.0;

  vtkBloomFastChain();
  ~vtkBloomFastChain();

  /**
   * False for what the fast chain does not handle: double input (which asks for double
   * precision, so vtkImageBloom runs its reference), Karis average, more than one slice.
   */
  static bool Supports(const vtkBloomFastChainParameters& p, vtkImageData* input);

  /**
   * True when this build has the passes compiled for AVX2 (GCC on x86) and the CPU and the
   * operating system support AVX2.
   */
  static bool AVX2Available();

  /**
   * Run the chain on `input` (float or double, 1-4 components, one slice) and write the output
   * extent `outExt` of `output` (allocated here, or sharing the input scalars).
   */
  void Execute(const vtkBloomFastChainParameters& p, vtkImageData* input, const int outExt[6],
    vtkImageData* output, vtkBloomFastChainReport& report, vtkAlgorithm* progress);

  /// Free the intermediate buffers and the recycled output array.
  void ReleaseWorkspace();

  struct Internals;

private:
  vtkBloomFastChain(const vtkBloomFastChain&) = delete;
  void operator=(const vtkBloomFastChain&) = delete;
  Internals* Impl;
};

#endif
// VTK-HeaderTest-Exclude: vtkBloomFastChain.h
