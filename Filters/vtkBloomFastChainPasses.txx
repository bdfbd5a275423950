// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// The passes of the fast chain, included by vtkBloomFastChain.cxx once per instruction set,
// each time inside a namespace of its own (so this file has no include guard). It uses the
// helpers that file defines first (Op, Box, Plane, ...) and vtkBloomFastChain::Internals.
// VTKBLOOM_VECTOR_BYTES, defined by the includer, is the width of the vector registers of the
// instruction set (16 or 32) for the loops written with GCC vector types.
//
// The passes come in three families, one file each: the separable sums (blurs, downsamples,
// upsamples), the bright pass and the composite. This file holds the vector types they share
// and Run(), which drives them in chain order.

constexpr int VectorBytes = VTKBLOOM_VECTOR_BYTES;
constexpr int VectorFloats = VectorBytes / 4;
typedef float FloatV __attribute__((vector_size(VectorBytes)));
typedef int32_t IntV __attribute__((vector_size(VectorBytes)));
typedef float FloatU __attribute__((vector_size(VectorBytes), aligned(4), may_alias));

#include "vtkBloomFastChainSeparable.txx"

#include "vtkBloomFastChainBrightPass.txx"

#include "vtkBloomFastChainComposite.txx"

// Calls f(std::integral_constant<int, NC>()) for the image's component count NC: one or two
// components hold one colour (C = 1), three or four hold RGB (C = 3).
template <int C, typename F>
void WithComponents(int nc, F&& f)
{
  if constexpr (C == 3)
  {
    nc == 3 ? f(std::integral_constant<int, 3>()) : f(std::integral_constant<int, 4>());
  }
  else
  {
    nc == 1 ? f(std::integral_constant<int, 1>()) : f(std::integral_constant<int, 2>());
  }
}

//------------------------------------------------------------------------------
// The number of levels to build: all of them, less the trailing levels of weight 0 when
// TrimPyramid is on (nothing coarser reads them, and they add nothing to the bloom).
inline int LevelsToBuild(const vtkBloomFastChainParameters& p)
{
  int levels = static_cast<int>(p.LevelSizes.size());
  if (p.TrimPyramid)
  {
    while (levels > 0 && p.LevelWeights[levels - 1] == 0.0)
    {
      --levels;
    }
  }
  return levels;
}

//------------------------------------------------------------------------------
// The levels of one run and the box each is written over (level 0: its rows that are not
// dark), which the steps of Run share.
struct Pyramid
{
  std::vector<Plane>& Levels;
  std::vector<Box> Boxes;
  BrightResult Bright;

  explicit Pyramid(std::vector<Plane>& levels)
    : Levels(levels)
  {
  }

  Box Full(int i) const { return Box{ 0, this->Levels[i].W, 0, this->Levels[i].H }; }

  // Makes `read` of level i defined: a pass that reads a level zeroes what it reads outside
  // the level's box first, instead of every level being cleared.
  void Define(int i, const Box& read)
  {
    if (i == 0)
    {
      ZeroDarkRows(this->Bright.Dark, read, this->Levels[0]);
    }
    else
    {
      this->Levels[i].ZeroAround(read, this->Boxes[i]);
    }
  }
};

//------------------------------------------------------------------------------
// 1. The bright pass into level 0 (already sized), through the chain's source resample.
template <typename T, int C>
BrightResult BrightPassToLevel0(
  const vtkBloomFastChainParameters& p, const T* in, int width, int height, int nc, Plane& level0)
{
  const vtkBloomChain& chain = *p.Chain;
  const Op rx =
    MakeOp(chain.SourceIsIdentity ? vtkBloomLinearOperator::Identity(width) : chain.Source.X);
  const Op ry =
    MakeOp(chain.SourceIsIdentity ? vtkBloomLinearOperator::Identity(height) : chain.Source.Y);
  BrightResult bright;
  WithComponents<C>(nc,
    [&](auto components) {
      bright = BrightPass<T, decltype(components)::value, C>(p, in, width, height, rx, ry, level0);
    });
  return bright;
}

