// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// libFuzzer target for vtkOpenEXRReader: each input is written to a file (the reader opens
// files, as users' scripts do) and read through the whole pipeline, every part of it, plus
// CanReadFile. Built and run by scripts/fuzz.sh under AddressSanitizer and UBSan; a crash, a
// sanitizer report, a leak, an input slower than -timeout or a resident size above
// -rss_limit_mb is a finding.
#include "vtkOpenEXRReader.h"

#include <vtkCommand.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkObject.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <unistd.h>

namespace
{
// Errors are the expected outcome for most inputs; keep them out of the fuzzer's log.
class Silence : public vtkCommand
{
public:
  static Silence* New() { return new Silence; }
  void Execute(vtkObject*, unsigned long, void*) override {}
};

std::string InputPath()
{
  const char* directory = std::getenv("TMPDIR");
  return std::string(directory && *directory ? directory : "/tmp") + "/vtkbloom-fuzz-" +
    std::to_string(::getpid()) + ".exr";
}
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  static const std::string path = InputPath();
  FILE* file = std::fopen(path.c_str(), "wb");
  if (!file)
  {
    return 0;
  }
  std::fwrite(data, 1, size, file);
  std::fclose(file);

  vtkObject::GlobalWarningDisplayOff();
  vtkNew<vtkOpenEXRReader> reader;
  vtkNew<Silence> silence;
  reader->AddObserver(vtkCommand::ErrorEvent, silence);
  reader->AddObserver(vtkCommand::WarningEvent, silence);
  reader->CanReadFile(path.c_str());
  reader->SetFileName(path.c_str());
  // Legitimate seeds are at most a few megapixels; a smaller limit than the default keeps
  // the fuzzer's memory limit meaningful for everything the header checks let through.
  reader->SetMaximumImagePixels(vtkTypeUInt64(1) << 23);
  reader->Update();
  const int parts = reader->GetNumberOfParts();
  for (int part = 1; part < parts && part < 4; ++part)
  {
    reader->SetPartIndex(part);
    reader->Update();
  }
  return 0;
}
