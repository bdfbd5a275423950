// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkOpenEXRReader.h"

#include "vtkErrorCode.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenEXRDWA.h"
#include "vtkOpenEXRDecode.h"
#include "vtkOpenEXRHeader.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"
#include "vtkUnsignedIntArray.h"

#include <cstdlib>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkOpenEXRReader);

namespace
{
//------------------------------------------------------------------------------
// The output array, allocated by us so that a failed allocation is an error, not an abort.
// Its pages are touched only as chunks decode, so a file that fails part-way costs only what
// it decoded.
vtkSmartPointer<vtkDataArray> AllocateScalars(
  const vtkOpenEXRHeader& header, vtkOpenEXRFailure& failure)
{
  const size_t values = static_cast<size_t>(header.Width) * static_cast<size_t>(header.Height) *
    static_cast<size_t>(header.NumberOfComponents);
  void* memory = std::malloc(values * 4);
  if (!memory)
  {
    failure.Set(vtkErrorCode::UnknownError, "out of memory");
    return nullptr;
  }
  vtkSmartPointer<vtkDataArray> scalars;
  if (header.ScalarType == VTK_UNSIGNED_INT)
  {
    vtkNew<vtkUnsignedIntArray> array;
    array->SetNumberOfComponents(header.NumberOfComponents);
    array->SetArray(static_cast<unsigned int*>(memory), static_cast<vtkIdType>(values), 0,
      vtkAbstractArray::VTK_DATA_ARRAY_FREE);
    scalars = array;
  }
  else
  {
    vtkNew<vtkFloatArray> array;
    array->SetNumberOfComponents(header.NumberOfComponents);
    array->SetArray(static_cast<float*>(memory), static_cast<vtkIdType>(values), 0,
      vtkAbstractArray::VTK_DATA_ARRAY_FREE);
    scalars = array;
  }
  return scalars;
}

//------------------------------------------------------------------------------
vtkOpenEXRLimits Limits(vtkOpenEXRReader* reader)
{
  vtkOpenEXRLimits limits;
  limits.MaximumImageBytes = reader->GetMaximumImageBytes();
  limits.MaximumImagePixels = reader->GetMaximumImagePixels();
  return limits;
}
}

//------------------------------------------------------------------------------
class vtkOpenEXRReader::vtkInternals
{
public:
  vtkOpenEXRHeader Header;
  bool HeaderValid = false;
  vtkNew<vtkStringArray> ChannelNames;
  vtkNew<vtkStringArray> ComponentNames;
};

//------------------------------------------------------------------------------
vtkOpenEXRReader::vtkOpenEXRReader()
  : FileName(nullptr)
  , PartIndex(0)
  , PartName(nullptr)
  , Layer(nullptr)
  , MaximumImageBytes(vtkTypeUInt64(4) << 30)
  , MaximumImagePixels(vtkTypeUInt64(1) << 28)
  , SelectedPartIndex(-1)
  , DataWindow{ 0, -1, 0, -1 }
  , DisplayWindow{ 0, -1, 0, -1 }
  , Internals(new vtkInternals)
{
  this->SetNumberOfInputPorts(0);
}

//------------------------------------------------------------------------------
vtkOpenEXRReader::~vtkOpenEXRReader()
{
  this->SetFileName(nullptr);
  this->SetPartName(nullptr);
  this->SetLayer(nullptr);
}

//------------------------------------------------------------------------------
int vtkOpenEXRReader::CanReadFile(const char* fname)
{
  if (!fname)
  {
    return 0;
  }
  vtkOpenEXRCoreFile file;
  vtkOpenEXRFailure failure;
  return file.Open(fname, failure) ? 3 : 0;
}

//------------------------------------------------------------------------------
int vtkOpenEXRReader::GetNumberOfParts()
{
  return static_cast<int>(this->Internals->Header.PartNames.size());
}

//------------------------------------------------------------------------------
const char* vtkOpenEXRReader::GetPartName(int index)
{
  const std::vector<std::string>& names = this->Internals->Header.PartNames;
  return index >= 0 && index < static_cast<int>(names.size()) ? names[index].c_str() : nullptr;
}