//------------------------------------------------------------------------------
// 2. The pyramid, each level over the region its terms reach.
template <int L>
void Downsample(const vtkBloomFastChainParameters& p, int levelsBuilt, Pyramid& pyramid,
  vtkBloomFastChainReport& report)
{
  const vtkBloomChain& chain = *p.Chain;
  std::vector<Plane>& levels = pyramid.Levels;
  std::vector<Box>& boxes = pyramid.Boxes;
  for (int i = 1; i < levelsBuilt; ++i)
  {
    const int outSize[2] = { p.LevelSizes[i].first, p.LevelSizes[i].second };
    levels[i].Resize(outSize[0], outSize[1], L);
    const auto& terms = chain.Levels[i].Down;
    std::vector<Term> down;
    Box box;
    for (const auto& t : terms)
    {
      down.push_back(Term{ MakeOp(t.X), MakeOp(t.Y), static_cast<float>(t.Weight) });
      box = Union(box, ReachBox(down.back().X, down.back().Y, boxes[i - 1]));
    }
    boxes[i] = p.RestrictToBrightRegion ? box : pyramid.Full(i);
    for (const Term& t : down)
    {
      pyramid.Define(i - 1, NeedsBox(t.X, t.Y, boxes[i]));
    }
    Separable<L>(levels[i - 1], down, boxes[i], levels[i]);
    report.SamplesProcessed += static_cast<long long>(boxes[i].X1 - boxes[i].X0) *
      (boxes[i].Y1 - boxes[i].Y0) * static_cast<long long>(terms.size());
  }
}

//------------------------------------------------------------------------------
// Level i's blur as the pass after it applies it: its operators (the identity on an axis the
// FFT has done), whether any is left to apply, and where the blurred level may be non-zero.
struct LevelBlur
{
  Op X, Y;
  bool Blurred = false;
  Box Region;
};

// The axes of level i's blur that go through the FFT, in place over the whole level (the
// region's reach on those axes, exact zeros elsewhere); the level's box grows by their reach,
// and `blur` keeps only the axes left for the fused pass.
template <int C>
void BlurThroughFFT(const std::array<std::unique_ptr<vtkBloomFFTConvolution>, 2>& fft, int i,
  Pyramid& pyramid, LevelBlur& blur, vtkBloomFastChainReport& report)
{
  constexpr int L = Lanes<C>();
  pyramid.Define(i, pyramid.Full(i));
  if (i == 0)
  {
    // Every row of level 0 is written now (the FFT changes dark rows too).
    std::fill(pyramid.Bright.Dark.begin(), pyramid.Bright.Dark.end(), char(0));
  }
  Plane& lv = pyramid.Levels[i];
  const int size[3] = { lv.W, lv.H, 1 };
  Box reach = pyramid.Boxes[i];
  for (int a = 0; a < 2; ++a)
  {
    if (fft[a])
    {
      fft[a]->ApplyAxis(lv.D.data(), size, L, C, a);
      report.FFTBlurs += 1;
      const Box grown = ReachBox(blur.X, blur.Y, reach);
      reach = a == 0 ? Box{ grown.X0, grown.X1, reach.Y0, reach.Y1 }
                     : Box{ reach.X0, reach.X1, grown.Y0, grown.Y1 };
    }
  }
  pyramid.Boxes[i] = reach;
  if (fft[0])
  {
    blur.X = MakeOp(vtkBloomLinearOperator::Identity(lv.W));
  }
  if (fft[1])
  {
    blur.Y = MakeOp(vtkBloomLinearOperator::Identity(lv.H));
  }
  blur.Blurred = !(fft[0] && fft[1]);
}

// Level i's blur, for a level of weight w (none for weight 0: the level is not read then).
template <int C>
LevelBlur PrepareBlur(const vtkBloomFastChainParameters& p, vtkBloomFastChain::Internals& ws, int i,
  float w, Pyramid& pyramid, vtkBloomFastChainReport& report)
{
  const vtkBloomChain::Level& chainLevel = p.Chain->Levels[i];
  LevelBlur blur;
  blur.Blurred = chainLevel.Blur;
  if (w != 0.0f && blur.Blurred)
  {
    blur.X = MakeOp(chainLevel.BlurPass.X);
    blur.Y = MakeOp(chainLevel.BlurPass.Y);
    const auto& fft = ws.BlurFFT[i];
    if (fft[0] || fft[1])
    {
      BlurThroughFFT<C>(fft, i, pyramid, blur, report);
    }
  }
  if (w != 0.0f)
  {
    if (blur.Blurred)
    {
      blur.Region = ReachBox(blur.X, blur.Y, pyramid.Boxes[i]);
    }
    else
    {
      blur.Region = pyramid.Boxes[i];
    }
  }
  return blur;
}

//------------------------------------------------------------------------------
// What each level contributes to the composite: the plane that holds it (an accumulation
// plane, or the level itself when nothing was left to blur) and the box it is written over.
struct Accumulation
{
  std::vector<Box> Boxes;
  std::vector<const Plane*> Planes;

  explicit Accumulation(int levels)
    : Boxes(levels)
    , Planes(levels, nullptr)
  {
  }
};

