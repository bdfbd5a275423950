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

/// NaN -> 0, -Inf -> 0, +Inf -> ceiling: what the bloom chain feeds its pyramid in every mode.
template <int N>
inline void vtkBloomMapNonFinite(double* colour, double ceiling)
{
  for (int c = 0; c < N; ++c)
  {
    if (std::isnan(colour[c]))
    {
      colour[c] = 0.0;
    }
    else if (std::isinf(colour[c]))
    {
      colour[c] = colour[c] > 0.0 ? ceiling : 0.0;
    }
  }
}

/// vtkImageBloomThreshold::BrightPass for N colour values (see that class for the formulas).
template <int N>
inline void vtkBloomBrightPass(
  double* colour, int mode, double threshold, double knee, double clampLuminance)
{
  if (mode == vtkImageBloomThreshold::NONE)
  {
    return;
  }
  vtkBloomMapNonFinite<N>(colour, std::min(clampLuminance, static_cast<double>(VTK_FLOAT_MAX)));
  auto luminance = [colour]()
  {
    return N == 3 ? vtkBloomKernels::LuminanceR * colour[0] +
        vtkBloomKernels::LuminanceG * colour[1] + vtkBloomKernels::LuminanceB * colour[2]
                  : colour[0];
  };

  // Firefly guard: scale the colour so its luminance does not exceed the clamp.
  double lum = luminance();
  if (lum > clampLuminance)
  {
    const double scale = clampLuminance / lum;
    for (int c = 0; c < N; ++c)
    {
      colour[c] *= scale;
    }
    lum = luminance();
  }

  const double k = threshold * knee;
  double factor = 1.0;
  switch (mode)
  {
    case vtkImageBloomThreshold::SMOOTHSTEP_KNEE:
      if (k > 0.0)
      {
        const double edge0 = threshold - k, edge1 = threshold + k;
        const double t = std::min(std::max((lum - edge0) / (edge1 - edge0), 0.0), 1.0);
        factor = t * t * (3.0 - 2.0 * t);
      }
      else
      {
        // knee 0 is the step lum >= T; smoothstep(T, T, x) is undefined.
        factor = lum >= threshold ? 1.0 : 0.0;
      }
      break;
    case vtkImageBloomThreshold::QUADRATIC_KNEE:
    {
      double brightness = colour[0];
      for (int c = 1; c < N; ++c)
      {
        brightness = std::max(brightness, colour[c]);
      }
      double q = std::min(std::max(brightness - threshold + k, 0.0), 2.0 * k);
      q = q * q / (4.0 * k + 1e-5);
      factor = std::max(q, brightness - threshold) / std::max(brightness, 1e-5);
      break;
    }
    case vtkImageBloomThreshold::HARD_LUMINANCE:
      factor = lum > threshold ? 1.0 : 0.0;
      break;
    case vtkImageBloomThreshold::PER_CHANNEL:
      for (int c = 0; c < N; ++c)
      {
        colour[c] = std::max(colour[c] - threshold, 0.0);
      }
      return;
    default:
      break;
  }
  for (int c = 0; c < N; ++c)
  {
    colour[c] = std::max(colour[c] * factor, 0.0);
  }
}

#endif
// VTK-HeaderTest-Exclude: vtkBloomBrightPass.h
