// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// vtkImageBloom's REFERENCE chain: the steps RequestData runs in double precision when the
// fused float32 chain does not (ExecutionMode REFERENCE, double input, Karis average, volumes):
// the bright pass, the pyramid down, the blur of each level, the upsample-and-accumulate, and
// the composite. The pipeline, parameters and statistics are in vtkImageBloom.cxx.
#include "vtkImageBloom.h"

#include "vtkBloomBrightPass.h"
#include "vtkBloomChain.h"
#include "vtkBloomImageOps.h"
#include "vtkImageData.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace
{

// The largest finite value of a float or double scalar type.
double FiniteMaximum(int scalarType)
{
  return scalarType == VTK_DOUBLE ? std::numeric_limits<double>::max()
                                  : static_cast<double>(std::numeric_limits<float>::max());
}

// SanitizeNonFinite on: NaN becomes 0 and +-Inf the finite extreme of its sign, so the chain only
// ever sees finite samples.
void ReplaceNonFinite(std::vector<double>& data, double maximum)
{
  vtkSMPTools::For(0, static_cast<vtkIdType>(data.size()),
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        const double v = data[i];
        if (std::isnan(v))
        {
          data[i] = 0.0;
        }
        else if (std::isinf(v))
        {
          data[i] = v > 0.0 ? maximum : -maximum;
        }
      }
    });
}

// out = Ry Rx in over the whole of a 2-D (per z slice) block of the given output size.
void Resample2D(const vtkBloomBuffer& in, const vtkBloomLinearOperator& rx,
  const vtkBloomLinearOperator& ry, vtkBloomBuffer& out)
{
  const vtkBloomLinearOperator* ops[3] = { &rx, &ry, nullptr };
  const int lo[3] = { 0, 0, 0 };
  const int size[3] = { rx.OutputSize, ry.OutputSize, in.Size[2] };
  vtkBloomApplySeparable(in, ops, lo, size, out, true);
}

// One level of the downsample chain: the chain's terms, combined (Karis-weighted or not).
void Downsample(const vtkBloomBuffer& in, const vtkBloomChain::Level& level, vtkBloomBuffer& out)
{
  std::vector<vtkBloomBuffer> results(level.Down.size());
  std::vector<double> weights;
  for (size_t t = 0; t < level.Down.size(); ++t)
  {
    Resample2D(in, level.Down[t].X, level.Down[t].Y, results[t]);
    weights.push_back(level.Down[t].Weight);
  }
  if (results.size() == 1 && weights[0] == 1.0)
  {
    out = std::move(results[0]);
    return;
  }
  vtkBloomCombineTerms(results, weights, level.Karis, out, true);
}
}

//------------------------------------------------------------------------------
void vtkImageBloom::ImportColours(vtkImageData* input, vtkBloomBuffer& colours)
{
  int inExt[6];
  input->GetExtent(inExt);
  const int wholeLo[3] = { inExt[0], inExt[2], inExt[4] };
  vtkBloomImport(
    input, inExt, wholeLo, 0, input->GetNumberOfScalarComponents() >= 3 ? 3 : 1, colours);
  if (this->Parameters->GetSanitizeNonFinite())
  {
    ReplaceNonFinite(colours.Data, FiniteMaximum(input->GetScalarType()));
  }
}

//------------------------------------------------------------------------------
void vtkImageBloom::BrightPassInPlace(vtkBloomBuffer& bright)
{
  const int colours = bright.NumberOfComponents;
  const int mode = this->Parameters->GetThresholdMode();
  const double t = this->Parameters->GetThreshold(), knee = this->Parameters->GetKnee(),
               clampLum = this->Parameters->GetClampLuminance();
  // The chain maps non-finite colours in every mode, NONE included, so that nothing
  // non-finite ever enters the pyramid (a no-op on finite samples).
  const double ceiling = std::min(clampLum, static_cast<double>(VTK_FLOAT_MAX));
  vtkSMPTools::For(0, static_cast<vtkIdType>(bright.GetNumberOfSamples()),
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType s = begin; s < end; ++s)
      {
        double* colour = bright.Data.data() + s * colours;
        if (colours == 3)
        {
          vtkBloomMapNonFinite<3>(colour, ceiling);
          vtkBloomBrightPass<3>(colour, mode, t, knee, clampLum);
        }
        else
        {
          vtkBloomMapNonFinite<1>(colour, ceiling);
          vtkBloomBrightPass<1>(colour, mode, t, knee, clampLum);
        }
      }
    });
}

