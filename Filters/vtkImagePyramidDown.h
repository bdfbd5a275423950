// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkImagePyramidDown
 * @brief   Halve an image in X and Y with a bloom-pyramid downsampling kernel.
 *
 * Each axis of size n becomes max(1, floor(n / 2)); Z is unchanged. Output pixel j samples the
 * input at the GPU position p = (j + 1/2) n / n' - 1/2 (in input pixels), so the output covers
 * exactly the input's footprint, and bilinear taps are placed around p:
 *
 * - JIMENEZ13 (default): the 13-tap filter of Jimenez (2014, CoD: Advanced Warfare): centre 1/8,
 *   four inner taps at (+-1/2, +-1/2) 1/8 each, four edge taps at distance 1 1/16 each, four
 *   corners 1/32 each. The weights sum to 1 (seed 000 sums them to 1.375). With KarisAverage on,
 *   the five 2x2 boxes are weighted by 1/(1 + max(luma, 0)) before averaging (and the weights
 *   renormalized), which suppresses fireflies in the first level (Karis 2013).
 * - BOX: the exact area-weighted resample; each input pixel is weighted by its overlap with
 *   the output pixel, so the mean is preserved for odd sizes as well (a 2x2 box for even ones).
 * - BINOMIAL: a 5-tap binomial 1 4 6 4 1 / 16 at integer offsets from p; with p half-way
 *   between input pixels that is the 6-tap binomial 1 5 10 10 5 1 / 32, centred on the
 *   footprint.
 *
 * Fetches clamp to the edge. Geometry: the output spacing is s n / n' (exactly twice the input
 * spacing for even sizes) and the origin is placed so that both images cover the same physical
 * footprint. The output extent starts at floor(start / 2).
 *
 * Input must be float or double with 1 to 4 components; every component is filtered (the
 * Karis weight uses the Rec. 709 luminance of RGB, or component 0 for 1-2 components).
 */

#ifndef vtkImagePyramidDown_h
#define vtkImagePyramidDown_h

#include "vtkFiltersBloomModule.h" // For export macro
#include "vtkImageSeparableAlgorithm.h"

class VTKFILTERSBLOOM_EXPORT vtkImagePyramidDown : public vtkImageSeparableAlgorithm
{
public:
  static vtkImagePyramidDown* New();
  vtkTypeMacro(vtkImagePyramidDown, vtkImageSeparableAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum KernelTypes
  {
    JIMENEZ13 = 0,
    BOX = 1,
    BINOMIAL = 2
  };

  ///@{
  /// The downsampling kernel: JIMENEZ13 (default), BOX or BINOMIAL.
  vtkSetClampMacro(Kernel, int, JIMENEZ13, BINOMIAL);
  vtkGetMacro(Kernel, int);
  void SetKernelToJimenez13() { this->SetKernel(JIMENEZ13); }
  void SetKernelToBox() { this->SetKernel(BOX); }
  void SetKernelToBinomial() { this->SetKernel(BINOMIAL); }
  const char* GetKernelAsString();
  ///@}

  ///@{
  /// Karis average of the 13-tap boxes (only with JIMENEZ13). Default off.
  vtkSetMacro(KarisAverage, bool);
  vtkGetMacro(KarisAverage, bool);
  vtkBooleanMacro(KarisAverage, bool);
  ///@}

  /// The size of one axis after halving: max(1, floor(n / 2)).
  static int HalvedSize(int n) { return n / 2 > 1 ? n / 2 : 1; }

  /**
   * Output whole extent, origin and spacing for an input geometry: X and Y halved, Z kept, the
   * physical footprint unchanged.
   */
  static void ComputeOutputGeometry(const int inExtent[6], const double inOrigin[3],
    const double inSpacing[3], int outExtent[6], double outOrigin[3], double outSpacing[3]);

protected:
  vtkImagePyramidDown();
  ~vtkImagePyramidDown() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  bool BuildTerms(const int inWhole[6], const int outWhole[6], std::vector<Term>& terms) override;
  void CombineTerms(const std::vector<vtkBloomBuffer>& results, vtkBloomBuffer& out) override;

  int Kernel;
  bool KarisAverage;

private:
  vtkImagePyramidDown(const vtkImagePyramidDown&) = delete;
  void operator=(const vtkImagePyramidDown&) = delete;
};

#endif