// DIRECT: blur level i into its accumulation plane; the composite weighs and sums the levels.
template <int L>
void BlurLevel(const vtkBloomFastChainParameters& p, int i, const LevelBlur& blur, Pyramid& pyramid,
  Plane& plane, Accumulation& acc, vtkBloomFastChainReport& report)
{
  const vtkBloomChain::Level& chainLevel = p.Chain->Levels[i];
  const Plane& level = pyramid.Levels[i];
  Box& box = acc.Boxes[i];
  box = p.RestrictToBrightRegion ? blur.Region : pyramid.Full(i);
  acc.Planes[i] = &level;
  pyramid.Define(i,
    blur.Blurred ? NeedsBox(blur.X, blur.Y, box)
                 : ReadBox(MakeOp(chainLevel.Full.X), MakeOp(chainLevel.Full.Y), box));
  if (blur.Blurred)
  {
    plane.Resize(level.W, level.H, L);
    plane.ZeroAround(ReadBox(MakeOp(chainLevel.Full.X), MakeOp(chainLevel.Full.Y), box), box);
    Separable<L>(level, { Term{ blur.X, blur.Y, 1.0f } }, box, plane);
    acc.Planes[i] = &plane;
    report.SamplesProcessed += static_cast<long long>(box.X1 - box.X0) * (box.Y1 - box.Y0);
  }
}

// CASCADE: acc_i = up(acc_{i+1}) + w_i blur(level_i), in one pass over the rows of the union
// of both terms' regions.
template <int L>
void AccumulateLevel(const vtkBloomFastChainParameters& p, int i, int levelsBuilt, float w,
  const LevelBlur& blur, const Op& finalX, const Op& finalY, Pyramid& pyramid, Plane& plane,
  Accumulation& acc, vtkBloomFastChainReport& report)
{
  const vtkBloomChain& chain = *p.Chain;
  const Plane& level = pyramid.Levels[i];
  const bool blurred = blur.Blurred;
  const Op& bx = blur.X;
  const Op& by = blur.Y;
  const bool up = i + 1 < levelsBuilt;
  Op ux, uy;
  Box upBox;
  if (up)
  {
    ux = MakeOp(chain.Levels[i].Up.X);
    uy = MakeOp(chain.Levels[i].Up.Y);
    upBox = ReachBox(ux, uy, acc.Boxes[i + 1]);
  }
  const Box box = p.RestrictToBrightRegion ? Union(upBox, blur.Region) : pyramid.Full(i);
  acc.Boxes[i] = box;
  plane.Resize(level.W, level.H, L);
  acc.Planes[i] = &plane;
  plane.ZeroAround(i > 0
      ? ReadBox(MakeOp(chain.Levels[i - 1].Up.X), MakeOp(chain.Levels[i - 1].Up.Y), box)
      : ReadBox(finalX, finalY, box),
    box);
  if (box.Empty())
  {
    return;
  }
  if (w != 0.0f)
  {
    pyramid.Define(i, blurred ? NeedsBox(bx, by, box) : box);
  }
  const size_t stride = static_cast<size_t>(box.X1 - box.X0) * L;
  const int n = static_cast<int>(stride);
  const Plane* below = up ? acc.Planes[i + 1] : nullptr;
  const Columns read = blurred && w != 0.0f ? Columns(bx, box.X0, box.X1) : Columns();
  vtkSMPThreadLocal<RingScratch<L>> scratch;
  vtkSMPTools::For(box.Y0, box.Y1, RowGrain(box.Y1 - box.Y0),
    [&](int begin, int end)
    {
      RingScratch<L>& local = scratch.Local();
      local.Rings.resize(1);
      local.Row.resize(stride);
      local.Row2.resize(stride);
      RowRing<L>& upRing = local.Rings[0];
      if (up)
      {
        upRing.Reset(below, &ux, box.X0, box.X1, uy.Width);
      }
      float* __restrict brow = local.Row.data();
      float* __restrict urow = local.Row2.data();
      for (int j = begin; j < end; ++j)
      {
        float* __restrict d = plane.Row(j) + box.X0 * L;
        const float* b = brow;
        if (w != 0.0f)
        {
          if (blurred)
          {
            YThenX<L>(bx, by, level, j, box.X0, box.X1, read, local.Line, brow);
          }
          else
          {
            b = level.Row(j) + box.X0 * L; // level i's own row
          }
        }
        if (up)
        {
          RowY(uy, j, upRing.Rows(), n, urow);
        }
        if (up && w != 0.0f)
        {
          SumSaturated<true>(d, urow, w, b, n);
        }
        else
        {
          SumSaturated<false>(d, nullptr, up ? 1.0f : w, up ? urow : b, n);
        }
      }
    });
  report.SamplesProcessed += static_cast<long long>(box.X1 - box.X0) * (box.Y1 - box.Y0);
}

