// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkImagePyramidUp
 * @brief   Upsample a coarse pyramid level onto the geometry of a finer one, optionally adding it.
 *
 * Input 0 is the coarse image; input 1 is the finer level whose whole extent, origin and
 * spacing the output takes. Output pixel j samples the coarse image at the GPU position
 * p = (j + 1/2) n_c / n_f - 1/2 (in coarse pixels), so footprints line up exactly with
 * vtkImagePyramidDown, and the result is
 *
 *   out = CoarseWeight * up(coarse) + FineWeight * fine
 *
 * where up() is TENT (default: the 3x3 tent 1 2 1 / 2 4 2 / 1 2 1 over 16 with taps one coarse
 * pixel apart, each a bilinear fetch; Jimenez 2014) or BILINEAR (a single bilinear fetch).
 * Fetches clamp to the edge. With FineWeight = 0 (the default) the finer image only supplies
 * the geometry. Z sizes of the two inputs must match. Both inputs must be float or double with
 * the same number of components (1 to 4); the output has the type of input 0.
 */

#ifndef vtkImagePyramidUp_h
#define vtkImagePyramidUp_h

#include "vtkFiltersBloomModule.h" // For export macro
#include "vtkImageSeparableAlgorithm.h"

class VTKFILTERSBLOOM_EXPORT vtkImagePyramidUp : public vtkImageSeparableAlgorithm
{
public:
  static vtkImagePyramidUp* New();
  vtkTypeMacro(vtkImagePyramidUp, vtkImageSeparableAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum KernelTypes
  {
    TENT = 0,
    BILINEAR = 1
  };

  ///@{
  /// The finer level: its geometry defines the output (input port 1).
  void SetFineInputConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }
  void SetFineInputData(vtkDataObject* image) { this->SetInputData(1, image); }
  ///@}

  ///@{
  /// The upsampling kernel: TENT (default) or BILINEAR.
  vtkSetClampMacro(Kernel, int, TENT, BILINEAR);
  vtkGetMacro(Kernel, int);
  void SetKernelToTent() { this->SetKernel(TENT); }
  void SetKernelToBilinear() { this->SetKernel(BILINEAR); }
  const char* GetKernelAsString();
  ///@}

  ///@{
  /// Weight of the upsampled coarse image. Default 1.
  vtkSetMacro(CoarseWeight, double);
  vtkGetMacro(CoarseWeight, double);
  ///@}

  ///@{
  /// Weight of the finer image added in the same pass. Default 0 (not added).
  vtkSetMacro(FineWeight, double);
  vtkGetMacro(FineWeight, double);
  ///@}

protected:
  vtkImagePyramidUp();
  ~vtkImagePyramidUp() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  bool BuildTerms(const int inWhole[6], const int outWhole[6], std::vector<Term>& terms) override;
  void ThreadedRequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector, vtkImageData*** inData, vtkImageData** outData,
    int outExt[6], int threadId) override;

  int Kernel;
  double CoarseWeight;
  double FineWeight;

private:
  vtkImagePyramidUp(const vtkImagePyramidUp&) = delete;
  void operator=(const vtkImagePyramidUp&) = delete;
};

#endif
