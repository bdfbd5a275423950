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
  int levelsBuilt = static_cast<int>(p.LevelSizes.size());
  if (p.TrimPyramid)
  {
    while (levelsBuilt > 0 && p.LevelWeights[levelsBuilt - 1] == 0.0)
    {
      --levelsBuilt;
    }
  }
  if (disabled || levelsBuilt == 0)
  {
    report.ChainSkipped = true;
    levelsBuilt = 0;
  }
  else
  {
    // 1. Bright pass into level 0.
    ws.Levels.resize(std::max<size_t>(ws.Levels.size(), levelsBuilt));
    auto& levels = ws.Levels;
    const int w0 = p.LevelSizes[0].first, h0 = p.LevelSizes[0].second;
    levels[0].Resize(w0, h0, L);
    const vtkBloomChain& chain = *p.Chain;
    const Op rx =
      MakeOp(chain.SourceIsIdentity ? vtkBloomLinearOperator::Identity(width) : chain.Source.X);
    const Op ry =
      MakeOp(chain.SourceIsIdentity ? vtkBloomLinearOperator::Identity(height) : chain.Source.Y);
    // The input is scanned for -0, NaN and Inf in any case (the composite takes a shorter loop
    // without them); the pass-through needs the scan, a whole output and keep = 1.
    const bool scan = p.SkipEmpty && keep == 1.0 && whole;
    BrightResult bright;
    WithComponents<C>(nc,
      [&](auto components)
      {
        bright =
          BrightPass<T, decltype(components)::value, C>(p, in, width, height, rx, ry, levels[0]);
      });
    clean = !bright.AnySpecial;
    report.SamplesProcessed += static_cast<long long>(w0) * h0;
    reportProgress(0.3);
    std::vector<Box> boxes(levelsBuilt);
    auto full = [&](int i) { return Box{ 0, levels[i].W, 0, levels[i].H }; };
    // Level i is written over boxes[i] (level 0: over its rows that are not dark); a pass that
    // reads it zeroes what it reads outside first, instead of every level being cleared.
    auto defineLevel = [&](int i, const Box& read)
    {
      if (i == 0)
      {
        ZeroDarkRows(bright.Dark, read, levels[0]);
      }
      else
      {
        levels[i].ZeroAround(read, boxes[i]);
      }
    };
    boxes[0] = p.RestrictToBrightRegion ? bright.Region : full(0);
    if (p.SkipEmpty && bright.Region.Empty())
    {
      report.ChainSkipped = true;
      passThrough = scan && !bright.AnySpecial;
      levelsBuilt = 0;
    }
    else
    {
      // 2. The pyramid, each level over the region its terms reach.
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
        boxes[i] = p.RestrictToBrightRegion ? box : full(i);
        for (const Term& t : down)
        {
          defineLevel(i - 1, NeedsBox(t.X, t.Y, boxes[i]));
        }
        Separable<L>(levels[i - 1], down, boxes[i], levels[i]);
        report.SamplesProcessed += static_cast<long long>(boxes[i].X1 - boxes[i].X0) *
          (boxes[i].Y1 - boxes[i].Y0) * static_cast<long long>(terms.size());
      }

      reportProgress(0.4);

      // 3. Blur, fused with the upsample-accumulate (CASCADE) or alone (DIRECT), into the
      // accumulation planes (level i's rows are read by their neighbours' outputs, so acc_i
      // cannot be written over level i). What the next pass reads of an accumulation plane
      // outside its box is zeroed; the rest of the plane is never read.
      const bool cascade = p.AccumulateMode != AccumulateDirect;
      const Op finalX =
        MakeOp(chain.FinalIsIdentity ? vtkBloomLinearOperator::Identity(width) : chain.Final.X);
      const Op finalY =
        MakeOp(chain.FinalIsIdentity ? vtkBloomLinearOperator::Identity(height) : chain.Final.Y);
      ws.Acc.resize(std::max<size_t>(ws.Acc.size(), levelsBuilt));
      ws.UpdateBlurFFT(p);
      std::vector<Box> acc(levelsBuilt);
      std::vector<const Plane*> accPlane(levelsBuilt, nullptr);
      for (int i = levelsBuilt - 1; i >= 0; --i)
      {
        const Plane& level = levels[i];
        const float w = static_cast<float>(p.LevelWeights[i]);
        bool blurred = chain.Levels[i].Blur;
        Op bx, by;
        Box blurBox;
        if (w != 0.0f && blurred)
        {
          bx = MakeOp(chain.Levels[i].BlurPass.X);
          by = MakeOp(chain.Levels[i].BlurPass.Y);
          const auto& fft = ws.BlurFFT[i];
          if (fft[0] || fft[1])
          {
            // The wide axes through the FFT, in place over the whole level (the region's reach
            // on those axes, exact zeros elsewhere); the fused pass below does the rest.
            defineLevel(i, full(i));
            if (i == 0)
            {
              // Every row of level 0 is written now (the FFT changes dark rows too).
              std::fill(bright.Dark.begin(), bright.Dark.end(), char(0));
            }
            Plane& lv = levels[i];
            const int size[3] = { lv.W, lv.H, 1 };
            Box reach = boxes[i];
            for (int a = 0; a < 2; ++a)
            {
              if (fft[a])
              {
                fft[a]->ApplyAxis(lv.D.data(), size, L, C, a);
                report.FFTBlurs += 1;
                const Box grown = ReachBox(bx, by, reach);
                reach = a == 0 ? Box{ grown.X0, grown.X1, reach.Y0, reach.Y1 }
                               : Box{ reach.X0, reach.X1, grown.Y0, grown.Y1 };
              }
            }
            boxes[i] = reach;
            if (fft[0])
            {
              bx = MakeOp(vtkBloomLinearOperator::Identity(lv.W));
            }
            if (fft[1])
            {
              by = MakeOp(vtkBloomLinearOperator::Identity(lv.H));
            }
            blurred = !(fft[0] && fft[1]);
          }
        }
        if (w != 0.0f)
        {
          if (blurred)
          {
            blurBox = ReachBox(bx, by, boxes[i]);
          }
          else
          {
            blurBox = boxes[i];
          }
        }
        Plane& plane = ws.Acc[i];
        if (!cascade)
        {
          // DIRECT: blur level i; the composite weighs and sums the levels.
          if (w == 0.0f)
          {
            continue;
          }
          acc[i] = p.RestrictToBrightRegion ? blurBox : full(i);
          accPlane[i] = &level;
          defineLevel(i,
            blurred
              ? NeedsBox(bx, by, acc[i])
              : ReadBox(MakeOp(chain.Levels[i].Full.X), MakeOp(chain.Levels[i].Full.Y), acc[i]));
          if (blurred)
          {
            plane.Resize(level.W, level.H, L);
            plane.ZeroAround(
              ReadBox(MakeOp(chain.Levels[i].Full.X), MakeOp(chain.Levels[i].Full.Y), acc[i]),
              acc[i]);
            Separable<L>(level, { Term{ bx, by, 1.0f } }, acc[i], plane);
            accPlane[i] = &plane;
            report.SamplesProcessed +=
              static_cast<long long>(acc[i].X1 - acc[i].X0) * (acc[i].Y1 - acc[i].Y0);
          }
          continue;
        }
        // CASCADE: acc_i = up(acc_{i+1}) + w_i blur(level_i).
        const bool up = i + 1 < levelsBuilt;
        Op ux, uy;
        Box upBox;
        if (up)
        {
          ux = MakeOp(chain.Levels[i].Up.X);
          uy = MakeOp(chain.Levels[i].Up.Y);
          upBox = ReachBox(ux, uy, acc[i + 1]);
        }
        const Box box = p.RestrictToBrightRegion ? Union(upBox, blurBox) : full(i);
        acc[i] = box;
        plane.Resize(level.W, level.H, L);
        accPlane[i] = &plane;
        plane.ZeroAround(i > 0
            ? ReadBox(MakeOp(chain.Levels[i - 1].Up.X), MakeOp(chain.Levels[i - 1].Up.Y), box)
            : ReadBox(finalX, finalY, box),
          box);
        if (box.Empty())
        {
          continue;
        }
        if (w != 0.0f)
        {
          defineLevel(i, blurred ? NeedsBox(bx, by, box) : box);
        }
        const size_t stride = static_cast<size_t>(box.X1 - box.X0) * L;
        const int n = static_cast<int>(stride);
        const Plane* below = up ? accPlane[i + 1] : nullptr;
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

      reportProgress(0.5);

      // The composite's sources.
      auto addSource = [&](int i, bool scaled)
      {
        Source s;
        s.Level = accPlane[i];
        s.Weight = static_cast<float>(p.LevelWeights[i]);
        s.Scaled = scaled;
        if (!cascade)
        {
          s.X = MakeOp(chain.Levels[i].Full.X);
          s.Y = MakeOp(chain.Levels[i].Full.Y);
        }
        else
        {
          s.X = finalX;
          s.Y = finalY;
        }
        s.Region = acc[i];
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
  vtkSmartPointer<vtkDataArray>& r = ws.Recycled;
  if (!(r && r->GetReferenceCount() == 1 && r->GetDataType() == inScalars->GetDataType() &&
        r->GetNumberOfComponents() == nc && r->GetNumberOfTuples() == tuples))
  {
    // A fresh array; the previous one is reused only when nothing else holds it any more.
    r.TakeReference(vtkDataArray::CreateDataArray(inScalars->GetDataType()));
    r->SetNumberOfComponents(nc);
    r->SetNumberOfTuples(tuples);
  }
  r->SetName(inScalars->GetName());
  r->Modified();
  output->GetPointData()->SetScalars(r);
  T* out = static_cast<T*>(r->GetVoidPointer(0));
  WithComponents<C>(nc,
    [&](auto components)
    {
      constexpr int NC = decltype(components)::value;
      p.SanitizeNonFinite
        ? Composite<T, NC, C, true>(p, in, inExt, clean, sources, st, out, outExt)
        : Composite<T, NC, C, false>(p, in, inExt, clean, sources, st, out, outExt);
    });
}
