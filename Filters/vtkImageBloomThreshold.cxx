// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkImageBloomThreshold.h"

#include "vtkBloomPieces.h"

#include "vtkBloomBrightPass.h"
#include "vtkImageData.h"
#include "vtkImageSeparableAlgorithm.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkImageBloomThreshold);

namespace
{
template <typename T>
void vtkImageBloomThresholdExecute(vtkImageBloomThreshold* self, vtkImageData* inData,
  vtkImageData* outData, const int outExt[6], int threadId)
{
  const int nc = inData->GetNumberOfScalarComponents();
  const int colours = nc >= 3 ? 3 : 1;
  const int mode = self->GetMode();
  const double threshold = self->GetThreshold();
  const double knee = self->GetKnee();
  const double clampLuminance = self->GetClampLuminance();
  const vtkIdType rows =
    static_cast<vtkIdType>(outExt[3] - outExt[2] + 1) * (outExt[5] - outExt[4] + 1);
  const vtkIdType progressStep = rows / 50 + 1;
  vtkIdType row = 0;
  for (int k = outExt[4]; k <= outExt[5]; ++k)
  {
    for (int j = outExt[2]; j <= outExt[3]; ++j, ++row)
    {
      if (self->AbortExecute)
      {
        return;
      }
      if (threadId == 0 && row % progressStep == 0)
      {
        self->UpdateProgress(static_cast<double>(row) / rows);
      }
      const T* in = static_cast<const T*>(inData->GetScalarPointer(outExt[0], j, k));
      T* out = static_cast<T*>(outData->GetScalarPointer(outExt[0], j, k));
      for (int i = outExt[0]; i <= outExt[1]; ++i, in += nc, out += nc)
      {
        double colour[3];
        for (int c = 0; c < colours; ++c)
        {
          colour[c] = static_cast<double>(in[c]);
        }
        vtkImageBloomThreshold::BrightPass(colour, colours, mode, threshold, knee, clampLuminance);
        for (int c = 0; c < colours; ++c)
        {
          out[c] = static_cast<T>(colour[c]);
        }
        for (int c = colours; c < nc; ++c)
        {
          out[c] = in[c];
        }
      }
    }
  }
}
}

//------------------------------------------------------------------------------
vtkImageBloomThreshold::vtkImageBloomThreshold()
{
  this->Mode = SMOOTHSTEP_KNEE;
  this->Threshold = 1.0;
  this->Knee = 0.5;
  this->ClampLuminance = VTK_FLOAT_MAX;
}

//------------------------------------------------------------------------------
vtkImageBloomThreshold::~vtkImageBloomThreshold() = default;

//------------------------------------------------------------------------------
const char* vtkImageBloomThreshold::GetModeName(int mode)
{
  switch (mode)
  {
    case SMOOTHSTEP_KNEE:
      return "SmoothstepKnee";
    case QUADRATIC_KNEE:
      return "QuadraticKnee";
    case HARD_LUMINANCE:
      return "HardLuminance";
    case PER_CHANNEL:
      return "PerChannel";
    case NONE:
      return "None";
    case EXCESS_KNEE:
      return "ExcessKnee";
    default:
      return "Unknown";
  }
}

//------------------------------------------------------------------------------
void vtkImageBloomThreshold::BrightPass(
  double* colour, int n, int mode, double threshold, double knee, double clampLuminance)
{
  switch (n)
  {
    case 1:
      vtkBloomBrightPass<1>(colour, mode, threshold, knee, clampLuminance);
      break;
    case 2:
      vtkBloomBrightPass<2>(colour, mode, threshold, knee, clampLuminance);
      break;
    case 3:
      vtkBloomBrightPass<3>(colour, mode, threshold, knee, clampLuminance);
      break;
    default:
      vtkBloomBrightPass<4>(colour, mode, threshold, knee, clampLuminance);
      break;
  }
}

//------------------------------------------------------------------------------
int vtkImageBloomThreshold::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  int extent[6];
  vtkBloomExecutionExtent(outputVector->GetInformationObject(0), extent);
  vtkBloomRequestExactExtent(inputVector[0]->GetInformationObject(0), extent);
  return 1;
}

//------------------------------------------------------------------------------
int vtkImageBloomThreshold::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkImageData* input = vtkImageData::GetData(inputVector[0]);
  vtkImageData* output = vtkImageData::GetData(outputVector);
  if (!input || !input->GetPointData()->GetScalars() ||
    !vtkImageSeparableAlgorithm::IsSupportedInput(
      input->GetScalarType(), input->GetNumberOfScalarComponents()))
  {
    vtkErrorMacro(<< "Input scalars must be float or double with 1 to 4 components"
                  << (input && input->GetPointData()->GetScalars()
                         ? std::string("; got ") + input->GetScalarTypeAsString() + " with " +
                           std::to_string(input->GetNumberOfScalarComponents()) + " components."
                         : std::string("; the input has no scalars.")));
    output->Initialize();
    return 0;
  }
  if (!std::isfinite(this->Threshold))
  {
    vtkErrorMacro(<< "Threshold must be finite; got " << this->Threshold << ".");
    output->Initialize();
    return 0;
  }
  vtkBloomMatchOutputScalars(outputVector->GetInformationObject(0), input);
  return this->Superclass::RequestData(request, inputVector, outputVector);
}

//------------------------------------------------------------------------------
void vtkImageBloomThreshold::ThreadedRequestData(vtkInformation*, vtkInformationVector**,
  vtkInformationVector*, vtkImageData*** inData, vtkImageData** outData, int outExt[6],
  int threadId)
{
  if (outExt[0] > outExt[1] || outExt[2] > outExt[3] || outExt[4] > outExt[5])
  {
    return;
  }
  switch (inData[0][0]->GetScalarType())
  {
    case VTK_FLOAT:
      vtkImageBloomThresholdExecute<float>(this, inData[0][0], outData[0], outExt, threadId);
      break;
    case VTK_DOUBLE:
      vtkImageBloomThresholdExecute<double>(this, inData[0][0], outData[0], outExt, threadId);
      break;
    default:
      vtkErrorMacro(<< "Unsupported scalar type " << inData[0][0]->GetScalarTypeAsString());
      break;
  }
}

//------------------------------------------------------------------------------
void vtkImageBloomThreshold::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Mode: " << this->GetModeAsString() << "\n";
  os << indent << "Threshold: " << this->Threshold << "\n";
  os << indent << "Knee: " << this->Knee << "\n";
  os << indent << "ClampLuminance: " << this->ClampLuminance << "\n";
}
