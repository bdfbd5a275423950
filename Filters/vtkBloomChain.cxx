// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkBloomChain.h"

#include "vtkBloomImageOps.h"
#include "vtkBloomParameters.h"
#include "vtkImagePyramidDown.h"
#include "vtkImagePyramidUp.h"

#include <algorithm>
#include <array>
#include <limits>

namespace
{
const int Clamp = vtkBloomLinearOperator::BORDER_CLAMP;

vtkBloomChain::Term Resample(const int in[2], const int out[2],
  const std::vector<vtkBloomKernels::Tap>& taps, double weight = 1.0)
{
  vtkBloomChain::Term term;
  term.Weight = weight;
  term.X = vtkBloomLinearOperator::Resample(in[0], out[0], taps, Clamp);
  term.Y = vtkBloomLinearOperator::Resample(in[1], out[1], taps, Clamp);
  return term;
}

// `passes` applications of one clamped convolution, folded into one operator.
vtkBloomLinearOperator RepeatedConvolution(
  int n, const std::vector<vtkBloomKernels::Tap>& taps, int passes)
{
  const vtkBloomLinearOperator once = vtkBloomLinearOperator::Convolve(n, taps, Clamp);
  vtkBloomLinearOperator result = once;
  for (int it = 1; it < passes; ++it)
  {
    result = once.Compose(result);
  }
  return result;
}
}

//------------------------------------------------------------------------------
void vtkBloomChain::Build(vtkBloomParameters* p, int width, int height)
{
  *this = vtkBloomChain();
  this->Width = width;
  this->Height = height;
  this->AccumulateMode = p->GetAccumulateMode();

  const int full[2] = { width, height };
  const auto sizes = p->ComputeLevelSizes(width, height);
  const auto bilinear = vtkBloomKernels::BilinearTaps();
  const auto up = p->GetUpsampleKernel() == vtkImagePyramidUp::BILINEAR
    ? vtkBloomKernels::BilinearTaps()
    : vtkBloomKernels::TentTaps();
  const auto blurTaps = vtkBloomKernels::SymmetricTaps(
    p->GetEffectiveBlurHalfKernel(height), p->GetEffectiveBlurTapSpacing(height));
  const int iterations = p->GetBlurIterations();

  this->Levels.resize(sizes.size());
  for (size_t i = 0; i < sizes.size(); ++i)
  {
    Level& level = this->Levels[i];
    level.Size[0] = sizes[i].first;
    level.Size[1] = sizes[i].second;
    level.Weight = p->GetEffectiveLevelWeight(static_cast<int>(i), height);
    if (i > 0)
    {
      const int* previous = this->Levels[i - 1].Size;
      level.Karis = p->GetKarisAverage() && i == 1 &&
        p->GetDownsampleKernel() == vtkImagePyramidDown::JIMENEZ13;
      for (auto& t :
        vtkBloomDownsampleTerms(p->GetDownsampleKernel(), level.Karis, previous, level.Size))
      {
        level.Down.push_back(Term{ t.Weight, std::move(t.X), std::move(t.Y) });
      }
    }
    level.Blur = level.Weight != 0.0 && iterations > 0;
    if (level.Blur)
    {
      level.BlurPass.X = RepeatedConvolution(level.Size[0], blurTaps, iterations);
      level.BlurPass.Y = RepeatedConvolution(level.Size[1], blurTaps, iterations);
    }
    if (this->AccumulateMode == vtkBloomParameters::DIRECT && level.Weight != 0.0)
    {
      level.Full = Resample(level.Size, full, bilinear);
    }
  }
  if (this->AccumulateMode != vtkBloomParameters::DIRECT)
  {
    for (size_t i = 0; i + 1 < this->Levels.size(); ++i)
    {
      this->Levels[i].Up = Resample(this->Levels[i + 1].Size, this->Levels[i].Size, up);
    }
  }
  if (!this->Levels.empty())
  {
    this->SourceIsIdentity = p->GetEffectiveStartLevel(height) == 0;
    if (!this->SourceIsIdentity)
    {
      this->Source = Resample(full, this->Levels[0].Size, bilinear);
    }
    this->FinalIsIdentity =
      this->AccumulateMode == vtkBloomParameters::DIRECT || p->GetEffectiveStartLevel(height) == 0;
    if (!this->FinalIsIdentity)
    {
      this->Final = Resample(this->Levels[0].Size, full, bilinear);
    }
  }
}

namespace
{
// [lo, hi] widened to the samples that `op` (an axis of a step) reads for it.
void Widen(const vtkBloomLinearOperator& op, int& lo, int& hi)
{
  op.GetInputRange(lo, hi, lo, hi);
}
}

