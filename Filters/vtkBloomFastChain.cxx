// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkBloomFastChain.h"

#include "vtkAlgorithm.h"
#include "vtkBloomBrightPass.h"
#include "vtkBloomChain.h"
#include "vtkBloomFFTConvolution.h"
#include "vtkBloomImageOps.h"
#include "vtkBloomKernels.h"
#include "vtkBloomLinearOperator.h"
#include "vtkBloomParameters.h"
#include "vtkBloomStatisticsRows.h"
#include "vtkDataArray.h"
#include "vtkImageBloomThreshold.h"
#include "vtkImageData.h"
#include "vtkImagePyramidDown.h"
#include "vtkPointData.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <type_traits>

#if defined(__SSE2__)
#include <emmintrin.h> // _mm_stream_ps, _mm_sfence
#endif

// Per-function AVX2 code generation (GCC on x86); other compilers build the baseline only.
#if defined(__GNUC__) && !defined(__clang__) && (defined(__x86_64__) || defined(__i386__))
#define VTKBLOOM_FAST_CHAIN_AVX2 1
#else
#define VTKBLOOM_FAST_CHAIN_AVX2 0
#endif

namespace
{
const int AccumulateDirect = vtkBloomParameters::DIRECT;
const int CompositeLerp = vtkBloomParameters::LERP;
const float FloatMax = std::numeric_limits<float>::max();

// A sample sanitized: NaN 0, +-Inf the finite extremes of T.
template <typename T>
inline T Finite(T v)
{
  const T m = std::numeric_limits<T>::max();
  return v == v ? std::min(std::max(v, -m), m) : T(0);
}

// Level samples saturate at +-FLT_MAX: a float32 sum that overflows stays the largest float
// instead of becoming Inf (and then NaN where a zero weight of a band meets it).
inline float Saturated(float v)
{
  return v > FloatMax ? FloatMax : (v < -FloatMax ? -FloatMax : v);
}

inline void Saturate(float* __restrict v, size_t n)
{
  for (size_t q = 0; q < n; ++q)
  {
    v[q] = Saturated(v[q]);
  }
}

// d[q] = Saturated(a[q] + s b[q]) (Add) or Saturated(s b[q]) over n values, in one pass; a may
// be d. With s = 1 the product is b[q] itself, bit for bit.
template <bool Add>
inline void SumSaturated(float* d, const float* a, float s, const float* __restrict b, int n)
{
  for (int q = 0; q < n; ++q)
  {
    d[q] = Saturated(Add ? a[q] + s * b[q] : s * b[q]);
  }
}

// Writes of a frame at least this large bypass the cache (see StreamCopy).
constexpr size_t StreamingBytes = size_t(16) << 20;

// dst[0, n) = src[0, n), with non-temporal stores where the target has them: a frame larger
// than the cache is written without first being read into it (a plain store reads each line
// before writing it), which saves a third of the traffic of a copy. Call StoreFence() before
// other threads may read dst.
inline void StreamCopy(float* __restrict dst, const float* __restrict src, size_t n)
{
  size_t i = 0;
#if defined(__SSE2__)
  const size_t head = ((16 - (reinterpret_cast<uintptr_t>(dst) & 15)) & 15) / sizeof(float);
  if (reinterpret_cast<uintptr_t>(dst) % sizeof(float) == 0 && head < n)
  {
    for (; i < head; ++i)
    {
      dst[i] = src[i];
    }
    for (; i + 4 <= n; i += 4)
    {
      _mm_stream_ps(dst + i, _mm_loadu_ps(src + i));
    }
  }
#endif
  for (; i < n; ++i)
  {
    dst[i] = src[i];
  }
}

inline void StoreFence()
{
#if defined(__SSE2__)
  _mm_sfence();
#endif
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
  // Outputs [PerLo, PerHi) repeat with period Period (1 or 2) moving Stride inputs: a resample
  // whose weights can be held in registers.
  int PerLo = 0;
  int PerHi = 0;
  int Period = 0;
  int Stride = 0;
};

Op MakeOp(const vtkBloomLinearOperator& d)
{
  Op o;
  o.In = d.InputSize;
  o.Out = d.OutputSize;
  o.Width = d.Width;
  o.First = d.First;
  o.W.assign(d.Weights.begin(), d.Weights.end());
  // The flat x loop reads input j + ToeShift for output j: a period-1 run of stride 1.
  const vtkBloomLinearOperator::InvariantRange range = d.FindInvariantRange(1, 1);
  if (range.Begin < range.End && range.Stride == 1)
  {
    o.ToeLo = range.Begin;
    o.ToeHi = range.End;
    o.ToeShift = o.First[range.Begin] - range.Begin;
    return o;
  }
  for (int period : { 1, 2 })
  {
    const vtkBloomLinearOperator::InvariantRange r = d.FindInvariantRange(period, 1);
    if (r.Begin < r.End)
    {
      o.PerLo = r.Begin;
      o.PerHi = r.End;
      o.Period = r.Period;
      o.Stride = r.Stride;
      break;
    }
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

// An interval map (Reach or Needs) applied to each axis of a box; an empty box stays empty.
template <typename Map>
Box PerAxis(Map map, const Op& ox, const Op& oy, const Box& box)
{
  Box out;
  if (!box.Empty())
  {
    map(ox, box.X0, box.X1, out.X0, out.X1);
    map(oy, box.Y0, box.Y1, out.Y0, out.Y1);
  }
  return out;
}

Box ReachBox(const Op& ox, const Op& oy, const Box& in)
{
  return PerAxis(Reach, ox, oy, in);
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

// The samples that the outputs in `box` read.
Box NeedsBox(const Op& ox, const Op& oy, const Box& box)
{
  return PerAxis(Needs, ox, oy, box);
}

// The samples that the outputs reaching from `region` read: what must be defined (zero where
// nothing was computed) for a separable operator to be applied over its reach.
Box ReadBox(const Op& ox, const Op& oy, const Box& region)
{
  return NeedsBox(ox, oy, ReachBox(ox, oy, region));
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
  // Zeroes the samples of `outer` outside `inner`.
  void ZeroAround(const Box& outer, const Box& inner)
  {
    for (int y = outer.Y0; y < outer.Y1; ++y)
    {
      float* row = this->Row(y);
      if (inner.Empty() || y < inner.Y0 || y >= inner.Y1)
      {
        std::fill(row + outer.X0 * this->C, row + outer.X1 * this->C, 0.0f);
        continue;
      }
      std::fill(row + outer.X0 * this->C, row + std::max(outer.X0, inner.X0) * this->C, 0.0f);
      std::fill(row + std::min(outer.X1, inner.X1) * this->C, row + outer.X1 * this->C, 0.0f);
    }
  }
};
}

//------------------------------------------------------------------------------
void vtkBloomFastChainParameters::Set(
  vtkBloomParameters* bloom, const vtkBloomChain* chain, int width, int height)
{
  this->ThresholdMode = bloom->GetThresholdMode();
  this->Threshold = bloom->GetThreshold();
  this->Knee = bloom->GetKnee();
  this->ClampLuminance = bloom->GetClampLuminance();
  this->Chain = chain;
  this->LevelSizes = bloom->ComputeLevelSizes(width, height);
  this->LevelWeights.clear();
  for (size_t i = 0; i < this->LevelSizes.size(); ++i)
  {
    this->LevelWeights.push_back(bloom->GetEffectiveLevelWeight(static_cast<int>(i), height));
  }
  this->DownsampleKernel = bloom->GetDownsampleKernel();
  this->KarisAverage = bloom->GetKarisAverage();
  this->BlurIterations = bloom->GetBlurIterations();
  this->AccumulateMode = bloom->GetAccumulateMode();
  this->CompositeMode = bloom->GetCompositeMode();
  this->Strength = bloom->GetStrength();
  bloom->GetTint(this->Tint);
  this->SanitizeNonFinite = bloom->GetSanitizeNonFinite();
  this->SkipEmpty = bloom->GetSkipEmptyBloom();
  this->TrimPyramid = bloom->GetTrimPyramid();
  this->RestrictToBrightRegion = bloom->GetRestrictToBrightRegion();
  this->SkipDisabled = bloom->GetSkipDisabledEffects();
  this->ConvolutionMode = bloom->GetConvolutionMode();
}

//------------------------------------------------------------------------------
struct vtkBloomFastChain::Internals
{
  std::vector<Plane> Levels;
  std::vector<Plane> Acc; // blurred or accumulated levels
  vtkSmartPointer<vtkDataArray> Recycled;

  // The level blurs that run through the FFT (null where direct), for the chain built at
  // FFTTime with FFTMode.
  std::vector<std::array<std::unique_ptr<vtkBloomFFTConvolution>, 2>> BlurFFT;
  const vtkBloomChain* FFTChain = nullptr;
  vtkMTimeType FFTTime = 0;
  int FFTMode = -1;

  /// Rebuild BlurFFT when the chain or the mode changed.
  void UpdateBlurFFT(const vtkBloomFastChainParameters& p);

  size_t Bytes() const
  {
    size_t n = 0;
    for (const auto* planes : { &this->Levels, &this->Acc })
    {
      for (const Plane& l : *planes)
      {
        n += l.D.capacity() * sizeof(float);
      }
    }
    return n;
  }
};

//------------------------------------------------------------------------------
void vtkBloomFastChain::Internals::UpdateBlurFFT(const vtkBloomFastChainParameters& p)
{
  if (this->FFTChain == p.Chain && this->FFTTime == p.ChainTime &&
    this->FFTMode == p.ConvolutionMode && this->BlurFFT.size() == p.Chain->Levels.size())
  {
    return;
  }
  this->FFTChain = p.Chain;
  this->FFTTime = p.ChainTime;
  this->FFTMode = p.ConvolutionMode;
  this->BlurFFT.clear();
  this->BlurFFT.resize(p.Chain->Levels.size());
  if (p.ConvolutionMode == vtkBloomParameters::CONVOLUTION_DIRECT)
  {
    return;
  }
  for (size_t i = 0; i < p.Chain->Levels.size(); ++i)
  {
    const vtkBloomChain::Level& level = p.Chain->Levels[i];
    if (!level.Blur)
    {
      continue;
    }
    const vtkBloomLinearOperator* ops[2] = { &level.BlurPass.X, &level.BlurPass.Y };
    for (int a = 0; a < 2; ++a)
    {
      auto fft = std::make_unique<vtkBloomFFTConvolution>();
      // The level blurs clamp (seed behaviour); the correction takes what padding cannot.
      if (!fft->Build(*ops[a], vtkBloomLinearOperator::BORDER_CLAMP, true))
      {
        continue;
      }
      if (p.ConvolutionMode == vtkBloomParameters::CONVOLUTION_FFT ||
        fft->Cost() <
          vtkBloomFFTConvolution::DirectCost(*ops[a]) / vtkBloomFastChain::DirectSpeedup)
      {
        this->BlurFFT[i][a] = std::move(fft);
      }
    }
  }
}

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

// The passes, compiled for the baseline instruction set and, where the compiler can target it
// per function, once more for AVX2 (without FMA, which would round differently), each copy in
// a namespace of its own so that no function of one can stand in for the other's. Both copies
// compute every sample with the same operations in the same order, so they give the same bits;
// Execute picks one at run time.
namespace
{
namespace baseline
{
#define VTKBLOOM_VECTOR_BYTES 16
#include "vtkBloomFastChainPasses.txx"
#undef VTKBLOOM_VECTOR_BYTES
}
}

#if VTKBLOOM_FAST_CHAIN_AVX2
#pragma GCC push_options
#pragma GCC target("avx2")
namespace
{
namespace avx2
{
#define VTKBLOOM_VECTOR_BYTES 32
#include "vtkBloomFastChainPasses.txx"
#undef VTKBLOOM_VECTOR_BYTES
}
}
#pragma GCC pop_options
#endif

//------------------------------------------------------------------------------
bool vtkBloomFastChain::AVX2Available()
{
#if VTKBLOOM_FAST_CHAIN_AVX2
  static const bool available = __builtin_cpu_supports("avx2");
  return available;
#else
  return false;
#endif
}

namespace
{
using RunFunction = void (*)(const vtkBloomFastChainParameters&, vtkImageData*, const int*,
  vtkImageData*, vtkBloomFastChainReport&, vtkBloomFastChain::Internals&, const float*, bool,
  vtkAlgorithm*);

template <typename T, int C>
RunFunction SelectRun(bool avx2)
{
#if VTKBLOOM_FAST_CHAIN_AVX2
  if (avx2)
  {
    return &avx2::Run<T, C>;
  }
#else
  (void)avx2;
#endif
  return &baseline::Run<T, C>;
}
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
  const bool avx2 = p.UseAVX2 && vtkBloomFastChain::AVX2Available();
  RunFunction run = colours == 3
    ? (isDouble ? SelectRun<double, 3>(avx2) : SelectRun<float, 3>(avx2))
    : (isDouble ? SelectRun<double, 1>(avx2) : SelectRun<float, 1>(avx2));
  run(p, input, outExt, output, report, *this->Impl, st, disabled, progress);
  report.UsedAVX2 = avx2;
  report.WorkspaceBytes = this->Impl->Bytes();
}
