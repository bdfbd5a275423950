// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// vtkOpenEXRReader on broken input: every file of ../shared/data/exr/Damaged (fuzzer cases
// that crashed, hung or leaked in older OpenEXR releases) plus missing, empty, truncated and
// otherwise unusable files. Each must produce exactly one error event, an error code and an
// empty output, quickly, with no exception escaping. Run it under ASan/UBSan too.
#include "vtkBloomTestSupport.h"
#include "vtkOpenEXRReader.h"
#include "vtkOpenEXRTestHelpers.h"

#include <vtkErrorCode.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace
{
namespace fs = std::filesystem;
using vtkOpenEXRTest::ReadResult;

//------------------------------------------------------------------------------
void ExpectCleanFailure(const ReadResult& result, const std::string& what)
{
  EXPECT_EQ(result.Errors, 1) << what;
  EXPECT_NE(result.ErrorCode, vtkErrorCode::NoError) << what;
  EXPECT_TRUE(result.Empty()) << what;
  EXPECT_FALSE(result.Message.empty()) << what;
}

//------------------------------------------------------------------------------
TEST(OpenEXRDamaged, EveryDamagedFileFailsCleanly)
{
  VTKBLOOM_REQUIRE_DATA(readme, "exr/Damaged/README.rst");
  const fs::path directory = fs::path(readme).parent_path();
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(directory))
  {
    if (entry.is_regular_file() && entry.path().filename() != "README.rst")
    {
      files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());
  EXPECT_EQ(files.size(), 145u);

  const double start = vtkOpenEXRTest::ProcessCPUSeconds();
  double slowest = 0.0;
  std::string slowestName;
  for (const fs::path& file : files)
  {
    const std::string name = file.filename().string();
    const double before = vtkOpenEXRTest::ProcessCPUSeconds();
    try
    {
      ExpectCleanFailure(vtkOpenEXRTest::Read(file.string()), name);

      // The other parts of the file, when the header could be parsed at all, must fail (or
      // read) just as cleanly; CanReadFile must not crash either.
      vtkNew<vtkOpenEXRReader> reader;
      vtkNew<vtkOpenEXRTest::ErrorObserver> observer;
      reader->AddObserver(vtkCommand::ErrorEvent, observer);
      reader->SetFileName(file.string().c_str());
      reader->CanReadFile(file.string().c_str());
      reader->UpdateInformation();
      const int parts = std::min(reader->GetNumberOfParts(), 16);
      for (int p = 1; p < parts; ++p)
      {
        reader->SetPartIndex(p);
        const int errorsBefore = observer->Errors;
        reader->Update();
        if (observer->Errors > errorsBefore)
        {
          EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 0) << name << " part " << p;
        }
      }
    }
    catch (...)
    {
      ADD_FAILURE() << "exception escaped for " << name;
    }
    // The work one file costs (CPU time of the process, not the clock, so that neither a busy
    // machine nor valgrind fails it): a reader looping on a damaged file shows up here long
    // before CTest's timeout.
    const double seconds = vtkOpenEXRTest::ProcessCPUSeconds() - before;
    EXPECT_LT(seconds, 30.0) << name;
    if (seconds > slowest)
    {
      slowest = seconds;
      slowestName = name;
    }
  }
  const double total = vtkOpenEXRTest::ProcessCPUSeconds() - start;
  std::cout << "[ work     ] " << files.size() << " damaged files in " << total
            << " s of CPU time; most " << slowestName << " (" << slowest << " s)" << std::endl;
}

//------------------------------------------------------------------------------
TEST(OpenEXRDamaged, MissingFile)
{
  const auto result = vtkOpenEXRTest::Read(vtkBloomTest::OutputPath("does_not_exist.exr"));
  ExpectCleanFailure(result, "missing");
  EXPECT_EQ(result.ErrorCode, vtkErrorCode::FileNotFoundError);
}

//------------------------------------------------------------------------------
TEST(OpenEXRDamaged, NoFileName)
{
  vtkNew<vtkOpenEXRReader> reader;
  vtkNew<vtkOpenEXRTest::ErrorObserver> observer;
  reader->AddObserver(vtkCommand::ErrorEvent, observer);
  reader->Update();
  EXPECT_EQ(observer->Errors, 1);
  EXPECT_EQ(reader->GetErrorCode(), vtkErrorCode::NoFileNameError);
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 0);
}

//------------------------------------------------------------------------------
TEST(OpenEXRDamaged, DirectoryInsteadOfFile)
{
  const std::string directory = vtkBloomTest::OutputPath("directory.exr");
  fs::create_directories(directory);
  const auto result = vtkOpenEXRTest::Read(directory);
  ExpectCleanFailure(result, "directory");
  EXPECT_EQ(result.ErrorCode, vtkErrorCode::CannotOpenFileError);
}

