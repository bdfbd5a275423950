#include "vtkImageBloomThreshold.h"

#include "vtkBloomKernels.h"
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
double Smoothstep(double edge0, double edge1, double x)
{
  const double t = std::min(std::max((x - edge0) / (edge1 - edge0), 0.0), 1.0);
  return t * t * (3.0 - 2.0 * t);
}

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
    default:
      return "Unknown";
  }
}

//------------------------------------------------------------------------------
void vtkImageBloomThreshold::BrightPass(
  double* colour, int n, int mode, double threshold, double knee, double clampLuminance)
{
  if (mode == NONE)
  {
    return;
  }
  const double ceiling = std::min(clampLuminance, static_cast<double>(VTK_FLOAT_MAX));
  for (int c = 0; c < n; ++c)
  {
    if (std::isnan(colour[c]))
    {
      colour[c] = 0.0;
    }
    else if (std::isinf(colour[c]))
    {
      colour[c] = colour[c] > 0.0 ? ceiling : 0.0;
    }
  }
  auto luminance = [&]()
  {
    return n == 3 ? vtkBloomKernels::LuminanceR * colour[0] +
        vtkBloomKernels::LuminanceG * colour[1] + vtkBloomKernels::LuminanceB * colour[2]
                  : colour[0];
  };

  // Firefly guard: scale the colour so its luminance does not exceed the clamp.
  double lum = luminance();
  if (lum > clampLuminance)
  {
    const double scale = clampLuminance / lum;
    for (int c = 0; c < n; ++c)
    {
      colour[c] *= scale;
    }
    lum = luminance();
  }

  const double k = threshold * knee;
  double factor = 1.0;
  switch (mode)
  {
    case SMOOTHSTEP_KNEE:
      factor = k > 0.0 ? Smoothstep(threshold - k, threshold + k, lum) : (lum >= threshold ? 1 : 0);
      break;
    case QUADRATIC_KNEE:
    {
      double brightness = colour[0];
      for (int c = 1; c < n; ++c)
      {
        brightness = std::max(brightness, colour[c]);
      }
      double q = std::min(std::max(brightness - threshold + k, 0.0), 2.0 * k);
      q = q * q / (4.0 * k + 1e-5);
      factor = std::max(q, brightness - threshold) / std::max(brightness, 1e-5);
      break;
    }
    case HARD_LUMINANCE:
      factor = lum > threshold ? 1.0 : 0.0;
      break;
    case PER_CHANNEL:
      for (int c = 0; c < n; ++c)
      {
        colour[c] = std::max(colour[c] - threshold, 0.0);
      }
      return;
    default:
      break;
  }
  for (int c = 0; c < n; ++c)
  {
    colour[c] = std::max(colour[c] * factor, 0.0);
  }
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
