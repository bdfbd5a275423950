// The passes of the fast chain, included by vtkBloomFastChain.cxx once per instruction set,
// each time inside a namespace of its own (so this file has no include guard). It uses the
// helpers that file defines first (Op, Box, Plane, ...) and vtkBloomFastChain::Internals.
// VTKBLOOM_VECTOR_BYTES, defined by the includer, is the width of the vector registers of the
// instruction set (16 or 32) for the loops written with GCC vector types.

constexpr int VectorBytes = VTKBLOOM_VECTOR_BYTES;
constexpr int VectorFloats = VectorBytes / 4;
typedef float FloatV __attribute__((vector_size(VectorBytes)));
typedef int32_t IntV __attribute__((vector_size(VectorBytes)));
typedef float FloatU __attribute__((vector_size(VectorBytes), aligned(4), may_alias));

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

// An input sample as the chain reads it: sanitized (NaN 0, +-Inf +-max) when asked, and in
// float range.
template <typename T>
inline float Load(T v, bool sanitize)
{
  const double m = static_cast<double>(FloatMax);
  double d = static_cast<double>(v);
  if (sanitize)
  {
    d = d == d ? std::min(std::max(d, -m), m) : 0.0;
  }
  else if (d == d)
  {
    // Out-of-range doubles become +-Inf, as the float conversion would make them.
    if (d > m)
    {
      return std::numeric_limits<float>::infinity();
    }
    if (d < -m)
    {
      return -std::numeric_limits<float>::infinity();
    }
  }
  return static_cast<float>(d);
}

template <>
inline float Load<float>(float v, bool sanitize)
{
  return sanitize ? Finite(v) : v;
}

// True when a sample is -0, NaN or +-Inf: the only values "v + 0" or sanitizing would change.
inline bool Special(float v)
{
  uint32_t u;
  std::memcpy(&u, &v, sizeof(u));
  return (u & 0x7f800000u) == 0x7f800000u || u == 0x80000000u;
}
inline bool Special(double v)
{
  uint64_t u;
  std::memcpy(&u, &v, sizeof(u));
  return (u & 0x7ff0000000000000ull) == 0x7ff0000000000000ull || u == 0x8000000000000000ull;
}

struct BrightResult
{
  Box Region;
  bool AnySpecial = false;
  std::vector<char> Dark; // level-0 rows left unwritten (their samples are all zero)
};

// Samples per pixel in the levels: colour images keep RGB in four lanes (the fourth is zero) so
// every per-pixel operation is one 4-wide vector operation; one colour keeps one lane.
template <int C>
constexpr int Lanes()
{
  return C == 3 ? 4 : C;
}

// line[q] = sum_k wy_k load(row_k[q]) over n values: the bright pass's y fetch, flat.
template <typename T, bool Sanitize>
void CombineRows(
  const Op& ry, int j, const T* base, size_t stride, size_t n, float* __restrict line)
{
  const float* wy = ry.W.data() + static_cast<size_t>(j) * ry.Width;
  for (int k = 0; k < ry.Width; ++k)
  {
    const T* __restrict in = base + static_cast<size_t>(ry.First[j] + k) * stride;
    const float w = wy[k];
    if (k == 0)
    {
      for (size_t q = 0; q < n; ++q)
      {
        line[q] = w * Load(in[q], Sanitize);
      }
    }
    else
    {
      for (size_t q = 0; q < n; ++q)
      {
        line[q] += w * Load(in[q], Sanitize);
      }
    }
  }
}

// out[x] = sum_t W[x, t] line[First[x] + t] for the w0 samples of a level-0 row, L lanes each.
// When the image's components line up with the lanes (NC == L), every lane is fetched (one
// vector operation per tap); otherwise the lanes past the C colours are left unset.
template <int NC, int C, int Width>
void FetchX(const Op& rx, const float* __restrict line, int w0, float* __restrict out)
{
  constexpr int L = Lanes<C>();
  constexpr int F = NC == L ? L : C;
  const int width = Width > 0 ? Width : rx.Width;
  for (int x = 0; x < w0; ++x)
  {
    const float* w = rx.W.data() + static_cast<size_t>(x) * width;
    const float* s = line + static_cast<size_t>(rx.First[x]) * NC;
    float a[F];
    for (int c = 0; c < F; ++c)
    {
      a[c] = w[0] * s[c];
    }
    for (int t = 1; t < width; ++t)
    {
      for (int c = 0; c < F; ++c)
      {
        a[c] += w[t] * s[t * NC + c];
      }
    }
    for (int c = 0; c < F; ++c)
    {
      out[static_cast<size_t>(x) * L + c] = a[c];
    }
  }
}

