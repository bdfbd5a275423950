// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// The steps of vtkBloomPass's chain (see vtkBloomPassChainRunner.h): Run() (the bright pass,
// the pyramid, the blur of each level, the accumulation), the composite and the copy. Each step
// describes its passes (PassSpec) and leaves drawing them to Pass(), in
// vtkBloomPassChainRunner.cxx.
#include "vtkBloomPassChainRunner.h"

#include "vtkBloomChain.h"
#include "vtkBloomParameters.h"
#include "vtkBloomPassFFTBlur.h"
#include "vtkBloomPassResources.h"
#include "vtkBloomVTKCompat.h"
#include "vtkImageBloomThreshold.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkTextureObject.h"

#include <algorithm>

namespace
{
/**
 * Whether a two-dimensional term costs fewer texel fetches as one pass (Wx Wy per output
 * sample) than as an x pass over the input rows and a y pass; one pass fewer and no
 * intermediate target count for a quarter of the separable cost. The 2:1 box (2 x 2 taps) is
 * one pass, the 2:1 tent (4 x 4) two.
 */
bool TwoDimensional(const vtkBloomChain::Term& term)
{
  const double wx = term.X.Width;
  const double wy = term.Y.Width;
  const double outputs = static_cast<double>(term.X.OutputSize) * term.Y.OutputSize;
  const double single = wx * wy * outputs;
  const double separable = wx * term.X.OutputSize * term.Y.InputSize + wy * outputs;
  return single <= 1.25 * separable;
}
}

//------------------------------------------------------------------------------
bool vtkBloomPassChainRunner::Run(const Light& light)
{
  this->In = light;
  this->Deferring = !this->Profiler.IsOn();
  const bool ran = this->RunSteps();
  this->FlushComputeWrites();
  this->Deferring = false;
  return ran;
}

//------------------------------------------------------------------------------
bool vtkBloomPassChainRunner::RunSteps()
{
  vtkBloomParameters* parameters = this->Frame.Parameters;
  const vtkBloomChain& c = this->Resources.Chain;
  this->SanitizeSource = parameters->GetSanitizeNonFinite();
  this->SanitizeOutput = parameters->GetSanitizeNonFinite();
  const size_t n = c.Levels.size();
  if (n == 0 ||
    (parameters->GetSkipDisabledEffects() &&
      parameters->IsBloomDisabled(3, c.Levels.size(), c.Height)))
  {
    return false;
  }
  ChainRegions regions;
  this->CollectCostTimings(); // earlier evaluations' timestamps, never waited for
  regions.Restrict = this->ChooseRestrict();
  // Timed only where the time is used: while RegionPays still decides (content-aware and not
  // declined), or every evaluation while vtkBloomPassTesting::SetTimeChains is on. A chain that
  // runs full for good (the region declined, or not asked for) issues no query.
  if ((this->Frame.Restrict && !this->RegionDeclined) || this->TimeEveryChain)
  {
    this->BeginCostTiming(regions.Restrict);
  }
  this->CompositeRestricted = false;
  this->ComputedSamples = this->FullSamples = 0.0;
  this->Coverage = 1.0;
  std::fill(this->BrightRegion, this->BrightRegion + 4, 0);
  regions.Level.resize(n);
  regions.Blur.resize(n);
  regions.Accum.resize(n);
  regions.Blurred.resize(n);

  if (!this->BrightPass(regions)) // 1. the bright pass
  {
    return false;
  }
  this->DownsampleAndBlurLevels(regions);             // 2. the pyramid, 3. the blur of each level
  if (c.AccumulateMode == vtkBloomParameters::DIRECT) // 4. accumulate
  {
    this->AccumulateDirect(regions);
  }
  else
  {
    this->AccumulateCascade(regions);
  }
  this->CompositeRestricted = regions.Restrict;
  this->EndCoverage(regions.Restrict);
  return true;
}

