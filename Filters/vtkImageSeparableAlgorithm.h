// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkImageSeparableAlgorithm
 * @brief   Abstract base of filters that are a weighted sum of separable linear operators.
 *
 * A subclass describes its output as sum_t w_t (Z_t Y_t X_t) input, where X_t, Y_t and Z_t are
 * one-dimensional vtkBloomLinearOperator instances built from the whole extents (so borders
 * behave the same in every streamed piece). This class then:
 * - grows the input UPDATE_EXTENT by exactly the support of those operators, clamped to the
 *   whole extent, so that a streamed piece equals the whole-image result bit for bit;
 * - checks the input (float or double scalars, 1 to 4 components) and reports anything else
 *   with vtkErrorMacro, leaving the output empty;
 * - runs the passes on each thread's piece in double precision and writes the input's type.
 *
 * Subclasses that combine the terms non-linearly (the Karis average of vtkImagePyramidDown)
 * override CombineTerms.
 */

#ifndef vtkImageSeparableAlgorithm_h
#define vtkImageSeparableAlgorithm_h

#include "vtkBloomLinearOperator.h" // For the operators
#include "vtkFiltersBloomModule.h"  // For export macro
#include "vtkThreadedImageAlgorithm.h"

#include <vector> // For the terms

struct vtkBloomBuffer;

class VTKFILTERSBLOOM_EXPORT vtkImageSeparableAlgorithm : public vtkThreadedImageAlgorithm
{
public:
  vtkTypeMacro(vtkImageSeparableAlgorithm, vtkThreadedImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * True when `scalarType` and `numberOfComponents` are supported by the bloom filters
   * (VTK_FLOAT or VTK_DOUBLE, 1 to 4 components).
   */
  static bool IsSupportedInput(int scalarType, int numberOfComponents);

protected:
  vtkImageSeparableAlgorithm();
  ~vtkImageSeparableAlgorithm() override;

  /// One term: Weight * (Z Y X); an axis whose Use flag is false is the identity.
  struct Term
  {
    double Weight = 1.0;
    vtkBloomLinearOperator Operators[3];
    bool Use[3] = { false, false, false };
  };

  /**
   * Fill `terms` for mapping an input of whole extent `inWhole` to an output of whole extent
   * `outWhole` (both inclusive). Return false, after vtkErrorMacro, if the parameters are
   * invalid.
   */
  virtual bool BuildTerms(
    const int inWhole[6], const int outWhole[6], std::vector<Term>& terms) = 0;

  /**
   * Combine the results of the terms (one buffer per term, all of the output piece's shape)
   * into `out`. The default is the weighted sum.
   */
  virtual void CombineTerms(const std::vector<vtkBloomBuffer>& results, vtkBloomBuffer& out);

  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  void ThreadedRequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector, vtkImageData*** inData, vtkImageData** outData,
    int outExt[6], int threadId) override;

  /// The input extent the terms read to produce `outExt` (all extents absolute, inclusive).
  static void ComputeInputExtent(const std::vector<Term>& terms, const int inWhole[6],
    const int outWhole[6], const int outExt[6], int inExt[6]);

  /// Terms for the current execution, built once in RequestData before threads start.
  std::vector<Term> Terms;
  int InputWholeExtent[6];
  int OutputWholeExtent[6];

private:
  vtkImageSeparableAlgorithm(const vtkImageSeparableAlgorithm&) = delete;
  void operator=(const vtkImageSeparableAlgorithm&) = delete;
};

#endif