// What one read of input rows tells the bright pass: whether a value is -0, NaN or +-Inf (the
// composite's short form needs none), whether one is NaN or +-Inf, and bounds that decide,
// without fetching, that the bright pass of every sample fetched from the rows is zero: the
// largest luminance (C = 3, Rec. 709) or value (C = 1), the largest colour value and the largest
// colour magnitude.
struct RowBounds
{
  float Luminance = -FloatMax;
  float Channel = -FloatMax;
  float Magnitude = 0.0f;
  bool NonFinite = false;
  bool Special = false;
};

// Per component extremes and flags of NC-component pixels. The float specialization below
// keeps 4 pixels' worth of running values and updates them element-wise, which vectorizes.
template <typename T, int NC>
void ScanRowScalar(
  const T* __restrict row, int width, float hi[NC], float mag[NC], bool& special, bool& nonFinite)
{
  for (int x = 0; x < width; ++x)
  {
    for (int c = 0; c < NC; ++c)
    {
      const T v = row[static_cast<size_t>(x) * NC + c];
      special |= Special(v);
      nonFinite |= !(v >= -std::numeric_limits<T>::max() && v <= std::numeric_limits<T>::max());
      hi[c] = std::max(hi[c], static_cast<float>(v));
      mag[c] = std::max(mag[c], static_cast<float>(std::abs(v)));
    }
  }
}

template <typename T, int NC>
void ScanRow(const T* row, int width, float hi[NC], float mag[NC], bool& special, bool& nonFinite)
{
  ScanRowScalar<T, NC>(row, width, hi, mag, special, nonFinite);
}

template <>
void ScanRow<float, 4>(
  const float* __restrict row, int width, float hi[4], float mag[4], bool& special, bool& nonFinite)
{
  // Three running values per lane: the largest value; the largest |v| as an integer (for
  // non-negative floats the integer order is the float order, and NaN and Inf are the bit
  // patterns from 0x7f800000 up, so one maximum answers both "how large" and "any NaN or
  // Inf"); and whether a -0 (bits 0x80000000) occurred. A vector holds whole pixels, so its
  // lane q is component q % 4.
  constexpr int NV = 64 / VectorBytes; // vectors per block of 16 values
  FloatV h[NV];
  IntV m[NV], sp[NV];
  for (int v = 0; v < NV; ++v)
  {
    for (int q = 0; q < VectorFloats; ++q)
    {
      h[v][q] = hi[q % 4];
    }
    m[v] = IntV{};
    sp[v] = IntV{};
  }
  const IntV absMask = IntV{} + 0x7fffffff;
  const IntV negativeZero = IntV{} + std::numeric_limits<int32_t>::min();
  const int n = width * 4, blocks = n / 16;
  for (int k = 0; k < blocks; ++k)
  {
    for (int v = 0; v < NV; ++v)
    {
      const FloatV x = LoadV(row + static_cast<size_t>(k) * 16 + v * VectorFloats);
      IntV u;
      std::memcpy(&u, &x, sizeof(u));
      const IntV a = u & absMask;
      h[v] = h[v] > x ? h[v] : x;
      m[v] = m[v] > a ? m[v] : a;
      sp[v] |= u == negativeZero;
    }
  }
  for (int v = 0; v < NV; ++v)
  {
    for (int q = 0; q < VectorFloats; ++q)
    {
      hi[q % 4] = std::max(hi[q % 4], h[v][q]);
      special |= sp[v][q] != 0;
      if (m[v][q] >= 0x7f800000)
      {
        nonFinite = true;
        special = true;
        continue;
      }
      float magnitude;
      const int32_t bits = m[v][q];
      std::memcpy(&magnitude, &bits, sizeof(magnitude));
      mag[q % 4] = std::max(mag[q % 4], magnitude);
    }
  }
  ScanRowScalar<float, 4>(
    row + static_cast<size_t>(blocks) * 16, (n - blocks * 16) / 4, hi, mag, special, nonFinite);
}