//------------------------------------------------------------------------------
bool vtkBloomPassChainRunner::ChooseRestrict()
{
  // The region costs a wait for the GPU (its read-back), which a chain of compute passes does
  // not hide. While the region keeps covering much of the chain, measure it only every
  // ProbeInterval frames and run the full chain in between, with no read-back at all: the
  // output is the same either way.
  if (!this->Frame.Restrict)
  {
    return false;
  }
  this->RegionDeclined = this->RegionDeclined || !this->RegionPays();
  if (this->RegionDeclined)
  {
    // The region's read-back costs more than the chain it saves (a fast GPU: docs/gpu.md).
    // Measuring it even one frame in eight makes that frame stutter, so it is not measured
    // again on this context: every frame runs the full chain, with no wait for the GPU.
    return false;
  }
  if (this->FramesUntilProbe > 0)
  {
    --this->FramesUntilProbe;
    return false;
  }
  if (this->CostTimingSupported() && --this->FramesUntilExplore <= 0)
  {
    // Now and then the full chain while the region pays, so that its cost stays known.
    this->FramesUntilExplore = ExploreInterval;
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
const vtkBloomPassChainRunner::Box* vtkBloomPassChainRunner::ChainRegions::Of(const Box& box) const
{
  return this->Restrict ? &box : nullptr;
}

//------------------------------------------------------------------------------
bool vtkBloomPassChainRunner::BrightPass(ChainRegions& regions)
{
  // The source fetch and the threshold in one pass. With SkipEmptyBloom the zero samples are
  // not written (the level is cleared first) and an occlusion query counts the others: a
  // reduction over the whole bright pass that costs no extra pass, and whose readback only
  // waits for this pass.
  vtkBloomPassResources& res = this->Resources;
  const vtkBloomChain& c = res.Chain;
  const int zero[2] = { 0, 0 };
  const bool skipEmpty = this->Frame.Parameters->GetSkipEmptyBloom();
  PassSpec bright;
  bright.Source = this->In.Emission;
  const int full[2] = { c.Width, c.Height };
  bright.SourceSize = full;
  bright.X = c.SourceIsIdentity ? nullptr : &c.Source.X;
  bright.Y = c.SourceIsIdentity ? nullptr : &c.Source.Y;
  bright.Step = STEP_THRESHOLD;
  bright.ReadsSource = true;
  // A multisampled scene, thresholded sample by sample: whole-scene bloom only (selective
  // bloom's emission is masked, weighted by alpha, or not thresholded; this is where that is
  // decided).
  if (this->In.Samples && this->In.Threshold && !this->In.Mask && !this->In.InAlpha &&
    this->Frame.Parameters->GetThresholdMode() != vtkImageBloomThreshold::NONE)
  {
    bright.Samples = this->In.Samples;
    bright.SampleCount = this->In.SampleCount;
  }
  // Restricted, the bright region's reduction also tells whether the bloom is empty. As
  // fragments, the zero samples are not written (the level is cleared first): fewer writes. A
  // compute bright pass that no query counts writes its zeros instead: a clear goes through
  // the graphics units, and on an NVIDIA H100 the cleared level then costs the compute passes
  // about 0.5 ms (docs/gpu.md).
  const bool query = skipEmpty && !this->Frame.Restrict;
  bright.DiscardZero = skipEmpty && (query || !this->Frame.UseCompute || !this->ComputeSupported());
  bright.Name = "bright";
  bright.Level = 0;
  if (bright.DiscardZero)
  {
    this->Clear(res.Levels[0]);
  }
  if (query)
  {
    if (!this->Query)
    {
      glGenQueries(1, &this->Query);
    }
    glBeginQuery(GL_SAMPLES_PASSED, this->Query);
  }
  this->CountingSamples = query;
  this->Pass(&res.Levels[0], zero, bright);
  this->CountingSamples = false;
  if (query)
  {
    glEndQuery(GL_SAMPLES_PASSED);
    GLuint samples = 0;
    glGetQueryObjectuiv(this->Query, GL_QUERY_RESULT, &samples);
    if (samples == 0)
    {
      return false; // nothing is bright: every level, and so the bloom, is zero
    }
  }
  // The box each target can be non-zero in (the whole target when not restricted).
  regions.Level[0] = Box::Whole(c.Levels[0].Size[0], c.Levels[0].Size[1]);
  if (regions.Restrict)
  {
    regions.Level[0] = this->MeasureBrightRegion();
    const Box& b = regions.Level[0];
    if (!b.Empty())
    {
      const int values[4] = { b.X0, b.X1, b.Y0, b.Y1 };
      std::copy(values, values + 4, this->BrightRegion);
    }
    else if (skipEmpty)
    {
      this->Coverage = 0.0; // nothing after the bright pass is computed
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkBloomPassChainRunner::BrightPassPSF(const Light& light, vtkBloomPassTarget& bright)
{
  // BrightPass's threshold with no resample and no region.
  this->In = light;
  vtkBloomParameters* parameters = this->Frame.Parameters;
  this->SanitizeSource = parameters->GetSanitizeNonFinite();
  this->SanitizeOutput = parameters->GetSanitizeNonFinite();
  this->CompositeRestricted = false;
  this->ComputedSamples = this->FullSamples = 0.0;
  this->Coverage = 1.0;
  std::fill(this->BrightRegion, this->BrightRegion + 4, 0);
  // Strength and tint only: PSF mode has no level weights.
  if (parameters->GetSkipDisabledEffects() && parameters->IsBloomDisabled(3, 0))
  {
    return false;
  }
  // No occlusion query for SkipEmptyBloom here: its result makes the CPU wait for the GPU
  // every frame (on an NVIDIA H100 at 3840x2160 that wait and the graphics clear it needs took
  // most of PSF bloom's cost outside its passes, docs/gpu.md), while an empty bright pass
  // convolves to exactly zero: the output is the same either way.
  const int zero[2] = { 0, 0 };
  PassSpec spec;
  spec.Source = light.Emission;
  spec.SourceSize = bright.Size;
  spec.Step = STEP_THRESHOLD;
  spec.ReadsSource = true;
  spec.Name = "bright";
  spec.Level = 0;
  this->Pass(&bright, zero, spec);
  return true;
}

//------------------------------------------------------------------------------
void vtkBloomPassChainRunner::DownsampleAndBlurLevels(ChainRegions& regions)
{
  const size_t n = this->Resources.Chain.Levels.size();
  regions.LastAccumulated = false;
  for (size_t i = 1; i < n; ++i)
  {
    this->DownsampleLevel(regions, i);
    this->BlurLevel(regions, i - 1); // reads level i - 1, as the downsample did: no barrier
  }
  this->BlurLevel(regions, n - 1);
}

//------------------------------------------------------------------------------
void vtkBloomPassChainRunner::DownsampleLevel(ChainRegions& regions, size_t i)
{
  // Level i from the unblurred level above it; each term is one two-dimensional pass, added
  // to the previous terms.
  vtkBloomPassResources& res = this->Resources;
  const vtkBloomChain& c = res.Chain;
  const int zero[2] = { 0, 0 };
  std::vector<Box>& levelBox = regions.Level;
  const vtkBloomChain::Level& level = c.Levels[i];
  vtkBloomPassTarget& dst = level.Karis ? res.Work[i] : res.Levels[i];
  const int* above = res.Levels[i - 1].Size;
  for (const vtkBloomChain::Term& term : level.Down)
  {
    levelBox[i] = levelBox[i].Union(Reach(&term.X, &term.Y, levelBox[i - 1], above[0], above[1]));
  }
  const std::vector<vtkBloomChain::Term>& terms = level.Down;
  if (!level.Karis && terms.size() == 2 &&
    this->FusesTwo(terms[1].X, terms[1].Y, terms[0].X, terms[0].Y))
  {
    // Both terms (the default's 2 x 2 box and 4 x 4 tent) in one tiled pass: the first as the
    // second's TILE2 term, as its own pass would have written it before the second blended.
    PassSpec first;
    first.Source = res.Levels[i - 1].Color;
    first.SourceSize = res.Levels[i - 1].Size;
    first.X = &terms[0].X;
    first.Y = &terms[0].Y;
    first.Weight = terms[0].Weight;
    PassSpec down = first;
    down.X = &terms[1].X;
    down.Y = &terms[1].Y;
    down.Weight = terms[1].Weight;
    down.Tiled = true;
    down.Second = &first;
    down.Name = "down";
    down.Level = static_cast<int>(i);
    down.Region = regions.Of(levelBox[i]);
    this->Pass(&dst, zero, down);
    return;
  }
  for (size_t t = 0; t < level.Down.size(); ++t)
  {
    const vtkBloomChain::Term& term = level.Down[t];
    PassSpec down;
    down.Source = res.Levels[i - 1].Color;
    down.SourceSize = res.Levels[i - 1].Size;
    down.X = &term.X;
    down.Y = &term.Y;
    down.Step = level.Karis ? STEP_KARIS_TERM : STEP_SCALE;
    down.Weight = term.Weight;
    down.Blend = t > 0;
    down.Name = "down";
    down.Level = static_cast<int>(i);
    down.Region = regions.Of(levelBox[i]);
    const int rows[2] = { level.Size[0], res.Levels[i - 1].Size[1] };
    if (!TwoDimensional(term) && this->Fuses(term.X, term.Y))
    {
      down.Tiled = true; // both halves in one dispatch
      down.Name = "down-xy";
    }
    else if (!TwoDimensional(term))
    {
      // The x half into Temp, then the y half and the step.
      PassSpec x;
      x.Source = down.Source;
      x.SourceSize = down.SourceSize;
      x.X = &term.X;
      x.Name = "down-x";
      x.Level = static_cast<int>(i);
      const Box xBox = Reach(&term.X, nullptr, levelBox[i - 1], above[0], above[1]);
      x.Region = regions.Of(xBox);
      this->Pass(&res.Temp, zero, x);
      down.Source = res.Temp.Color;
      down.SourceSize = rows;
      down.X = nullptr;
      down.Name = "down-y";
    }
    this->Pass(&dst, zero, down);
  }
  if (level.Karis)
  {
    PassSpec normalize;
    normalize.Source = res.Work[i].Color;
    normalize.SourceSize = level.Size;
    normalize.Step = STEP_KARIS_NORMALIZE;
    normalize.Name = "karis-normalize";
    normalize.Level = static_cast<int>(i);
    normalize.Region = regions.Of(levelBox[i]);
    this->Pass(&res.Levels[i], zero, normalize);
  }
}

//------------------------------------------------------------------------------
void vtkBloomPassChainRunner::BlurLevel(ChainRegions& regions, size_t i)
{
  // x into Temp, y into Work (CASCADE: the last level goes straight into its accumulation,
  // scaled by its weight).
  vtkBloomPassResources& res = this->Resources;
  const vtkBloomChain& c = res.Chain;
  const size_t last = c.Levels.size() - 1;
  const bool cascade = c.AccumulateMode != vtkBloomParameters::DIRECT;
  const vtkBloomChain::Level& level = c.Levels[i];
  regions.Blurred[i] = &res.Levels[i];
  regions.Blur[i] = regions.Level[i];
  if (!level.Blur)
  {
    return;
  }
  const Box xBox =
    Reach(&level.BlurPass.X, nullptr, regions.Level[i], level.Size[0], level.Size[1]);
  regions.Blur[i] = Reach(nullptr, &level.BlurPass.Y, xBox, level.Size[0], level.Size[1]);
  if (this->BlurInUpsample(i))
  {
    return; // AccumulateCascade blurs it, inside level i's upsample
  }
  vtkBloomPassTarget& blurred = cascade && i == last ? res.Accum[last] : res.Work[i];
  regions.LastAccumulated = cascade && i == last;
  regions.Blurred[i] = regions.LastAccumulated ? &res.Levels[i] : &res.Work[i];
  const double weight = regions.LastAccumulated ? level.Weight : 1.0;
  if (!this->UsesFFT(level.BlurPass.X) && !this->UsesFFT(level.BlurPass.Y) &&
    this->Fuses(level.BlurPass.X, level.BlurPass.Y))
  {
    PassSpec xy;
    xy.Source = res.Levels[i].Color;
    xy.SourceSize = level.Size;
    xy.X = &level.BlurPass.X;
    xy.Y = &level.BlurPass.Y;
    xy.Tiled = true;
    xy.Weight = weight;
    xy.Name = "blur-xy";
    xy.Level = static_cast<int>(i);
    xy.Region = regions.Of(regions.Blur[i]);
    const int zero[2] = { 0, 0 };
    this->Pass(&blurred, zero, xy);
    return;
  }
  PassSpec x;
  x.Source = res.Levels[i].Color;
  x.SourceSize = level.Size;
  x.X = &level.BlurPass.X;
  x.Name = "blur-x";
  x.Level = static_cast<int>(i);
  x.Region = regions.Of(xBox);
  this->BlurPass(res.Temp, x, 0);
  PassSpec y;
  y.Source = res.Temp.Color;
  y.SourceSize = level.Size;
  y.Y = &level.BlurPass.Y;
  y.Name = "blur-y";
  y.Level = static_cast<int>(i);
  y.Region = regions.Of(regions.Blur[i]);
  y.Weight = weight;
  this->BlurPass(blurred, y, 1);
}

//------------------------------------------------------------------------------
bool vtkBloomPassChainRunner::BlurInUpsample(size_t i)
{
  const vtkBloomChain& c = this->Resources.Chain;
  const vtkBloomChain::Level& level = c.Levels[i];
  return c.AccumulateMode != vtkBloomParameters::DIRECT && i + 1 < c.Levels.size() && level.Blur &&
    level.Weight != 0.0 && !this->UsesFFT(level.BlurPass.X) && !this->UsesFFT(level.BlurPass.Y) &&
    !this->UsesFFT(level.Up.X) &&
    this->FusesTwo(level.Up.X, level.Up.Y, level.BlurPass.X, level.BlurPass.Y);
}

//------------------------------------------------------------------------------
bool vtkBloomPassChainRunner::UsesFFT(const vtkBloomLinearOperator& op)
{
  // Compute shaders only, as any compute pass: without them (or when they are made to fail)
  // the direct pass runs, whatever ConvolutionMode asks.
  return this->Frame.UseCompute && !this->Frame.SimulateComputeFailure &&
    this->ComputeSupported() &&
    this->FFTBlur->Choose(
      this->Resources.Context, op, this->Frame.Parameters->GetConvolutionMode());
}

//------------------------------------------------------------------------------
void vtkBloomPassChainRunner::BlurPass(vtkBloomPassTarget& target, const PassSpec& spec, int axis)
{
  const int zero[2] = { 0, 0 };
  if (!this->FFTBlurPass(target, spec, axis))
  {
    this->Pass(&target, zero, spec);
  }
}

//------------------------------------------------------------------------------
bool vtkBloomPassChainRunner::FFTBlurPass(
  vtkBloomPassTarget& target, const PassSpec& spec, int axis)
{
  const vtkBloomLinearOperator& op = axis == 0 ? *spec.X : *spec.Y;
  if (!this->UsesFFT(op))
  {
    return false;
  }
  const int width = spec.SourceSize[0], height = spec.SourceSize[1];
  const int lines = axis == 0 ? height : width;
  const unsigned int format = target.Color->GetInternalFormat(VTK_FLOAT, 4, false);
  // Traffic: the source read and both signals written, then read and the target written.
  const double texel = this->Resources.Format == GL_RGBA32F ? 16.0 : 8.0;
  const double samples = static_cast<double>(width) * height;
  const double bytes = (texel + 16.0) * samples;
  // The profile's names, made only where the frame is profiled.
  const auto label = [&spec](const char* stage)
  {
    const std::string level = spec.Level >= 0 ? " L" + std::to_string(spec.Level) : "";
    return std::string(spec.Name) + stage + level;
  };
  this->FlushComputeWrites(); // the FFT's own passes barrier after themselves
  this->Profiler.Begin();
  if (!this->FFTBlur->Convolve(op, axis, lines, spec.Source, format))
  {
    return false;
  }
  if (this->Profiler.IsOn())
  {
    this->Profiler.End(label("-fft"), width, height, bytes);
    this->Profiler.Begin();
  }
  // The pass replaces the whole level (its region, when restricted, only bounds the zeros).
  this->PrepareTarget(target, nullptr, width, height);
  this->FFTBlur->Finish(op, axis, lines, target.Color->GetHandle(), format, spec.Weight);
  this->EndCompute();
  if (this->Profiler.IsOn())
  {
    this->Profiler.End(label("-fft-finish"), width, height, bytes);
  }
  this->FullSamples += samples;
  this->ComputedSamples += samples;
  this->Passes += 2;
  this->ComputePasses += 2;
  return true;
}

//------------------------------------------------------------------------------
void vtkBloomPassChainRunner::AccumulateDirect(ChainRegions& regions)
{
  // Each weighted level straight to the full size, added into Full.
  vtkBloomPassResources& res = this->Resources;
  const vtkBloomChain& c = res.Chain;
  const int zero[2] = { 0, 0 };
  const size_t n = c.Levels.size();
  Box full;
  for (size_t i = 0; i < n; ++i)
  {
    if (c.Levels[i].Weight != 0.0)
    {
      full = full.Union(
        Reach(&c.Levels[i].Full.X, &c.Levels[i].Full.Y, regions.Blur[i], c.Width, c.Height));
    }
  }
  this->CompositeRegion = full;
  bool first = true;
  for (size_t i = 0; i < n; ++i)
  {
    const vtkBloomChain::Level& level = c.Levels[i];
    if (level.Weight != 0.0)
    {
      PassSpec up;
      up.Source = regions.Blurred[i]->Color;
      up.SourceSize = level.Size;
      up.X = &level.Full.X;
      up.Y = &level.Full.Y;
      up.Weight = level.Weight;
      up.Blend = !first;
      up.Name = "accumulate";
      up.Level = static_cast<int>(i);
      up.Region = regions.Of(this->CompositeRegion);
      this->Pass(&res.Full, zero, up);
      first = false;
    }
  }
  if (first)
  {
    this->Clear(res.Full);
  }
}

//------------------------------------------------------------------------------
void vtkBloomPassChainRunner::AccumulateCascade(ChainRegions& regions)
{
  // From the last level up: A_i = up(A_{i+1}) + w_i blurred_i, x into Temp then y into Accum.
  vtkBloomPassResources& res = this->Resources;
  const vtkBloomChain& c = res.Chain;
  const int zero[2] = { 0, 0 };
  const size_t last = c.Levels.size() - 1;
  std::vector<Box>& accumBox = regions.Accum;
  accumBox[last] = regions.Blur[last];
  if (!regions.LastAccumulated)
  {
    PassSpec scale;
    scale.Source = regions.Blurred[last]->Color;
    scale.SourceSize = c.Levels[last].Size;
    scale.Weight = c.Levels[last].Weight;
    scale.Name = "scale";
    scale.Level = static_cast<int>(last);
    scale.Region = regions.Of(accumBox[last]);
    this->Pass(&res.Accum[last], zero, scale);
  }
  for (size_t i = last; i-- > 0;)
  {
    const vtkBloomChain::Level& level = c.Levels[i];
    PassSpec x;
    x.Source = res.Accum[i + 1].Color;
    x.SourceSize = res.Accum[i + 1].Size;
    x.X = &level.Up.X;
    x.Name = "up-x";
    x.Level = static_cast<int>(i);
    const int* below = res.Accum[i + 1].Size;
    const Box xBox = Reach(&level.Up.X, nullptr, accumBox[i + 1], below[0], below[1]);
    accumBox[i] = Reach(nullptr, &level.Up.Y, xBox, level.Size[0], level.Size[1]);
    if (level.Weight != 0.0)
    {
      accumBox[i] = accumBox[i].Union(regions.Blur[i]);
    }
    PassSpec y;
    const int size[2] = { level.Size[0], res.Accum[i + 1].Size[1] };
    if (!this->UsesFFT(level.Up.X) && this->Fuses(level.Up.X, level.Up.Y))
    {
      y = x; // both halves in one dispatch
      y.Tiled = true;
      y.Name = "up-xy";
    }
    else
    {
      x.Region = regions.Of(xBox);
      this->BlurPass(res.Temp, x, 0);
      y.Source = res.Temp.Color;
      y.SourceSize = size;
      y.Name = "up-y";
    }
    y.Y = &level.Up.Y;
    y.Level = static_cast<int>(i);
    y.Region = regions.Of(accumBox[i]);
    PassSpec blur; // the level's blur, as the pass BlurLevel left out would have written it
    if (level.Weight != 0.0)
    {
      y.Step = STEP_ADD;
      y.Weight = level.Weight;
      y.Addend = regions.Blurred[i]->Color;
    }
    if (this->BlurInUpsample(i))
    {
      blur.Source = res.Levels[i].Color;
      blur.SourceSize = level.Size;
      blur.X = &level.BlurPass.X;
      blur.Y = &level.BlurPass.Y;
      y.Second = &blur;
      y.SecondIsAddend = true;
      y.Addend = nullptr;
    }
    this->Pass(&res.Accum[i], zero, y);
  }
  this->CompositeRegion =
    c.FinalIsIdentity ? accumBox[0] : Reach(&c.Final.X, &c.Final.Y, accumBox[0], c.Width, c.Height);
}

//------------------------------------------------------------------------------
void vtkBloomPassChainRunner::EndCoverage(bool measured)
{
  this->Coverage = this->FullSamples > 0.0 ? this->ComputedSamples / this->FullSamples : 1.0;
  if (measured && (this->Coverage >= DenseCoverage || !this->RegionPays()))
  {
    this->FramesUntilProbe = ProbeInterval - 1;
  }
}

//------------------------------------------------------------------------------
vtkBloomPassChainRunner::PassSpec vtkBloomPassChainRunner::CompositeSpec(bool bloom)
{
  // out = keep * scene + Strength * Tint * bloom, the final resample of CASCADE included.
  vtkBloomPassResources& res = this->Resources;
  const vtkBloomChain& c = res.Chain;
  // PSF mode builds no chain: the size is its bloom term's.
  this->CompositeSize[0] = this->Out.PSFBloom ? this->Out.PSFBloom->Size[0] : c.Width;
  this->CompositeSize[1] = this->Out.PSFBloom ? this->Out.PSFBloom->Size[1] : c.Height;
  PassSpec composite;
  composite.Step = STEP_COMPOSITE;
  composite.Source = res.Scene.Color;
  composite.SourceSize = this->CompositeSize;
  composite.CompositeBloom = bloom;
  composite.Name = "composite";
  composite.Region = bloom && this->CompositeRestricted ? &this->CompositeRegion : nullptr;
  if (bloom && this->Out.PSFBloom)
  {
    composite.Source = this->Out.PSFBloom->Color;
  }
  else if (bloom && c.AccumulateMode == vtkBloomParameters::DIRECT)
  {
    composite.Source = res.Full.Color;
  }
  else if (bloom)
  {
    composite.Source = res.Accum[0].Color;
    if (!c.FinalIsIdentity)
    {
      composite.SourceSize = res.Accum[0].Size;
      composite.X = &c.Final.X;
      composite.Y = &c.Final.Y;
    }
  }
  return composite;
}

//------------------------------------------------------------------------------
void vtkBloomPassChainRunner::Composite(
  const Output& output, vtkBloomPassTarget* target, const int origin[2], bool bloom)
{
  this->Out = output;
  this->Pass(target, origin, this->CompositeSpec(bloom));
  if (!target)
  {
    this->CompositeEdges(output, origin, bloom);
  }
  this->EndCostTiming();
}

//------------------------------------------------------------------------------
void vtkBloomPassChainRunner::CompositeEdges(const Output& output, const int origin[2], bool bloom)
{
  this->Out = output;
  vtkTextureObject* samples = this->CompositeSamples();
  if (!samples)
  {
    return;
  }
  PassSpec edges = this->CompositeSpec(bloom);
  edges.SceneSamples = samples;
  edges.SceneSampleCount = this->Out.SceneSampleCount;
  edges.Name = "composite-samples";
  this->Pass(nullptr, origin, edges);
}

//------------------------------------------------------------------------------
void vtkBloomPassChainRunner::Copy(
  const Output& output, vtkBloomPassTarget* target, const int origin[2], vtkBloomPassTarget& source)
{
  this->Out = output;
  PassSpec copy;
  copy.Source = source.Color;
  copy.SourceSize = source.Size;
  copy.Name = "copy";
  this->Pass(target, origin, copy);
}
