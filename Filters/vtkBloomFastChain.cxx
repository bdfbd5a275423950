#include "vtkBloomFastChain.h"

#include "vtkAlgorithm.h"
#include "vtkBloomBrightPass.h"
#include "vtkBloomChain.h"
#include "vtkBloomImageOps.h"
#include "vtkBloomKernels.h"
#include "vtkBloomLinearOperator.h"
#include "vtkDataArray.h"
#include "vtkImageBloomThreshold.h"
#include "vtkImageData.h"
#include "vtkImagePyramidDown.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

namespace
{
const int AccumulateDirect = 1; // vtkImageBloom::DIRECT
const int CompositeLerp = 1;    // vtkImageBloom::LERP
const float FloatMax = std::numeric_limits<float>::max();

// A sample sanitized: NaN 0, +-Inf the finite extremes of T.
template <typename T>
inline T Finite(T v)
{
  const T m = std::numeric_limits<T>::max();
  return v == v ? std::min(std::max(v, -m), m) : T(0);
}

// A vtkBloomLinearOperator in float, with its translation-invariant interior found once so the
// x passes can run it as a flat convolution over interleaved samples (which vectorizes).
struct Op
{
  int In = 0;
  int Out = 0;
  int Width = 0;
  std::vector<int> First;
  std::vector<float> W;
  int ToeLo = 0; // outputs [ToeLo, ToeHi) read First[j] = j + ToeShift with row ToeLo's weights
  int ToeHi = 0;
  int ToeShift = 0;
};

Op MakeOp(const vtkBloomLinearOperator& d)
{
  Op o;
  o.In = d.InputSize;
  o.Out = d.OutputSize;
  o.Width = d.Width;
  o.First = d.First;
  o.W.assign(d.Weights.begin(), d.Weights.end());
  if (o.Out > 0 && o.Width > 0)
  {
    const int ref = o.Out / 2;
    const int shift = o.First[ref] - ref;
    const size_t w = static_cast<size_t>(o.Width);
    auto same = [&](int j)
    {
      return o.First[j] - j == shift &&
        std::equal(o.W.begin() + j * w, o.W.begin() + (j + 1) * w, o.W.begin() + ref * w);
    };
    int lo = ref, hi = ref + 1;
    while (lo > 0 && same(lo - 1))
    {
      --lo;
    }
    while (hi < o.Out && same(hi))
    {
      ++hi;
    }
    o.ToeLo = lo;
    o.ToeHi = hi;
    o.ToeShift = shift;
  }
  return o;
}

// A half-open box of samples.
struct Box
{
  int X0 = 0, X1 = 0, Y0 = 0, Y1 = 0;
  bool Empty() const { return this->X0 >= this->X1 || this->Y0 >= this->Y1; }
};

Box Union(const Box& a, const Box& b)
{
  if (a.Empty())
  {
    return b;
  }
  if (b.Empty())
  {
    return a;
  }
  return { std::min(a.X0, b.X0), std::max(a.X1, b.X1), std::min(a.Y0, b.Y0), std::max(a.Y1, b.Y1) };
}

// Outputs of `o` whose inputs meet [lo, hi).
void Reach(const Op& o, int lo, int hi, int& jlo, int& jhi)
{
  jlo = o.Out;
  jhi = 0;
  for (int j = 0; j < o.Out; ++j)
  {
    if (o.First[j] < hi && o.First[j] + o.Width > lo)
    {
      jlo = std::min(jlo, j);
      jhi = j + 1;
    }
  }
  if (jlo >= jhi)
  {
    jlo = jhi = 0;
  }
}

Box ReachBox(const Op& ox, const Op& oy, const Box& in)
{
  Box out;
  if (!in.Empty())
  {
    Reach(ox, in.X0, in.X1, out.X0, out.X1);
    Reach(oy, in.Y0, in.Y1, out.Y0, out.Y1);
  }
  return out;
}

// Inputs read by outputs [jlo, jhi).
void Needs(const Op& o, int jlo, int jhi, int& lo, int& hi)
{
  lo = o.In;
  hi = 0;
  for (int j = jlo; j < jhi; ++j)
  {
    lo = std::min(lo, o.First[j]);
    hi = std::max(hi, o.First[j] + o.Width);
  }
  if (lo >= hi)
  {
    lo = hi = 0;
  }
}

// A level: Width x Height samples of C interleaved colour values.
struct Plane
{
  int W = 0;
  int H = 0;
  int C = 0;
  std::vector<float> D;
  void Resize(int w, int h, int c)
  {
    this->W = w;
    this->H = h;
    this->C = c;
    this->D.resize(static_cast<size_t>(w) * h * c);
  }
  float* Row(int y) { return this->D.data() + static_cast<size_t>(y) * this->W * this->C; }
  const float* Row(int y) const
  {
    return this->D.data() + static_cast<size_t>(y) * this->W * this->C;
  }
  void Zero(const Box& b)
  {
    for (int y = b.Y0; y < b.Y1; ++y)
    {
      std::fill(this->Row(y) + b.X0 * this->C, this->Row(y) + b.X1 * this->C, 0.0f);
    }
  }
};

// out[(j - j0) C + c] = sum_k W[j, k] in[(First[j] + k) C + c] for j in [j0, j1). Every output
// is the same expression (w0 x0, then += wk xk in order) in both loops, so which loop computes
// a sample never changes its bits.
template <int C>
void RowX(const Op& o, const float* in, float* out, int j0, int j1)
{
  const int width = o.Width;
  auto generic = [&](int a, int b)
  {
    for (int j = a; j < b; ++j)
    {
      const float* w = o.W.data() + static_cast<size_t>(j) * width;
      const float* s = in + static_cast<size_t>(o.First[j]) * C;
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
    generic(j0, j1);
    return;
  }
  generic(j0, a);
  const float* w = o.W.data() + static_cast<size_t>(a) * width;
  float* __restrict dst = out + (a - j0) * C;
  const float* src = in + static_cast<size_t>(a + o.ToeShift) * C;
  const int n = (b - a) * C;
  {
    const float w0 = w[0];
    const float* __restrict s = src;
    for (int q = 0; q < n; ++q)
    {
      dst[q] = w0 * s[q];
    }
  }
  for (int k = 1; k < width; ++k)
  {
    const float wk = w[k];
    const float* __restrict s = src + k * C;
    for (int q = 0; q < n; ++q)
    {
      dst[q] += wk * s[q];
    }
  }
  generic(b, j1);
}

// out[q] = sum_k W[j, k] rows(First[j] + k)[q], q < n; rows(r) = block + (r - r0) * stride.
void RowY(
  const Op& o, int j, const float* block, int r0, size_t stride, int n, float* __restrict out)
{
  const float* w = o.W.data() + static_cast<size_t>(j) * o.Width;
  const float* __restrict s = block + static_cast<size_t>(o.First[j] - r0) * stride;
  const float w0 = w[0];
  for (int q = 0; q < n; ++q)
  {
    out[q] = w0 * s[q];
  }
  for (int k = 1; k < o.Width; ++k)
  {
    const float wk = w[k];
    const float* __restrict sk = block + static_cast<size_t>(o.First[j] + k - r0) * stride;
    for (int q = 0; q < n; ++q)
    {
      out[q] += wk * sk[q];
    }
  }
}

// block rows [r0, r1) = ox applied to src rows, for output columns [x0, x1).
template <int C>
void BlockX(
  const Plane& src, const Op& ox, int r0, int r1, int x0, int x1, std::vector<float>& block)
{
  const size_t stride = static_cast<size_t>(x1 - x0) * C;
  block.resize(static_cast<size_t>(r1 - r0) * stride);
  vtkSMPTools::For(r0, r1, 8,
    [&](int begin, int end)
    {
      for (int r = begin; r < end; ++r)
      {
        RowX<C>(ox, src.Row(r), block.data() + (r - r0) * stride, x0, x1);
      }
    });
}

// dst over `box` = scale * Y X src (or += with `add`).
template <int C>
void Separable(const Plane& src, const Op& ox, const Op& oy, const Box& box, float scale, bool add,
  Plane& dst, std::vector<float>& block)
{
  if (box.Empty())
  {
    return;
  }
  int r0, r1;
  Needs(oy, box.Y0, box.Y1, r0, r1);
  BlockX<C>(src, ox, r0, r1, box.X0, box.X1, block);
  const size_t stride = static_cast<size_t>(box.X1 - box.X0) * C;
  const int n = static_cast<int>(stride);
  vtkSMPTools::For(box.Y0, box.Y1, 8,
    [&](int begin, int end)
    {
      std::vector<float> row(stride);
      for (int j = begin; j < end; ++j)
      {
        RowY(oy, j, block.data(), r0, stride, n, row.data());
        float* __restrict d = dst.Row(j) + box.X0 * C;
        if (add)
        {
          for (int q = 0; q < n; ++q)
          {
            d[q] += scale * row[q];
          }
        }
        else if (scale == 1.0f)
        {
          std::copy(row.begin(), row.end(), d);
        }
        else
        {
          for (int q = 0; q < n; ++q)
          {
            d[q] = scale * row[q];
          }
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
};

// Pass 1: level 0 = threshold(bilinear(input)), one read of the input, fused per level-0 row.
template <typename T, int C>
BrightResult BrightPass(const vtkBloomFastChainParameters& p, const T* base, int width, int height,
  int nc, const Op& rx, const Op& ry, bool scan, Plane& level)
{
  const int w0 = level.W, h0 = level.H;
  std::vector<int> rowLo(h0), rowHi(h0);
  std::vector<char> special(h0, 0);
  const double ceiling = std::min(p.ClampLuminance, static_cast<double>(VTK_FLOAT_MAX));
  const bool sanitize = p.SanitizeNonFinite;
  const size_t inStride = static_cast<size_t>(width) * nc;
  vtkSMPTools::For(0, h0, 4,
    [&](int begin, int end)
    {
      std::vector<float> xrow(static_cast<size_t>(w0) * C), acc(static_cast<size_t>(w0) * C);
      for (int j = begin; j < end; ++j)
      {
        for (int k = 0; k < ry.Width; ++k)
        {
          const T* in = base + static_cast<size_t>(ry.First[j] + k) * inStride;
          for (int x = 0; x < w0; ++x)
          {
            const float* w = rx.W.data() + static_cast<size_t>(x) * rx.Width;
            const T* s = in + static_cast<size_t>(rx.First[x]) * nc;
            float a[C];
            for (int c = 0; c < C; ++c)
            {
              a[c] = w[0] * Load(s[c], sanitize);
            }
            for (int t = 1; t < rx.Width; ++t)
            {
              for (int c = 0; c < C; ++c)
              {
                a[c] += w[t] * Load(s[t * nc + c], sanitize);
              }
            }
            for (int c = 0; c < C; ++c)
            {
              xrow[x * C + c] = a[c];
            }
          }
          const float wy = ry.W[static_cast<size_t>(j) * ry.Width + k];
          if (k == 0)
          {
            for (size_t q = 0; q < xrow.size(); ++q)
            {
              acc[q] = wy * xrow[q];
            }
          }
          else
          {
            for (size_t q = 0; q < xrow.size(); ++q)
            {
              acc[q] += wy * xrow[q];
            }
          }
        }
        float* out = level.Row(j);
        int lo = w0, hi = 0;
        for (int x = 0; x < w0; ++x)
        {
          double colour[C];
          for (int c = 0; c < C; ++c)
          {
            colour[c] = acc[x * C + c];
          }
          vtkBloomMapNonFinite<C>(colour, ceiling);
          vtkBloomBrightPass<C>(colour, p.ThresholdMode, p.Threshold, p.Knee, p.ClampLuminance);
          bool nonzero = false;
          for (int c = 0; c < C; ++c)
          {
            out[x * C + c] = static_cast<float>(colour[c]);
            nonzero |= out[x * C + c] != 0.0f;
          }
          if (nonzero)
          {
            lo = std::min(lo, x);
            hi = x + 1;
          }
        }
        rowLo[j] = lo;
        rowHi[j] = hi;
        if (scan)
        {
          // Input rows [j H / h0, (j + 1) H / h0) belong to this row, so every row is scanned
          // once (for a 2:1 level they are the rows just read, still in cache).
          const int r0 = static_cast<int>(static_cast<long long>(j) * height / h0);
          const int r1 = static_cast<int>(static_cast<long long>(j + 1) * height / h0);
          bool any = false;
          for (int r = r0; r < r1; ++r)
          {
            const T* in = base + static_cast<size_t>(r) * inStride;
            for (size_t q = 0; q < inStride; ++q)
            {
              any |= Special(in[q]);
            }
          }
          special[j] = any;
        }
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
  return result;
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

// One output row: colour = keep * in + term, alpha copied (sanitized when asked).
template <typename T, int NC, int C>
void CompositeRow(const T* __restrict src, const float* __restrict term, T keep, bool sanitize,
  int n, T* __restrict dst)
{
  if (sanitize)
  {
    for (int x = 0; x < n; ++x)
    {
      for (int c = 0; c < NC; ++c)
      {
        const T v = Finite(src[x * NC + c]);
        dst[x * NC + c] =
          c < C ? Finite(static_cast<T>(keep * v + static_cast<T>(term[x * C + c]))) : v;
      }
    }
  }
  else
  {
    for (int x = 0; x < n; ++x)
    {
      for (int c = 0; c < NC; ++c)
      {
        const T v = src[x * NC + c];
        dst[x * NC + c] = c < C ? static_cast<T>(keep * v + static_cast<T>(term[x * C + c])) : v;
      }
    }
  }
}

// Pass 4: out = keep * in + (S t bloom + 0) over outExt, the bloom row interpolated per row.
template <typename T, int C>
void Composite(const vtkBloomFastChainParameters& p, const T* in, const int inExt[6], int nc,
  const std::vector<Source>& sources, const float st[3], T* out, const int outExt[6])
{
  const int inW = inExt[1] - inExt[0] + 1;
  const int outW = outExt[1] - outExt[0] + 1;
  const int x0 = outExt[0] - inExt[0];
  const T keep = static_cast<T>(p.CompositeMode == CompositeLerp ? 1.0 - p.Strength : 1.0);
  const bool sanitize = p.SanitizeNonFinite;
  // Full-resolution bloom columns and rows each source reaches.
  std::vector<Box> reach(sources.size());
  for (size_t i = 0; i < sources.size(); ++i)
  {
    reach[i] = ReachBox(sources[i].X, sources[i].Y, sources[i].Region);
  }
  vtkSMPTools::For(outExt[2], outExt[3] + 1, 4,
    [&](int begin, int end)
    {
      std::vector<float> bloom(static_cast<size_t>(inW) * C), yrow;
      std::vector<float> term(static_cast<size_t>(outW) * C), stRow(term.size());
      for (size_t q = 0; q < stRow.size(); ++q)
      {
        stRow[q] = st[q % C];
      }
      for (int y = begin; y < end; ++y)
      {
        const int j = y - inExt[2];
        std::fill(bloom.begin(), bloom.end(), 0.0f);
        for (size_t i = 0; i < sources.size(); ++i)
        {
          const Source& s = sources[i];
          const Box& r = reach[i];
          if (j < r.Y0 || j >= r.Y1 || r.Empty())
          {
            continue;
          }
          int c0, c1;
          Needs(s.X, r.X0, r.X1, c0, c1);
          const size_t stride = static_cast<size_t>(s.Level->W) * C;
          yrow.resize(static_cast<size_t>(c1 - c0) * C);
          RowY(s.Y, j, s.Level->Row(0) + c0 * C, 0, stride, (c1 - c0) * C, yrow.data());
          for (int x = r.X0; x < r.X1; ++x)
          {
            const float* w = s.X.W.data() + static_cast<size_t>(x) * s.X.Width;
            const float* v = yrow.data() + static_cast<size_t>(s.X.First[x] - c0) * C;
            for (int c = 0; c < C; ++c)
            {
              float a = w[0] * v[c];
              for (int t = 1; t < s.X.Width; ++t)
              {
                a += w[t] * v[t * C + c];
              }
              float& b = bloom[x * C + c];
              b = s.Scaled ? b + s.Weight * a : a;
            }
          }
        }
        // term = S t clamp(bloom) + 0 over the row (flat, vectorizable), then the composite.
        const float* b = bloom.data() + static_cast<size_t>(x0) * C;
        const int n = outW * C;
        for (int q = 0; q < n; ++q)
        {
          float bv = b[q];
          bv = bv == bv ? std::min(std::max(bv, -FloatMax), FloatMax) : 0.0f;
          term[q] = stRow[q] * bv + 0.0f;
        }
        const T* src = in + (static_cast<size_t>(j) * inW + x0) * nc;
        T* dst = out + static_cast<size_t>(y - outExt[2]) * outW * nc;
        switch (nc)
        {
          case 1:
            CompositeRow<T, 1, C>(src, term.data(), keep, sanitize, outW, dst);
            break;
          case 2:
            CompositeRow<T, 2, C>(src, term.data(), keep, sanitize, outW, dst);
            break;
          case 3:
            CompositeRow<T, 3, C>(src, term.data(), keep, sanitize, outW, dst);
            break;
          default:
            CompositeRow<T, 4, C>(src, term.data(), keep, sanitize, outW, dst);
            break;
        }
      }
    });
}
}

//------------------------------------------------------------------------------
struct vtkBloomFastChain::Internals
{
  std::vector<Plane> Levels;
  std::vector<float> Block;
  std::vector<float> Block2;
  vtkSmartPointer<vtkDataArray> Recycled;

  size_t Bytes() const
  {
    size_t n = (this->Block.capacity() + this->Block2.capacity()) * sizeof(float);
    for (const Plane& l : this->Levels)
    {
      n += l.D.capacity() * sizeof(float);
    }
    return n;
  }
};

//------------------------------------------------------------------------------
vtkBloomFastChain::vtkBloomFastChain()
  : Impl(new Internals)
{
}

//------------------------------------------------------------------------------
vtkBloomFastChain::~vtkBloomFastChain()
{
  delete this->Impl;
}

//------------------------------------------------------------------------------
void vtkBloomFastChain::ReleaseWorkspace()
{
  delete this->Impl;
  this->Impl = new Internals;
}

//------------------------------------------------------------------------------
bool vtkBloomFastChain::Supports(const vtkBloomFastChainParameters& p, vtkImageData* input)
{
  int ext[6];
  input->GetExtent(ext);
  return ext[4] == ext[5] && input->GetScalarType() == VTK_FLOAT &&
    !(p.KarisAverage && p.DownsampleKernel == vtkImagePyramidDown::JIMENEZ13);
}

namespace
{
template <typename T, int C>
void Run(const vtkBloomFastChainParameters& p, vtkImageData* input, const int outExt[6],
  vtkImageData* output, vtkBloomFastChainReport& report, vtkBloomFastChain::Internals& ws,
  const float st[3], bool disabled, vtkAlgorithm* progress);
}

//------------------------------------------------------------------------------
void vtkBloomFastChain::Execute(const vtkBloomFastChainParameters& p, vtkImageData* input,
  const int outExt[6], vtkImageData* output, vtkBloomFastChainReport& report,
  vtkAlgorithm* progress)
{
  report = vtkBloomFastChainReport();
  const int nc = input->GetNumberOfScalarComponents();
  const int colours = nc >= 3 ? 3 : 1;
  float st[3];
  double tint[3] = { p.Tint[0], p.Tint[1], p.Tint[2] };
  if (colours == 1)
  {
    tint[0] = vtkBloomKernels::LuminanceR * tint[0] + vtkBloomKernels::LuminanceG * tint[1] +
      vtkBloomKernels::LuminanceB * tint[2];
  }
  bool disabled = true;
  for (int c = 0; c < colours; ++c)
  {
    st[c] = static_cast<float>(p.Strength * tint[c]);
    disabled &= st[c] == 0.0f;
  }
  bool anyWeight = false;
  for (double w : p.LevelWeights)
  {
    anyWeight |= w != 0.0;
  }
  disabled = p.SkipDisabled && (disabled || !anyWeight || p.LevelSizes.empty());
  const bool isDouble = input->GetScalarType() == VTK_DOUBLE;
  if (colours == 3)
  {
    isDouble ? Run<double, 3>(p, input, outExt, output, report, *this->Impl, st, disabled, progress)
             : Run<float, 3>(p, input, outExt, output, report, *this->Impl, st, disabled, progress);
  }
  else
  {
    isDouble ? Run<double, 1>(p, input, outExt, output, report, *this->Impl, st, disabled, progress)
             : Run<float, 1>(p, input, outExt, output, report, *this->Impl, st, disabled, progress);
  }
  report.WorkspaceBytes = this->Impl->Bytes();
}

namespace
{
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
    levels[0].Resize(w0, h0, C);
    const vtkBloomChain& chain = *p.Chain;
    const Op rx =
      MakeOp(chain.SourceIsIdentity ? vtkBloomLinearOperator::Identity(width) : chain.Source.X);
    const Op ry =
      MakeOp(chain.SourceIsIdentity ? vtkBloomLinearOperator::Identity(height) : chain.Source.Y);
    const bool scan = p.SkipEmpty && keep == 1.0 && whole;
    const BrightResult bright = BrightPass<T, C>(p, in, width, height, nc, rx, ry, scan, levels[0]);
    report.SamplesProcessed += static_cast<long long>(w0) * h0;
    reportProgress(0.3);
    std::vector<Box> boxes(levelsBuilt);
    auto full = [&](int i) { return Box{ 0, levels[i].W, 0, levels[i].H }; };
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
        levels[i].Resize(outSize[0], outSize[1], C);
        std::fill(levels[i].D.begin(), levels[i].D.end(), 0.0f);
        const auto& terms = chain.Levels[i].Down;
        std::vector<Op> ox, oy;
        Box box;
        for (const auto& t : terms)
        {
          ox.push_back(MakeOp(t.X));
          oy.push_back(MakeOp(t.Y));
          box = Union(box, ReachBox(ox.back(), oy.back(), boxes[i - 1]));
        }
        boxes[i] = p.RestrictToBrightRegion ? box : full(i);
        for (size_t t = 0; t < terms.size(); ++t)
        {
          Separable<C>(levels[i - 1], ox[t], oy[t], boxes[i], static_cast<float>(terms[t].Weight),
            t > 0, levels[i], ws.Block);
        }
        report.SamplesProcessed += static_cast<long long>(boxes[i].X1 - boxes[i].X0) *
          (boxes[i].Y1 - boxes[i].Y0) * static_cast<long long>(terms.size());
      }

      reportProgress(0.4);

      // 3. Blur, fused with the upsample-accumulate (CASCADE) or in place (DIRECT).
      const bool cascade = p.AccumulateMode != AccumulateDirect;
      std::vector<Box> acc(levelsBuilt);
      for (int i = levelsBuilt - 1; i >= 0; --i)
      {
        Plane& level = levels[i];
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
        if (!cascade)
        {
          // DIRECT: blur level i in place; the composite weighs and sums the levels.
          if (w == 0.0f)
          {
            continue;
          }
          acc[i] = p.RestrictToBrightRegion ? blurBox : full(i);
          if (blurred)
          {
            Plane blurredLevel;
            blurredLevel.Resize(level.W, level.H, C);
            Separable<C>(level, bx, by, acc[i], 1.0f, false, blurredLevel, ws.Block);
            std::swap(level.D, blurredLevel.D);
            report.SamplesProcessed +=
              static_cast<long long>(acc[i].X1 - acc[i].X0) * (acc[i].Y1 - acc[i].Y0);
          }
          continue;
        }
        // CASCADE: acc_i = up(acc_{i+1}) + w_i blur(level_i), stored over level i.
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
        if (box.Empty())
        {
          level.Zero(boxes[i]); // acc_i is zero: clear what level i held
          continue;
        }
        const size_t stride = static_cast<size_t>(box.X1 - box.X0) * C;
        const int n = static_cast<int>(stride);
        int b0 = 0, b1 = 0, u0 = 0, u1 = 0;
        if (w != 0.0f)
        {
          if (blurred)
          {
            Needs(by, box.Y0, box.Y1, b0, b1);
            BlockX<C>(level, bx, b0, b1, box.X0, box.X1, ws.Block);
          }
          else
          {
            // Unblurred level: its own rows over the box.
            b0 = box.Y0;
            b1 = box.Y1;
            ws.Block.resize(static_cast<size_t>(b1 - b0) * stride);
            for (int r = b0; r < b1; ++r)
            {
              std::copy(level.Row(r) + box.X0 * C, level.Row(r) + box.X1 * C,
                ws.Block.data() + (r - b0) * stride);
            }
          }
        }
        if (up)
        {
          Needs(uy, box.Y0, box.Y1, u0, u1);
          BlockX<C>(levels[i + 1], ux, u0, u1, box.X0, box.X1, ws.Block2);
        }
        if (p.RestrictToBrightRegion)
        {
          // Level i was read into the blocks above; clear its samples outside acc_i's box.
          level.Zero(boxes[i]);
        }
        vtkSMPTools::For(box.Y0, box.Y1, 8,
          [&](int begin, int end)
          {
            std::vector<float> brow(stride), urow(stride);
            for (int j = begin; j < end; ++j)
            {
              float* __restrict d = level.Row(j) + box.X0 * C;
              if (w != 0.0f)
              {
                if (blurred)
                {
                  RowY(by, j, ws.Block.data(), b0, stride, n, brow.data());
                }
                else
                {
                  std::copy(ws.Block.data() + (j - b0) * stride,
                    ws.Block.data() + (j - b0 + 1) * stride, brow.data());
                }
              }
              if (up)
              {
                RowY(uy, j, ws.Block2.data(), u0, stride, n, urow.data());
                if (w != 0.0f)
                {
                  for (int q = 0; q < n; ++q)
                  {
                    d[q] = urow[q] + w * brow[q];
                  }
                }
                else
                {
                  std::copy(urow.begin(), urow.end(), d);
                }
              }
              else if (w == 1.0f)
              {
                std::copy(brow.begin(), brow.end(), d);
              }
              else
              {
                for (int q = 0; q < n; ++q)
                {
                  d[q] = w * brow[q];
                }
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
        s.Level = &levels[i];
        s.Weight = static_cast<float>(p.LevelWeights[i]);
        s.Scaled = scaled;
        if (!cascade)
        {
          s.X = MakeOp(chain.Levels[i].Full.X);
          s.Y = MakeOp(chain.Levels[i].Full.Y);
        }
        else
        {
          s.X =
            MakeOp(chain.FinalIsIdentity ? vtkBloomLinearOperator::Identity(width) : chain.Final.X);
          s.Y = MakeOp(
            chain.FinalIsIdentity ? vtkBloomLinearOperator::Identity(height) : chain.Final.Y);
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

  // 4. Composite (or pass the input through when the result is the input bit for bit).
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
  Composite<T, C>(p, in, inExt, nc, sources, st, static_cast<T*>(r->GetVoidPointer(0)), outExt);
}
}