// The bounds of rows [r0, r1) (NaN and Inf are looked for in every component, alpha included,
// which only makes the dark decision stricter).
template <typename T, int NC, int C>
RowBounds ScanRows(const T* base, size_t stride, int width, int r0, int r1)
{
  RowBounds b;
  float hi[NC], mag[NC];
  for (int c = 0; c < NC; ++c)
  {
    hi[c] = -FloatMax;
    mag[c] = 0.0f;
  }
  for (int r = r0; r < r1; ++r)
  {
    ScanRow<T, NC>(base + static_cast<size_t>(r) * stride, width, hi, mag, b.Special, b.NonFinite);
  }
  // The luminance of any pixel is at most the luminance of the per-channel maxima, since the
  // Rec. 709 weights are positive.
  b.Luminance = C == 3 ? static_cast<float>(vtkBloomKernels::LuminanceR) * hi[0] +
      static_cast<float>(vtkBloomKernels::LuminanceG) * hi[1] +
      static_cast<float>(vtkBloomKernels::LuminanceB) * hi[2]
                       : hi[0];
  for (int c = 0; c < C; ++c)
  {
    b.Channel = std::max(b.Channel, hi[c]);
    b.Magnitude = std::max(b.Magnitude, mag[c]);
  }
  return b;
}

// True when every sample fetched from rows with these bounds passes vtkBloomBrightPassIsZero.
// A fetched sample is a convex combination of the rows' colours (see DarkRowsDecidable), so its
// luminance and largest colour are at most the bounds plus the float32 rounding of the fetch,
// which the margin covers; the comparisons are IsZero's, which are monotone.
bool RowsAreDark(const RowBounds& b, const vtkBloomFastChainParameters& p)
{
  if (b.NonFinite)
  {
    return false;
  }
  const float margin = 1e-5f * b.Magnitude;
  return vtkBloomBrightPassIsZeroBelow(b.Luminance + margin, b.Channel + margin, p.ThresholdMode,
    p.Threshold, p.Knee, p.ClampLuminance);
}

// Rows can be decided dark when the fetch is a convex combination: weights >= 0 summing to 1
// within 1e-6 in every output row of both operators.
bool DarkRowsDecidable(const Op& rx, const Op& ry)
{
  for (const Op* o : { &rx, &ry })
  {
    for (int j = 0; j < o->Out; ++j)
    {
      double sum = 0.0;
      for (int t = 0; t < o->Width; ++t)
      {
        const float w = o->W[static_cast<size_t>(j) * o->Width + t];
        if (!(w >= 0.0f))
        {
          return false;
        }
        sum += w;
      }
      if (std::abs(sum - 1.0) > 1e-6)
      {
        return false;
      }
    }
  }
  return true;
}

// The bright pass over the w0 samples of a level-0 row, in place (the lane past the colours
// set to zero), and the columns [lo, hi) of its non-zero samples. The mode is a constant, so
// the formulas' switch folds away.
template <int C, int Mode>
void ThresholdRow(
  const vtkBloomFastChainParameters& p, double ceiling, float* row, int w0, int& lo, int& hi)
{
  constexpr int L = Lanes<C>();
  lo = w0;
  hi = 0;
  for (int x = 0; x < w0; ++x)
  {
    float* a = row + static_cast<size_t>(x) * L;
    for (int c = C; c < L; ++c)
    {
      a[c] = 0.0f; // the lane past the colours (alpha when NC == 4) stays zero
    }
    if (vtkBloomBrightPassIsZero<C>(a, Mode, p.Threshold, p.Knee, p.ClampLuminance))
    {
      for (int c = 0; c < C; ++c)
      {
        a[c] = 0.0f;
      }
      continue;
    }
    vtkBloomMapNonFinite<C>(a, ceiling);
    vtkBloomBrightPass<C>(a, Mode, p.Threshold, p.Knee, p.ClampLuminance);
    bool nonzero = false;
    for (int c = 0; c < C; ++c)
    {
      nonzero |= a[c] != 0.0f;
    }
    if (nonzero)
    {
      lo = std::min(lo, x);
      hi = x + 1;
    }
  }
}

