// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file    vtkBloomBrightPass.h
 * @brief   Internal: the one CPU definition of the bloom bright pass, inline for N colours.
 *
 * vtkImageBloomThreshold::BrightPass, the reference and the fused chains of vtkImageBloom and
 * the statistics all call these; Rendering/glsl/vtkBloomPassFS.glsl mirrors them in GLSL.
 * The mode values are vtkImageBloomThreshold's. N is 1 (the value itself is the luminance) or
 * 3 (Rec. 709 luminance).
 */

#ifndef vtkBloomBrightPass_h
#define vtkBloomBrightPass_h

#include "vtkBloomKernels.h"
#include "vtkImageBloomThreshold.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>

/**
 * Calls f(std::integral_constant<int, Mode>()) for a vtkImageBloomThreshold mode (an unknown
 * mode as NONE), so that a loop templated on the mode runs the formulas below with their
 * switch folded away.
 */
template <typename F>
inline decltype(auto) vtkBloomWithThresholdMode(int mode, F&& f)
{
  using T = vtkImageBloomThreshold;
  switch (mode)
  {
    case T::SMOOTHSTEP_KNEE:
      return f(std::integral_constant<int, T::SMOOTHSTEP_KNEE>());
    case T::QUADRATIC_KNEE:
      return f(std::integral_constant<int, T::QUADRATIC_KNEE>());
    case T::HARD_LUMINANCE:
      return f(std::integral_constant<int, T::HARD_LUMINANCE>());
    case T::PER_CHANNEL:
      return f(std::integral_constant<int, T::PER_CHANNEL>());
    case T::EXCESS_KNEE:
      return f(std::integral_constant<int, T::EXCESS_KNEE>());
    default:
      return f(std::integral_constant<int, T::NONE>());
  }
}

/// NaN -> 0, -Inf -> 0, +Inf -> ceiling: what the bloom chain feeds its pyramid in every mode.
template <int N, typename Real>
inline void vtkBloomMapNonFinite(Real* colour, double ceiling)
{
  for (int c = 0; c < N; ++c)
  {
    if (std::isnan(colour[c]))
    {
      colour[c] = Real(0);
    }
    else if (std::isinf(colour[c]))
    {
      colour[c] = colour[c] > Real(0) ? static_cast<Real>(ceiling) : Real(0);
    }
  }
}

///@{
/**
 * std::max and std::min written as selects, as the standard defines them (the first argument
 * unless the comparison says otherwise), so that they also take GCC vector types lane by lane.
 */
template <typename Real>
inline Real vtkBloomMax(Real a, Real b)
{
  return a < b ? b : a;
}
template <typename Real>
inline Real vtkBloomMin(Real a, Real b)
{
  return b < a ? b : a;
}
///@}

/**
 * The factor by which vtkBloomBrightPass scales a finite colour of luminance `lum` and largest
 * value `brightness` that the firefly guard left as it is, for the modes that scale the colour
 * (SMOOTHSTEP_KNEE, QUADRATIC_KNEE, HARD_LUMINANCE, EXCESS_KNEE; 1 for the others). It is never
 * negative, so the bright pass keeps a value > 0 exactly when brightness * factor > 0.
 * Real is float or double, or a GCC vector of them (every lane computed as a scalar would be:
 * the formulas are written with selects, which for a scalar evaluate only the branch taken).
 */
template <typename Real, typename Scalar>
inline Real vtkBloomBrightPassFactor(Real lum, Real brightness, int mode, Scalar t0, Scalar k)
{
  const Real zero = Real{}, one = zero + Scalar(1);
  switch (mode)
  {
    case vtkImageBloomThreshold::SMOOTHSTEP_KNEE:
      if (k > Scalar(0))
      {
        const Scalar edge0 = t0 - k, edge1 = t0 + k;
        const Real t = vtkBloomMin(vtkBloomMax((lum - edge0) / (edge1 - edge0), zero), one);
        return t * t * (Scalar(3) - Scalar(2) * t);
      }
      // knee 0 is the step lum >= T; smoothstep(T, T, x) is undefined.
      return lum >= t0 ? one : zero;
    case vtkImageBloomThreshold::QUADRATIC_KNEE:
    {
      Real q = vtkBloomMin(vtkBloomMax(brightness - t0 + k, zero), zero + Scalar(2) * k);
      q = q * q / (Scalar(4) * k + Scalar(1e-5));
      return vtkBloomMax(q, brightness - t0) / vtkBloomMax(brightness, zero + Scalar(1e-5));
    }
    case vtkImageBloomThreshold::HARD_LUMINANCE:
      return lum > t0 ? one : zero;
    case vtkImageBloomThreshold::EXCESS_KNEE:
    {
      // The excess over T, its first 2k softened by a quadratic that starts at T.
      const Real excess = brightness - t0;
      const Real soft = excess > zero
        ? (excess < Scalar(2) * k ? excess * excess / (Scalar(4) * k) : excess - k)
        : zero;
      return brightness > zero ? soft / brightness : zero;
    }
    default:
      return one;
  }
}

/**
 * vtkImageBloomThreshold::BrightPass for N colour values (see that class for the formulas), in
 * the arithmetic of Real: double for the reference chain and the filters, float for the fused
 * float32 chain of vtkImageBloom's FAST mode.
 */
