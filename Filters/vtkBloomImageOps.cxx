// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkBloomImageOps.h"

#include "vtkBloomKernels.h"
#include "vtkImageData.h"
#include "vtkImagePyramidDown.h"
#include "vtkSMPTools.h"
#include "vtkType.h"

#include <algorithm>
#include <cassert>

namespace
{
// Run f(begin, end) over [0, n), in parallel when asked.
template <typename F>
void ForRange(vtkIdType n, bool parallel, F&& f)
{
  if (parallel && n > 1)
  {
    vtkSMPTools::For(0, n, [&](vtkIdType begin, vtkIdType end) { f(begin, end); });
  }
  else
  {
    f(0, n);
  }
}

// Filtering along x: a gather dot product per output sample, components interleaved.
void ApplyX(
  const vtkBloomBuffer& in, const vtkBloomLinearOperator& op, vtkBloomBuffer& out, bool parallel)
{
  const int nc = in.NumberOfComponents;
  const int width = op.Width;
  const vtkIdType rows = static_cast<vtkIdType>(out.Size[1]) * out.Size[2];
  ForRange(rows, parallel,
    [&](vtkIdType begin, vtkIdType end)
    {
      double acc[16];
      for (vtkIdType r = begin; r < end; ++r)
      {
        const int j = out.Lo[1] + static_cast<int>(r % out.Size[1]);
        const int k = out.Lo[2] + static_cast<int>(r / out.Size[1]);
        const double* src = in.Data.data() + in.Offset(in.Lo[0], j, k);
        double* dst = out.Data.data() + out.Offset(out.Lo[0], j, k);
        for (int x = 0; x < out.Size[0]; ++x)
        {
          const int o = out.Lo[0] + x;
          const double* w = op.Weights.data() + static_cast<size_t>(o) * width;
          const double* s = src + static_cast<size_t>(op.First[o] - in.Lo[0]) * nc;
          std::fill(acc, acc + nc, 0.0);
          for (int t = 0; t < width; ++t)
          {
            for (int c = 0; c < nc; ++c)
            {
              acc[c] += w[t] * s[t * nc + c];
            }
          }
          std::copy(acc, acc + nc, dst + static_cast<size_t>(x) * nc);
        }
      }
    });
}

// Filtering along y or z: whole rows combined with one weight each, which vectorizes.
void ApplyOuter(const vtkBloomBuffer& in, int axis, const vtkBloomLinearOperator& op,
  vtkBloomBuffer& out, bool parallel)
{
  const int width = op.Width;
  const size_t rowLength = static_cast<size_t>(out.Size[0]) * out.NumberOfComponents;
  const int other = axis == 1 ? 2 : 1;
  const vtkIdType rows = static_cast<vtkIdType>(out.Size[axis]) * out.Size[other];
  ForRange(rows, parallel,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType r = begin; r < end; ++r)
      {
        int idx[3] = { out.Lo[0], 0, 0 };
        const int o = out.Lo[axis] + static_cast<int>(r % out.Size[axis]);
        idx[axis] = o;
        idx[other] = out.Lo[other] + static_cast<int>(r / out.Size[axis]);
        double* dst = out.Data.data() + out.Offset(idx[0], idx[1], idx[2]);
        std::fill(dst, dst + rowLength, 0.0);
        const double* w = op.Weights.data() + static_cast<size_t>(o) * width;
        for (int t = 0; t < width; ++t)
        {
          if (w[t] == 0.0)
          {
            continue;
          }
          int src[3] = { in.Lo[0], idx[1], idx[2] };
          src[axis] = op.First[o] + t;
          const double* s = in.Data.data() + in.Offset(src[0], src[1], src[2]);
          const double wt = w[t];
          for (size_t e = 0; e < rowLength; ++e)
          {
            dst[e] += wt * s[e];
          }
        }
      }
    });
}

template <typename T>
void ImportTyped(const T* base, vtkImageData* image, const int extent[6], const int wholeLo[3],
  int first, int count, vtkBloomBuffer& buffer)
{
  const int nc = image->GetNumberOfScalarComponents();
  for (int k = extent[4]; k <= extent[5]; ++k)
  {
    for (int j = extent[2]; j <= extent[3]; ++j)
    {
      int ijk[3] = { extent[0], j, k };
      const T* src = base + image->ComputePointId(ijk) * static_cast<vtkIdType>(nc);
      double* dst =
        buffer.Data.data() + buffer.Offset(extent[0] - wholeLo[0], j - wholeLo[1], k - wholeLo[2]);
      for (int i = extent[0]; i <= extent[1]; ++i, src += nc, dst += count)
      {
        for (int c = 0; c < count; ++c)
        {
          dst[c] = static_cast<double>(src[first + c]);
        }
      }
    }
  }
}