// Pass 1: level 0 = threshold(bilinear(input)), one read of the input, fused per level-0 row:
// the y fetch combines whole input rows (flat), the x fetch gathers C colours into L lanes, and
// the bright pass runs in float, its full formula only where vtkBloomBrightPassIsZero cannot
// decide.
template <typename T, int NC, int C>
BrightResult BrightPass(const vtkBloomFastChainParameters& p, const T* base, int width, int height,
  const Op& rx, const Op& ry, Plane& level)
{
  const int w0 = level.W, h0 = level.H;
  std::vector<int> rowLo(h0), rowHi(h0);
  std::vector<char> special(h0, 0);
  const double ceiling = std::min(p.ClampLuminance, static_cast<double>(VTK_FLOAT_MAX));
  const size_t inStride = static_cast<size_t>(width) * NC;
  const bool decidable = DarkRowsDecidable(rx, ry);
  std::vector<char> dark(h0, 0);
  vtkSMPThreadLocal<std::vector<float>> lines;
  vtkSMPTools::For(0, h0, 4,
    [&](int begin, int end)
    {
      std::vector<float>& scratch = lines.Local();
      scratch.resize(inStride);
      float* line = scratch.data();
      for (int j = begin; j < end; ++j)
      {
        // Input rows [j H / h0, (j + 1) H / h0) belong to this row, which reports their -0,
        // NaN and Inf. For a 2:1 level these are the rows fetched, read once for both answers.
        const int r0 = static_cast<int>(static_cast<long long>(j) * height / h0);
        const int r1 = static_cast<int>(static_cast<long long>(j + 1) * height / h0);
        const int f0 = ry.First[j], f1 = ry.First[j] + ry.Width;
        rowLo[j] = w0;
        rowHi[j] = 0;
        bool finite = false; // the fetched rows are known to hold no NaN or Inf
        if (decidable && f0 == r0 && f1 == r1)
        {
          const RowBounds bounds = ScanRows<T, NC, C>(base, inStride, width, r0, r1);
          special[j] = bounds.Special;
          if (RowsAreDark(bounds, p))
          {
            dark[j] = 1; // not fetched (ZeroDarkRows zeroes what a later pass reads)
            continue;
          }
          finite = !bounds.NonFinite;
        }
        else
        {
          special[j] = ScanRows<T, NC, C>(base, inStride, width, r0, r1).Special;
          if (decidable)
          {
            const RowBounds fetched = ScanRows<T, NC, C>(base, inStride, width, f0, f1);
            if (RowsAreDark(fetched, p))
            {
              dark[j] = 1;
              continue;
            }
            finite = !fetched.NonFinite;
          }
        }
        // Sanitizing leaves finite samples as they are: rows without NaN or Inf skip it.
        if (p.SanitizeNonFinite && !finite)
        {
          CombineRows<T, true>(ry, j, base, inStride, inStride, line);
        }
        else
        {
          CombineRows<T, false>(ry, j, base, inStride, inStride, line);
        }
        float* __restrict out = level.Row(j);
        if (rx.Width == 2)
        {
          FetchX<NC, C, 2>(rx, line, w0, out);
        }
        else
        {
          FetchX<NC, C, 0>(rx, line, w0, out);
        }
        vtkBloomWithThresholdMode(p.ThresholdMode,
          [&](auto mode)
          { ThresholdRow<C, decltype(mode)::value>(p, ceiling, out, w0, rowLo[j], rowHi[j]); });
      }
    });
  BrightResult result;
  Box& b = result.Region;
  b.X0 = w0;
  b.Y0 = h0;
  for (int j = 0; j < h0; ++j)
  {
    result.AnySpecial |= special[j] != 0;
    if (rowLo[j] < rowHi[j])
    {
      b.X0 = std::min(b.X0, rowLo[j]);
      b.X1 = std::max(b.X1, rowHi[j]);
      b.Y0 = std::min(b.Y0, j);
      b.Y1 = j + 1;
    }
  }
  if (b.Empty())
  {
    b = Box();
  }
  result.Dark = std::move(dark);
  return result;
}

