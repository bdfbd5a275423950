/**
 * @class   vtkImageBloom
 * @brief   HDR bloom in one filter: bright pass, pyramid, per-level blur, accumulate, composite.
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
 * widest sigma for Gaussians) and normalized to sum 1. The convolution scatters each bright
 * sample through the PSF and folds what leaves the image back in by half-sample reflection
 * (PSFBorderMode REFLECT, the default) or drops it (ZERO). With REFLECT the bloom's energy in
 * each channel equals the bright pass's (tested to 1e-6 relative), so the composite adds exactly
 * Strength times the bright pass's energy. It runs through a two-dimensional FFT in single
 * precision (vtkBloomPSF), in both execution modes, on 2-D images. The PSFs, FFTW's plans and
 * the PSFs' spectra are kept until a parameter, the PSF image or the image size changes.
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
 *   gate of the seed belong to the scene, not to the filter.
 *
 * The bloom reads the whole input (its support is the whole image), so RequestUpdateExtent asks
 * for the whole extent and any requested output piece equals the whole result bit for bit.
 * Work runs in double precision, threaded with vtkSMPTools. Input must be float or double with
 * 1 to 4 components.
 *
 * Execution. ExecutionMode FAST (the default) runs a fused float32 chain (vtkBloomFastChain,
 * internal): the bright pass is one read of the input fused with the fetch to the start level;
 * each level's blur is fused with the upsample-accumulate; the composite is fused with the
 * last upsample, one output row at a time; rows are threaded with vtkSMPTools. It keeps its
 * intermediate levels between updates (LastWorkspaceBytes; ReleaseWorkspace() frees them) and
 * reuses its previous output array when nothing else holds it. It agrees with REFERENCE, the
 * double-precision implementation of the steps above, to float32 rounding (tested: relative
 * L2 <= 1e-5 for every preset). Double input (which asks for double precision), KarisAverage
 * and inputs of more than one slice always run REFERENCE.
 * In both modes the bloom term is S t bloom + 0, so a zero term is always +0.
 *
 * Content-aware work (each part on by default, each exact: the output is bit-identical with
 * it on or off):
 * - SkipEmptyBloom: when the bright pass leaves only zeros the bloom is zero and no pyramid is
 *   built. In FAST, when moreover the output is the whole image, keep = 1 (ADDITIVE or LERP
 *   with Strength 0) and the input holds no -0, NaN or Inf (the only samples "in + 0" or
 *   sanitizing could change), the output shares the input scalars: one read pass in all.
 * - SkipDisabledEffects: Strength 0, a black tint or weights all 0 skip the bloom work.
 * - TrimPyramid (FAST): trailing levels of weight 0 are not built. The depth is otherwise
 *   NumberOfLevels, bounded by the image size (LimitLevelsToImageSize).
 * - RestrictToBrightRegion (FAST): each step computes only the box its operators can reach
 *   from the bounding box of the non-zero bright samples; elsewhere the bloom is zero and the
 *   output is keep * in + 0.
 * Exactness needs a finite bloom; FAST clamps each bloom sample to the float range first.
 *
 * Wide blurs (FAST). A level blur whose folded operator is wide (the ping-pong preset's 32
 * passes make one of 385 taps) costs O(width) per sample directly. With ConvolutionMode
 * AUTOMATIC (the default) each level and axis whose FFT is modeled cheaper runs through it
 * instead (vtkBloomFFTConvolution in single precision: the same weights, the clamp borders of
 * the repeated passes as a low-rank correction near each end). It agrees with the direct blur
 * to about 1e-7 relative L2 (tested <= 1e-6 for the ping-pong preset), leaves exact zeros where
 * no bright sample reaches (so the content-aware skips stay exact) and is deterministic.
 *
 * UseAVX2 (FAST, default on): where the library was built with GCC for x86, the fast chain is
 * compiled twice, for the baseline instruction set and for AVX2 without FMA, and runs the AVX2
 * copy when the CPU supports it. Both compute every sample with the same operations in the
 * same order, so the output is the same bit for bit (tested); only the speed differs.
 *
 * Non-finite input (SanitizeNonFinite):
 * - On (the default): every input sample that is not finite is replaced before use, NaN by 0,
 *   +Inf by the largest finite value of the input scalar type and -Inf by the lowest, in every
 *   component (alpha included), both where the chain reads the input and in the composite. The
 *   result is then clamped to the finite range of the output scalar type (NaN, which finite
 *   arithmetic cannot produce from finite input but an overflow can, becomes 0), so every
 *   output sample is finite.
 * - Off: the bright pass maps NaN and -Inf to 0 and +Inf to min(ClampLuminance, float max), as
 *   vtkImageBloomThreshold does, in every ThresholdMode (NONE included), so nothing non-finite
 *   enters the pyramid. The composite reads the input as stored, so a non-finite input sample
 *   reaches only its own output pixel.
 * Finite input gives the same output bit for bit either way.
 *
 * Statistics. With ComputeStatistics on (the default), every successful update measures the
 * bloom over the output extent E (the whole image unless a piece was requested). With L(p) the
 * Rec. 709 luminance 0.2126 R + 0.7152 G + 0.0722 B of pixel p for 3-4 components, or the value
 * itself for 1-2 components, evaluated in double on the scalars as stored (input and output
 * share the input's scalar type):
 * - EnergyIn = sum_{p in E} L(input p) and EnergyOut = sum_{p in E} L(output p), the exact sum
 *   of the L values rounded once to nearest (Neal's superaccumulator): the result does not
 *   depend on the number of threads, and values that cancel lose nothing (a signed image whose
 *   values cancel has energy 0 exactly).
 * - NumberOfBrightPixels = the number of full-resolution input pixels p in E whose bright pass
 *   vtkImageBloomThreshold::BrightPass(colour(p)) (ThresholdMode, Threshold, Knee,
 *   ClampLuminance as set here) has at least one colour value > 0. It is taken on the input
 *   pixel itself, whatever StartLevel is: with HARD_LUMINANCE it counts L > Threshold, with
 *   PER_CHANNEL a colour value > Threshold, with the knees L (or max(R, G, B)) inside or above
 *   the knee, and with NONE every pixel with a positive colour value.
 * - PeakLuminanceIn = max_{p in E} L(input p) and PeakLuminanceOut = max_{p in E} L(output p)
 *   (NaN pixels are ignored).
 * - NumberOfLevelsUsed = the number of pyramid levels the chain ran, ComputeLevelSizes(W,
 *   H).size() (0 when no level fits and the bloom is black).
 * They are attached to the output as one-tuple field data arrays (names from the
 * Get*ArrayName() functions: vtkDoubleArray for energies and peaks, vtkIdTypeArray for the
 * pixel count, vtkIntArray for the levels) and returned by the getters. After a failed update,
 * or with ComputeStatistics off, the getters return 0 and the arrays are absent. The point
 * scalars are the same bit for bit with statistics on or off. The statistics see the input as
 * stored (they are not sanitized, so a NaN or Inf input sample makes EnergyIn non-finite;
 * PeakLuminanceIn ignores NaN) and the output as written.
 */