//------------------------------------------------------------------------------
bool vtkImageBloom::ThresholdStep(
  vtkImageData* input, std::vector<vtkBloomBuffer>& levels, int& levelsUsed)
{
  // Bilinear fetch to the start level first, threshold second.
  int inExt[6];
  input->GetExtent(inExt);
  const int width = inExt[1] - inExt[0] + 1;
  const int height = inExt[3] - inExt[2] + 1;
  const int colours = input->GetNumberOfScalarComponents() >= 3 ? 3 : 1;
  const vtkBloomChain& chain = *this->Chain;
  vtkBloomBuffer source;
  this->ImportColours(input, source);
  this->UpdateProgress(0.05);
  const auto sizes = this->ComputeLevelSizes(width, height);
  if (sizes.empty() ||
    (this->Parameters->GetSkipDisabledEffects() &&
      this->Parameters->IsBloomDisabled(colours, sizes.size(), height)))
  {
    // No level fits (LimitLevelsToImageSize with a start level beyond the mip chain), or the
    // bloom term is zero: there is nothing to bloom, and the composite sees a black bloom.
    this->LastBloomSkipped = !sizes.empty();
    levelsUsed = 0;
    return false;
  }
  levelsUsed = static_cast<int>(sizes.size());
  levels.resize(chain.Levels.size());
  if (chain.SourceIsIdentity)
  {
    levels[0] = std::move(source);
  }
  else
  {
    Resample2D(source, chain.Source.X, chain.Source.Y, levels[0]);
  }
  vtkBloomBuffer& bright = levels[0];
  this->BrightPassInPlace(bright);
  if (this->Parameters->GetSkipEmptyBloom() &&
    std::all_of(bright.Data.begin(), bright.Data.end(), [](double v) { return v == 0.0; }))
  {
    // Nothing is bright: every level, and so the bloom, is zero.
    this->LastBloomSkipped = true;
    levels.clear();
    return false;
  }
  this->UpdateProgress(0.15);
  return true;
}

//------------------------------------------------------------------------------
void vtkImageBloom::DownsampleStep(std::vector<vtkBloomBuffer>& levels)
{
  // Each level from the unblurred level above it.
  const vtkBloomChain& chain = *this->Chain;
  for (size_t i = 1; i < levels.size() && !this->AbortExecute; ++i)
  {
    Downsample(levels[i - 1], chain.Levels[i], levels[i]);
  }
  this->UpdateProgress(0.35);
}

//------------------------------------------------------------------------------
void vtkImageBloom::BlurStep(std::vector<vtkBloomBuffer>& levels)
{
  // Each level that contributes; repeated passes are folded into one operator.
  const vtkBloomChain& chain = *this->Chain;
  const size_t n = levels.size();
  for (size_t i = 0; i < n && !this->AbortExecute; ++i)
  {
    const vtkBloomChain::Level& level = chain.Levels[i];
    if (level.Blur)
    {
      vtkBloomBuffer blurred;
      Resample2D(levels[i], level.BlurPass.X, level.BlurPass.Y, blurred);
      levels[i] = std::move(blurred);
    }
    this->UpdateProgress(0.35 + 0.35 * (i + 1) / n);
  }
}

