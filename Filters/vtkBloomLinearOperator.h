// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkBloomLinearOperator
 * @brief   A one-dimensional linear resampling operator: a banded sparse matrix.
 *
 * Every linear step of the bloom chain is separable or a sum of separable terms: a bilinear
 * fetch at a new resolution, the 13-tap downsample, a tent upsample, a blur with fractional tap
 * spacing, an area-weighted resample and a plain convolution. Each axis of such a step is an
 * operator that maps `InputSize` samples to `OutputSize` samples:
 *
 *   out[j] = sum_k Weights[j * Width + k] * in[First[j] + k]
 *
 * Borders are folded into the weights when the operator is built, so applying it never reads
 * outside [0, InputSize). Because the operator knows exactly which inputs each output reads, it
 * also gives the input range a streamed piece needs (`GetInputRange`), which makes a streamed
 * piece equal to the whole-image result bit for bit.
 *
 * Sampling positions follow the GPU convention: output sample j (centre at (j + 1/2) / OutputSize
 * in normalized coordinates) maps to source texel coordinate
 * p = (j + 1/2) * InputSize / OutputSize - 1/2, where texel centres sit at integers. A tap at
 * offset o reads p + o * scale with a bilinear fetch; `scale` is 1 unless stated otherwise.
 */

#ifndef vtkBloomLinearOperator_h
#define vtkBloomLinearOperator_h

#include "vtkBloomKernels.h"       // For vtkBloomKernels::Tap
#include "vtkFiltersBloomModule.h" // For export macro

#include <vector>

class VTKFILTERSBLOOM_EXPORT vtkBloomLinearOperator
{
public:
  /// How a kernel sees samples beyond the ends of the input.
  enum BorderMode
  {
    BORDER_CLAMP = 0,   ///< repeat the edge sample (GL clamp-to-edge)
    BORDER_REFLECT = 1, ///< half-sample symmetric mirror, d c b a | a b c d | d c b a
    BORDER_ZERO = 2     ///< samples outside are zero
  };

  /// Map input index i (any integer) into [0, n) under a border mode; -1 means "zero".
  static int FoldIndex(int i, int n, int border);

  /// The identity on n samples.
  static vtkBloomLinearOperator Identity(int n);

  /**
   * Resample from inputSize to outputSize samples with the given taps, each tap a bilinear
   * fetch at p + offset (offsets in source texels). Used for the bilinear fetch, the tent
   * upsample and the 13-tap downsample.
   */
  static vtkBloomLinearOperator Resample(
    int inputSize, int outputSize, const std::vector<vtkBloomKernels::Tap>& taps, int border);

  /// Same-size convolution with taps at (possibly fractional) offsets, bilinear in between.
  static vtkBloomLinearOperator Convolve(
    int size, const std::vector<vtkBloomKernels::Tap>& taps, int border);

  /**
   * Exact area-weighted resample: output j covers source [j * n / m, (j + 1) * n / m] and each
   * source texel is weighted by its overlap. An exact 2x2 box for even sizes; it preserves the
   * mean for odd sizes.
   */
  static vtkBloomLinearOperator Area(int inputSize, int outputSize);

  /// The product this * other (apply `other` first). Used to fold repeated passes.
  vtkBloomLinearOperator Compose(const vtkBloomLinearOperator& other) const;

  /// Inputs read by outputs [outMin, outMax] (inclusive, clamped to the operator's range).
  void GetInputRange(int outMin, int outMax, int& inMin, int& inMax) const;

  /**
   * This operator's rows [outBegin, outEnd) over the inputs [inBegin, inEnd): the operator of a
   * part of the image (a tile with its guard band) that reads a part of the input. A row keeps
   * its weights; a tap outside the inputs kept goes to the nearest one kept (such a row is only
   * right where it reads none).
   */
  vtkBloomLinearOperator Cut(int outBegin, int outEnd, int inBegin, int inEnd) const;

  /// True when this is the identity (so a pass can be skipped).
  bool IsIdentity() const;

  /**
   * Where the operator is translation invariant with a period of `period` output rows (1: a
   * convolution; 2: an exact 2:1 or 1:2 resample): the longest run of rows [Begin, End) around
   * the middle row in which row j + Period is row j moved by Stride >= 1 input samples, with
   * the same weights compared in float32 (the precision the fused CPU chain and vtkBloomPass
   * apply them in). Fast paths run such a run with one set of weights. Empty (Begin == End)
   * when shorter than max(minimum, 2 * period) rows.
   */
  struct InvariantRange
  {
    int Begin = 0;
    int End = 0;
    int Period = 0;
    int Stride = 0;
  };
  InvariantRange FindInvariantRange(int period, int minimum) const;

  int InputSize = 0;
  int OutputSize = 0;
  int Width = 0;
  std::vector<int> First;
  std::vector<double> Weights;

private:
  static vtkBloomLinearOperator FromRows(
    int inputSize, int outputSize, std::vector<std::vector<std::pair<int, double>>>& rows);
};

#endif
// VTK-HeaderTest-Exclude: vtkBloomLinearOperator.h
