// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkPVBloomParameters
 * @brief   The hand-set parameters of the plugin's Bloom filter and bloom view.
 *
 * The vtkBloomParameters of vtkPVImageBloom's CustomParameters. It adds what ParaView's vector
 * properties need to set the two weight lists element by element: a count, then one call per
 * element with its index.
 */

#ifndef vtkPVBloomParameters_h
#define vtkPVBloomParameters_h

#include "vtkBloomParameters.h"
#include "vtkParaViewBloomModule.h" // For export macro

class VTKPARAVIEWBLOOM_EXPORT vtkPVBloomParameters : public vtkBloomParameters
{
public:
  static vtkPVBloomParameters* New();
  vtkTypeMacro(vtkPVBloomParameters, vtkBloomParameters);

  /// Resize the per-level weights; new levels weigh 1. Zero clears them (every level weighs 1).
  void SetNumberOfLevelWeights(int n);

  ///@{
  /// Resize the custom blur half kernel (new taps weigh 0), and set one tap (centre first).
  void SetNumberOfBlurHalfKernelWeights(int n);
  void SetBlurHalfKernelWeight(int i, double weight);
  ///@}

protected:
  vtkPVBloomParameters() = default;
  ~vtkPVBloomParameters() override = default;

private:
  vtkPVBloomParameters(const vtkPVBloomParameters&) = delete;
  void operator=(const vtkPVBloomParameters&) = delete;
};

#endif
