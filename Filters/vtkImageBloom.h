// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkImageBloom
 * @brief   HDR bloom in one filter: bright pass, pyramid, per-level blur, accumulate, composite.
 *
 * What the bloom computes (the bright pass, pyramid, blur, accumulation and composite, PSF
 * mode, the presets) is defined by its parameters, a vtkBloomParameters (GetParameters(); see
 * that class for each step and preset). The filter's own setters for them (SetThreshold,
 * SetPreset, ...) are shortcuts for GetParameters()->Set...; a vtkBloomPass given the same
 * parameters (vtkBloomPass::SetParameters) renders the same bloom on the GPU. PSF mode runs
 * through a two-dimensional FFT in single precision (vtkBloomPSF), in both execution modes, on
 * 2-D images; with REFLECT borders the bloom's energy in each channel equals the bright pass's
 * (tested to 1e-6 relative). The PSFs, FFTW's plans and the PSFs' spectra are kept until a
 * parameter, the PSF image or the image size changes.
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
 * In both modes the bloom term is Strength Tint bloom + 0, so a zero term is always +0.
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
 * scalars are the same bit for bit with statistics on or off. FAST measures them in its
 * composite, each input row and the output row written from it while they are in the cache,
 * instead of in passes of their own over the frame; the values are the same either way. The
 * statistics see the input as stored (they are not sanitized, so a NaN or Inf input sample makes
 * EnergyIn non-finite; PeakLuminanceIn ignores NaN) and the output as written.
 */

#ifndef vtkImageBloom_h
#define vtkImageBloom_h

#include "vtkBloomParameters.h"    // For the parameters and their shortcuts
#include "vtkFiltersBloomModule.h" // For export macro
#include "vtkImageAlgorithm.h"
#include "vtkSmartPointer.h" // For the parameters
#include "vtkTimeStamp.h"    // For ChainTime