#ifndef vtkImageBloom_h
#define vtkImageBloom_h

#include "vtkFiltersBloomModule.h" // For export macro
#include "vtkImageAlgorithm.h"
#include "vtkSmartPointer.h" // For the PSF image
#include "vtkTimeStamp.h"    // For ChainTime

#include <string> // For preset names
#include <vector> // For level weights

struct vtkBloomBuffer;
struct vtkBloomPSFKernels;
class vtkBloomChain;
class vtkBloomFastChain;

class VTKFILTERSBLOOM_EXPORT vtkImageBloom : public vtkImageAlgorithm
{
public:
  static vtkImageBloom* New();
  vtkTypeMacro(vtkImageBloom, vtkImageAlgorithm);
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

  enum ExecutionModes
  {
    FAST = 0,
    REFERENCE = 1
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
  ///@}

  /**
   * The normalized PSF of colour channel `channel` (0 red, 1 green, 2 blue) with the current
   * parameters, (2 radius + 1)^2 values, row-major, centred; empty, with an error, when the
   * parameters (or the PSF image) are invalid.
   */
  std::vector<double> ComputePSF(int channel, int& radius);

  /// Include the PSF image's modification time.
  vtkMTimeType GetMTime() override;

  /**
   * Configure every parameter to reproduce a seed system: "webgpu-market", "mip-atlas",
   * "ping-pong" or "crt-halfres" (see the class description). Returns false, with an error,
   * for an unknown name and leaves the parameters unchanged.
   */
  bool SetPreset(const char* name);

