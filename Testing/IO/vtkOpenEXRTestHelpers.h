// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// Helpers shared by the OpenEXR reader/writer GoogleTest suites.
#ifndef vtkOpenEXRTestHelpers_h
#define vtkOpenEXRTestHelpers_h

#include "vtkOpenEXRReader.h"

#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkErrorCode.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>
#include <vector>

#ifndef _WIN32
#include <sys/resource.h>
#endif

namespace vtkOpenEXRTest
{
/// Counts ErrorEvent / WarningEvent and keeps the last error text. Observing the events also
/// keeps the expected errors out of the test log.
class ErrorObserver : public vtkCommand
{
public:
  static ErrorObserver* New() { return new ErrorObserver; }
  void Execute(vtkObject*, unsigned long event, void* data) override
  {
    if (event == vtkCommand::ErrorEvent)
    {
      ++this->Errors;
      this->Message = data ? static_cast<const char*>(data) : "";
    }
    else if (event == vtkCommand::WarningEvent)
    {
      ++this->Warnings;
    }
  }
  int Errors = 0;
  int Warnings = 0;
  std::string Message;
};

/// Outcome of one read: the output image (shallow copy) and what the reader reported.
struct ReadResult
{
  vtkSmartPointer<vtkImageData> Image;
  int Errors = 0;
  std::string Message;
  unsigned long ErrorCode = vtkErrorCode::NoError;
  bool Empty() const
  {
    return this->Image->GetNumberOfPoints() == 0 &&
      this->Image->GetPointData()->GetScalars() == nullptr;
  }
};

/// Read `path` with a fresh reader, configured by `configure` before Update().
inline ReadResult Read(
  const std::string& path, const std::function<void(vtkOpenEXRReader*)>& configure = nullptr)
{
  vtkNew<vtkOpenEXRReader> reader;
  vtkNew<ErrorObserver> observer;
  reader->AddObserver(vtkCommand::ErrorEvent, observer);
  reader->AddObserver(vtkCommand::WarningEvent, observer);
  reader->SetFileName(path.c_str());
  if (configure)
  {
    configure(reader);
  }
  reader->Update();
  ReadResult result;
  result.Image = vtkSmartPointer<vtkImageData>::New();
  result.Image->ShallowCopy(reader->GetOutput());
  result.Errors = observer->Errors;
  result.Message = observer->Message;
  result.ErrorCode = reader->GetErrorCode();
  return result;
}

/// The raw bytes of a file ("" if it cannot be read).
/// The CPU time (user and system, every thread) this process has used so far: the work a read
/// did, which a busy machine does not stretch as it stretches the clock. 0 where unknown.
inline double ProcessCPUSeconds()
{
#ifndef _WIN32
  rusage usage{};
  if (getrusage(RUSAGE_SELF, &usage) == 0)
  {
    return static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
      1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
  }
#endif
  return 0.0;
}

inline std::string FileBytes(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/// Write `bytes` to `path`.
inline void WriteBytes(const std::string& path, const std::string& bytes)
{
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

/// The 32 bits of a float, so that NaN payloads compare exactly.
inline uint32_t Bits(float value)
{
  uint32_t bits;
  std::memcpy(&bits, &value, sizeof(bits));
  return bits;
}

/// Float value at structured index (i, j, 0), component c, without going through double.
inline float FloatAt(vtkImageData* image, int i, int j, int c)
{
  int extent[6];
  image->GetExtent(extent);
  const vtkIdType w = extent[1] - extent[0] + 1;
  const vtkIdType t = (j - extent[2]) * w + (i - extent[0]);
  const float* data =
    static_cast<const float*>(image->GetPointData()->GetScalars()->GetVoidPointer(0));
  return data[t * image->GetNumberOfScalarComponents() + c];
}
}

#endif