#include <string>  // For preset names
#include <utility> // For level sizes
#include <vector>  // For level weights

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

  enum ExecutionModes
  {
    FAST = 0,
    REFERENCE = 1
  };

  ///@{
  /**
   * The bloom's parameters. A filter makes its own; setting another shares it (with a
   * vtkBloomPass, say) and a null pointer is ignored. Modifying them modifies the filter.
   */
  void SetParameters(vtkBloomParameters* parameters);
  vtkBloomParameters* GetParameters() { return this->Parameters; }
  ///@}

  /**
   * Copy `source`'s parameters (vtkBloomParameters::DeepCopy) and its execution options
   * (ExecutionMode, UseAVX2, ComputeStatistics). Modified() is called only
   * when a value changes, so copying equal parameters does not re-execute.
   */
  void CopyParameters(vtkImageBloom* source);

  ///@{
  /**
   * The parameters' enums by the names this class gave them before vtkBloomParameters held
   * them; new code names vtkBloomParameters'.
   */
  enum BlurKernels
  {
    BLUR_GAUSSIAN = vtkBloomParameters::BLUR_GAUSSIAN,
    BLUR_CUSTOM = vtkBloomParameters::BLUR_CUSTOM
  };
  enum AccumulateModes
  {
    CASCADE = vtkBloomParameters::CASCADE,
    DIRECT = vtkBloomParameters::DIRECT
  };
  enum CompositeModes
  {
    ADDITIVE = vtkBloomParameters::ADDITIVE,
    LERP = vtkBloomParameters::LERP
  };
  enum BloomModes
  {
    BLOOM_PYRAMID = vtkBloomParameters::BLOOM_PYRAMID,
    BLOOM_PSF = vtkBloomParameters::BLOOM_PSF
  };
  enum PSFTypes
  {
    PSF_AIRY = vtkBloomParameters::PSF_AIRY,
    PSF_GAUSSIANS = vtkBloomParameters::PSF_GAUSSIANS,
    PSF_IMAGE = vtkBloomParameters::PSF_IMAGE
  };
  enum ConvolutionModes
  {
    CONVOLUTION_AUTOMATIC = vtkBloomParameters::CONVOLUTION_AUTOMATIC,
    CONVOLUTION_DIRECT = vtkBloomParameters::CONVOLUTION_DIRECT,
    CONVOLUTION_FFT = vtkBloomParameters::CONVOLUTION_FFT
  };
  ///@}

  ///@{
  /**
   * Shortcuts for the parameters' accessors (GetParameters()->...), documented in
   * vtkBloomParameters.
   */
  void SetBloomMode(int v) { this->Parameters->SetBloomMode(v); }
  int GetBloomMode() { return this->Parameters->GetBloomMode(); }
  void SetPSFType(int v) { this->Parameters->SetPSFType(v); }
  int GetPSFType() { return this->Parameters->GetPSFType(); }
  void SetAiryRadius(double v) { this->Parameters->SetAiryRadius(v); }
  double GetAiryRadius() { return this->Parameters->GetAiryRadius(); }
  void SetWavelengths(double a, double b, double c) { this->Parameters->SetWavelengths(a, b, c); }
  void SetWavelengths(const double v[3]) { this->Parameters->SetWavelengths(v[0], v[1], v[2]); }
  double* GetWavelengths() VTK_SIZEHINT(3) { return this->Parameters->GetWavelengths(); }
  void GetWavelengths(double v[3]) { this->Parameters->GetWavelengths(v); }
  void SetPSFRadius(int v) { this->Parameters->SetPSFRadius(v); }
  int GetPSFRadius() { return this->Parameters->GetPSFRadius(); }
  void SetPSFBorderMode(int v) { this->Parameters->SetPSFBorderMode(v); }
  int GetPSFBorderMode() { return this->Parameters->GetPSFBorderMode(); }
  void SetPSFTailScale(int v) { this->Parameters->SetPSFTailScale(v); }
  int GetPSFTailScale() { return this->Parameters->GetPSFTailScale(); }
  void SetPSFCoreRadius(int v) { this->Parameters->SetPSFCoreRadius(v); }
  int GetPSFCoreRadius() { return this->Parameters->GetPSFCoreRadius(); }
  void SetThresholdMode(int v) { this->Parameters->SetThresholdMode(v); }
  int GetThresholdMode() { return this->Parameters->GetThresholdMode(); }
  void SetThreshold(double v) { this->Parameters->SetThreshold(v); }
  double GetThreshold() { return this->Parameters->GetThreshold(); }
  void SetKnee(double v) { this->Parameters->SetKnee(v); }
  double GetKnee() { return this->Parameters->GetKnee(); }
  void SetClampLuminance(double v) { this->Parameters->SetClampLuminance(v); }
  double GetClampLuminance() { return this->Parameters->GetClampLuminance(); }
  void SetStartLevel(int v) { this->Parameters->SetStartLevel(v); }
  int GetStartLevel() { return this->Parameters->GetStartLevel(); }
  void SetReferenceHeight(int v) { this->Parameters->SetReferenceHeight(v); }
  int GetReferenceHeight() { return this->Parameters->GetReferenceHeight(); }
  void SetNumberOfLevels(int v) { this->Parameters->SetNumberOfLevels(v); }
  int GetNumberOfLevels() { return this->Parameters->GetNumberOfLevels(); }
  void SetLimitLevelsToImageSize(bool v) { this->Parameters->SetLimitLevelsToImageSize(v); }
  bool GetLimitLevelsToImageSize() { return this->Parameters->GetLimitLevelsToImageSize(); }
  void LimitLevelsToImageSizeOn() { this->Parameters->LimitLevelsToImageSizeOn(); }
  void LimitLevelsToImageSizeOff() { this->Parameters->LimitLevelsToImageSizeOff(); }
  void SetDownsampleKernel(int v) { this->Parameters->SetDownsampleKernel(v); }
  int GetDownsampleKernel() { return this->Parameters->GetDownsampleKernel(); }
  void SetKarisAverage(bool v) { this->Parameters->SetKarisAverage(v); }
  bool GetKarisAverage() { return this->Parameters->GetKarisAverage(); }
  void KarisAverageOn() { this->Parameters->KarisAverageOn(); }
  void KarisAverageOff() { this->Parameters->KarisAverageOff(); }
  void SetBlurKernel(int v) { this->Parameters->SetBlurKernel(v); }
  int GetBlurKernel() { return this->Parameters->GetBlurKernel(); }
  void SetBlurStandardDeviation(double v) { this->Parameters->SetBlurStandardDeviation(v); }
  double GetBlurStandardDeviation() { return this->Parameters->GetBlurStandardDeviation(); }
  void SetBlurRadius(int v) { this->Parameters->SetBlurRadius(v); }
  int GetBlurRadius() { return this->Parameters->GetBlurRadius(); }
  void SetBlurGaussianKind(int v) { this->Parameters->SetBlurGaussianKind(v); }
  int GetBlurGaussianKind() { return this->Parameters->GetBlurGaussianKind(); }
  void SetBlurTapSpacing(double v) { this->Parameters->SetBlurTapSpacing(v); }
  double GetBlurTapSpacing() { return this->Parameters->GetBlurTapSpacing(); }
  void SetBlurIterations(int v) { this->Parameters->SetBlurIterations(v); }
  int GetBlurIterations() { return this->Parameters->GetBlurIterations(); }
  void SetUpsampleKernel(int v) { this->Parameters->SetUpsampleKernel(v); }
  int GetUpsampleKernel() { return this->Parameters->GetUpsampleKernel(); }
  void SetAccumulateMode(int v) { this->Parameters->SetAccumulateMode(v); }
  int GetAccumulateMode() { return this->Parameters->GetAccumulateMode(); }
  void SetCompositeMode(int v) { this->Parameters->SetCompositeMode(v); }
  int GetCompositeMode() { return this->Parameters->GetCompositeMode(); }
  void SetStrength(double v) { this->Parameters->SetStrength(v); }
  double GetStrength() { return this->Parameters->GetStrength(); }
  void SetTint(double a, double b, double c) { this->Parameters->SetTint(a, b, c); }
  void SetTint(const double v[3]) { this->Parameters->SetTint(v[0], v[1], v[2]); }
  double* GetTint() VTK_SIZEHINT(3) { return this->Parameters->GetTint(); }
  void GetTint(double v[3]) { this->Parameters->GetTint(v); }
  void SetConvolutionMode(int v) { this->Parameters->SetConvolutionMode(v); }
  int GetConvolutionMode() { return this->Parameters->GetConvolutionMode(); }
  void SetSkipEmptyBloom(bool v) { this->Parameters->SetSkipEmptyBloom(v); }
  bool GetSkipEmptyBloom() { return this->Parameters->GetSkipEmptyBloom(); }
  void SkipEmptyBloomOn() { this->Parameters->SkipEmptyBloomOn(); }
  void SkipEmptyBloomOff() { this->Parameters->SkipEmptyBloomOff(); }
  void SetSkipDisabledEffects(bool v) { this->Parameters->SetSkipDisabledEffects(v); }
  bool GetSkipDisabledEffects() { return this->Parameters->GetSkipDisabledEffects(); }
  void SkipDisabledEffectsOn() { this->Parameters->SkipDisabledEffectsOn(); }
  void SkipDisabledEffectsOff() { this->Parameters->SkipDisabledEffectsOff(); }
  void SetTrimPyramid(bool v) { this->Parameters->SetTrimPyramid(v); }
  bool GetTrimPyramid() { return this->Parameters->GetTrimPyramid(); }
  void TrimPyramidOn() { this->Parameters->TrimPyramidOn(); }
  void TrimPyramidOff() { this->Parameters->TrimPyramidOff(); }
  void SetRestrictToBrightRegion(bool v) { this->Parameters->SetRestrictToBrightRegion(v); }
  bool GetRestrictToBrightRegion() { return this->Parameters->GetRestrictToBrightRegion(); }
  void RestrictToBrightRegionOn() { this->Parameters->RestrictToBrightRegionOn(); }
  void RestrictToBrightRegionOff() { this->Parameters->RestrictToBrightRegionOff(); }
  void SetSanitizeNonFinite(bool v) { this->Parameters->SetSanitizeNonFinite(v); }
  bool GetSanitizeNonFinite() { return this->Parameters->GetSanitizeNonFinite(); }
  void SanitizeNonFiniteOn() { this->Parameters->SanitizeNonFiniteOn(); }
  void SanitizeNonFiniteOff() { this->Parameters->SanitizeNonFiniteOff(); }
  void SetBloomModeToPyramid() { this->Parameters->SetBloomModeToPyramid(); }
  void SetBloomModeToPSF() { this->Parameters->SetBloomModeToPSF(); }
  void SetPSFGaussians(const std::vector<double>& sigmas, const std::vector<double>& weights)
  {
    this->Parameters->SetPSFGaussians(sigmas, weights);
  }
  const std::vector<double>& GetPSFGaussianSigmas() const
  {
    return this->Parameters->GetPSFGaussianSigmas();
  }
  const std::vector<double>& GetPSFGaussianWeights() const
  {
    return this->Parameters->GetPSFGaussianWeights();
  }
  void SetPSFImage(vtkImageData* image) { this->Parameters->SetPSFImage(image); }
  vtkImageData* GetPSFImage() { return this->Parameters->GetPSFImage(); }
  void SetBlurHalfKernel(int n, const double* weights)
  {
    this->Parameters->SetBlurHalfKernel(n, weights);
  }
  void SetBlurHalfKernel(const std::vector<double>& weights)
  {
    this->Parameters->SetBlurHalfKernel(weights);
  }
  const std::vector<double>& GetBlurHalfKernel() const
  {
    return this->Parameters->GetBlurHalfKernel();
  }
  std::vector<double> GetEffectiveBlurHalfKernel() const
  {
    return this->Parameters->GetEffectiveBlurHalfKernel();
  }
  void SetLevelWeight(int level, double weight) { this->Parameters->SetLevelWeight(level, weight); }
  double GetLevelWeight(int level) const { return this->Parameters->GetLevelWeight(level); }
  void SetLevelWeights(int n, const double* weights)
  {
    this->Parameters->SetLevelWeights(n, weights);
  }
  void SetLevelWeights(const std::vector<double>& weights)
  {
    this->Parameters->SetLevelWeights(weights);
  }
  const std::vector<double>& GetLevelWeights() const { return this->Parameters->GetLevelWeights(); }
  void SetConvolutionModeToAutomatic() { this->Parameters->SetConvolutionModeToAutomatic(); }
  void SetConvolutionModeToDirect() { this->Parameters->SetConvolutionModeToDirect(); }
  void SetConvolutionModeToFFT() { this->Parameters->SetConvolutionModeToFFT(); }
  /// As GetParameters()->SetPreset(name), with an unknown name reported by this filter.
  bool SetPreset(const char* name);
  static std::vector<std::string> GetPresetNames() { return vtkBloomParameters::GetPresetNames(); }
  std::vector<std::pair<int, int>> ComputeLevelSizes(int width, int height) const
  {
    return this->Parameters->ComputeLevelSizes(width, height);
  }
  ///@}

  /**
   * The normalized PSF of colour channel `channel` (0 red, 1 green, 2 blue) with the current
   * parameters, (2 radius + 1)^2 values, row-major, centred; empty, with an error, when the
   * parameters (or the PSF image) are invalid.
   */
  std::vector<double> ComputePSF(int channel, int& radius);

  /// Include the parameters' modification time.
  vtkMTimeType GetMTime() override;

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