template <typename T>
void ExportTyped(const vtkBloomBuffer& buffer, const int wholeLo[3], T* base, vtkImageData* image,
  const int extent[6], int first)
{
  const int nc = image->GetNumberOfScalarComponents();
  const int count = buffer.NumberOfComponents;
  for (int k = extent[4]; k <= extent[5]; ++k)
  {
    for (int j = extent[2]; j <= extent[3]; ++j)
    {
      int ijk[3] = { extent[0], j, k };
      T* dst = base + image->ComputePointId(ijk) * static_cast<vtkIdType>(nc);
      const double* src =
        buffer.Data.data() + buffer.Offset(extent[0] - wholeLo[0], j - wholeLo[1], k - wholeLo[2]);
      for (int i = extent[0]; i <= extent[1]; ++i, dst += nc, src += count)
      {
        for (int c = 0; c < count; ++c)
        {
          dst[first + c] = static_cast<T>(src[c]);
        }
      }
    }
  }
}
}

//------------------------------------------------------------------------------
void vtkBloomBuffer::Allocate(const int lo[3], const int size[3], int numberOfComponents)
{
  for (int a = 0; a < 3; ++a)
  {
    this->Lo[a] = lo[a];
    this->Size[a] = size[a];
  }
  this->NumberOfComponents = numberOfComponents;
  this->Data.assign(this->GetNumberOfSamples() * numberOfComponents, 0.0);
}

//------------------------------------------------------------------------------
void vtkBloomApplyAxis(const vtkBloomBuffer& in, int axis, const vtkBloomLinearOperator& op,
  int outLo, int outSize, vtkBloomBuffer& out, bool parallel)
{
  int lo[3] = { in.Lo[0], in.Lo[1], in.Lo[2] };
  int size[3] = { in.Size[0], in.Size[1], in.Size[2] };
  lo[axis] = outLo;
  size[axis] = outSize;
  out.Allocate(lo, size, in.NumberOfComponents);
  if (out.GetNumberOfSamples() == 0)
  {
    return;
  }
  if (axis == 0)
  {
    ApplyX(in, op, out, parallel);
  }
  else
  {
    ApplyOuter(in, axis, op, out, parallel);
  }
}

//------------------------------------------------------------------------------
void vtkBloomApplySeparable(const vtkBloomBuffer& in, const vtkBloomLinearOperator* const ops[3],
  const int outLo[3], const int outSize[3], vtkBloomBuffer& out, bool parallel)
{
  // Range of each axis that is still to be filtered: what its operator reads.
  int needLo[3], needSize[3];
  for (int a = 0; a < 3; ++a)
  {
    if (ops[a] && outSize[a] > 0)
    {
      int inMin, inMax;
      ops[a]->GetInputRange(outLo[a], outLo[a] + outSize[a] - 1, inMin, inMax);
      needLo[a] = inMin;
      needSize[a] = inMax - inMin + 1;
    }
    else
    {
      needLo[a] = outLo[a];
      needSize[a] = outSize[a];
    }
  }

  // Crop the input to what is needed, then filter one axis at a time.
  vtkBloomBuffer current;
  current.Allocate(needLo, needSize, in.NumberOfComponents);
  const size_t rowLength = static_cast<size_t>(needSize[0]) * in.NumberOfComponents;
  for (int k = 0; k < needSize[2]; ++k)
  {
    for (int j = 0; j < needSize[1]; ++j)
    {
      const double* src = in.Data.data() + in.Offset(needLo[0], needLo[1] + j, needLo[2] + k);
      std::copy(src, src + rowLength,
        current.Data.data() + current.Offset(needLo[0], needLo[1] + j, needLo[2] + k));
    }
  }
  for (int a = 0; a < 3; ++a)
  {
    if (!ops[a])
    {
      continue;
    }
    vtkBloomBuffer next;
    vtkBloomApplyAxis(current, a, *ops[a], outLo[a], outSize[a], next, parallel);
    current.Data.swap(next.Data);
    std::copy(next.Lo, next.Lo + 3, current.Lo);
    std::copy(next.Size, next.Size + 3, current.Size);
  }
  out = std::move(current);
}

//------------------------------------------------------------------------------
void vtkBloomAddScaled(const vtkBloomBuffer& in, double scale, vtkBloomBuffer& out)
{
  assert(in.Data.size() == out.Data.size());
  const size_t n = out.Data.size();
  for (size_t e = 0; e < n; ++e)
  {
    out.Data[e] += scale * in.Data[e];
  }
}

//------------------------------------------------------------------------------
void vtkBloomImport(vtkImageData* image, const int extent[6], const int wholeLo[3],
  int firstComponent, int numberOfComponents, vtkBloomBuffer& buffer)
{
  const int lo[3] = { extent[0] - wholeLo[0], extent[2] - wholeLo[1], extent[4] - wholeLo[2] };
  const int size[3] = { extent[1] - extent[0] + 1, extent[3] - extent[2] + 1,
    extent[5] - extent[4] + 1 };
  buffer.Allocate(lo, size, numberOfComponents);
  void* base = image->GetScalarPointer();
  switch (image->GetScalarType())
  {
    case VTK_FLOAT:
      ImportTyped(static_cast<const float*>(base), image, extent, wholeLo, firstComponent,
        numberOfComponents, buffer);
      break;
    case VTK_DOUBLE:
      ImportTyped(static_cast<const double*>(base), image, extent, wholeLo, firstComponent,
        numberOfComponents, buffer);
      break;
    default:
      break;
  }
}

