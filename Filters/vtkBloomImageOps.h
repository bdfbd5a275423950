// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file    vtkBloomImageOps.h
 * @brief   Internal: apply vtkBloomLinearOperator passes to dense double-precision blocks.
 *
 * Not installed and not part of the public API. The filters copy the input region they need
 * into a vtkBloomBuffer, run the separable passes in double precision and write the requested
 * output extent back in the input's scalar type. Indices are relative to the minimum of the
 * whole extent, which is where the operators' index 0 sits.
 */

#ifndef vtkBloomImageOps_h
#define vtkBloomImageOps_h

#include "vtkBloomLinearOperator.h"

#include <cstddef>
#include <vector>

class vtkImageData;

/// A dense block of samples with interleaved components, x fastest.
struct vtkBloomBuffer
{
  int Lo[3] = { 0, 0, 0 };   ///< index of the first sample on each axis
  int Size[3] = { 0, 0, 0 }; ///< samples on each axis
  int NumberOfComponents = 0;
  std::vector<double> Data;

  void Allocate(const int lo[3], const int size[3], int numberOfComponents);
  size_t Offset(int i, int j, int k) const
  {
    return ((static_cast<size_t>(k - this->Lo[2]) * this->Size[1] + (j - this->Lo[1])) *
               this->Size[0] +
             (i - this->Lo[0])) *
      this->NumberOfComponents;
  }
  size_t GetNumberOfSamples() const
  {
    return static_cast<size_t>(this->Size[0]) * this->Size[1] * this->Size[2];
  }
};

/**
 * out = op applied along `axis` to `in`, for output indices [outLo, outLo + outSize) on that
 * axis; the other axes keep the block of `in`. The input block must hold every input index
 * the operator reads for those outputs.
 */
void vtkBloomApplyAxis(const vtkBloomBuffer& in, int axis, const vtkBloomLinearOperator& op,
  int outLo, int outSize, vtkBloomBuffer& out, bool parallel);

/**
 * Apply up to one operator per axis (nullptr = identity), x then y then z, producing the block
 * [outLo, outLo + outSize). Intermediate blocks keep only the rows later passes read.
 */
void vtkBloomApplySeparable(const vtkBloomBuffer& in, const vtkBloomLinearOperator* const ops[3],
  const int outLo[3], const int outSize[3], vtkBloomBuffer& out, bool parallel);

/// One separable term of a two-dimensional step: Weight * (Y X).
struct vtkBloomSeparableTerm
{
  double Weight = 1.0;
  vtkBloomLinearOperator X;
  vtkBloomLinearOperator Y;
};

/**
 * The terms of one pyramid-down step with a vtkImagePyramidDown kernel, from inSize to outSize
 * (x, y). JIMENEZ13 is 1/2 inner box + 1/2 tent x tent; with `karis` it is the five 2x2 boxes
 * that vtkBloomCombineTerms averages with Karis weights.
 */
std::vector<vtkBloomSeparableTerm> vtkBloomDownsampleTerms(
  int kernel, bool karis, const int inSize[2], const int outSize[2]);

/**
 * out = sum_t weights[t] * results[t], or with `karis` the Karis average: each result weighted
 * by weights[t] / (1 + max(luma, 0)) and the weights renormalized per sample. Luma is Rec. 709
 * for 3 or more components, component 0 otherwise.
 */
void vtkBloomCombineTerms(const std::vector<vtkBloomBuffer>& results,
  const std::vector<double>& weights, bool karis, vtkBloomBuffer& out, bool parallel);

/// out += scale * in, over the same block. Both must have the same shape.
void vtkBloomAddScaled(const vtkBloomBuffer& in, double scale, vtkBloomBuffer& out);

/**
 * Copy components [firstComponent, firstComponent + numberOfComponents) of `image` over the
 * structured extent `extent` into `buffer`, whose indices become extent - wholeLo.
 * `image` must be float or double.
 */
void vtkBloomImport(vtkImageData* image, const int extent[6], const int wholeLo[3],
  int firstComponent, int numberOfComponents, vtkBloomBuffer& buffer);

/**
 * Write `buffer` into components [firstComponent, ...) of `image` over `extent` (structured
 * indices; buffer indices are extent - wholeLo), converting to the image's scalar type.
 */
void vtkBloomExport(const vtkBloomBuffer& buffer, const int wholeLo[3], vtkImageData* image,
  const int extent[6], int firstComponent);

#endif
// VTK-HeaderTest-Exclude: vtkBloomImageOps.h
