// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// Included by vtkBloomFastChainPasses.txx, once per instruction set inside a namespace of its
// own (so no include guard); see that file.
//
// The composite: out = keep * in + S t bloom, fused with the last upsample of each bloom
// source, one output row at a time, with non-temporal stores for large outputs.

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
// With `statistics`, each input row and the output row written from it are measured there,
// while they are in the cache (float images; a row copied from the input is measured once).
template <typename T, int NC, int C, bool Sanitize>
void Composite(const vtkBloomFastChainParameters& p, const T* in, const int inExt[6], bool clean,
  const std::vector<Source>& sources, const float st[3], T* out, const int outExt[6],
  vtkBloomStatisticsRows* statistics)
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
  vtkSMPThreadLocal<vtkBloomStatisticsRows> measured(
    statistics ? *statistics : vtkBloomStatisticsRows());
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
        const bool copy = copyIsComposite && b0 >= b1; // dst is src, bit for bit
        if (stream && copy)
        {
          StreamCopy(reinterpret_cast<float*>(dst), reinterpret_cast<const float*>(src), n);
        }
        else
        {
          CompositeSpans<T, NC, C, Sanitize>(src, bloom.data() + static_cast<size_t>(x0) * L,
            b0 - x0, b1 - x0, stL, stFlat.data(), colour.data(), keep, clean, outW, dst);
        }
        if constexpr (std::is_same<T, float>::value)
        {
          if (statistics)
          {
            // Outside the bloom's columns a clean composite with keep 1 copies the input.
            const int begin = copyIsComposite ? b0 - x0 : 0;
            const int end = copyIsComposite ? b1 - x0 : outW;
            measured.Local().AddRow(src, copy ? nullptr : dst, outW, NC, begin, end);
          }
        }
      }
      StoreFence();
    });
  if (statistics)
  {
    for (const vtkBloomStatisticsRows& m : measured)
    {
      statistics->Merge(m);
    }
  }
}