//------------------------------------------------------------------------------
void vtkImageBloom::UpsampleStep(
  std::vector<vtkBloomBuffer>& levels, int width, int height, vtkBloomBuffer& bloom)
{
  // Accumulate the levels into a full-resolution bloom image: each straight to full size
  // (DIRECT), or up the cascade level by level (CASCADE).
  const vtkBloomChain& chain = *this->Chain;
  const size_t n = levels.size();
  if (chain.AccumulateMode == DIRECT)
  {
    int lo[3] = { 0, 0, 0 };
    int size[3] = { width, height, levels[0].Size[2] };
    bloom.Allocate(lo, size, levels[0].NumberOfComponents);
    for (size_t i = 0; i < n; ++i)
    {
      const vtkBloomChain::Level& level = chain.Levels[i];
      if (level.Weight != 0.0)
      {
        vtkBloomBuffer full;
        Resample2D(levels[i], level.Full.X, level.Full.Y, full);
        vtkBloomAddScaled(full, level.Weight, bloom);
      }
    }
  }
  else
  {
    const size_t last = n - 1;
    vtkBloomBuffer acc = std::move(levels[last]);
    if (chain.Levels[last].Weight != 1.0)
    {
      for (double& v : acc.Data)
      {
        v *= chain.Levels[last].Weight;
      }
    }
    for (size_t i = last; i-- > 0;)
    {
      const vtkBloomChain::Level& level = chain.Levels[i];
      vtkBloomBuffer upsampled;
      Resample2D(acc, level.Up.X, level.Up.Y, upsampled);
      if (level.Weight != 0.0)
      {
        vtkBloomAddScaled(levels[i], level.Weight, upsampled);
      }
      acc = std::move(upsampled);
    }
    if (chain.FinalIsIdentity)
    {
      bloom = std::move(acc);
    }
    else
    {
      Resample2D(acc, chain.Final.X, chain.Final.Y, bloom);
    }
  }
  levels.clear();
  this->UpdateProgress(0.9);
}

//------------------------------------------------------------------------------
void vtkImageBloom::Composite(
  vtkImageData* input, const vtkBloomBuffer* bloom, vtkImageData* output)
{
  // out = keep * in + S * tint * bloom over the output extent; alpha is copied.
  int inExt[6], outExt[6];
  input->GetExtent(inExt);
  output->GetExtent(outExt);
  const int nc = input->GetNumberOfScalarComponents();
  const int colours = nc >= 3 ? 3 : 1;
  const double s = this->Parameters->GetStrength();
  const double keep = this->Parameters->GetCompositeMode() == LERP ? 1.0 - s : 1.0;
  double tint[3] = { this->Parameters->GetTint()[0], this->Parameters->GetTint()[1],
    this->Parameters->GetTint()[2] };
  if (colours == 1)
  {
    tint[0] = vtkBloomKernels::LuminanceR * tint[0] + vtkBloomKernels::LuminanceG * tint[1] +
      vtkBloomKernels::LuminanceB * tint[2];
  }
  const int wholeLo[3] = { inExt[0], inExt[2], inExt[4] };
  vtkBloomBuffer piece;
  vtkBloomImport(input, outExt, wholeLo, 0, nc, piece);
  const double maximum = FiniteMaximum(output->GetScalarType());
  if (this->Parameters->GetSanitizeNonFinite())
  {
    ReplaceNonFinite(piece.Data, FiniteMaximum(input->GetScalarType()));
  }
  const size_t samples = piece.GetNumberOfSamples();
  const size_t slice = static_cast<size_t>(piece.Size[0]) * piece.Size[1];
  for (size_t p = 0; p < samples; ++p)
  {
    // piece and bloom index the same pixel through their own blocks.
    const int i = piece.Lo[0] + static_cast<int>(p % piece.Size[0]);
    const int j = piece.Lo[1] + static_cast<int>((p / piece.Size[0]) % piece.Size[1]);
    const int k = piece.Lo[2] + static_cast<int>(p / slice);
    const double* b = bloom ? bloom->Data.data() + bloom->Offset(i, j, k) : nullptr;
    double* v = piece.Data.data() + p * nc;
    for (int c = 0; c < colours; ++c)
    {
      // "+ 0.0" makes a zero bloom term +0 whatever the sign of the zero, so skipping a zero
      // bloom gives the same bits as computing it.
      v[c] = keep * v[c] + (s * tint[c] * (b ? b[c] : 0.0) + 0.0);
      if (this->Parameters->GetSanitizeNonFinite())
      {
        // Clamp to the output type's finite range; NaN (only an overflow makes one) becomes 0.
        v[c] = std::isnan(v[c]) ? 0.0 : std::min(std::max(v[c], -maximum), maximum);
      }
    }
  }
  vtkBloomExport(piece, wholeLo, output, outExt, 0);
}