// Zeroes the dark level-0 rows (BrightPass leaves them unwritten) over the samples of `read`.
void ZeroDarkRows(const std::vector<char>& dark, const Box& read, Plane& level)
{
  for (int y = read.Y0; y < read.Y1; ++y)
  {
    if (dark[y])
    {
      std::fill(level.Row(y) + read.X0 * level.C, level.Row(y) + read.X1 * level.C, 0.0f);
    }
  }
}

// One bloom source for the composite: a plane, its weight and its bilinear ops to full size.
struct Source
{
  const Plane* Level;
  float Weight;
  bool Scaled; // multiply by Weight (DIRECT); CASCADE adds acc_0 as it is
  Op X;
  Op Y;
  Box Region; // non-zero samples of the plane
};

// out = keep * in + term over n pixels, term = S t clamp(bloom) + 0 (+0 without bloom); alpha
// and any component past the colours are copied (sanitized when asked).
template <typename T, int NC, int C, bool Sanitize, bool HasBloom>
void CompositeSpan(const T* __restrict src, const float* __restrict bloom, const float* st, T keep,
  int n, T* __restrict dst)
{
  constexpr int L = Lanes<C>();
  for (int x = 0; x < n; ++x)
  {
    for (int c = 0; c < NC; ++c)
    {
      const T v = Sanitize ? Finite(src[x * NC + c]) : src[x * NC + c];
      if (c < C)
      {
        float term = 0.0f;
        if (HasBloom)
        {
          float b = bloom[x * L + c];
          b = b == b ? std::min(std::max(b, -FloatMax), FloatMax) : 0.0f;
          term = st[c] * b + 0.0f;
        }
        const T o = static_cast<T>(keep * v + static_cast<T>(term));
        dst[x * NC + c] = Sanitize ? Finite(o) : o;
      }
      else
      {
        dst[x * NC + c] = v;
      }
    }
  }
}

// CompositeSpan when the bloom samples line up with the image's components (L == NC): one flat
// loop over the n values, which vectorizes. stFlat and colour repeat per pixel (S t, 0 for the
// component past the colours; 1 where a component is a colour). KeepOne drops the product
// 1 * v, which is v bit for bit. Sanitized, v and the term are finite, so their sum can only
// overflow, never be NaN: clamping it is Finite().
template <typename T, bool Sanitize, bool HasBloom, bool KeepOne>
void CompositeFlat(const T* __restrict src, const float* __restrict bloom,
  const float* __restrict stFlat, const unsigned char* __restrict colour, T keep, int n,
  T* __restrict dst)
{
  const T m = std::numeric_limits<T>::max();
  for (int q = 0; q < n; ++q)
  {
    const T v = Sanitize ? Finite(src[q]) : src[q];
    float term = 0.0f;
    if (HasBloom)
    {
      float b = bloom[q];
      b = b == b ? std::min(std::max(b, -FloatMax), FloatMax) : 0.0f;
      term = stFlat[q] * b + 0.0f;
    }
    T o = static_cast<T>((KeepOne ? v : keep * v) + static_cast<T>(term));
    o = Sanitize ? std::min(std::max(o, -m), m) : o;
    dst[q] = colour[q] ? o : v;
  }
}