//------------------------------------------------------------------------------
TEST(OpenEXRDamaged, EmptyFile)
{
  const std::string path = vtkBloomTest::OutputPath("empty.exr");
  vtkOpenEXRTest::WriteBytes(path, "");
  ExpectCleanFailure(vtkOpenEXRTest::Read(path), "empty");
}

//------------------------------------------------------------------------------
TEST(OpenEXRDamaged, NotAnOpenEXRFile)
{
  const std::string path = vtkBloomTest::OutputPath("text.exr");
  vtkOpenEXRTest::WriteBytes(path, "P6\n2 2\n255\n0123456789ab");
  const auto result = vtkOpenEXRTest::Read(path);
  ExpectCleanFailure(result, "text");
  EXPECT_EQ(result.ErrorCode, vtkErrorCode::FileFormatError);
}

//------------------------------------------------------------------------------
TEST(OpenEXRDamaged, DeviceIsNotRead)
{
#ifdef _WIN32
  GTEST_SKIP() << "POSIX device";
#else
  // /dev/zero never ends; the reader must refuse it rather than read forever.
  ExpectCleanFailure(vtkOpenEXRTest::Read("/dev/zero"), "/dev/zero");
#endif
}

//------------------------------------------------------------------------------
std::string WriteTruncatedCopy(const std::string& bytes, size_t length, const char* name)
{
  const std::string path =
    vtkBloomTest::OutputPath("truncated_" + std::to_string(length) + "_" + name);
  vtkOpenEXRTest::WriteBytes(path, bytes.substr(0, length));
  return path;
}

//------------------------------------------------------------------------------
TEST(OpenEXRDamaged, TruncatedCopies)
{
  for (const char* name :
    { "ScanLines_Desk.exr", "Tiles_GoldenGate.exr", "LuminanceChroma_StarField.exr" })
  {
    VTKBLOOM_REQUIRE_DATA(path, std::string("exr/") + name);
    const std::string bytes = vtkOpenEXRTest::FileBytes(path);
    ASSERT_GT(bytes.size(), 4096u);
    // Inside the magic number, inside the header, inside the offset table, in the middle of
    // the pixel data and one byte short of the end.
    for (const size_t length :
      { size_t(3), size_t(200), size_t(1500), bytes.size() / 2, bytes.size() - 1 })
    {
      ExpectCleanFailure(vtkOpenEXRTest::Read(WriteTruncatedCopy(bytes, length, name)),
        std::string(name) + " truncated to " + std::to_string(length));
    }
  }
}

//------------------------------------------------------------------------------
TEST(OpenEXRDamaged, TruncatedMultiPartFile)
{
  // Parts are validated one at a time, so a part whose chunks all survive the cut may still
  // be read; the parts that lost data must fail cleanly, and some part always does.
  const char* name = "Beachball_multipart.0001.exr";
  VTKBLOOM_REQUIRE_DATA(path, std::string("exr/") + name);
  const std::string bytes = vtkOpenEXRTest::FileBytes(path);
  for (const size_t length : { bytes.size() / 2, bytes.size() - 1 })
  {
    const std::string truncated = WriteTruncatedCopy(bytes, length, name);
    int failures = 0;
    for (int part = 0; part < 10; ++part)
    {
      const auto result =
        vtkOpenEXRTest::Read(truncated, [part](vtkOpenEXRReader* r) { r->SetPartIndex(part); });
      if (result.Errors > 0)
      {
        ++failures;
        ExpectCleanFailure(result, "part " + std::to_string(part));
      }
      else
      {
        EXPECT_GT(result.Image->GetNumberOfPoints(), 0);
      }
    }
    EXPECT_GT(failures, 0) << "truncated to " << length;
  }
}

//------------------------------------------------------------------------------
TEST(OpenEXRDamaged, CorruptedPixelDataNeverEscapes)
{
  VTKBLOOM_REQUIRE_DATA(path, "exr/ScanLines_Desk.exr");
  std::string bytes = vtkOpenEXRTest::FileBytes(path);
  // Overwrite a stretch of compressed pixel data. Whether the decoder notices depends on the
  // compression; either way the result must be a full image or a clean failure.
  for (size_t i = bytes.size() / 2; i < bytes.size() / 2 + 4096; ++i)
  {
    bytes[i] = static_cast<char>(i * 131u);
  }
  const std::string corrupted = vtkBloomTest::OutputPath("corrupted_ScanLines_Desk.exr");
  vtkOpenEXRTest::WriteBytes(corrupted, bytes);
  const auto result = vtkOpenEXRTest::Read(corrupted);
  if (result.Errors == 0)
  {
    EXPECT_EQ(result.Image->GetNumberOfPoints(), 644 * 874);
  }
  else
  {
    ExpectCleanFailure(result, "corrupted");
  }
}
}