template <int N, typename Real>
inline void vtkBloomBrightPass(
  Real* colour, int mode, double threshold, double knee, double clampLuminance)
{
  if (mode == vtkImageBloomThreshold::NONE)
  {
    return;
  }
  vtkBloomMapNonFinite<N>(colour, std::min(clampLuminance, static_cast<double>(VTK_FLOAT_MAX)));
  auto luminance = [colour]()
  {
    return N == 3 ? static_cast<Real>(vtkBloomKernels::LuminanceR) * colour[0] +
        static_cast<Real>(vtkBloomKernels::LuminanceG) * colour[1] +
        static_cast<Real>(vtkBloomKernels::LuminanceB) * colour[2]
                  : colour[0];
  };
  const Real zero(0);
  const Real clampLum = static_cast<Real>(clampLuminance);
  const Real t0 = static_cast<Real>(threshold);

  // Firefly guard: scale the colour so its luminance does not exceed the clamp.
  Real lum = luminance();
  if (lum > clampLum)
  {
    const Real scale = clampLum / lum;
    for (int c = 0; c < N; ++c)
    {
      colour[c] *= scale;
    }
    lum = luminance();
  }

  if (mode == vtkImageBloomThreshold::PER_CHANNEL)
  {
    for (int c = 0; c < N; ++c)
    {
      colour[c] = std::max(colour[c] - t0, zero);
    }
    return;
  }
  Real brightness = colour[0];
  for (int c = 1; c < N; ++c)
  {
    brightness = std::max(brightness, colour[c]);
  }
  const Real factor = vtkBloomBrightPassFactor<Real, Real>(
    lum, brightness, mode, t0, static_cast<Real>(threshold * knee));
  for (int c = 0; c < N; ++c)
  {
    colour[c] = std::max(colour[c] * factor, zero);
  }
}

/**
 * Whether vtkBloomBrightPass keeps a value > 0 of `colour` (the bright pixels that
 * vtkImageBloom's statistics count).
 */
template <int N, typename Real>
inline bool vtkBloomBrightPassKeepsAny(
  const Real* colour, int mode, double threshold, double knee, double clampLuminance)
{
  Real kept[N];
  std::copy(colour, colour + N, kept);
  vtkBloomBrightPass<N>(kept, mode, threshold, knee, clampLuminance);
  bool any = false;
  for (int c = 0; c < N; ++c)
  {
    any = any || kept[c] > Real(0);
  }
  return any;
}

/// The scalar type of Real: Real itself, or the lanes' type of a GCC vector.
template <typename Real, typename = void>
struct vtkBloomScalarOf
{
  using type = Real;
};
template <typename Real>
struct vtkBloomScalarOf<Real, std::enable_if_t<!std::is_arithmetic<Real>::value>>
{
  using type = std::decay_t<decltype(std::declval<Real>()[0])>;
};

/**
 * True when vtkBloomBrightPass certainly gives zero for every finite colour whose luminance is at
 * most `luminance` and whose largest value is at most `brightness` (the comparisons are the
 * formula's own, evaluated as it evaluates them, and monotone). False when that cannot be
 * decided: a luminance above the clamp (the firefly guard rescales first) or NaN, mode NONE, or
 * a colour the mode keeps. For a GCC vector Real the answer is a lane mask (what Real's
 * comparisons give), each lane the scalar answer for its own values.
 */
template <typename Real>
inline auto vtkBloomBrightPassIsZeroBelow(
  Real luminance, Real brightness, int mode, double threshold, double knee, double clampLuminance)
{
  using Scalar = typename vtkBloomScalarOf<Real>::type;
  using Mask = decltype(luminance < luminance);
  const Scalar t0 = static_cast<Scalar>(threshold);
  const Scalar k = static_cast<Scalar>(threshold * knee);
  const Scalar zero(0);
  Mask below{}; // false: undecided
  switch (mode)
  {
    case vtkImageBloomThreshold::SMOOTHSTEP_KNEE:
      // smoothstep 0, or the step lum >= T
      below = k > zero ? Mask(luminance <= t0 - k) : Mask(luminance < t0);
      break;
    case vtkImageBloomThreshold::HARD_LUMINANCE:
      below = luminance <= t0;
      break;
    case vtkImageBloomThreshold::QUADRATIC_KNEE:
      // Both terms of the factor <= 0, evaluated as the formula evaluates them.
      if (k >= zero)
      {
        below = Mask((brightness - t0 + k <= zero) & (brightness - t0 <= zero));
      }
      break;
    case vtkImageBloomThreshold::PER_CHANNEL:
    case vtkImageBloomThreshold::EXCESS_KNEE:
      below = brightness <= t0;
      break;
    default:
      break;
  }
  return Mask(below & (luminance <= static_cast<Scalar>(clampLuminance)));
}

/**
 * True when vtkBloomBrightPass<N, Real> certainly gives zero for `colour` (it may answer false
 * for some colours that do give zero): every value finite and the measure the mode compares
 * below its zero edge. The fused chain uses it to skip the full formula for dark samples.
 */
template <int N, typename Real>
inline bool vtkBloomBrightPassIsZero(
  const Real* colour, int mode, double threshold, double knee, double clampLuminance)
{
  const Real m = std::numeric_limits<Real>::max();
  bool finite = true;
  Real brightness = colour[0];
  for (int c = 0; c < N; ++c)
  {
    finite &= colour[c] >= -m && colour[c] <= m;
    brightness = std::max(brightness, colour[c]);
  }
  // Non-finite colours are mapped first: not decided here.
  if (!finite)
  {
    return false;
  }
  const Real lum = N == 3 ? static_cast<Real>(vtkBloomKernels::LuminanceR) * colour[0] +
      static_cast<Real>(vtkBloomKernels::LuminanceG) * colour[1] +
      static_cast<Real>(vtkBloomKernels::LuminanceB) * colour[2]
                          : colour[0];
  return vtkBloomBrightPassIsZeroBelow(lum, brightness, mode, threshold, knee, clampLuminance);
}

#endif
// VTK-HeaderTest-Exclude: vtkBloomBrightPass.h
