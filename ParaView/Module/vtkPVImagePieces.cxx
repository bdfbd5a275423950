// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkPVImagePieces.h"

#include "vtkFieldData.h"

#include "vtkImageAppend.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include <algorithm>

vtkStandardNewMacro(vtkPVImagePieces);

//------------------------------------------------------------------------------
vtkPVImagePieces::vtkPVImagePieces()
{
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(1);
}

//------------------------------------------------------------------------------
int vtkPVImagePieces::FillInputPortInformation(int port, vtkInformation* info)
{
  this->Superclass::FillInputPortInformation(port, info);
  info->Set(vtkAlgorithm::INPUT_IS_REPEATABLE(), 1);
  return 1;
}

//------------------------------------------------------------------------------
int vtkPVImagePieces::RequestInformation(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  // The helpers run on data objects set directly; the whole extent is each input's own.
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  int whole[6] = { 0, -1, 0, -1, 0, -1 };
  for (int i = 0; i < inputVector[0]->GetNumberOfInformationObjects(); ++i)
  {
    int ext[6];
    inputVector[0]->GetInformationObject(i)->Get(
      vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), ext);
    for (int a = 0; a < 3; ++a)
    {
      const bool first = whole[2 * a] > whole[2 * a + 1];
      whole[2 * a] = first ? ext[2 * a] : std::min(whole[2 * a], ext[2 * a]);
      whole[2 * a + 1] = first ? ext[2 * a + 1] : std::max(whole[2 * a + 1], ext[2 * a + 1]);
    }
  }
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), whole, 6);
  return 1;
}

//------------------------------------------------------------------------------
int vtkPVImagePieces::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  for (int i = 0; i < inputVector[0]->GetNumberOfInformationObjects(); ++i)
  {
    vtkInformation* inInfo = inputVector[0]->GetInformationObject(i);
    int ext[6];
    inInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), ext);
    inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), ext, 6);
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkPVImagePieces::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkImageData* output = vtkImageData::GetData(outputVector);
  const int inputs = inputVector[0]->GetNumberOfInformationObjects();
  if (this->Mode == TAG)
  {
    vtkImageData* input = vtkImageData::GetData(inputVector[0]);
    if (!input)
    {
      vtkErrorMacro(<< "TAG needs one image.");
      return 0;
    }
    output->ShallowCopy(input);
    vtkNew<vtkIntArray> extent;
    extent->SetName(GetExtentArrayName());
    extent->SetNumberOfValues(6);
    for (int i = 0; i < 6; ++i)
    {
      extent->SetValue(i, input->GetExtent()[i]);
    }
    output->GetFieldData()->AddArray(extent);
    return 1;
  }

  vtkNew<vtkImageAppend> append;
  append->PreserveExtentsOn();
  for (int i = 0; i < inputs; ++i)
  {
    vtkImageData* piece = vtkImageData::GetData(inputVector[0], i);
    if (!piece || piece->GetNumberOfPoints() == 0)
    {
      continue; // a rank with no piece
    }
    vtkNew<vtkImageData> placed;
    placed->ShallowCopy(piece);
    auto* tag =
      vtkIntArray::SafeDownCast(piece->GetFieldData()->GetAbstractArray(GetExtentArrayName()));
    if (tag && tag->GetNumberOfValues() == 6)
    {
      int ext[6];
      for (int a = 0; a < 6; ++a)
      {
        ext[a] = tag->GetValue(a);
      }
      const int* dims = piece->GetDimensions();
      if (ext[1] - ext[0] + 1 != dims[0] || ext[3] - ext[2] + 1 != dims[1] ||
        ext[5] - ext[4] + 1 != dims[2])
      {
        vtkErrorMacro(<< "Piece " << i << "'s tagged extent does not match its size.");
        return 0;
      }
      // The legacy format moved the piece's first sample to index 0 at the same position.
      double origin[3];
      piece->GetOrigin(origin);
      const double* spacing = piece->GetSpacing();
      for (int a = 0; a < 3; ++a)
      {
        origin[a] -= ext[2 * a] * spacing[a];
      }
      placed->SetOrigin(origin);
      placed->SetExtent(ext);
      placed->GetFieldData()->RemoveArray(GetExtentArrayName());
    }
    append->AddInputData(placed);
  }
  if (append->GetNumberOfInputConnections(0) == 0)
  {
    output->Initialize();
    return 1;
  }
  append->Update();
  output->ShallowCopy(append->GetOutput());
  return 1;
}

//------------------------------------------------------------------------------
void vtkPVImagePieces::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Mode: " << (this->Mode == TAG ? "TAG" : "ASSEMBLE") << "\n";
}
