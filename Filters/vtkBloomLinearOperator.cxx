// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkBloomLinearOperator.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace
{
using Row = std::vector<std::pair<int, double>>;

// Add weight w at source index i, folding the index into range first.
void Accumulate(Row& row, int i, double w, int n, int border)
{
  if (w == 0.0)
  {
    return;
  }
  const int folded = vtkBloomLinearOperator::FoldIndex(i, n, border);
  if (folded >= 0)
  {
    row.emplace_back(folded, w);
  }
}

// A bilinear fetch at source texel coordinate q (centres at integers).
void AccumulateBilinear(Row& row, double q, double w, int n, int border)
{
  const double base = std::floor(q);
  const double f = q - base;
  const int i0 = static_cast<int>(base);
  Accumulate(row, i0, w * (1.0 - f), n, border);
  Accumulate(row, i0 + 1, w * f, n, border);
}
}

//------------------------------------------------------------------------------
int vtkBloomLinearOperator::FoldIndex(int i, int n, int border)
{
  if (i >= 0 && i < n)
  {
    return i;
  }
  switch (border)
  {
    case BORDER_ZERO:
      return -1;
    case BORDER_REFLECT:
    {
      // Half-sample symmetric extension is periodic with period 2n.
      const long long period = 2LL * n;
      long long m = static_cast<long long>(i) % period;
      if (m < 0)
      {
        m += period;
      }
      return static_cast<int>(m < n ? m : period - 1 - m);
    }
    case BORDER_CLAMP:
    default:
      return i < 0 ? 0 : n - 1;
  }
}

//------------------------------------------------------------------------------
vtkBloomLinearOperator vtkBloomLinearOperator::FromRows(
  int inputSize, int outputSize, std::vector<Row>& rows)
{
  vtkBloomLinearOperator op;
  op.InputSize = inputSize;
  op.OutputSize = outputSize;
  op.First.assign(outputSize, 0);
  // Merge duplicate indices (folding sends several taps to the edge) and find the band.
  std::vector<std::map<int, double>> merged(outputSize);
  int width = 1;
  for (int j = 0; j < outputSize; ++j)
  {
    for (const auto& entry : rows[j])
    {
      merged[j][entry.first] += entry.second;
    }
    if (!merged[j].empty())
    {
      op.First[j] = merged[j].begin()->first;
      width = std::max(width, merged[j].rbegin()->first - op.First[j] + 1);
    }
    else
    {
      op.First[j] = std::min(j, inputSize - 1);
    }
  }
  op.Width = width;
  op.Weights.assign(static_cast<size_t>(outputSize) * width, 0.0);
  for (int j = 0; j < outputSize; ++j)
  {
    // Keep the band inside the input so that applying never reads out of range.
    op.First[j] = std::min(op.First[j], std::max(0, inputSize - width));
    for (const auto& entry : merged[j])
    {
      op.Weights[static_cast<size_t>(j) * width + (entry.first - op.First[j])] = entry.second;
    }
  }
  return op;
}

//------------------------------------------------------------------------------
vtkBloomLinearOperator vtkBloomLinearOperator::Identity(int n)
{
  vtkBloomLinearOperator op;
  op.InputSize = n;
  op.OutputSize = n;
  op.Width = 1;
  op.First.resize(n);
  for (int j = 0; j < n; ++j)
  {
    op.First[j] = j;
  }
  op.Weights.assign(n, 1.0);
  return op;
}

//------------------------------------------------------------------------------
vtkBloomLinearOperator vtkBloomLinearOperator::Resample(
  int inputSize, int outputSize, const std::vector<vtkBloomKernels::Tap>& taps, int border)
{
  std::vector<Row> rows(outputSize);
  const double scale = static_cast<double>(inputSize) / outputSize;
  for (int j = 0; j < outputSize; ++j)
  {
    const double p = (j + 0.5) * scale - 0.5;
    for (const auto& tap : taps)
    {
      AccumulateBilinear(rows[j], p + tap.Offset, tap.Weight, inputSize, border);
    }
  }
  return FromRows(inputSize, outputSize, rows);
}

//------------------------------------------------------------------------------
vtkBloomLinearOperator vtkBloomLinearOperator::Convolve(
  int size, const std::vector<vtkBloomKernels::Tap>& taps, int border)
{
  if (taps.size() == 1 && taps[0].Offset == 0.0 && taps[0].Weight == 1.0)
  {
    return Identity(size);
  }
  return Resample(size, size, taps, border);
}

//------------------------------------------------------------------------------
vtkBloomLinearOperator vtkBloomLinearOperator::Area(int inputSize, int outputSize)
{
  std::vector<Row> rows(outputSize);
  for (int j = 0; j < outputSize; ++j)
  {
    // Work in units of 1 / outputSize source texels so the bounds are exact integers:
    // output j covers [j * n, (j + 1) * n] in those units, texel i covers [i * m, (i + 1) * m].
    const long long lo = static_cast<long long>(j) * inputSize;
    const long long hi = lo + inputSize;
    const int first = static_cast<int>(lo / outputSize);
    const int last = static_cast<int>((hi - 1) / outputSize);
    for (int i = first; i <= last && i < inputSize; ++i)
    {
      const long long a = std::max(lo, static_cast<long long>(i) * outputSize);
      const long long b = std::min(hi, static_cast<long long>(i + 1) * outputSize);
      if (b > a)
      {
        rows[j].emplace_back(i, static_cast<double>(b - a) / inputSize);
      }
    }
  }
  return FromRows(inputSize, outputSize, rows);
}