//------------------------------------------------------------------------------
vtkStringArray* vtkOpenEXRReader::GetChannelNames()
{
  return this->Internals->ChannelNames;
}

//------------------------------------------------------------------------------
vtkStringArray* vtkOpenEXRReader::GetComponentNames()
{
  return this->Internals->ComponentNames;
}

//------------------------------------------------------------------------------
int vtkOpenEXRReader::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  this->SetErrorCode(vtkErrorCode::NoError);
  vtkInternals& internals = *this->Internals;
  internals.HeaderValid = false;
  internals.Header = vtkOpenEXRHeader();
  internals.ChannelNames->Initialize();
  internals.ComponentNames->Initialize();
  this->SelectedPartIndex = -1;
  for (int i = 0; i < 4; ++i)
  {
    this->DataWindow[i] = this->DisplayWindow[i] = (i % 2 == 0) ? 0 : -1;
  }

  // An empty whole extent makes downstream filters see "no data" rather than a stale image.
  static const int emptyExtent[6] = { 0, -1, 0, -1, 0, -1 };
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), emptyExtent, 6);
  if (vtkImageData* output = vtkImageData::SafeDownCast(outInfo->Get(vtkDataObject::DATA_OBJECT())))
  {
    output->Initialize();
  }

  vtkOpenEXRFailure failure;
  vtkOpenEXRCoreFile file;
  if (!this->FileName || !*this->FileName)
  {
    failure.Set(vtkErrorCode::NoFileNameError, "no file name was set");
  }
  else if (file.Open(this->FileName, failure))
  {
    vtkOpenEXRReadHeader(file, this->PartIndex, this->PartName ? this->PartName : "",
      this->Layer ? this->Layer : "", Limits(this), internals.Header, failure);
  }
  const vtkOpenEXRHeader& header = internals.Header;
  // Whatever was learnt before a failure (the part list, say) stays available to the caller.
  for (const vtkOpenEXRChannel& channel : header.Channels)
  {
    internals.ChannelNames->InsertNextValue(channel.Name);
  }
  if (failure.Code != vtkErrorCode::NoError)
  {
    this->SetErrorCode(failure.Code);
    vtkErrorMacro("Cannot read OpenEXR file '" << (this->FileName ? this->FileName : "")
                                               << "': " << failure.Message);
    return 1;
  }

  for (const std::string& name : header.ComponentNames)
  {
    internals.ComponentNames->InsertNextValue(name);
  }
  this->SelectedPartIndex = header.Part;
  for (int i = 0; i < 4; ++i)
  {
    this->DataWindow[i] = header.DataWindow[i];
    this->DisplayWindow[i] = header.DisplayWindow[i];
  }
  const int extent[6] = { header.DataWindow[0], header.DataWindow[1], header.DataWindow[2],
    header.DataWindow[3], 0, 0 };
  const double spacing[3] = { 1.0, 1.0, 1.0 };
  const double origin[3] = { 0.0, 0.0, 0.0 };
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  outInfo->Set(vtkDataObject::SPACING(), spacing, 3);
  outInfo->Set(vtkDataObject::ORIGIN(), origin, 3);
  vtkDataObject::SetPointDataActiveScalarInfo(
    outInfo, header.ScalarType, header.NumberOfComponents);
  internals.HeaderValid = true;
  return 1;
}

