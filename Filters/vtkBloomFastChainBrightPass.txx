// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// Included by vtkBloomFastChainPasses.txx, once per instruction set inside a namespace of its
// own (so no include guard); see that file.
//
// The bright pass: loading and sanitizing input samples, the scan that bounds each row's
// magnitude (and finds NaN and Inf), the threshold of one row, and the fused fetch of the
// thresholded input to the start level, with its dark-row bookkeeping.

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
