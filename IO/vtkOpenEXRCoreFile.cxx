// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkOpenEXRCoreFile.h"

#include "vtkErrorCode.h"

#include <algorithm>
#include <filesystem>
#include <limits>
#include <system_error>

//------------------------------------------------------------------------------
bool vtkOpenEXRFailure::Set(unsigned long code, const std::string& message)
{
  this->Code = code;
  // Library messages quote names from the damaged header verbatim; keep control bytes and
  // binary junk out of the log, and keep the message short.
  this->Message.clear();
  for (const char c : message.substr(0, 400))
  {
    const auto u = static_cast<unsigned char>(c);
    this->Message += (u >= 0x20 && u < 0x7f) ? c : '?';
  }
  return false;
}

//------------------------------------------------------------------------------
int64_t vtkOpenEXRCoreFile::Read(exr_const_context_t, void* userData, void* buffer, uint64_t size,
  uint64_t offset, exr_stream_error_func_ptr_t)
{
  auto* self = static_cast<vtkOpenEXRCoreFile*>(userData);
  const auto fileSize = static_cast<uint64_t>(self->FileSize);
  if (offset >= fileSize)
  {
    return 0;
  }
  // A short read tells the library that the file ended early.
  const uint64_t count = std::min(size, fileSize - offset);
  std::lock_guard<std::mutex> guard(self->Lock);
  self->Stream.clear();
  self->Stream.seekg(static_cast<std::streamoff>(offset), std::ios::beg);
  if (!self->Stream)
  {
    return -1;
  }
  self->Stream.read(static_cast<char*>(buffer), static_cast<std::streamsize>(count));
  return static_cast<int64_t>(self->Stream.gcount());
}

//------------------------------------------------------------------------------
int64_t vtkOpenEXRCoreFile::QuerySize(exr_const_context_t, void* userData)
{
  return static_cast<vtkOpenEXRCoreFile*>(userData)->FileSize;
}

//------------------------------------------------------------------------------
void vtkOpenEXRCoreFile::Error(exr_const_context_t context, exr_result_t, const char* message)
{
  // The library reports details here and returns only a code; keep the text for our error.
  void* userData = nullptr;
  if (exr_get_user_data(context, &userData) == EXR_ERR_SUCCESS && userData && message)
  {
    auto* self = static_cast<vtkOpenEXRCoreFile*>(userData);
    std::lock_guard<std::mutex> guard(self->Lock);
    self->LastMessage = message;
  }
}

//------------------------------------------------------------------------------
std::string vtkOpenEXRCoreFile::Describe(exr_result_t result)
{
  std::lock_guard<std::mutex> guard(this->Lock);
  std::string message = this->LastMessage.empty()
    ? std::string(exr_get_default_error_message(result))
    : this->LastMessage;
  this->LastMessage.clear();
  return message;
}

//------------------------------------------------------------------------------
void vtkOpenEXRCoreFile::Close()
{
  if (this->Context)
  {
    exr_finish(&this->Context);
    this->Context = nullptr;
  }
}

//------------------------------------------------------------------------------
bool vtkOpenEXRCoreFile::Open(const std::string& fileName, vtkOpenEXRFailure& failure)
{
  this->Close();
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path path(fileName);
  const fs::file_status status = fs::status(path, ec);
  if (ec || !fs::exists(status))
  {
    return failure.Set(vtkErrorCode::FileNotFoundError, "file does not exist");
  }
  if (fs::is_directory(status))
  {
    return failure.Set(vtkErrorCode::CannotOpenFileError, "is a directory, not a file");
  }
  // Devices and pipes have no size and may block forever; only plain files are read.
  if (!fs::is_regular_file(status))
  {
    return failure.Set(vtkErrorCode::CannotOpenFileError, "is not a regular file");
  }
  const std::uintmax_t size = fs::file_size(path, ec);
  if (ec || size > static_cast<std::uintmax_t>(std::numeric_limits<int64_t>::max()))
  {
    return failure.Set(vtkErrorCode::CannotOpenFileError, "cannot determine the file size");
  }
  if (size == 0)
  {
    return failure.Set(vtkErrorCode::PrematureEndOfFileError, "file is empty");
  }
  this->FileSize = static_cast<vtkTypeInt64>(size);
  this->Stream.close();
  this->Stream.clear();
  this->Stream.open(path, std::ios::in | std::ios::binary);
  if (!this->Stream)
  {
    return failure.Set(vtkErrorCode::CannotOpenFileError, "cannot open the file for reading");
  }

  exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
  init.error_handler_fn = &vtkOpenEXRCoreFile::Error;
  init.user_data = this;
  init.read_fn = &vtkOpenEXRCoreFile::Read;
  init.size_fn = &vtkOpenEXRCoreFile::QuerySize;
  // Strict mode refuses the damage that the C++ library would paper over, such as a missing
  // required attribute or a chunkCount that contradicts the data window.
  init.flags = EXR_CONTEXT_FLAG_STRICT_HEADER;
  this->LastMessage.clear();
  const exr_result_t result = exr_start_read(&this->Context, fileName.c_str(), &init);
  if (result != EXR_ERR_SUCCESS)
  {
    // exr_start_read releases the context itself when it fails.
    this->Context = nullptr;
    const unsigned long code = result == EXR_ERR_READ_IO ? vtkErrorCode::PrematureEndOfFileError
                                                         : vtkErrorCode::FileFormatError;
    return failure.Set(code, "not a valid OpenEXR file: " + this->Describe(result));
  }
  return true;
}