  /// The names SetPreset accepts.
  static std::vector<std::string> GetPresetNames();

  /**
   * Copy every parameter of `source` into this filter: the bright pass, pyramid, blur,
   * composite, PSF (the PSF image is shared, not copied) and execution options, everything a
   * preset or a setter can change, but not the input, the outputs or the statistics. Modified()
   * is called only when a value changes, so copying equal parameters does not re-execute.
   */
  void CopyParameters(vtkImageBloom* source);

  ///@{
  /// Bright pass (see vtkImageBloomThreshold). Defaults: SMOOTHSTEP_KNEE, 1, 0.5, off.
  vtkSetClampMacro(ThresholdMode, int, 0, 4);
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
  ///@}

  ///@{
  /// Number of pyramid levels from the start level. Default 5.
  vtkSetClampMacro(NumberOfLevels, int, 1, 32);
  vtkGetMacro(NumberOfLevels, int);
  ///@}

  ///@{
  /// Drop levels deeper than floor(log2(max(W, H))), like a hardware mip chain. Default off.
  vtkSetMacro(LimitLevelsToImageSize, bool);
  vtkGetMacro(LimitLevelsToImageSize, bool);
  vtkBooleanMacro(LimitLevelsToImageSize, bool);
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
   * FAST (the default) runs the fused float32 chain (see "Execution" in the class
   * description); REFERENCE runs the double-precision reference implementation.
   */
  vtkSetClampMacro(ExecutionMode, int, FAST, REFERENCE);
  vtkGetMacro(ExecutionMode, int);
  void SetExecutionModeToFast() { this->SetExecutionMode(FAST); }
  void SetExecutionModeToReference() { this->SetExecutionMode(REFERENCE); }
  ///@}

  enum ConvolutionModes
  {
    CONVOLUTION_AUTOMATIC = 0,
    CONVOLUTION_DIRECT = 1,
    CONVOLUTION_FFT = 2
  };

  ///@{
  /**
   * How FAST applies the level blurs (see "Wide blurs" in the class description): AUTOMATIC
   * (default: per level and axis, the FFT where its modeled cost is lower), DIRECT or FFT
   * (wherever the blur has a convolution interior). REFERENCE always sums the taps.
   */
  vtkSetClampMacro(ConvolutionMode, int, CONVOLUTION_AUTOMATIC, CONVOLUTION_FFT);
  vtkGetMacro(ConvolutionMode, int);
  void SetConvolutionModeToAutomatic() { this->SetConvolutionMode(CONVOLUTION_AUTOMATIC); }
  void SetConvolutionModeToDirect() { this->SetConvolutionMode(CONVOLUTION_DIRECT); }
  void SetConvolutionModeToFFT() { this->SetConvolutionMode(CONVOLUTION_FFT); }
  ///@}

  ///@{
  /**
   * Content-aware work, each on by default and each exact: the output is bit-identical with
   * it on or off (see "Content-aware work" in the class description).
   * - SkipEmptyBloom: no bloom work when the bright pass leaves nothing (both modes).
   * - SkipDisabledEffects: no bloom work when Strength, the tint or every level weight makes
   *   the bloom term zero (both modes).
   * - TrimPyramid: trailing levels of weight 0 are not built (FAST).
   * - RestrictToBrightRegion: only the region the bright samples can reach is processed
   *   (FAST).
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
   * Run the fast chain's AVX2 code when the CPU supports it (see the class description).
   * Default on; off forces the baseline code, for comparison.
   */
  vtkSetMacro(UseAVX2, bool);
  vtkGetMacro(UseAVX2, bool);
  vtkBooleanMacro(UseAVX2, bool);
  ///@}