//------------------------------------------------------------------------------
void vtkBloomChain::GetInputRange(int axis, int outMin, int outMax, int& inMin, int& inMax) const
{
  inMin = outMin;
  inMax = outMax;
  if (this->Levels.empty())
  {
    return;
  }
  auto along = [axis](const Term& t) -> const vtkBloomLinearOperator& { return axis ? t.Y : t.X; };
  // Each level's samples that the output reads (at the level's resolution)...
  std::vector<std::pair<int, int>> read(this->Levels.size(), { 0, -1 });
  int a = outMin, b = outMax;
  if (!this->FinalIsIdentity)
  {
    Widen(along(this->Final), a, b);
  }
  for (size_t i = 0; i < this->Levels.size(); ++i)
  {
    if (this->AccumulateMode == vtkBloomParameters::DIRECT)
    {
      if (this->Levels[i].Weight != 0.0)
      {
        read[i] = { outMin, outMax };
        Widen(along(this->Levels[i].Full), read[i].first, read[i].second);
      }
      continue;
    }
    read[i] = { a, b };
    if (i + 1 < this->Levels.size())
    {
      Widen(along(this->Levels[i].Up), a, b);
    }
  }
  // ... then back through its blur and the pyramid to the image.
  for (size_t i = 0; i < this->Levels.size(); ++i)
  {
    a = read[i].first;
    b = read[i].second;
    if (b < a)
    {
      continue;
    }
    if (this->Levels[i].Blur)
    {
      Widen(along(this->Levels[i].BlurPass), a, b);
    }
    for (size_t k = i; k > 0; --k)
    {
      // Level k is the sum of its Down terms over level k - 1.
      int a2 = std::numeric_limits<int>::max(), b2 = std::numeric_limits<int>::min();
      for (const Term& t : this->Levels[k].Down)
      {
        int ta = a, tb = b;
        Widen(along(t), ta, tb);
        a2 = std::min(a2, ta);
        b2 = std::max(b2, tb);
      }
      a = a2 <= b2 ? a2 : a;
      b = a2 <= b2 ? b2 : b;
    }
    if (!this->SourceIsIdentity)
    {
      Widen(along(this->Source), a, b);
    }
    inMin = std::min(inMin, a);
    inMax = std::max(inMax, b);
  }
}

//------------------------------------------------------------------------------
void vtkBloomChain::Cut(const vtkBloomChain& frame, const int begin[2], const int end[2])
{
  *this = frame;
  this->Width = end[0] - begin[0];
  this->Height = end[1] - begin[1];
  const int full[2] = { frame.Width, frame.Height };
  // The samples of level i kept along each axis: those under the part, two more each side;
  // where level 0 is the image itself (the bright pass at full resolution), the part.
  const std::array<int, 4> image = { begin[0], end[0], begin[1], end[1] };
  std::vector<std::array<int, 4>> kept(frame.Levels.size());
  for (size_t i = 0; i < frame.Levels.size(); ++i)
  {
    if (i == 0 && frame.SourceIsIdentity)
    {
      kept[0] = image;
      this->Levels[0].Size[0] = this->Width;
      this->Levels[0].Size[1] = this->Height;
      continue;
    }
    for (int a = 0; a < 2; ++a)
    {
      const long long n = frame.Levels[i].Size[a];
      const int lo = static_cast<int>(begin[a] * n / full[a]) - 2;
      const int hi = static_cast<int>((end[a] * n + full[a] - 1) / full[a]) + 2;
      kept[i][2 * a] = std::max(lo, 0);
      kept[i][2 * a + 1] = std::min(hi, static_cast<int>(n));
      this->Levels[i].Size[a] = kept[i][2 * a + 1] - kept[i][2 * a];
    }
  }
  // One term, its rows `out` over its inputs `in`.
  auto cut = [](const Term& t, const std::array<int, 4>& out, const std::array<int, 4>& in)
  {
    return Term{ t.Weight, t.X.Cut(out[0], out[1], in[0], in[1]),
      t.Y.Cut(out[2], out[3], in[2], in[3]) };
  };
  for (size_t i = 0; i < frame.Levels.size(); ++i)
  {
    const Level& from = frame.Levels[i];
    Level& to = this->Levels[i];
    for (size_t t = 0; t < from.Down.size(); ++t)
    {
      to.Down[t] = cut(from.Down[t], kept[i], kept[i - 1]);
    }
    if (from.Blur)
    {
      to.BlurPass = cut(from.BlurPass, kept[i], kept[i]);
    }
    if (i + 1 < frame.Levels.size() && this->AccumulateMode != vtkBloomParameters::DIRECT)
    {
      to.Up = cut(from.Up, kept[i], kept[i + 1]);
    }
    if (this->AccumulateMode == vtkBloomParameters::DIRECT && from.Weight != 0.0)
    {
      to.Full = cut(from.Full, image, kept[i]);
    }
  }
  if (!frame.Levels.empty() && !frame.SourceIsIdentity)
  {
    this->Source = cut(frame.Source, kept[0], image);
  }
  if (!frame.Levels.empty() && !frame.FinalIsIdentity)
  {
    this->Final = cut(frame.Final, image, kept[0]);
  }
}
