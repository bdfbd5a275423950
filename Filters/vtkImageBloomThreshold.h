// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkImageBloomThreshold
 * @brief   Bright-pass filter: keep what should glow, with a choice of knee.
 *
 * Let c be the colour (RGB for 3-4 components, the single value for 1-2 components), T the
 * Threshold, k = T * Knee the absolute knee width, L the Rec. 709 luminance
 * 0.2126 R + 0.7152 G + 0.0722 B (or the value itself) and B = max(R, G, B). Modes:
 *
 * - SMOOTHSTEP_KNEE (seed 000): c * smoothstep(T - k, T + k, L); with k = 0 it is c * [L >= T]
 *   (the seed's smoothstep(T, T, L) is undefined in WGSL and GLSL).
 * - QUADRATIC_KNEE (Jimenez 2014 / Unity): c * max(q, B - T) / max(B, 1e-5) with
 *   q = clamp(B - T + k, 0, 2k)^2 / (4k + 1e-5); the 1e-5 guard keeps k = 0 finite, where it
 *   becomes the hard knee c * max(B - T, 0) / B.
 * - HARD_LUMINANCE (seed 002): c if L > T (strictly), else 0.
 * - PER_CHANNEL (seed 003): max(c_i - T, 0) per channel.
 * - NONE (seed 001): c unchanged.
 * - EXCESS_KNEE (the default of vtkBloomParameters): c * e(B) / B, where e is the excess of B
 *   over T softened by a quadratic knee that starts at T and does not reach below it:
 *   e = 0 for B <= T, (B - T)^2 / (4k) for T < B < T + 2k, and B - T - k above (value and
 *   slope continuous at T + 2k); with k = 0 it is the excess max(B - T, 0) itself. A colour no
 *   channel of which exceeds T gives exactly 0, so at T = 1 display white and everything darker
 *   never glow: only light brighter than display white does, by how much brighter it is.
 *
 * Before the threshold, ClampLuminance guards against fireflies: a pixel whose luminance
 * exceeds it is scaled down to it (hue preserved). Every mode but NONE clamps its result to
 * >= 0, so negative input never emits light; NONE is an exact identity.
 *
 * Non-finite input: NaN and -Inf colours become 0 and +Inf becomes ClampLuminance (or the float
 * maximum) in every mode but NONE, so the bright pass never feeds NaN or Inf into a blur.
 *
 * Alpha (the 2nd of 2 or 4th of 4 components) passes through unchanged. Input must be float or
 * double with 1 to 4 components.
 */

#ifndef vtkImageBloomThreshold_h
#define vtkImageBloomThreshold_h

#include "vtkFiltersBloomModule.h" // For export macro
#include "vtkThreadedImageAlgorithm.h"

class VTKFILTERSBLOOM_EXPORT vtkImageBloomThreshold : public vtkThreadedImageAlgorithm
{
public:
  static vtkImageBloomThreshold* New();
  vtkTypeMacro(vtkImageBloomThreshold, vtkThreadedImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Modes
  {
    SMOOTHSTEP_KNEE = 0,
    QUADRATIC_KNEE = 1,
    HARD_LUMINANCE = 2,
    PER_CHANNEL = 3,
    NONE = 4,
    EXCESS_KNEE = 5
  };

  ///@{
  /// Threshold mode. Default SMOOTHSTEP_KNEE (vtkBloomParameters' default is EXCESS_KNEE).
  vtkSetClampMacro(Mode, int, SMOOTHSTEP_KNEE, EXCESS_KNEE);
  vtkGetMacro(Mode, int);
  void SetModeToSmoothstepKnee() { this->SetMode(SMOOTHSTEP_KNEE); }
  void SetModeToQuadraticKnee() { this->SetMode(QUADRATIC_KNEE); }
  void SetModeToHardLuminance() { this->SetMode(HARD_LUMINANCE); }
  void SetModeToPerChannel() { this->SetMode(PER_CHANNEL); }
  void SetModeToNone() { this->SetMode(NONE); }
  void SetModeToExcessKnee() { this->SetMode(EXCESS_KNEE); }
  const char* GetModeAsString() { return vtkImageBloomThreshold::GetModeName(this->Mode); }
  static const char* GetModeName(int mode);
  ///@}

  ///@{
  /// Threshold T, in the image's linear units. Default 1.
  vtkSetMacro(Threshold, double);
  vtkGetMacro(Threshold, double);
  ///@}

  ///@{
  /// Knee width relative to the threshold (k = T * Knee), in [0, 1]. Default 0.5.
  vtkSetClampMacro(Knee, double, 0.0, 1.0);
  vtkGetMacro(Knee, double);
  ///@}

  ///@{
  /// Firefly guard: the largest luminance let through. Default VTK_FLOAT_MAX (off).
  vtkSetClampMacro(ClampLuminance, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(ClampLuminance, double);
  ///@}

  /**
   * The bright-pass of one pixel: `colour` holds `n` colour values (1 or 3) and is replaced by
   * its bright part. Shared with vtkImageBloom so the two can never disagree.
   */
  static void BrightPass(
    double* colour, int n, int mode, double threshold, double knee, double clampLuminance);

protected:
  vtkImageBloomThreshold();
  ~vtkImageBloomThreshold() override;

  /// Asks for exactly the extent it computes (its piece under MPI).
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  void ThreadedRequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector, vtkImageData*** inData, vtkImageData** outData,
    int outExt[6], int threadId) override;

  int Mode;
  double Threshold;
  double Knee;
  double ClampLuminance;

private:
  vtkImageBloomThreshold(const vtkImageBloomThreshold&) = delete;
  void operator=(const vtkImageBloomThreshold&) = delete;
};

#endif
