// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// Included by vtkBloomFastChainPasses.txx, once per instruction set inside a namespace of its
// own (so no include guard); see that file.
//
// The separable sums: vector helpers, weighted sums of rows, the x and y operators of one row,
// rings of x-filtered rows, and Separable(), which applies a sum of x-then-y (or y-then-x)
// operator terms over a box. Every blur, downsample and upsample of the chain runs here.

// Unaligned vector loads and stores of floats, and a vector with every lane v (1 v is v bit
// for bit, -0 and NaN included).
inline FloatV LoadV(const float* p)
{
  return *reinterpret_cast<const FloatU*>(p);
}

inline void StoreV(float* p, FloatV v)
{
  *reinterpret_cast<FloatU*>(p) = v;
}

inline FloatV Broadcast(float v)
{
  return v * (FloatV{} + 1.0f);
}

// out[q] = sum_k w[k] src[k][q] from q, by blocks of NV vectors while a whole block fits,
// summed in k order from w[0] src[0][q] (added to out[q] when Accumulate): each block is summed
// over all taps in NV independent registers and stored once. Returns where it stopped.
template <bool Accumulate, int NV>
int WeightedSumBlocks(
  const float* w, const float* const* src, int taps, int q, int n, float* __restrict out)
{
  constexpr int B = NV * VectorFloats;
  const int k0 = Accumulate ? 0 : 1;
  for (; q + B <= n; q += B)
  {
    FloatV acc[NV];
    if (Accumulate)
    {
      for (int v = 0; v < NV; ++v)
      {
        acc[v] = LoadV(out + q + v * VectorFloats);
      }
    }
    else
    {
      const FloatV w0 = Broadcast(w[0]);
      for (int v = 0; v < NV; ++v)
      {
        acc[v] = w0 * LoadV(src[0] + q + v * VectorFloats);
      }
    }
    for (int k = k0; k < taps; ++k)
    {
      const FloatV wk = Broadcast(w[k]);
      const float* s = src[k] + q;
      for (int v = 0; v < NV; ++v)
      {
        acc[v] += wk * LoadV(s + v * VectorFloats);
      }
    }
    for (int v = 0; v < NV; ++v)
    {
      StoreV(out + q + v * VectorFloats, acc[v]);
    }
  }
  return q;
}

// out[q] = sum_k w[k] src[k][q] for q < n, summed in k order from w[0] src[0][q] (added to
// out[q] when Accumulate). Blocks of four vectors (independent sums, so that the additions of
// one tap do not wait on each other), then of one vector, then single values: each value gets
// the same sum whatever the block.
template <bool Accumulate>
void WeightedSum(const float* w, const float* const* src, int taps, int n, float* __restrict out)
{
  int q = WeightedSumBlocks<Accumulate, 4>(w, src, taps, 0, n, out);
  q = WeightedSumBlocks<Accumulate, 1>(w, src, taps, q, n, out);
  const int k0 = Accumulate ? 0 : 1;
  for (; q < n; ++q)
  {
    float acc = Accumulate ? out[q] : w[0] * src[0][q];
    for (int k = k0; k < taps; ++k)
    {
      acc += w[k] * src[k][q];
    }
    out[q] = acc;
  }
}

// WeightedSum over any number of taps, `Group` sources at a time.
template <typename Source>
void WeightedSumOf(const float* w, Source&& source, int taps, int n, float* out)
{
  constexpr int Group = 32;
  const float* src[Group];
  for (int k0 = 0; k0 < taps; k0 += Group)
  {
    const int count = std::min(Group, taps - k0);
    for (int k = 0; k < count; ++k)
    {
      src[k] = source(k0 + k);
    }
    k0 > 0 ? WeightedSum<true>(w + k0, src, count, n, out)
           : WeightedSum<false>(w + k0, src, count, n, out);
  }
}

// RowX over a periodic run from output a (on the run's phase): each of the Period rows' weights
// are held in registers, and output a + m Period + p reads from First[a + p] + m Stride. Every
// output is summed as the generic loop sums it. Returns how many outputs it wrote (whole
// periods; the caller finishes the rest).
template <int C, int P, int Width>
int PeriodicXOf(const Op& o, const float* in, int c0, float* __restrict out, int a, int b)
{
  float w[P][Width];
  const float* s0[P];
  for (int p = 0; p < P; ++p)
  {
    for (int k = 0; k < Width; ++k)
    {
      w[p][k] = o.W[static_cast<size_t>(a + p) * Width + k];
    }
    s0[p] = in + static_cast<size_t>(o.First[a + p] - c0) * C;
  }
  const int periods = (b - a) / P;
  const size_t step = static_cast<size_t>(o.Stride) * C;
  for (int m = 0; m < periods; ++m)
  {
    for (int p = 0; p < P; ++p)
    {
      const float* s = s0[p] + m * step;
      float acc[C];
      for (int c = 0; c < C; ++c)
      {
        acc[c] = w[p][0] * s[c];
      }
      for (int k = 1; k < Width; ++k)
      {
        for (int c = 0; c < C; ++c)
        {
          acc[c] += w[p][k] * s[k * C + c];
        }
      }
      for (int c = 0; c < C; ++c)
      {
        out[(static_cast<size_t>(m) * P + p) * C + c] = acc[c];
      }
    }
  }
  return periods * P;
}