// CompositeFlat for any keep. With keep = 1, an input without -0, NaN or Inf (`clean`) and a
// finite bloom, the loop above reduces to in + (S t bloom + 0) bit for bit: sanitizing changes
// nothing, and v + (+0) is v for the components past the colours. Only an overflow of the sum
// is left to sanitize; the row is checked after and, if one occurred, recomputed in full.
template <typename T, bool Sanitize, bool HasBloom>
void CompositeFlat(const T* src, const float* bloom, const float* stFlat,
  const unsigned char* colour, T keep, bool clean, int n, T* dst)
{
  if (keep != T(1))
  {
    CompositeFlat<T, Sanitize, HasBloom, false>(src, bloom, stFlat, colour, keep, n, dst);
    return;
  }
  if (std::is_same<T, float>::value && clean)
  {
    if (!HasBloom)
    {
      std::copy(src, src + n, dst);
      return;
    }
    // One pass that also notes whether a bloom value, or (sanitized) a result, is NaN or Inf.
    const float* __restrict in = reinterpret_cast<const float*>(src);
    float* __restrict out = reinterpret_cast<float*>(dst);
    const uint32_t e = 0x7f800000u;
    uint32_t bad = 0;
    for (int q = 0; q < n; ++q)
    {
      const float o = in[q] + (stFlat[q] * bloom[q] + 0.0f);
      out[q] = o;
      uint32_t ub, uo;
      std::memcpy(&ub, bloom + q, sizeof(ub));
      std::memcpy(&uo, &o, sizeof(uo));
      bad |=
        static_cast<uint32_t>((ub & e) == e) | static_cast<uint32_t>(Sanitize && (uo & e) == e);
    }
    if (bad == 0)
    {
      return;
    }
  }
  CompositeFlat<T, Sanitize, HasBloom, true>(src, bloom, stFlat, colour, keep, n, dst);
}

template <typename T, int NC, int C, bool Sanitize>
void CompositeSpans(const T* src, const float* bloom, int b0, int b1, const float* st,
  const float* stFlat, const unsigned char* colour, T keep, bool clean, int n, T* dst)
{
  constexpr int L = Lanes<C>();
  b0 = std::min(std::max(b0, 0), n);
  b1 = std::min(std::max(b1, b0), n);
  const size_t s0 = static_cast<size_t>(b0) * NC, s1 = static_cast<size_t>(b1) * NC;
  if (L == NC)
  {
    CompositeFlat<T, Sanitize, false>(src, nullptr, stFlat, colour, keep, clean, b0 * NC, dst);
    CompositeFlat<T, Sanitize, true>(
      src + s0, bloom + s0, stFlat, colour, keep, clean, (b1 - b0) * NC, dst + s0);
    CompositeFlat<T, Sanitize, false>(
      src + s1, nullptr, stFlat, colour, keep, clean, (n - b1) * NC, dst + s1);
    return;
  }
  CompositeSpan<T, NC, C, Sanitize, false>(src, nullptr, st, keep, b0, dst);
  CompositeSpan<T, NC, C, Sanitize, true>(
    src + s0, bloom + static_cast<size_t>(b0) * L, st, keep, b1 - b0, dst + s0);
  CompositeSpan<T, NC, C, Sanitize, false>(src + s1, nullptr, st, keep, n - b1, dst + s1);
}

