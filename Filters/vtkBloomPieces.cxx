// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkBloomPieces.h"

#include "vtkAlgorithm.h"
#include "vtkDataObject.h"
#include "vtkExtentTranslator.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationIntegerRequestKey.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

//------------------------------------------------------------------------------
void vtkBloomExecutionExtent(vtkInformation* outInfo, int extent[6])
{
  using SDDP = vtkStreamingDemandDrivenPipeline;
  outInfo->Set(vtkAlgorithm::CAN_PRODUCE_SUB_EXTENT(), 1);
  outInfo->Get(SDDP::UPDATE_EXTENT(), extent);
  const int pieces = outInfo->Has(SDDP::UPDATE_NUMBER_OF_PIECES())
    ? outInfo->Get(SDDP::UPDATE_NUMBER_OF_PIECES())
    : 1;
  if (pieces <= 1)
  {
    return;
  }
  const int piece = outInfo->Get(SDDP::UPDATE_PIECE_NUMBER());
  int splitMode = vtkExtentTranslator::BLOCK_MODE;
  if (outInfo->Has(vtkExtentTranslator::UPDATE_SPLIT_MODE()))
  {
    splitMode = outInfo->Get(vtkExtentTranslator::UPDATE_SPLIT_MODE());
  }
  int all[6];
  outInfo->Get(SDDP::UPDATE_EXTENT(), all);
  vtkNew<vtkExtentTranslator> translator;
  translator->PieceToExtentThreadSafe(piece, pieces, 0, all, extent, splitMode, 0);
}

//------------------------------------------------------------------------------
void vtkBloomRequestExactExtent(vtkInformation* inInfo, const int extent[6])
{
  using SDDP = vtkStreamingDemandDrivenPipeline;
  inInfo->Set(SDDP::UPDATE_EXTENT(), extent, 6);
  inInfo->Set(SDDP::UPDATE_PIECE_NUMBER(), 0);
  inInfo->Set(SDDP::UPDATE_NUMBER_OF_PIECES(), 1);
  inInfo->Set(SDDP::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
}

//------------------------------------------------------------------------------
void vtkBloomMatchOutputScalars(vtkInformation* outInfo, vtkImageData* input)
{
  if (input && input->GetPointData()->GetScalars())
  {
    vtkDataObject::SetPointDataActiveScalarInfo(
      outInfo, input->GetScalarType(), input->GetNumberOfScalarComponents());
  }
}