protected:
  vtkImageBloom();
  ~vtkImageBloom() override;

  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  ///@{
  /**
   * The steps of RequestData. CheckInput: vtkErrorMacro and false for input the filter cannot
   * use. UpdateChain: rebuild the operators when a parameter or the size changed.
   * ExecuteFast: the fused float32 chain, false when it does not apply (see the class
   * description), with the number of levels it used and, in `measured`, whether its composite
   * measured the statistics (then already set). The REFERENCE chain, in double: ThresholdStep
   * (the bright pass at the start level into levels[0]; false, with levelsUsed, when there is
   * nothing to bloom), DownsampleStep, BlurStep and UpsampleStep (up and accumulate into `bloom`).
   */
  bool CheckInput(vtkImageData* input);
  void UpdateChain(int width, int height);
  bool ExecuteFast(vtkImageData* input, vtkInformation* outInfo, vtkImageData* output,
    int& levelsUsed, bool& measured);
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

  /**
   * Measure the statistics over the output's extent (unless the chain has, `measured`) and
   * attach them to its field data.
   */
  void ComputeOutputStatistics(
    vtkImageData* input, vtkImageData* output, int levelsUsed, bool measured);

  vtkSmartPointer<vtkBloomParameters> Parameters;
  bool ComputeStatistics;
  int ExecutionMode;
  bool UseAVX2;
  bool LastRunWasFast;
  bool LastBloomSkipped;
  bool LastPassedThrough;
  int LastLevelsBuilt;
  vtkIdType LastWorkspaceBytes;
  bool LastRunUsedAVX2;
  int LastFFTBlurs;
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