// 3. Blur, fused with the upsample-accumulate (CASCADE) or alone (DIRECT), into the
// accumulation planes (level i's rows are read by their neighbours' outputs, so acc_i
// cannot be written over level i). What the next pass reads of an accumulation plane
// outside its box is zeroed; the rest of the plane is never read.
template <int C>
Accumulation BlurAndAccumulate(const vtkBloomFastChainParameters& p, int levelsBuilt,
  const Op& finalX, const Op& finalY, vtkBloomFastChain::Internals& ws, Pyramid& pyramid,
  vtkBloomFastChainReport& report)
{
  constexpr int L = Lanes<C>();
  const bool cascade = p.AccumulateMode != AccumulateDirect;
  ws.Acc.resize(std::max<size_t>(ws.Acc.size(), levelsBuilt));
  ws.UpdateBlurFFT(p);
  Accumulation acc(levelsBuilt);
  for (int i = levelsBuilt - 1; i >= 0; --i)
  {
    const float w = static_cast<float>(p.LevelWeights[i]);
    const LevelBlur blur = PrepareBlur<C>(p, ws, i, w, pyramid, report);
    Plane& plane = ws.Acc[i];
    if (!cascade)
    {
      if (w != 0.0f)
      {
        BlurLevel<L>(p, i, blur, pyramid, plane, acc, report);
      }
    }
    else
    {
      AccumulateLevel<L>(p, i, levelsBuilt, w, blur, finalX, finalY, pyramid, plane, acc, report);
    }
  }
  return acc;
}

//------------------------------------------------------------------------------
// The composite's sources: acc_0 as it is (CASCADE), or each level of non-zero weight,
// scaled by its weight (DIRECT), each with the operators that take it to full size.
inline void AddSources(const vtkBloomFastChainParameters& p, int levelsBuilt, const Op& finalX,
  const Op& finalY, const Accumulation& acc, std::vector<Source>& sources)
{
  const bool cascade = p.AccumulateMode != AccumulateDirect;
  auto addSource = [&](int i, bool scaled)
  {
    Source s;
    s.Level = acc.Planes[i];
    s.Weight = static_cast<float>(p.LevelWeights[i]);
    s.Scaled = scaled;
    if (!cascade)
    {
      s.X = MakeOp(p.Chain->Levels[i].Full.X);
      s.Y = MakeOp(p.Chain->Levels[i].Full.Y);
    }
    else
    {
      s.X = finalX;
      s.Y = finalY;
    }
    s.Region = acc.Boxes[i];
    sources.push_back(std::move(s));
  };
  if (cascade)
  {
    addSource(0, false);
  }
  else
  {
    for (int i = 0; i < levelsBuilt; ++i)
    {
      if (p.LevelWeights[i] != 0.0)
      {
        addSource(i, true);
      }
    }
  }
}

//------------------------------------------------------------------------------
// The array for the output's scalars: the previous run's when nothing else holds it any more
// and it has the input's type and the output's size, else a fresh one.
inline vtkDataArray* OutputScalars(
  vtkBloomFastChain::Internals& ws, vtkDataArray* inScalars, int nc, vtkIdType tuples)
{
  vtkSmartPointer<vtkDataArray>& r = ws.Recycled;
  if (!(r && r->GetReferenceCount() == 1 && r->GetDataType() == inScalars->GetDataType() &&
        r->GetNumberOfComponents() == nc && r->GetNumberOfTuples() == tuples))
  {
    r.TakeReference(vtkDataArray::CreateDataArray(inScalars->GetDataType()));
    r->SetNumberOfComponents(nc);
    r->SetNumberOfTuples(tuples);
  }
  r->SetName(inScalars->GetName());
  r->Modified();
  return r;
}