//------------------------------------------------------------------------------
int vtkOpenEXRReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkImageData* output = vtkImageData::GetData(outInfo);
  if (!output)
  {
    return 0;
  }
  output->Initialize();
  vtkInternals& internals = *this->Internals;
  if (!internals.HeaderValid)
  {
    // RequestInformation already reported the error and set the error code.
    return 1;
  }

  // Everything is checked again: the file may have changed since RequestInformation, and
  // only here is the chunk table read. Nothing is allocated before it has been validated.
  vtkOpenEXRFailure failure;
  vtkOpenEXRCoreFile file;
  vtkOpenEXRHeader header;
  std::vector<vtkOpenEXRChunk> chunks;
  const vtkOpenEXRLimits limits = Limits(this);
  vtkSmartPointer<vtkDataArray> scalars;
  if (file.Open(this->FileName, failure) &&
    vtkOpenEXRReadHeader(file, this->PartIndex, this->PartName ? this->PartName : "",
      this->Layer ? this->Layer : "", limits, header, failure))
  {
    if (!header.SameLayout(internals.Header))
    {
      failure.Set(vtkErrorCode::FileFormatError, "the file changed after UpdateInformation()");
    }
    else if (vtkOpenEXRReadChunkTable(file, header, limits, chunks, failure))
    {
      scalars = AllocateScalars(header, failure);
    }
  }

  if (scalars)
  {
    const bool dwa =
      header.Compression == EXR_COMPRESSION_DWAA || header.Compression == EXR_COMPRESSION_DWAB;
    if (header.LuminanceChroma)
    {
      // Every chunk is checked before the C++ library reads it: DWA chunks stream by stream
      // against the channel list, the others by decoding them with the core library.
      if (dwa ? vtkOpenEXRCheckDWAChunks(file, header, chunks, failure)
              : vtkOpenEXRDecodeChunks(file, header, chunks, nullptr, false, this, failure))
      {
        file.Close();
        vtkOpenEXRConvertLuminanceChroma(
          this->FileName, header, static_cast<float*>(scalars->GetVoidPointer(0)), failure);
      }
    }
    else if (dwa)
    {
      if (vtkOpenEXRCheckDWAChunks(file, header, chunks, failure))
      {
        file.Close();
        vtkOpenEXRDecodeWithImf(this->FileName, header, scalars->GetVoidPointer(0),
          header.ScalarType == VTK_UNSIGNED_INT, failure);
      }
    }
    else
    {
      vtkOpenEXRDecodeChunks(file, header, chunks, scalars->GetVoidPointer(0),
        header.ScalarType == VTK_UNSIGNED_INT, this, failure);
    }
  }

  if (failure.Code != vtkErrorCode::NoError)
  {
    output->Initialize();
    if (!this->AbortExecute)
    {
      this->SetErrorCode(failure.Code);
      vtkErrorMacro("Cannot read OpenEXR file '" << this->FileName << "': " << failure.Message);
    }
    return 1;
  }

  for (int c = 0; c < header.NumberOfComponents; ++c)
  {
    scalars->SetComponentName(c, header.ComponentNames[c].c_str());
  }
  scalars->SetName("OpenEXRImage");
  output->SetExtent(
    header.DataWindow[0], header.DataWindow[1], header.DataWindow[2], header.DataWindow[3], 0, 0);
  output->SetSpacing(1.0, 1.0, 1.0);
  output->SetOrigin(0.0, 0.0, 0.0);
  output->GetPointData()->SetScalars(scalars);
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkOpenEXRReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "PartIndex: " << this->PartIndex << "\n";
  os << indent << "PartName: " << (this->PartName ? this->PartName : "(none)") << "\n";
  os << indent << "Layer: " << (this->Layer ? this->Layer : "(default)") << "\n";
  os << indent << "MaximumImageBytes: " << this->MaximumImageBytes << "\n";
  os << indent << "MaximumImagePixels: " << this->MaximumImagePixels << "\n";
  os << indent << "NumberOfParts: " << this->GetNumberOfParts() << "\n";
  os << indent << "SelectedPartIndex: " << this->SelectedPartIndex << "\n";
  os << indent << "DataWindow: " << this->DataWindow[0] << " " << this->DataWindow[1] << " "
     << this->DataWindow[2] << " " << this->DataWindow[3] << "\n";
  os << indent << "DisplayWindow: " << this->DisplayWindow[0] << " " << this->DisplayWindow[1]
     << " " << this->DisplayWindow[2] << " " << this->DisplayWindow[3] << "\n";
}