//------------------------------------------------------------------------------
vtkBloomLinearOperator vtkBloomLinearOperator::Compose(const vtkBloomLinearOperator& other) const
{
  // (this * other)[j][i] = sum_m this[j][m] * other[m][i], accumulated in a dense row.
  vtkBloomLinearOperator op;
  op.InputSize = other.InputSize;
  op.OutputSize = this->OutputSize;
  op.First.assign(this->OutputSize, 0);
  std::vector<int> last(this->OutputSize, 0);
  int width = 1;
  for (int j = 0; j < this->OutputSize; ++j)
  {
    const int m0 = this->First[j];
    const int m1 = this->First[j] + this->Width - 1;
    op.First[j] = other.First[m0];
    last[j] = other.First[m1] + other.Width - 1;
    for (int m = m0; m <= m1; ++m)
    {
      op.First[j] = std::min(op.First[j], other.First[m]);
      last[j] = std::max(last[j], other.First[m] + other.Width - 1);
    }
    width = std::max(width, last[j] - op.First[j] + 1);
  }
  width = std::min(width, other.InputSize);
  op.Width = width;
  op.Weights.assign(static_cast<size_t>(this->OutputSize) * width, 0.0);
  for (int j = 0; j < this->OutputSize; ++j)
  {
    op.First[j] = std::min(op.First[j], other.InputSize - width);
    double* row = op.Weights.data() + static_cast<size_t>(j) * width;
    for (int k = 0; k < this->Width; ++k)
    {
      const double a = this->Weights[static_cast<size_t>(j) * this->Width + k];
      if (a == 0.0)
      {
        continue;
      }
      const int m = this->First[j] + k;
      const double* b = other.Weights.data() + static_cast<size_t>(m) * other.Width;
      double* target = row + (other.First[m] - op.First[j]);
      for (int l = 0; l < other.Width; ++l)
      {
        target[l] += a * b[l];
      }
    }
  }
  return op;
}

//------------------------------------------------------------------------------
void vtkBloomLinearOperator::GetInputRange(int outMin, int outMax, int& inMin, int& inMax) const
{
  outMin = std::max(outMin, 0);
  outMax = std::min(outMax, this->OutputSize - 1);
  inMin = this->InputSize;
  inMax = -1;
  for (int j = outMin; j <= outMax; ++j)
  {
    inMin = std::min(inMin, this->First[j]);
    inMax = std::max(inMax, this->First[j] + this->Width - 1);
  }
  inMin = std::max(inMin, 0);
  inMax = std::min(inMax, this->InputSize - 1);
}

//------------------------------------------------------------------------------
vtkBloomLinearOperator vtkBloomLinearOperator::Cut(
  int outBegin, int outEnd, int inBegin, int inEnd) const
{
  const int n = inEnd - inBegin;
  std::vector<Row> rows(std::max(outEnd - outBegin, 0));
  for (int j = outBegin; j < outEnd; ++j)
  {
    Row& row = rows[j - outBegin];
    for (int k = 0; k < this->Width; ++k)
    {
      const double w = this->Weights[static_cast<size_t>(j) * this->Width + k];
      if (w != 0.0)
      {
        row.emplace_back(std::min(std::max(this->First[j] + k - inBegin, 0), n - 1), w);
      }
    }
  }
  return FromRows(n, outEnd - outBegin, rows);
}

//------------------------------------------------------------------------------
vtkBloomLinearOperator::InvariantRange vtkBloomLinearOperator::FindInvariantRange(
  int period, int minimum) const
{
  const int n = this->OutputSize;
  const int c = n / 2;
  InvariantRange range;
  if (period < 1 || n < minimum || c + period >= n)
  {
    return range;
  }
  // Row b is row a moved by `stride` input samples.
  auto repeats = [this](int a, int b, int stride)
  {
    if (this->First[b] != this->First[a] + stride)
    {
      return false;
    }
    const size_t w = static_cast<size_t>(this->Width);
    for (size_t k = 0; k < w; ++k)
    {
      if (static_cast<float>(this->Weights[a * w + k]) !=
        static_cast<float>(this->Weights[b * w + k]))
      {
        return false;
      }
    }
    return true;
  };
  const int stride = this->First[c + period] - this->First[c];
  if (stride < 1 || !repeats(c, c + period, stride))
  {
    return range;
  }
  int begin = c, end = c + period + 1;
  while (begin > 0 && repeats(begin - 1, begin - 1 + period, stride))
  {
    --begin;
  }
  while (end < n && repeats(end - period, end, stride))
  {
    ++end;
  }
  if (end - begin < std::max(minimum, 2 * period))
  {
    return range;
  }
  range.Begin = begin;
  range.End = end;
  range.Period = period;
  range.Stride = stride;
  return range;
}

//------------------------------------------------------------------------------
bool vtkBloomLinearOperator::IsIdentity() const
{
  if (this->InputSize != this->OutputSize)
  {
    return false;
  }
  for (int j = 0; j < this->OutputSize; ++j)
  {
    for (int k = 0; k < this->Width; ++k)
    {
      const double w = this->Weights[static_cast<size_t>(j) * this->Width + k];
      const bool diagonal = this->First[j] + k == j;
      if (w != (diagonal ? 1.0 : 0.0))
      {
        return false;
      }
    }
  }
  return true;
}
