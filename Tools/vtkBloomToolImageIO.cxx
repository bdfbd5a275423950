// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkBloomToolImageIO.h"

#include "vtkOpenEXRReader.h"
#include "vtkOpenEXRWriter.h"

#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPointData.h>
#include <vtkSMPTools.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <system_error>
#include <unistd.h>

namespace fs = std::filesystem;

namespace vtkBloomTool
{
//------------------------------------------------------------------------------
InputImage ReadInput(const std::string& path, vtkTypeUInt64 maximumPixels, ErrorCollector& errors,
  ProgressBar& progress)
{
  vtkNew<vtkOpenEXRReader> reader;
  errors.Watch(reader);
  progress.Watch(reader);
  reader->SetFileName(path.c_str());
  reader->SetMaximumImagePixels(maximumPixels);
  // Up to 4 float components per pixel.
  reader->SetMaximumImageBytes(std::max(reader->GetMaximumImageBytes(), maximumPixels * 16));
  reader->Update();
  for (std::string& message : errors.Messages)
  {
    if (message.find("MaximumImagePixels") != std::string::npos)
    {
      message += " (--max-pixels " + std::to_string(maximumPixels) + ")";
    }
  }
  errors.ThrowIfAny("cannot read " + path + ":");
  vtkImageData* image = reader->GetOutput();
  if (!image || image->GetNumberOfPoints() == 0 || !image->GetPointData()->GetScalars())
  {
    throw RunError{ "cannot read " + path + ": no image data" };
  }
  InputImage result;
  result.Image = vtkSmartPointer<vtkImageData>::New();
  result.Image->ShallowCopy(image);
  reader->GetDisplayWindow(result.DisplayWindow);
  return result;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkImageData> AsFloatRGBA(vtkImageData* image)
{
  vtkDataArray* in = image->GetPointData()->GetScalars();
  const int nc = image->GetNumberOfScalarComponents();
  if (vtkFloatArray::FastDownCast(in) && nc == 4)
  {
    return image;
  }
  auto rgba = vtkSmartPointer<vtkImageData>::New();
  rgba->CopyStructure(image);
  rgba->AllocateScalars(VTK_FLOAT, 4);
  float* out = static_cast<float*>(rgba->GetScalarPointer());
  vtkSMPTools::For(0, image->GetNumberOfPoints(),
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType p = begin; p < end; ++p)
      {
        float* o = out + 4 * p;
        const double v0 = in->GetComponent(p, 0);
        o[0] = static_cast<float>(v0);
        o[1] = static_cast<float>(nc >= 3 ? in->GetComponent(p, 1) : v0);
        o[2] = static_cast<float>(nc >= 3 ? in->GetComponent(p, 2) : v0);
        o[3] = nc == 4 ? static_cast<float>(in->GetComponent(p, 3))
                       : (nc == 2 ? static_cast<float>(in->GetComponent(p, 1)) : 1.0f);
      }
    });
  return rgba;
}

//------------------------------------------------------------------------------
unsigned char ToneMap(double linear, double exposure)
{
  double x = std::isnan(linear) ? 0.0 : std::max(linear * exposure, 0.0);
  x = std::min(x, 1e6);
  double y = (x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14);
  y = std::min(std::max(y, 0.0), 1.0);
  const double s = y <= 0.0031308 ? 12.92 * y : 1.055 * std::pow(y, 1.0 / 2.4) - 0.055;
  return static_cast<unsigned char>(std::lround(255.0 * std::min(std::max(s, 0.0), 1.0)));
}

//------------------------------------------------------------------------------
void WriteFileAtomically(const std::string& path, const unsigned char* data, size_t size)
{
  const std::string temporary = path + ".tmp-" + std::to_string(::getpid());
  std::error_code ec;
  {
    std::ofstream file(temporary, std::ios::binary | std::ios::trunc);
    if (file)
    {
      file.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
      file.close();
    }
    if (!file)
    {
      fs::remove(temporary, ec);
      throw RunError{ "cannot write " + path + ": " + std::strerror(errno) };
    }
  }
  fs::rename(temporary, path, ec);
  if (ec)
  {
    fs::remove(temporary, ec);
    throw RunError{ "cannot write " + path + ": " + ec.message() };
  }
}

namespace
{
//------------------------------------------------------------------------------
// Tone-map to 8-bit and write through WriteFileAtomically. The PNG is opaque RGB: OpenEXR
// colour is premultiplied by alpha, so showing it as is composites it over black, which keeps
// the glow that bloom spreads into transparent pixels.
void WritePNG(vtkImageData* rgba, const std::string& path, double exposure, ErrorCollector& errors)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  int ext[6];
  rgba->GetExtent(ext);
  const int w = ext[1] - ext[0] + 1, h = ext[3] - ext[2] + 1;
  image->SetDimensions(w, h, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  const float* in = static_cast<const float*>(rgba->GetScalarPointer());
  unsigned char* out = static_cast<unsigned char*>(image->GetScalarPointer());
  vtkSMPTools::For(0, h,
    [&](vtkIdType first, vtkIdType last)
    {
      for (vtkIdType j = first; j < last; ++j)
      {
        // Row 0 is the top of the picture; VTK's PNG writer puts the last row on top.
        const float* src = in + static_cast<size_t>(j) * w * 4;
        unsigned char* dst = out + static_cast<size_t>(h - 1 - j) * w * 3;
        for (int i = 0; i < w; ++i)
        {
          for (int c = 0; c < 3; ++c)
          {
            dst[3 * i + c] = ToneMap(src[4 * i + c], exposure);
          }
        }
      }
    });
  // Encode in memory: VTK 9.1's vtkPNGWriter leaks libpng state when it cannot open its file.
  vtkNew<vtkPNGWriter> writer;
  errors.Watch(writer);
  writer->WriteToMemoryOn();
  writer->SetInputData(image);
  writer->Write();
  vtkUnsignedCharArray* bytes = writer->GetResult();
  if (!errors.Messages.empty() || !bytes || bytes->GetNumberOfValues() == 0)
  {
    errors.Messages.push_back("PNG encoding failed");
    errors.ThrowIfAny("cannot write " + path + ":");
  }
  WriteFileAtomically(path, bytes->GetPointer(0), static_cast<size_t>(bytes->GetNumberOfValues()));
}
}

//------------------------------------------------------------------------------
void WriteOutput(vtkImageData* image, const int displayWindow[4], const std::string& path,
  double exposure, ErrorCollector& errors, ProgressBar& progress)
{
  auto rgba = AsFloatRGBA(image);
  if (Extension(path) == ".png")
  {
    WritePNG(rgba, path, exposure, errors);
    return;
  }
  vtkNew<vtkOpenEXRWriter> writer;
  errors.Watch(writer);
  progress.Watch(writer);
  writer->SetFileName(path.c_str());
  writer->SetInputData(rgba);
  writer->SetPixelTypeToFloat();
  writer->SetDisplayWindow(const_cast<int*>(displayWindow));
  writer->Write();
  errors.ThrowIfAny("cannot write " + path + ":");
}
}
