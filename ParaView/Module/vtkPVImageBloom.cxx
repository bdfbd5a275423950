// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkPVImageBloom.h"

#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"

#include <algorithm>

vtkStandardNewMacro(vtkPVImageBloom);

//------------------------------------------------------------------------------
vtkPVImageBloom::vtkPVImageBloom()
  : Preset("custom")
{
  this->SetCustomParameters(nullptr);
}

//------------------------------------------------------------------------------
vtkPVImageBloom::~vtkPVImageBloom()
{
  if (this->CustomParameters && this->CustomObserver)
  {
    this->CustomParameters->RemoveObserver(this->CustomObserver);
  }
}

//------------------------------------------------------------------------------
void vtkPVImageBloom::SetPreset(const char* name)
{
  const std::string preset = name ? name : "";
  if (preset == this->Preset)
  {
    return;
  }
  const auto names = vtkBloomParameters::GetPresetNames();
  if (preset != "custom" && std::find(names.begin(), names.end(), preset) == names.end())
  {
    vtkErrorMacro(<< "Unknown bloom preset '" << preset << "'; expected custom, "
                  << vtkBloomParameters::GetPresetNamesList() << ".");
    return;
  }
  this->Preset = preset;
  this->UpdateParameters();
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkPVImageBloom::SetCustomParameters(vtkBloomParameters* parameters)
{
  if (parameters && parameters == this->CustomParameters)
  {
    return;
  }
  if (this->CustomParameters && this->CustomObserver)
  {
    this->CustomParameters->RemoveObserver(this->CustomObserver);
  }
  this->CustomParameters =
    parameters ? parameters : vtkSmartPointer<vtkBloomParameters>::New().Get();
  this->CustomObserver = this->CustomParameters->AddObserver(
    vtkCommand::ModifiedEvent, this, &vtkPVImageBloom::UpdateParameters);
  this->UpdateParameters();
}

//------------------------------------------------------------------------------
void vtkPVImageBloom::UpdateParameters()
{
  vtkNew<vtkBloomParameters> effective;
  effective->DeepCopy(this->CustomParameters);
  if (this->Preset != "custom")
  {
    effective->SetPreset(this->Preset.c_str());
  }
  // Calls Modified() only when a parameter changed.
  this->GetParameters()->DeepCopy(effective);
}

//------------------------------------------------------------------------------
int vtkPVImageBloom::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkImageData* input = vtkImageData::GetData(inputVector[0]);
  vtkInformationVector* arrays = this->GetInformation()->Get(INPUT_ARRAYS_TO_PROCESS());
  vtkDataArray* chosen = input && arrays && arrays->GetNumberOfInformationObjects() > 0
    ? this->GetInputArrayToProcess(0, inputVector)
    : nullptr;
  if (!chosen || chosen == input->GetPointData()->GetScalars())
  {
    return this->Superclass::RequestData(request, inputVector, outputVector);
  }
  vtkNew<vtkImageData> view;
  view->ShallowCopy(input);
  view->GetPointData()->SetScalars(chosen);
  vtkNew<vtkInformation> info;
  info->Copy(inputVector[0]->GetInformationObject(0));
  info->Set(vtkDataObject::DATA_OBJECT(), view);
  vtkNew<vtkInformationVector> viewVector;
  viewVector->Append(info);
  vtkInformationVector* viewInputs[1] = { viewVector };
  return this->Superclass::RequestData(request, viewInputs, outputVector);
}

//------------------------------------------------------------------------------
void vtkPVImageBloom::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Preset: " << this->Preset << "\n";
  os << indent << "CustomParameters: " << this->CustomParameters.Get() << "\n";
}