template <int C>
int PeriodicX(const Op& o, const float* in, int c0, float* out, int a, int b, int period, int width)
{
  auto of = [&](auto p)
  {
    constexpr int P = decltype(p)::value;
    switch (width)
    {
      case 2:
        return PeriodicXOf<C, P, 2>(o, in, c0, out, a, b);
      case 3:
        return PeriodicXOf<C, P, 3>(o, in, c0, out, a, b);
      case 4:
        return PeriodicXOf<C, P, 4>(o, in, c0, out, a, b);
      case 5:
        return PeriodicXOf<C, P, 5>(o, in, c0, out, a, b);
      case 6:
        return PeriodicXOf<C, P, 6>(o, in, c0, out, a, b);
      default:
        return 0;
    }
  };
  return period == 1 ? of(std::integral_constant<int, 1>()) : of(std::integral_constant<int, 2>());
}

// out[(j - j0) C + c] = sum_k W[j, k] in[(First[j] + k - c0) C + c] for j in [j0, j1): `in`
// holds the row from column c0. Every output is the same expression (w0 x0, then += wk xk in
// order) in both loops, so which loop computes a sample never changes its bits.
template <int C>
void RowX(const Op& o, const float* in, int c0, float* out, int j0, int j1)
{
  const int width = o.Width;
  auto generic = [&](int a, int b)
  {
    for (int j = a; j < b; ++j)
    {
      const float* w = o.W.data() + static_cast<size_t>(j) * width;
      const float* s = in + static_cast<size_t>(o.First[j] - c0) * C;
      float acc[C];
      for (int c = 0; c < C; ++c)
      {
        acc[c] = w[0] * s[c];
      }
      for (int k = 1; k < width; ++k)
      {
        for (int c = 0; c < C; ++c)
        {
          acc[c] += w[k] * s[k * C + c];
        }
      }
      for (int c = 0; c < C; ++c)
      {
        out[(j - j0) * C + c] = acc[c];
      }
    }
  };
  int a = std::max(j0, o.ToeLo), b = std::min(j1, o.ToeHi);
  if (a >= b || b - a < 8)
  {
    a = std::max(j0, o.PerLo);
    b = std::min(j1, o.PerHi);
    if (b - a >= 2 * o.Period && o.Period > 0)
    {
      generic(j0, a);
      // Start on the run's phase so that row a + p has row PerLo + p's weights.
      const int phase = (a - o.PerLo) % o.Period;
      if (phase != 0)
      {
        generic(a, a + o.Period - phase);
        a += o.Period - phase;
      }
      const int done =
        PeriodicX<C>(o, in, c0, out + static_cast<size_t>(a - j0) * C, a, b, o.Period, width);
      generic(a + done, j1);
      return;
    }
    generic(j0, j1);
    return;
  }
  generic(j0, a);
  const float* src = in + static_cast<size_t>(a + o.ToeShift - c0) * C;
  WeightedSumOf(
    o.W.data() + static_cast<size_t>(a) * width, [&](int k) { return src + k * C; }, width,
    (b - a) * C, out + (a - j0) * C);
  generic(b, j1);
}

// out[q] = sum_k W[j, k] rows(First[j] + k)[q] for q < n; rows(r) points at row r's values.
template <typename Rows>
void RowY(const Op& o, int j, Rows&& rows, int n, float* out)
{
  WeightedSumOf(
    o.W.data() + static_cast<size_t>(j) * o.Width, [&](int k) { return rows(o.First[j] + k); },
    o.Width, n, out);
}

// The rows of a plane after an x operator, over output columns [X0, X1), each computed when
// first asked for and kept in a ring of slots. A thread that walks output rows upwards asks
// for a window of source rows that only moves up, so it computes each row once, and the ring
// (a few rows) stays in cache for the y pass: no whole-level intermediate is written or read.
template <int C>
class RowRing
{
public:
  void Reset(const Plane* src, const Op* ox, int x0, int x1, int slots)
  {
    this->Src = src;
    this->X = ox;
    this->X0 = x0;
    this->X1 = x1;
    this->Stride = static_cast<size_t>(x1 - x0) * C;
    this->Data.resize(this->Stride * slots);
    this->Held.assign(slots, -1);
  }