  /// True when this build has the AVX2 code and the CPU supports it.
  static bool IsAVX2Available();

  ///@{
  /**
   * What the last update did, for tests and benchmarks: whether it ran the fast chain, whether
   * the bloom work was skipped, whether the output shares the input scalars, how many levels
   * were built (-1 in REFERENCE), the bytes of intermediate buffers the fast chain holds, and
   * whether the fast chain ran its AVX2 code.
   */
  vtkGetMacro(LastRunWasFast, bool);
  vtkGetMacro(LastBloomSkipped, bool);
  vtkGetMacro(LastPassedThrough, bool);
  vtkGetMacro(LastLevelsBuilt, int);
  vtkGetMacro(LastWorkspaceBytes, vtkIdType);
  vtkGetMacro(LastRunUsedAVX2, bool);
  /// Level blur axes the last FAST update ran through the FFT.
  vtkGetMacro(LastFFTBlurs, int);
  ///@}

  /**
   * Free the fast chain's intermediate buffers and PSF mode's kernels, plans and spectra (both
   * are kept between updates otherwise).
   */
  void ReleaseWorkspace();

  ///@{
  /**
   * Replace non-finite input samples and clamp the output to the finite range of its scalar
   * type (see the class description). Default on.
   */
  vtkSetMacro(SanitizeNonFinite, bool);
  vtkGetMacro(SanitizeNonFinite, bool);
  vtkBooleanMacro(SanitizeNonFinite, bool);
  ///@}

  ///@{
  /**
   * Measure the bloom statistics (see the class description) on every update and attach them
   * to the output's field data. Default on; the cost is one read of the input and the output.
   */
  vtkSetMacro(ComputeStatistics, bool);
  vtkGetMacro(ComputeStatistics, bool);
  vtkBooleanMacro(ComputeStatistics, bool);
  ///@}

  ///@{
  /**
   * Statistics of the last update (see the class description); 0 before the first update,
   * after a failed update and when ComputeStatistics is off.
   */
  vtkGetMacro(EnergyIn, double);
  vtkGetMacro(EnergyOut, double);
  vtkGetMacro(NumberOfBrightPixels, vtkIdType);
  vtkGetMacro(PeakLuminanceIn, double);
  vtkGetMacro(PeakLuminanceOut, double);
  vtkGetMacro(NumberOfLevelsUsed, int);
  ///@}

  ///@{
  /// Names of the output field data arrays that carry the statistics.
  static const char* GetEnergyInArrayName() { return "BloomEnergyIn"; }
  static const char* GetEnergyOutArrayName() { return "BloomEnergyOut"; }
  static const char* GetNumberOfBrightPixelsArrayName() { return "BloomNumberOfBrightPixels"; }
  static const char* GetPeakLuminanceInArrayName() { return "BloomPeakLuminanceIn"; }
  static const char* GetPeakLuminanceOutArrayName() { return "BloomPeakLuminanceOut"; }
  static const char* GetNumberOfLevelsUsedArrayName() { return "BloomNumberOfLevelsUsed"; }
  ///@}

  /**
   * Sizes of the levels the chain would use for an input of `width` x `height`, first level
   * first, as (width, height) pairs. Exposed for testing and for the render pass.
   */
  std::vector<std::pair<int, int>> ComputeLevelSizes(int width, int height) const;

protected:
  vtkImageBloom();
  ~vtkImageBloom() override;

  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  /// vtkErrorMacro and false when a parameter is out of its domain.
  bool CheckParameters();

