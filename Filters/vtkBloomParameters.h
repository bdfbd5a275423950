// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkBloomParameters
 * @brief   The parameters of one HDR bloom, held once for the filter, the render pass, the
 *          command line and ParaView.
 *
 * A bloom is defined by these values alone; vtkImageBloom (on the CPU) and vtkBloomPass (on the
 * GPU) evaluate the same definition. Both hold a vtkBloomParameters (GetParameters()), and a
 * filter and a pass can share one: `pass->SetParameters(filter->GetParameters())`. Presets
 * are defined and named here, nowhere else.
 *
 * With I the input colour (RGB, or the single value of 1-2 component images):
 *
 * 1. Bright pass. B_s = threshold(bilinear(I) at level s), where s = StartLevel and level k has
 *    size max(1, floor(n / 2)) applied k times per axis (level 0 is the input itself). The
 *    fetch comes first and the threshold second, as a fragment shader does it. The threshold
 *    is vtkImageBloomThreshold::BrightPass with ThresholdMode, Threshold, Knee and
 *    ClampLuminance.
 * 2. Pyramid. B_{k+1} = down(B_k) with DownsampleKernel (see vtkImagePyramidDown), taken
 *    before any blur, for NumberOfLevels levels. KarisAverage applies to the first downsample
 *    only. With LimitLevelsToImageSize on, levels deeper than floor(log2(max(W, H))) are
 *    dropped, as a hardware mip chain ends there (when none is left the bloom is black);
 *    otherwise 1x1 levels repeat.
 * 3. Blur. Each level is blurred BlurIterations times, horizontally then vertically, by a
 *    symmetric kernel whose taps are BlurTapSpacing level pixels apart (fractional spacing means
 *    bilinear fetches), clamped at the edges. The kernel is a Gaussian (BLUR_GAUSSIAN:
 *    BlurStandardDeviation in level pixels, BlurRadius taps, BlurGaussianKind) or a given half
 *    kernel (BLUR_CUSTOM: SetBlurHalfKernel). Levels whose weight is 0 are not blurred.
 * 4. Accumulate, with w_i = GetLevelWeight(i) (i counts from the first level):
 *    - CASCADE: A_last = w_last Bb_last, A_i = up(A_{i+1}) + w_i Bb_i, with UpsampleKernel
 *      TENT or BILINEAR (see vtkImagePyramidUp); the bloom is bilinear(A_first) at full size.
 *    - DIRECT: the bloom is sum_i w_i bilinear(Bb_i) at full size.
 * 5. Composite, with S = Strength and t = Tint:
 *    - ADDITIVE: out = I + S t bloom.
 *    - LERP: out = (1 - S) I + S t bloom (energy-conserving when the weights sum to 1).
 *    Alpha is copied from the input unchanged.
 *
 * PSF mode (BloomMode PSF) replaces steps 2 to 4 by one convolution with a point-spread
 * function, as Unreal's convolution bloom and Blender's glare do: bloom = PSF * B_0, where B_0 is
 * the bright pass at full resolution (StartLevel, the pyramid, blur and accumulation parameters
 * are not used). The PSF (PSFType) is an Airy diffraction pattern (AiryRadius: the first dark
 * ring's radius in pixels at the green wavelength; each colour channel's pattern is scaled by
 * its wavelength over the green one, Wavelengths in nm), a sum of Gaussians
 * (SetPSFGaussians) or a measured PSF image (SetPSFImage: odd square size, centred; one
 * component for all channels, or one per channel). Each channel's PSF is truncated at
 * PSFRadius (automatic by default: 12 first-ring radii of the reddest channel for Airy, 4 of the
 * widest sigma for Gaussians) and normalized to sum 1. What leaves the image is folded back in
 * by half-sample reflection (PSFBorderMode REFLECT, the default: energy-conserving) or dropped
 * (ZERO). vtkImageBloom runs PSF mode on the CPU, vtkBloomPass on the GPU (an FFT in compute
 * shaders: OpenGL 4.3).
 *
 * A wide PSF may be split (PSFTailScale f > 1, as Unreal's convolution bloom adds a
 * full-resolution centre to a low-resolution convolution): each PSF k = k w + k (1 - w), w = 1
 * within PSFCoreRadius rc / 2 of the centre, falling as a raised cosine to 0 at rc. The core k w
 * is convolved at full resolution; the tail k (1 - w) on a grid f times coarser: the bright pass
 * is spread onto the grid's nodes (the transpose of bilinear interpolation: the sum and the
 * centroid of every pixel kept), convolved with the tail sampled every f pixels (less a sixth of
 * its Laplacian, which undoes the two interpolations' spread, and scaled to the tail's share),
 * and interpolated back bilinearly. f = 1 (default) is the exact convolution; f = 4 with the
 * automatic core (rc = 16) costs a sixteenth of a frame-wide PSF's transforms at an error of
 * about 1e-3 relative L2 (docs/wide-kernels.md measures it per PSF).
 *
 * Work-skipping options (SkipEmptyBloom, SkipDisabledEffects, TrimPyramid,
 * RestrictToBrightRegion) change what is computed, never the result: each is exact.
 *
 * Presets (SetPreset) reproduce the seed systems exactly as ../shared/seeds/PRESETS.md reads
 * them, with the seeds' known defects fixed:
 * - "webgpu-market" (seed 000): SMOOTHSTEP_KNEE, T 0.8, knee 0.5, start level 1, 5 levels,
 *   JIMENEZ13, 9-tap blur with spacing 0.5, TENT cascade, ADDITIVE, strength 1. Deviations: the
 *   13-tap weights sum to 1 (the seed's sum to 1.375); every level is accumulated (the seed
 *   throws away levels 2 and deeper); knee 0 is the step lum >= T (the seed's smoothstep(t, t,
 *   x) is undefined).
 * - "mip-atlas" (seed 001): no threshold, start level 0, LODs 2..8 (weights 0, 0, then 0.14 x
 *   1, 1, 1, .8, .8, .6, .4), exact area-weighted BOX mip chain limited to the image size, 7x7
 *   binomial blur, DIRECT accumulation, LERP with strength 0.52. Deviations: odd sizes keep
 *   their last row and column (the seed's 2 x dst source size drops them); no RGBA8
 *   pow(x/128, 0.25) atlas encoding, so nothing above 128 is clipped; no darkness boost and no
 *   tone mapping. By design this darkens flat regions: a constant c becomes 0.88768 c.
 * - "ping-pong" (seed 002): HARD_LUMINANCE at T 1 (strict), full resolution, the 13-tap blur
 *   repeated 32 times, ADDITIVE strength 1. Deviation: the 7 weights are divided by their
 *   symmetric sum 1.0179994; the seed's gain compounds to about 3x over 64 passes.
 * - "crt-halfres" (seed 003): PER_CHANNEL at T 0.8, start level 1, one level, 9-tap sampled
 *   Gaussian with sigma 1.8, ADDITIVE strength 1.5. The emission multiplier and the boolean
 *   gate of the seed belong to the scene, not to the bloom.
 *
 * @sa vtkImageBloom vtkBloomPass vtkBloomChain
 */

#ifndef vtkBloomParameters_h
#define vtkBloomParameters_h

#include "vtkFiltersBloomModule.h" // For export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h" // For the PSF image

#include <string>  // For preset names
#include <utility> // For level sizes
#include <vector>  // For level weights

class vtkImageData;

class VTKFILTERSBLOOM_EXPORT vtkBloomParameters : public vtkObject
{
public:
  static vtkBloomParameters* New();
  vtkTypeMacro(vtkBloomParameters, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum BlurKernels
  {
    BLUR_GAUSSIAN = 0,
    BLUR_CUSTOM = 1
  };

  enum AccumulateModes
  {
    CASCADE = 0,
    DIRECT = 1
  };

  enum CompositeModes
  {
    ADDITIVE = 0,
    LERP = 1
  };

  enum BloomModes
  {
    BLOOM_PYRAMID = 0,
    BLOOM_PSF = 1
  };

  enum PSFTypes
  {
    PSF_AIRY = 0,
    PSF_GAUSSIANS = 1,
    PSF_IMAGE = 2
  };

  /// How a wide separable blur is applied (vtkImageBloom's FAST chain, vtkImageSeparableGaussian).
  enum ConvolutionModes
  {
    CONVOLUTION_AUTOMATIC = 0,
    CONVOLUTION_DIRECT = 1,
    CONVOLUTION_FFT = 2
  };

  /**
   * Configure every parameter of the bloom's definition to reproduce a seed system:
   * "webgpu-market", "mip-atlas", "ping-pong" or "crt-halfres" (see the class description).
   * Work-skipping options and the PSF parameters stay as set. Returns false, with an error
   * naming the presets, for an unknown name and leaves the parameters unchanged.
   */
  bool SetPreset(const char* name);

  /// The names SetPreset accepts, in a fixed order.
  static std::vector<std::string> GetPresetNames();

  /// The names of GetPresetNames() joined by ", ", for messages and help.
  static std::string GetPresetNamesList();

  /// The preset a tool applies where none is named (vtk-bloom image): the first of
  /// GetPresetNames().
  static std::string GetDefaultPresetName();

  /**
   * An empty string when `name` is a preset, else the one-line error SetPreset reports (the
   * filter and the pass report it as their own).
   */
  static std::string CheckPresetName(const char* name);

  /**
   * Copy every parameter of `source` (the PSF image is shared, not copied). Modified() is called
   * only when a value changes, so copying equal parameters does not re-execute a pipeline.
   */
  void DeepCopy(vtkBloomParameters* source);

  /// Include the PSF image's modification time.
  vtkMTimeType GetMTime() override;

  ///@{
  /// BLOOM_PYRAMID (default: steps 1-5) or BLOOM_PSF (see "PSF mode" in the class description).
  vtkSetClampMacro(BloomMode, int, BLOOM_PYRAMID, BLOOM_PSF);
  vtkGetMacro(BloomMode, int);
  void SetBloomModeToPyramid() { this->SetBloomMode(BLOOM_PYRAMID); }
  void SetBloomModeToPSF() { this->SetBloomMode(BLOOM_PSF); }
  ///@}

  ///@{
  /// PSF mode: the PSF's kind, PSF_AIRY (default), PSF_GAUSSIANS or PSF_IMAGE.
  vtkSetClampMacro(PSFType, int, PSF_AIRY, PSF_IMAGE);
  vtkGetMacro(PSFType, int);
  /// Airy: radius of the first dark ring at the green wavelength, in pixels. Default 3.
  vtkSetClampMacro(AiryRadius, double, 0.1, 1.0e3);
  vtkGetMacro(AiryRadius, double);
  /// Airy: the wavelengths of the red, green and blue channels in nm. Default (610, 550, 465).
  vtkSetVector3Macro(Wavelengths, double);
  vtkGetVector3Macro(Wavelengths, double);
  /// Gaussians: standard deviations (pixels) and weights. Default (1.5, 6, 24) x (0.6, 0.3, 0.1).
  void SetPSFGaussians(const std::vector<double>& sigmas, const std::vector<double>& weights);
  const std::vector<double>& GetPSFGaussianSigmas() const { return this->PSFGaussianSigmas; }
  const std::vector<double>& GetPSFGaussianWeights() const { return this->PSFGaussianWeights; }
  /// Image: a measured PSF (float or double, odd square size, centred, non-negative).
  void SetPSFImage(vtkImageData* image);
  vtkImageData* GetPSFImage();
  /// Truncation radius in pixels; -1 (default) chooses it (see the class description).
  vtkSetClampMacro(PSFRadius, int, -1, 2048);
  vtkGetMacro(PSFRadius, int);
  /// REFLECT (1, default: energy-conserving) or ZERO (2), as vtkImageSeparableGaussian's modes.
  vtkSetClampMacro(PSFBorderMode, int, 1, 2);
  vtkGetMacro(PSFBorderMode, int);
  /// The tail's grid spacing f: 1 (default: exact, no split), 2, 4 or 8; other values are
  /// refused with an error.
  void SetPSFTailScale(int scale);
  vtkGetMacro(PSFTailScale, int);
  /// The core's radius rc in pixels, 1 to 2048, or -1 (default: 16); other values are refused
  /// with an error. A core as wide as the PSF leaves no tail.
  void SetPSFCoreRadius(int radius);
  vtkGetMacro(PSFCoreRadius, int);
  /// The core radius in use: PSFCoreRadius, or 16 when it is -1.
  int GetEffectivePSFCoreRadius() const;
  ///@}

  ///@{
  /**
   * Bright pass (see vtkImageBloomThreshold). Defaults: EXCESS_KNEE, 1, 0.5, off: light
   * brighter than display white glows by its excess over 1 (its knee lies above 1), and a frame
   * with nothing above 1 is left exactly as it is. The presets set their seeds' modes.
   */
  vtkSetClampMacro(ThresholdMode, int, 0, 5);
  vtkGetMacro(ThresholdMode, int);
  vtkSetMacro(Threshold, double);
  vtkGetMacro(Threshold, double);
  vtkSetClampMacro(Knee, double, 0.0, 1.0);
  vtkGetMacro(Knee, double);
  vtkSetClampMacro(ClampLuminance, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(ClampLuminance, double);
  ///@}

  ///@{
  /// Pyramid level of the bright pass (0 = full resolution). Default 1 (half resolution).
  vtkSetClampMacro(StartLevel, int, 0, 16);
  vtkGetMacro(StartLevel, int);
  /// Number of pyramid levels from the start level. Default 5.
  vtkSetClampMacro(NumberOfLevels, int, 1, 32);
  vtkGetMacro(NumberOfLevels, int);
  /// Drop levels deeper than floor(log2(max(W, H))), like a hardware mip chain. Default off.
  vtkSetMacro(LimitLevelsToImageSize, bool);
  vtkGetMacro(LimitLevelsToImageSize, bool);
  vtkBooleanMacro(LimitLevelsToImageSize, bool);
  ///@}

  ///@{
  /**
   * The height, in pixels, of the frame the sizes above are meant for. 0: they are pixels of
   * whatever image comes (the presets' seed semantics). Above 0 (the default, 1080): the bloom
   * keeps its size relative to the frame's height, so a frame H pixels tall looks like this
   * one rescaled. The pyramid starts and ends log2(H / ReferenceHeight) levels deeper
   * (rounded; a frame too small to start above level 0 drops its finest levels instead), and
   * the blur's sigma, radius and tap spacing take the factor that remains (GetBlurScale). At
   * H = ReferenceHeight nothing changes. PSF mode's sizes (AiryRadius,
   * the Gaussians, PSFRadius) stay in pixels.
   */
  vtkSetClampMacro(ReferenceHeight, int, 0, 65536);
  vtkGetMacro(ReferenceHeight, int);
  /// round(log2(height / ReferenceHeight)): how many levels deeper the pyramid starts and ends.
  int GetLevelShift(int height) const;
  /// The pyramid level of the bright pass for a frame `height` pixels tall (at least 0).
  int GetEffectiveStartLevel(int height) const;
  /**
   * The finest levels of the reference frame's pyramid that a frame `height` pixels tall has
   * no room for (its pyramid cannot start above level 0). Level i > 0 there weighs
   * GetLevelWeight(i + GetDroppedLevels(height)); level 0 weighs the sum of the weights of
   * the levels it stands for, so that the weights keep their sum (GetEffectiveLevelWeight).
   */
  int GetDroppedLevels(int height) const;
  double GetEffectiveLevelWeight(int level, int height) const;
  /// The factor on the blur's sizes that the shift by whole levels leaves (1 with no reference).
  double GetBlurScale(int height) const;
  /// The blur's half kernel and tap spacing for a frame `height` pixels tall.
  std::vector<double> GetEffectiveBlurHalfKernel(int height) const;
  double GetEffectiveBlurTapSpacing(int height) const;
  ///@}

  ///@{
  /// Downsampling kernel: vtkImagePyramidDown::JIMENEZ13 (default), BOX or BINOMIAL.
  vtkSetClampMacro(DownsampleKernel, int, 0, 2);
  vtkGetMacro(DownsampleKernel, int);
  /// Karis average on the first downsample (JIMENEZ13 only). Default off.
  vtkSetMacro(KarisAverage, bool);
  vtkGetMacro(KarisAverage, bool);
  vtkBooleanMacro(KarisAverage, bool);
  ///@}

  ///@{
  /// Per-level blur kernel: BLUR_GAUSSIAN (default) or BLUR_CUSTOM.
  vtkSetClampMacro(BlurKernel, int, BLUR_GAUSSIAN, BLUR_CUSTOM);
  vtkGetMacro(BlurKernel, int);
  /// Gaussian sigma in level pixels (default 1), its radius in taps (-1, the default, means
  /// ceil(3 sigma)) and kind (vtkBloomKernels::GaussianKind, default sampled).
  vtkSetClampMacro(BlurStandardDeviation, double, 0.0, 1.0e4);
  vtkGetMacro(BlurStandardDeviation, double);
  vtkSetClampMacro(BlurRadius, int, -1, 4096);
  vtkGetMacro(BlurRadius, int);
  vtkSetClampMacro(BlurGaussianKind, int, 0, 2);
  vtkGetMacro(BlurGaussianKind, int);
  /// The custom half kernel (centre first); used as given, not renormalized.
  void SetBlurHalfKernel(int n, const double* weights);
  void SetBlurHalfKernel(const std::vector<double>& weights);
  const std::vector<double>& GetBlurHalfKernel() const { return this->BlurHalfKernel; }
  /// Distance between blur taps in level pixels. Default 1.
  vtkSetClampMacro(BlurTapSpacing, double, 0.0, 1.0e4);
  vtkGetMacro(BlurTapSpacing, double);
  /// Times the blur is repeated. Default 1.
  vtkSetClampMacro(BlurIterations, int, 0, 1024);
  vtkGetMacro(BlurIterations, int);
  /// The half kernel the blur uses with the current parameters.
  std::vector<double> GetEffectiveBlurHalfKernel() const;
  ///@}

  ///@{
  /// Upsampling kernel for CASCADE: vtkImagePyramidUp::TENT (default) or BILINEAR.
  vtkSetClampMacro(UpsampleKernel, int, 0, 1);
  vtkGetMacro(UpsampleKernel, int);
  /// CASCADE (default) or DIRECT accumulation.
  vtkSetClampMacro(AccumulateMode, int, CASCADE, DIRECT);
  vtkGetMacro(AccumulateMode, int);
  ///@}

  ///@{
  /// Per-level weights, indexed from the first level. Levels without one weigh 1.
  void SetLevelWeight(int level, double weight);
  double GetLevelWeight(int level) const;
  void SetLevelWeights(int n, const double* weights);
  void SetLevelWeights(const std::vector<double>& weights);
  const std::vector<double>& GetLevelWeights() const { return this->LevelWeights; }
  ///@}

  ///@{
  /// ADDITIVE (default) or LERP, with Strength (default 1) and an RGB Tint (default white).
  vtkSetClampMacro(CompositeMode, int, ADDITIVE, LERP);
  vtkGetMacro(CompositeMode, int);
  vtkSetMacro(Strength, double);
  vtkGetMacro(Strength, double);
  vtkSetVector3Macro(Tint, double);
  vtkGetVector3Macro(Tint, double);
  ///@}

  ///@{
  /**
   * How the FAST chain applies wide level blurs: AUTOMATIC (default: per level and axis, the
   * FFT where its modeled cost is lower), DIRECT or FFT (see vtkImageBloom, "Wide blurs").
   */
  vtkSetClampMacro(ConvolutionMode, int, CONVOLUTION_AUTOMATIC, CONVOLUTION_FFT);
  vtkGetMacro(ConvolutionMode, int);
  void SetConvolutionModeToAutomatic() { this->SetConvolutionMode(CONVOLUTION_AUTOMATIC); }
  void SetConvolutionModeToDirect() { this->SetConvolutionMode(CONVOLUTION_DIRECT); }
  void SetConvolutionModeToFFT() { this->SetConvolutionMode(CONVOLUTION_FFT); }
  ///@}

  ///@{
  /**
   * Work-skipping, each on by default and each exact (see vtkImageBloom, "Content-aware
   * work", and vtkBloomPass):
   * - SkipEmptyBloom: no bloom work when the bright pass leaves nothing.
   * - SkipDisabledEffects: no bloom work when Strength, the tint or every level weight makes
   *   the bloom term zero.
   * - TrimPyramid: trailing levels of weight 0 are not built.
   * - RestrictToBrightRegion: only the region the bright samples can reach is processed.
   */
  vtkSetMacro(SkipEmptyBloom, bool);
  vtkGetMacro(SkipEmptyBloom, bool);
  vtkBooleanMacro(SkipEmptyBloom, bool);
  vtkSetMacro(SkipDisabledEffects, bool);
  vtkGetMacro(SkipDisabledEffects, bool);
  vtkBooleanMacro(SkipDisabledEffects, bool);
  vtkSetMacro(TrimPyramid, bool);
  vtkGetMacro(TrimPyramid, bool);
  vtkBooleanMacro(TrimPyramid, bool);
  vtkSetMacro(RestrictToBrightRegion, bool);
  vtkGetMacro(RestrictToBrightRegion, bool);
  vtkBooleanMacro(RestrictToBrightRegion, bool);
  ///@}

  ///@{
  /**
   * Replace non-finite input samples and clamp the output to the finite range of its type
   * (see vtkImageBloom, "Non-finite input", and vtkBloomPass). Default on.
   */
  vtkSetMacro(SanitizeNonFinite, bool);
  vtkGetMacro(SanitizeNonFinite, bool);
  vtkBooleanMacro(SanitizeNonFinite, bool);
  ///@}

  /**
   * Sizes of the pyramid levels for an input of `width` x `height` (from
   * GetEffectiveStartLevel(height)), first level first, as (width, height) pairs (empty when no
   * level fits).
   */
  std::vector<std::pair<int, int>> ComputeLevelSizes(int width, int height) const;

  /**
   * True when Strength, the tint or the weights of the first `levels` levels (of a frame
   * `height` pixels tall: GetEffectiveLevelWeight) make the bloom term zero. With one colour
   * channel the tint counts by its luminance.
   */
  bool IsBloomDisabled(int colours, size_t levels, int height = 0) const;

  /**
   * The first reason these parameters cannot be evaluated (a non-finite threshold, strength,
   * tint, blur or level weight), or an empty string when they can.
   */
  std::string Validate() const;

protected:
  vtkBloomParameters();
  ~vtkBloomParameters() override;

  int ThresholdMode;
  double Threshold;
  double Knee;
  double ClampLuminance;
  int StartLevel;
  int ReferenceHeight;
  int NumberOfLevels;
  bool LimitLevelsToImageSize;
  int DownsampleKernel;
  bool KarisAverage;
  int BlurKernel;
  double BlurStandardDeviation;
  int BlurRadius;
  int BlurGaussianKind;
  std::vector<double> BlurHalfKernel;
  double BlurTapSpacing;
  int BlurIterations;
  int UpsampleKernel;
  int AccumulateMode;
  std::vector<double> LevelWeights;
  int CompositeMode;
  double Strength;
  double Tint[3];
  int ConvolutionMode;
  bool SkipEmptyBloom;
  bool SkipDisabledEffects;
  bool TrimPyramid;
  bool RestrictToBrightRegion;
  bool SanitizeNonFinite;
  int BloomMode;
  int PSFType;
  double AiryRadius;
  double Wavelengths[3];
  std::vector<double> PSFGaussianSigmas;
  std::vector<double> PSFGaussianWeights;
  vtkSmartPointer<vtkImageData> PSFImage;
  int PSFRadius;
  int PSFTailScale;
  int PSFCoreRadius;
  int PSFBorderMode;

private:
  vtkBloomParameters(const vtkBloomParameters&) = delete;
  void operator=(const vtkBloomParameters&) = delete;
};

#endif