  const float* Row(int r)
  {
    const size_t slot = static_cast<size_t>(r) % this->Held.size();
    float* row = this->Data.data() + slot * this->Stride;
    if (this->Held[slot] != r)
    {
      RowX<C>(*this->X, this->Src->Row(r), 0, row, this->X0, this->X1);
      Saturate(row, this->Stride);
      this->Held[slot] = r;
    }
    return row;
  }

  auto Rows()
  {
    return [this](int r) { return this->Row(r); };
  }

private:
  const Plane* Src = nullptr;
  const Op* X = nullptr;
  int X0 = 0, X1 = 0;
  size_t Stride = 0;
  std::vector<float> Data;
  std::vector<int> Held;
};

// Per-thread rings and a row of y results.
template <int C>
struct RingScratch
{
  std::vector<RowRing<C>> Rings;
  std::vector<float> Row, Row2, Line;
};

// The source columns [C0, C1) that outputs [x0, x1) of an x operator read: the same for every
// row of a pass, so a pass finds them once (Needs walks the operator's rows).
struct Columns
{
  int C0 = 0, C1 = 0;
  Columns() = default;
  Columns(const Op& ox, int x0, int x1) { Needs(ox, x0, x1, this->C0, this->C1); }
};

// Output row j of (oy ox) src over columns [x0, x1), y first: oy combines the source rows over
// the columns ox reads (`read`, the Columns of [x0, x1)) in one flat pass, and ox runs on that
// one line. For an operator that keeps or shrinks the size this is no more work than x first,
// and it needs no ring, so a task does not recompute the rows its first output row needs (oy's
// support, which a wide blur makes long).
template <int C>
void YThenX(const Op& ox, const Op& oy, const Plane& src, int j, int x0, int x1,
  const Columns& read, std::vector<float>& line, float* out)
{
  const int c0 = read.C0, c1 = read.C1;
  line.resize(static_cast<size_t>(c1 - c0) * C);
  RowY(
    oy, j, [&](int r) { return src.Row(r) + c0 * C; }, (c1 - c0) * C, line.data());
  Saturate(line.data(), line.size());
  RowX<C>(ox, line.data(), c0, out, x0, x1);
}

// Rows per task of the streaming passes over `rows` output rows: about two tasks per thread,
// so that the threads share a level, between 32 and 128 rows. Long tasks matter where a pass
// runs x first through a ring (upsamples, the composite): each task first computes again the
// source rows its first output row needs.
int RowGrain(int rows)
{
  const int tasks = 2 * std::max(1, vtkSMPTools::GetEstimatedNumberOfThreads());
  return std::min(std::max(rows / tasks, 32), 128);
}

// One term of a sum of separable operators.
struct Term
{
  Op X, Y;
  float Weight = 1.0f;
};

// dst over `box` = sum_t Weight_t Y_t X_t src, term by term in order (saturated after each),
// in one sweep over the output rows. A term that keeps or shrinks the number of rows runs y
// first (YThenX), so the x operator, the costly per-sample one, runs on the output rows only;
// a term that enlarges it (an upsample) runs x first through a ring, on the fewer source rows.
template <int C>
void Separable(const Plane& src, const std::vector<Term>& terms, const Box& box, Plane& dst)
{
  if (box.Empty())
  {
    return;
  }
  const size_t stride = static_cast<size_t>(box.X1 - box.X0) * C;
  const int n = static_cast<int>(stride);
  std::vector<Columns> read;
  for (const Term& term : terms)
  {
    read.emplace_back(term.X, box.X0, box.X1);
  }
  vtkSMPThreadLocal<RingScratch<C>> scratch;
  vtkSMPTools::For(box.Y0, box.Y1, RowGrain(box.Y1 - box.Y0),
    [&](int begin, int end)
    {
      RingScratch<C>& local = scratch.Local();
      local.Rings.resize(terms.size());
      local.Row.resize(stride);
      for (size_t t = 0; t < terms.size(); ++t)
      {
        if (terms[t].Y.Out > terms[t].Y.In) // the terms that run x first (see below)
        {
          local.Rings[t].Reset(&src, &terms[t].X, box.X0, box.X1, terms[t].Y.Width);
        }
      }
      float* __restrict row = local.Row.data();
      for (int j = begin; j < end; ++j)
      {
        float* __restrict d = dst.Row(j) + box.X0 * C;
        for (size_t t = 0; t < terms.size(); ++t)
        {
          const Term& term = terms[t];
          if (term.Y.Out <= term.Y.In)
          {
            YThenX<C>(term.X, term.Y, src, j, box.X0, box.X1, read[t], local.Line, row);
          }
          else
          {
            RowY(term.Y, j, local.Rings[t].Rows(), n, row);
          }
          t > 0 ? SumSaturated<true>(d, d, term.Weight, row, n)
                : SumSaturated<false>(d, nullptr, term.Weight, row, n);
        }
      }
    });
}