  ///@{
  /**
   * The steps of RequestData. CheckInput: vtkErrorMacro and false for input the filter cannot
   * use. UpdateChain: rebuild the operators when a parameter or the size changed.
   * ExecuteFast: the fused float32 chain, false when it does not apply (see the class
   * description), with the number of levels it used. The REFERENCE chain, in double: ThresholdStep
   * (the bright pass at the start level into levels[0]; false, with levelsUsed, when there is
   * nothing to bloom), DownsampleStep, BlurStep and UpsampleStep (up and accumulate into `bloom`).
   */
  bool CheckInput(vtkImageData* input);
  void UpdateChain(int width, int height);
  bool ExecuteFast(
    vtkImageData* input, vtkInformation* outInfo, vtkImageData* output, int& levelsUsed);
  bool ThresholdStep(vtkImageData* input, std::vector<vtkBloomBuffer>& levels, int& levelsUsed);
  void DownsampleStep(std::vector<vtkBloomBuffer>& levels);
  void BlurStep(std::vector<vtkBloomBuffer>& levels);
  void UpsampleStep(
    std::vector<vtkBloomBuffer>& levels, int width, int height, vtkBloomBuffer& bloom);
  ///@}

  ///@{
  /**
   * Shared by the REFERENCE chain and PSF mode: ImportColours copies the colours of the input
   * (sanitized when SanitizeNonFinite is on) into `colours`; BrightPassInPlace maps non-finite
   * samples and applies the bright pass to every sample.
   */
  void ImportColours(vtkImageData* input, vtkBloomBuffer& colours);
  void BrightPassInPlace(vtkBloomBuffer& buffer);
  ///@}

  /// PSF mode: the bloom is the PSF convolution of the full-resolution bright pass.
  int ExecutePSF(vtkImageData* input, vtkInformation* outInfo, vtkImageData* output);

  /// Step 5 over the output's extent; a null bloom means a black one.
  void Composite(vtkImageData* input, const vtkBloomBuffer* bloom, vtkImageData* output);

  /// Zero every statistic.
  void ResetStatistics();

  /// True when Strength, Tint or the weights of `levels` levels make the bloom term zero.
  bool BloomIsDisabled(int colours, size_t levels) const;

  /// Measure the statistics over the output's extent and attach them to its field data.
  void ComputeOutputStatistics(vtkImageData* input, vtkImageData* output, int levelsUsed);

  int ThresholdMode;
  double Threshold;
  double Knee;
  double ClampLuminance;
  int StartLevel;
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
  bool ComputeStatistics;
  bool SanitizeNonFinite;
  int ExecutionMode;
  bool SkipEmptyBloom;
  bool SkipDisabledEffects;
  bool TrimPyramid;
  bool RestrictToBrightRegion;
  bool UseAVX2;
  bool LastRunWasFast;
  bool LastBloomSkipped;
  bool LastPassedThrough;
  int LastLevelsBuilt;
  vtkIdType LastWorkspaceBytes;
  bool LastRunUsedAVX2;
  int LastFFTBlurs;
  int ConvolutionMode;
  int BloomMode;
  int PSFType;
  double AiryRadius;
  double Wavelengths[3];
  std::vector<double> PSFGaussianSigmas;
  std::vector<double> PSFGaussianWeights;
  vtkSmartPointer<vtkImageData> PSFImage;
  int PSFRadius;
  int PSFBorderMode;
  vtkBloomPSFKernels* PSFKernels; ///< the PSF of each channel, rebuilt when a parameter changes
  vtkBloomFastChain* FastChain;
  // The chain's operators, rebuilt only when a parameter or the input size changed.
  vtkBloomChain* Chain;
  vtkTimeStamp ChainTime;
  int ChainSize[2];

  double EnergyIn;
  double EnergyOut;
  vtkIdType NumberOfBrightPixels;
  double PeakLuminanceIn;
  double PeakLuminanceOut;
  int NumberOfLevelsUsed;

private:
  vtkImageBloom(const vtkImageBloom&) = delete;
  void operator=(const vtkImageBloom&) = delete;
};

#endif