//------------------------------------------------------------------------------
template <typename T, int C>
void Run(const vtkBloomFastChainParameters& p, vtkImageData* input, const int outExt[6],
  vtkImageData* output, vtkBloomFastChainReport& report, vtkBloomFastChain::Internals& ws,
  const float st[3], bool disabled, vtkAlgorithm* progress)
{
  auto reportProgress = [progress](double amount)
  {
    if (progress)
    {
      progress->UpdateProgress(amount);
    }
  };
  constexpr int L = Lanes<C>();
  int inExt[6];
  input->GetExtent(inExt);
  const int width = inExt[1] - inExt[0] + 1;
  const int height = inExt[3] - inExt[2] + 1;
  const int nc = input->GetNumberOfScalarComponents();
  vtkDataArray* inScalars = input->GetPointData()->GetScalars();
  const T* in = static_cast<const T*>(inScalars->GetVoidPointer(0));
  const bool whole = std::equal(inExt, inExt + 6, outExt);
  const double keep = p.CompositeMode == CompositeLerp ? 1.0 - p.Strength : 1.0;

  std::vector<Source> sources;
  bool clean = false; // the input holds no -0, NaN or Inf (known after the bright pass)
  bool passThrough = false;
  int levelsBuilt = LevelsToBuild(p);
  if (disabled || levelsBuilt == 0)
  {
    report.ChainSkipped = true;
    levelsBuilt = 0;
  }
  else
  {
    // 1. Bright pass into level 0.
    ws.Levels.resize(std::max<size_t>(ws.Levels.size(), levelsBuilt));
    Pyramid pyramid(ws.Levels);
    const int w0 = p.LevelSizes[0].first, h0 = p.LevelSizes[0].second;
    pyramid.Levels[0].Resize(w0, h0, L);
    // The input is scanned for -0, NaN and Inf in any case (the composite takes a shorter loop
    // without them); the pass-through needs the scan, a whole output and keep = 1.
    const bool scan = p.SkipEmpty && keep == 1.0 && whole;
    pyramid.Bright = BrightPassToLevel0<T, C>(p, in, width, height, nc, pyramid.Levels[0]);
    clean = !pyramid.Bright.AnySpecial;
    report.SamplesProcessed += static_cast<long long>(w0) * h0;
    reportProgress(0.3);
    pyramid.Boxes.resize(levelsBuilt);
    pyramid.Boxes[0] = p.RestrictToBrightRegion ? pyramid.Bright.Region : pyramid.Full(0);
    if (p.SkipEmpty && pyramid.Bright.Region.Empty())
    {
      report.ChainSkipped = true;
      passThrough = scan && !pyramid.Bright.AnySpecial;
      levelsBuilt = 0;
    }
    else
    {
      // 2. The pyramid.
      Downsample<L>(p, levelsBuilt, pyramid, report);
      reportProgress(0.4);

      // 3. The blurs and their accumulation.
      const vtkBloomChain& chain = *p.Chain;
      const Op finalX =
        MakeOp(chain.FinalIsIdentity ? vtkBloomLinearOperator::Identity(width) : chain.Final.X);
      const Op finalY =
        MakeOp(chain.FinalIsIdentity ? vtkBloomLinearOperator::Identity(height) : chain.Final.Y);
      const Accumulation acc =
        BlurAndAccumulate<C>(p, levelsBuilt, finalX, finalY, ws, pyramid, report);
      reportProgress(0.5);
      AddSources(p, levelsBuilt, finalX, finalY, acc, sources);
    }
  }
  report.LevelsBuilt = levelsBuilt;

  // 4. Composite (or pass the input through when the result is the input bit for bit). The
  // output's previous scalars are dropped first, so that the array recycled below is held by
  // nobody else unless a consumer still uses it.
  output->GetPointData()->Initialize();
  output->SetExtent(const_cast<int*>(outExt));
  if (passThrough)
  {
    report.PassedThrough = true;
    output->GetPointData()->SetScalars(inScalars);
    return;
  }
  const vtkIdType tuples = static_cast<vtkIdType>(outExt[1] - outExt[0] + 1) *
    (outExt[3] - outExt[2] + 1) * (outExt[5] - outExt[4] + 1);
  vtkDataArray* scalars = OutputScalars(ws, inScalars, nc, tuples);
  output->GetPointData()->SetScalars(scalars);
  T* out = static_cast<T*>(scalars->GetVoidPointer(0));
  std::unique_ptr<vtkBloomStatisticsRows> statistics;
  if (p.MeasureStatistics && std::is_same<T, float>::value)
  {
    statistics.reset(
      new vtkBloomStatisticsRows(p.ThresholdMode, p.Threshold, p.Knee, p.ClampLuminance));
  }
  WithComponents<C>(nc,
    [&](auto components)
    {
      constexpr int NC = decltype(components)::value;
      p.SanitizeNonFinite
        ? Composite<T, NC, C, true>(p, in, inExt, clean, sources, st, out, outExt, statistics.get())
        : Composite<T, NC, C, false>(
            p, in, inExt, clean, sources, st, out, outExt, statistics.get());
    });
  if (statistics)
  {
    report.StatisticsMeasured = true;
    report.StatisticsIn = statistics->In();
    report.StatisticsOut = statistics->Out();
    report.BrightPixels = statistics->BrightPixels();
  }
}