// Pass 4: out = keep * in + (S t bloom + 0) over outExt, the bloom row interpolated per row.
template <typename T, int NC, int C, bool Sanitize>
void Composite(const vtkBloomFastChainParameters& p, const T* in, const int inExt[6], bool clean,
  const std::vector<Source>& sources, const float st[3], T* out, const int outExt[6])
{
  constexpr int L = Lanes<C>();
  const int inW = inExt[1] - inExt[0] + 1;
  const int outW = outExt[1] - outExt[0] + 1;
  const int x0 = outExt[0] - inExt[0];
  const T keep = static_cast<T>(p.CompositeMode == CompositeLerp ? 1.0 - p.Strength : 1.0);
  float stL[L];
  for (int c = 0; c < L; ++c)
  {
    stL[c] = c < C ? st[c] : 0.0f;
  }
  // Full-resolution bloom columns and rows each source reaches. Weighted sources (DIRECT)
  // accumulate into a zeroed row; CASCADE's one source is assigned.
  std::vector<Box> reach(sources.size());
  bool accumulate = false;
  for (size_t i = 0; i < sources.size(); ++i)
  {
    reach[i] = ReachBox(sources[i].X, sources[i].Y, sources[i].Region);
    accumulate |= sources[i].Scaled;
  }
  // S t and "is a colour" for every value of a row, for the flat composite loop.
  std::vector<float> stFlat(static_cast<size_t>(inW) * NC);
  std::vector<unsigned char> colour(stFlat.size());
  for (size_t q = 0; q < stFlat.size(); ++q)
  {
    const int c = static_cast<int>(q % NC);
    stFlat[q] = c < C ? st[c] : 0.0f;
    colour[q] = c < C;
  }
  // Rows of a large float output without bloom whose result is the input (keep 1, no -0, NaN
  // or Inf) are streamed from it (StreamCopy).
  const bool stream = std::is_same<T, float>::value &&
    static_cast<size_t>(outW) * (outExt[3] - outExt[2] + 1) * NC * sizeof(T) >= StreamingBytes;
  const bool copyIsComposite = keep == T(1) && clean;
  // Each source's rows are interpolated in x once per task, through a ring, and the y pass
  // combines them.
  struct Scratch
  {
    std::vector<float> Bloom, YRow;
    std::vector<RowRing<L>> Rings;
  };
  vtkSMPThreadLocal<Scratch> scratch;
  vtkSMPTools::For(outExt[2], outExt[3] + 1, RowGrain(outExt[3] - outExt[2] + 1),
    [&](int begin, int end)
    {
      Scratch& local = scratch.Local();
      std::vector<float>& bloom = local.Bloom;
      bloom.resize(static_cast<size_t>(inW) * L);
      local.Rings.resize(sources.size());
      for (size_t i = 0; i < sources.size(); ++i)
      {
        local.Rings[i].Reset(
          sources[i].Level, &sources[i].X, reach[i].X0, reach[i].X1, sources[i].Y.Width);
      }
      for (int y = begin; y < end; ++y)
      {
        const int j = y - inExt[2];
        int b0 = inW, b1 = 0; // bloom columns of this row
        for (size_t i = 0; i < sources.size(); ++i)
        {
          if (!reach[i].Empty() && j >= reach[i].Y0 && j < reach[i].Y1)
          {
            b0 = std::min(b0, reach[i].X0);
            b1 = std::max(b1, reach[i].X1);
          }
        }
        if (b0 < b1 && accumulate)
        {
          std::fill(bloom.begin() + static_cast<size_t>(b0) * L,
            bloom.begin() + static_cast<size_t>(b1) * L, 0.0f);
        }
        for (size_t i = 0; i < sources.size(); ++i)
        {
          const Source& s = sources[i];
          const Box& r = reach[i];
          if (r.Empty() || j < r.Y0 || j >= r.Y1)
          {
            continue;
          }
          const int n = (r.X1 - r.X0) * L;
          float* b = bloom.data() + static_cast<size_t>(r.X0) * L;
          if (!s.Scaled)
          {
            RowY(s.Y, j, local.Rings[i].Rows(), n, b);
            continue;
          }
          local.YRow.resize(n);
          float* __restrict a = local.YRow.data();
          RowY(s.Y, j, local.Rings[i].Rows(), n, a);
          const float weight = s.Weight;
          for (int q = 0; q < n; ++q)
          {
            b[q] = b[q] + weight * a[q];
          }
        }
        const T* src = in + (static_cast<size_t>(j) * inW + x0) * NC;
        T* dst = out + static_cast<size_t>(y - outExt[2]) * outW * NC;
        const size_t n = static_cast<size_t>(outW) * NC;
        if (stream && copyIsComposite && b0 >= b1)
        {
          StreamCopy(reinterpret_cast<float*>(dst), reinterpret_cast<const float*>(src), n);
          continue;
        }
        CompositeSpans<T, NC, C, Sanitize>(src, bloom.data() + static_cast<size_t>(x0) * L, b0 - x0,
          b1 - x0, stL, stFlat.data(), colour.data(), keep, clean, outW, dst);
      }
      StoreFence();
    });
}

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
      std::vector<Box> acc(levelsBuilt);
      std::vector<const Plane*> accPlane(levelsBuilt, nullptr);
      for (int i = levelsBuilt - 1; i >= 0; --i)
      {
        const Plane& level = levels[i];
        const float w = static_cast<float>(p.LevelWeights[i]);
        const bool blurred = chain.Levels[i].Blur;
        Op bx, by;
        Box blurBox;
        if (w != 0.0f)
        {
          if (blurred)
          {
            bx = MakeOp(chain.Levels[i].BlurPass.X);
            by = MakeOp(chain.Levels[i].BlurPass.Y);
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
