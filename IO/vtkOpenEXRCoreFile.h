// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkOpenEXRCoreFile.h
 * @brief  (private to vtkOpenEXRReader) an OpenEXR core-library read context on a file that
 *         the reader opens itself, and the failure record every reading step fills in.
 *
 * Owning the stream lets the library's error callback reach this object through the context's
 * user data, lets every read refuse bytes past the end of the file, and lets several threads
 * decode chunks of one context at once: reads are serialized by a mutex (they are short next to
 * decompression), and the library's last message is kept under the same lock.
 */
#ifndef vtkOpenEXRCoreFile_h
#define vtkOpenEXRCoreFile_h

#include "vtkType.h"

#include <openexr.h>

#include <fstream>
#include <mutex>
#include <string>

//------------------------------------------------------------------------------
// A failure: the message for vtkErrorMacro and the vtkErrorCode for the caller. Set() returns
// false so that a check can end with `return failure.Set(...)`.
struct vtkOpenEXRFailure
{
  unsigned long Code = 0; // vtkErrorCode::NoError
  std::string Message;

  bool Set(unsigned long code, const std::string& message);
  bool Failed() const { return this->Code != 0; }
};

//------------------------------------------------------------------------------
class vtkOpenEXRCoreFile
{
public:
  vtkOpenEXRCoreFile() = default;
  ~vtkOpenEXRCoreFile() { this->Close(); }
  vtkOpenEXRCoreFile(const vtkOpenEXRCoreFile&) = delete;
  vtkOpenEXRCoreFile& operator=(const vtkOpenEXRCoreFile&) = delete;

  /**
   * Open a regular file and parse every part's header in strict mode. Missing files,
   * directories, devices, empty files and invalid headers are failures.
   */
  bool Open(const std::string& fileName, vtkOpenEXRFailure& failure);
  void Close();

  /**
   * The library's own message for the last failure when it gave one, else its generic text.
   */
  std::string Describe(exr_result_t result);

  exr_context_t Context = nullptr;
  vtkTypeInt64 FileSize = 0;

private:
  static int64_t Read(exr_const_context_t, void* userData, void* buffer, uint64_t size,
    uint64_t offset, exr_stream_error_func_ptr_t);
  static int64_t QuerySize(exr_const_context_t, void* userData);
  static void Error(exr_const_context_t context, exr_result_t, const char* message);

  std::mutex Lock; // guards Stream and LastMessage
  std::ifstream Stream;
  std::string LastMessage;
};

#endif
// VTK-HeaderTest-Exclude: vtkOpenEXRCoreFile.h
