// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkPVImageBloom
 * @brief   vtkImageBloom for ParaView: a preset name over a set of hand-set parameters.
 *
 * ParaView pushes a proxy's properties in the alphabetical order of their names, and pushes
 * all of them when the proxy is created, so a "Preset" property calling
 * vtkImageBloom::SetPreset would be undone by whichever parameter properties sort after it.
 * This filter keeps the two apart:
 *
 * - the hand-set parameters live in a separate vtkBloomParameters, CustomParameters (in the
 *   plugin, a sub-proxy whose properties the Bloom proxy exposes);
 * - Preset is "custom" (the parameters as set) or a name of
 *   vtkBloomParameters::GetPresetNames().
 *
 * Whenever either changes, the parameters this filter runs with (GetParameters()) are
 * rebuilt: a copy of the custom parameters, then SetPreset(Preset) unless the preset is
 * "custom". A preset defines the bloom's shape (bright pass, pyramid, blur, composite), exactly
 * as `vtk-bloom image --preset NAME` does; what no preset sets (convolution mode, skipping and
 * sanitizing options, the PSF parameters) stays as set. Parameters are copied with
 * vtkBloomParameters::DeepCopy, so an unchanged configuration does not re-execute. The bloom
 * render view (vtkPVBloomRenderView) resolves its preset with one of these too, and gives its
 * pass the resolved parameters.
 *
 * The filter blooms the point array chosen with SetInputArrayToProcess(0, ...) (ParaView's
 * "Scalars" property), or the active scalars when none is chosen.
 */

#ifndef vtkPVImageBloom_h
#define vtkPVImageBloom_h

#include "vtkImageBloom.h"
#include "vtkParaViewBloomModule.h" // For export macro
#include "vtkSmartPointer.h"        // For CustomParameters

#include <string> // For Preset

class VTKPARAVIEWBLOOM_EXPORT vtkPVImageBloom : public vtkImageBloom
{
public:
  static vtkPVImageBloom* New();
  vtkTypeMacro(vtkPVImageBloom, vtkImageBloom);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * "custom" (default) or a preset name. An unknown name is an error and leaves the preset
   * unchanged. (This hides vtkImageBloom::SetPreset, which applies a preset once.)
   */
  void SetPreset(const char* name);
  const char* GetPreset() const { return this->Preset.c_str(); }
  ///@}

  ///@{
  /**
   * The hand-set parameters; a new filter holds a default set. Setting null restores such a
   * default set.
   */
  void SetCustomParameters(vtkBloomParameters* parameters);
  vtkBloomParameters* GetCustomParameters() { return this->CustomParameters; }
  ///@}

protected:
  vtkPVImageBloom();
  ~vtkPVImageBloom() override;

  /// Rebuild the parameters this filter runs with from CustomParameters and Preset.
  void UpdateParameters();

  /// Bloom the chosen array: the input, shallow-copied with it as the active scalars.
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  std::string Preset;
  vtkSmartPointer<vtkBloomParameters> CustomParameters;
  unsigned long CustomObserver = 0;

private:
  vtkPVImageBloom(const vtkPVImageBloom&) = delete;
  void operator=(const vtkPVImageBloom&) = delete;
};

#endif