//------------------------------------------------------------------------------
void vtkBloomExport(const vtkBloomBuffer& buffer, const int wholeLo[3], vtkImageData* image,
  const int extent[6], int firstComponent)
{
  void* base = image->GetScalarPointer();
  switch (image->GetScalarType())
  {
    case VTK_FLOAT:
      ExportTyped(buffer, wholeLo, static_cast<float*>(base), image, extent, firstComponent);
      break;
    case VTK_DOUBLE:
      ExportTyped(buffer, wholeLo, static_cast<double*>(base), image, extent, firstComponent);
      break;
    default:
      break;
  }
}

//------------------------------------------------------------------------------
std::vector<vtkBloomSeparableTerm> vtkBloomDownsampleTerms(
  int kernel, bool karis, const int inSize[2], const int outSize[2])
{
  using Taps = std::vector<vtkBloomKernels::Tap>;
  const int clamp = vtkBloomLinearOperator::BORDER_CLAMP;
  std::vector<vtkBloomSeparableTerm> terms;
  auto add = [&](double weight, const Taps& tx, const Taps& ty)
  {
    vtkBloomSeparableTerm term;
    term.Weight = weight;
    term.X = vtkBloomLinearOperator::Resample(inSize[0], outSize[0], tx, clamp);
    term.Y = vtkBloomLinearOperator::Resample(inSize[1], outSize[1], ty, clamp);
    terms.push_back(std::move(term));
  };
  switch (kernel)
  {
    case vtkImagePyramidDown::BOX:
    {
      vtkBloomSeparableTerm term;
      term.X = vtkBloomLinearOperator::Area(inSize[0], outSize[0]);
      term.Y = vtkBloomLinearOperator::Area(inSize[1], outSize[1]);
      terms.push_back(std::move(term));
      break;
    }
    case vtkImagePyramidDown::BINOMIAL:
      add(1.0, vtkBloomKernels::Binomial5Taps(), vtkBloomKernels::Binomial5Taps());
      break;
    case vtkImagePyramidDown::JIMENEZ13:
    default:
      if (karis)
      {
        const Taps inner = vtkBloomKernels::HalfTexelPairTaps();
        const Taps left = vtkBloomKernels::LeftPairTaps();
        const Taps right = vtkBloomKernels::RightPairTaps();
        add(vtkBloomKernels::Jimenez13InnerWeight, inner, inner);
        add(vtkBloomKernels::Jimenez13OuterWeight, left, left);
        add(vtkBloomKernels::Jimenez13OuterWeight, right, left);
        add(vtkBloomKernels::Jimenez13OuterWeight, left, right);
        add(vtkBloomKernels::Jimenez13OuterWeight, right, right);
      }
      else
      {
        // 1/2 inner box + 4 x 1/8 outer boxes == 1/2 inner box + 1/2 tent (x) tent.
        add(0.5, vtkBloomKernels::HalfTexelPairTaps(), vtkBloomKernels::HalfTexelPairTaps());
        add(0.5, vtkBloomKernels::TentTaps(), vtkBloomKernels::TentTaps());
      }
      break;
  }
  return terms;
}

//------------------------------------------------------------------------------
void vtkBloomCombineTerms(const std::vector<vtkBloomBuffer>& results,
  const std::vector<double>& weights, bool karis, vtkBloomBuffer& out, bool parallel)
{
  out = results[0];
  if (results.size() == 1 && weights[0] == 1.0 && !karis)
  {
    return; // exactly the one result, signed zeros and NaN payloads included
  }
  const int nc = out.NumberOfComponents;
  const size_t terms = results.size();
  ForRange(static_cast<vtkIdType>(out.GetNumberOfSamples()), parallel,
    [&](vtkIdType begin, vtkIdType end)
    {
      double acc[16];
      for (vtkIdType s = begin; s < end; ++s)
      {
        double total = 0.0;
        for (size_t t = 0; t < terms; ++t)
        {
          const double* v = results[t].Data.data() + s * nc;
          double w = weights[t];
          if (karis)
          {
            const double luma = nc >= 3 ? vtkBloomKernels::LuminanceR * v[0] +
                vtkBloomKernels::LuminanceG * v[1] + vtkBloomKernels::LuminanceB * v[2]
                                        : v[0];
            w /= 1.0 + std::max(luma, 0.0);
          }
          total += w;
          for (int c = 0; c < nc; ++c)
          {
            acc[c] = t == 0 ? w * v[c] : acc[c] + w * v[c];
          }
        }
        const double norm = karis ? 1.0 / total : 1.0;
        for (int c = 0; c < nc; ++c)
        {
          out.Data[s * nc + c] = acc[c] * norm;
        }
      }
    });
}
