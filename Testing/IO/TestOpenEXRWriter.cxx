// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// vtkOpenEXRWriter: write -> read round trips (bit-exact), the file's header as the OpenEXR
// C++ library sees it, the documented half rounding, and clean failures.
#include "vtkBloomTestSupport.h"
#include "vtkOpenEXRReader.h"
#include "vtkOpenEXRTestHelpers.h"
#include "vtkOpenEXRWriter.h"

#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkErrorCode.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnsignedIntArray.h>

#include <Imath/half.h>
#include <ImfChannelList.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfTileDescription.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#ifndef _WIN32
#include <grp.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#endif

namespace
{
namespace fs = std::filesystem;
using vtkOpenEXRTest::Bits;

//------------------------------------------------------------------------------
// An image with an extent that does not start at 0, so the data window must carry it.
const int TestExtent[6] = { -7, 29, 11, 33, 0, 0 };

//------------------------------------------------------------------------------
float FromBits(uint32_t bits)
{
  float value;
  std::memcpy(&value, &bits, sizeof(value));
  return value;
}

//------------------------------------------------------------------------------
// Random floats covering the awkward cases: both signs, subnormals, huge magnitudes, zeros,
// infinities and NaNs with payloads (bit patterns, so nothing is rounded on the way).
float AwkwardFloat(std::mt19937& random)
{
  const uint32_t sign = (random() & 1u) << 31;
  switch (random() % 8)
  {
    case 0: // subnormal
      return FromBits(sign | (random() & 0x007fffffu));
    case 1: // huge
      return FromBits(sign | (0x7e000000u + (random() & 0x00ffffffu)));
    case 2: // +/-0, +/-Inf
      return FromBits(sign | ((random() & 1u) ? 0x7f800000u : 0u));
    case 3: // NaN with a payload
      return FromBits(sign | 0x7f800000u | ((random() & 0x007fffffu) | 1u));
    default: // any finite value
      return FromBits(sign | (random() % 0x7f000000u));
  }
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkImageData> MakeFloatImage(int components, std::mt19937& random)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetExtent(const_cast<int*>(TestExtent));
  image->AllocateScalars(VTK_FLOAT, components);
  float* data = static_cast<float*>(image->GetScalarPointer());
  const vtkIdType count = image->GetNumberOfPoints() * components;
  for (vtkIdType v = 0; v < count; ++v)
  {
    data[v] = AwkwardFloat(random);
  }
  return image;
}

//------------------------------------------------------------------------------
// Write `image` with `configure`d options; return the writer's result and error count.
struct WriteResult
{
  int Returned = 0;
  int Errors = 0;
  std::string Message;
  unsigned long ErrorCode = vtkErrorCode::NoError;
};

WriteResult Write(vtkImageData* image, const std::string& path,
  const std::function<void(vtkOpenEXRWriter*)>& configure = nullptr)
{
  vtkNew<vtkOpenEXRWriter> writer;
  vtkNew<vtkOpenEXRTest::ErrorObserver> observer;
  writer->AddObserver(vtkCommand::ErrorEvent, observer);
  writer->SetInputData(image);
  writer->SetFileName(path.c_str());
  if (configure)
  {
    configure(writer);
  }
  WriteResult result;
  result.Returned = writer->Write();
  result.Errors = observer->Errors;
  result.Message = observer->Message;
  result.ErrorCode = writer->GetErrorCode();
  return result;
}

//------------------------------------------------------------------------------
bool SameExtent(vtkImageData* a, vtkImageData* b)
{
  int ea[6], eb[6];
  a->GetExtent(ea);
  b->GetExtent(eb);
  return std::equal(ea, ea + 6, eb);
}

//------------------------------------------------------------------------------
// Temporary files left in `directory` by the writer (".name.<random>.tmp").
int CountTemporaries(const std::string& directory)
{
  int count = 0;
  for (const auto& entry : fs::directory_iterator(directory))
  {
    const std::string name = entry.path().filename().string();
    // Only the writer's pattern: CTest keeps its own LastTest.log.tmp in the same directory.
    count +=
      (name.size() > 5 && name[0] == '.' && name.compare(name.size() - 4, 4, ".tmp") == 0) ? 1 : 0;
  }
  return count;
}

//------------------------------------------------------------------------------
using RoundTripParameters = std::tuple<int, int, bool>; // components, compression, tiled

class OpenEXRWriterFloatRoundTrip : public ::testing::TestWithParam<RoundTripParameters>
{
};

TEST_P(OpenEXRWriterFloatRoundTrip, IsBitExact)
{
  const int components = std::get<0>(GetParam());
  const int compression = std::get<1>(GetParam());
  const bool tiled = std::get<2>(GetParam());
  std::mt19937 random(1234u + components * 31u + compression * 7u + (tiled ? 1u : 0u));
  auto image = MakeFloatImage(components, random);
  std::ostringstream name;
  name << "FloatRoundTrip_" << components << "_" << compression << "_" << tiled << ".exr";
  const std::string path = vtkBloomTest::OutputPath(name.str());

  const WriteResult written = Write(image, path,
    [&](vtkOpenEXRWriter* w)
    {
      w->SetCompression(compression);
      w->SetTiled(tiled);
      w->SetTileSize(16, 8); // smaller than the image, with partial edge tiles
    });
  ASSERT_EQ(written.Returned, 1) << written.Message;
  ASSERT_EQ(written.Errors, 0);

  // The header as the C++ library reads it.
  Imf::InputFile file(path.c_str());
  const Imf::Header& header = file.header();
  EXPECT_EQ(header.dataWindow(),
    Imath::Box2i(
      Imath::V2i(TestExtent[0], TestExtent[2]), Imath::V2i(TestExtent[1], TestExtent[3])));
  EXPECT_EQ(header.displayWindow(), header.dataWindow());
  EXPECT_EQ(static_cast<int>(header.compression()), compression);
  EXPECT_EQ(header.hasTileDescription(), tiled);
  if (tiled)
  {
    EXPECT_EQ(header.tileDescription().xSize, 16u);
    EXPECT_EQ(header.tileDescription().ySize, 8u);
  }
  static const std::vector<std::vector<std::string>> expectedNames = { { "Y" }, { "A", "Y" },
    { "B", "G", "R" }, { "A", "B", "G", "R" } };
  std::vector<std::string> names;
  for (auto it = header.channels().begin(); it != header.channels().end(); ++it)
  {
    names.emplace_back(it.name());
    EXPECT_EQ(it.channel().type, Imf::FLOAT);
  }
  EXPECT_EQ(names, expectedNames[components - 1]);

  const auto read = vtkOpenEXRTest::Read(path);
  ASSERT_EQ(read.Errors, 0) << read.Message;
  EXPECT_TRUE(SameExtent(read.Image, image));
  EXPECT_TRUE(vtkBloomTest::BitIdentical(read.Image, image));
}

INSTANTIATE_TEST_SUITE_P(LosslessCompressions, OpenEXRWriterFloatRoundTrip,
  ::testing::Combine(::testing::Values(1, 2, 3, 4),
    ::testing::Values(vtkOpenEXRWriter::COMPRESSION_NONE, vtkOpenEXRWriter::COMPRESSION_RLE,
      vtkOpenEXRWriter::COMPRESSION_ZIPS, vtkOpenEXRWriter::COMPRESSION_ZIP,
      vtkOpenEXRWriter::COMPRESSION_PIZ),
    ::testing::Bool()));

//------------------------------------------------------------------------------
class OpenEXRWriterHalfRoundTrip : public ::testing::TestWithParam<std::tuple<int, bool>>
{
};

TEST_P(OpenEXRWriterHalfRoundTrip, RepresentableValuesAreBitExact)
{
  const int components = std::get<0>(GetParam());
  const bool tiled = std::get<1>(GetParam());
  // Every one of the 65536 half bit patterns (NaNs and infinities included) in every
  // component, widened to float: those are exactly what half storage can hold.
  const int extent[6] = { 100, 355, -300, -45, 0, 0 };
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetExtent(const_cast<int*>(extent));
  image->AllocateScalars(VTK_FLOAT, components);
  float* data = static_cast<float*>(image->GetScalarPointer());
  for (uint32_t p = 0; p < 65536u; ++p)
  {
    for (int c = 0; c < components; ++c)
    {
      Imath::half h;
      h.setBits(static_cast<uint16_t>((p + 4099u * static_cast<uint32_t>(c)) & 0xffffu));
      data[p * components + c] = h;
    }
  }
  const std::string path = vtkBloomTest::OutputPath(
    "HalfRoundTrip_" + std::to_string(components) + (tiled ? "_tiled" : "") + ".exr");
  const WriteResult written = Write(image, path,
    [tiled](vtkOpenEXRWriter* w)
    {
      w->SetPixelTypeToHalf();
      w->SetCompressionToPiz();
      w->SetTiled(tiled);
    });
  ASSERT_EQ(written.Returned, 1) << written.Message;

  Imf::InputFile file(path.c_str());
  for (auto it = file.header().channels().begin(); it != file.header().channels().end(); ++it)
  {
    EXPECT_EQ(it.channel().type, Imf::HALF) << it.name();
  }
  const auto read = vtkOpenEXRTest::Read(path);
  ASSERT_EQ(read.Errors, 0) << read.Message;
  EXPECT_TRUE(SameExtent(read.Image, image));
  EXPECT_TRUE(vtkBloomTest::BitIdentical(read.Image, image));
}

INSTANTIATE_TEST_SUITE_P(Components, OpenEXRWriterHalfRoundTrip,
  ::testing::Combine(::testing::Values(1, 2, 3, 4), ::testing::Bool()));

//------------------------------------------------------------------------------
TEST(OpenEXRWriter, HalfRoundingIsDocumented)
{
  const float infinity = std::numeric_limits<float>::infinity();
  // input -> value stored as half, as the class documentation states.
  const std::vector<std::pair<float, float>> cases = { { 65504.0f, 65504.0f },
    { 65519.0f, 65504.0f }, { 65520.0f, 65504.0f }, { -70000.0f, -65504.0f }, { 1e30f, 65504.0f },
    { infinity, infinity }, { -infinity, -infinity }, { 1.0e-8f, 0.0f }, { -1.0e-8f, -0.0f },
    { 5.9604645e-8f /* 2^-24 */, 5.9604645e-8f }, { 1.0009765625f, 1.0009765625f },
    { 1.00048828125f /* tie -> even */, 1.0f }, { 0.1f, 0.0999755859375f } };
  const int extent[6] = { 0, static_cast<int>(cases.size()), 0, 0, 0, 0 };
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetExtent(const_cast<int*>(extent));
  image->AllocateScalars(VTK_FLOAT, 1);
  float* data = static_cast<float*>(image->GetScalarPointer());
  for (size_t i = 0; i < cases.size(); ++i)
  {
    data[i] = cases[i].first;
  }
  data[cases.size()] = std::numeric_limits<float>::quiet_NaN();

  const std::string path = vtkBloomTest::OutputPath("HalfRounding.exr");
  ASSERT_EQ(Write(image, path, [](vtkOpenEXRWriter* w) { w->SetPixelTypeToHalf(); }).Returned, 1);
  const auto read = vtkOpenEXRTest::Read(path);
  ASSERT_EQ(read.Errors, 0) << read.Message;
  for (size_t i = 0; i < cases.size(); ++i)
  {
    EXPECT_EQ(
      Bits(vtkOpenEXRTest::FloatAt(read.Image, static_cast<int>(i), 0, 0)), Bits(cases[i].second))
      << "input " << cases[i].first;
  }
  EXPECT_TRUE(
    std::isnan(vtkOpenEXRTest::FloatAt(read.Image, static_cast<int>(cases.size()), 0, 0)));
}

//------------------------------------------------------------------------------
TEST(OpenEXRWriter, DoubleIsRoundedToFloat)
{
  const std::vector<double> values = { 3.141592653589793, -2.718281828459045, 1e300, -1e300, 1e-300,
    3.4028235e38 /* above FLT_MAX, below the rounding threshold */, 0.1 };
  const int extent[6] = { 0, static_cast<int>(values.size()) - 1, 0, 0, 0, 0 };
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetExtent(const_cast<int*>(extent));
  image->AllocateScalars(VTK_DOUBLE, 1);
  double* data = static_cast<double*>(image->GetScalarPointer());
  std::copy(values.begin(), values.end(), data);
  const std::string path = vtkBloomTest::OutputPath("Double.exr");
  const WriteResult written = Write(image, path);
  ASSERT_EQ(written.Returned, 1) << written.Message;
  const auto read = vtkOpenEXRTest::Read(path);
  ASSERT_EQ(read.Errors, 0) << read.Message;
  ASSERT_EQ(read.Image->GetScalarType(), VTK_FLOAT);
  const float infinity = std::numeric_limits<float>::infinity();
  const std::vector<float> expected = { static_cast<float>(values[0]),
    static_cast<float>(values[1]), infinity, -infinity, 0.0f, std::numeric_limits<float>::max(),
    0.1f };
  for (size_t i = 0; i < values.size(); ++i)
  {
    EXPECT_EQ(
      Bits(vtkOpenEXRTest::FloatAt(read.Image, static_cast<int>(i), 0, 0)), Bits(expected[i]))
      << values[i];
  }
}

//------------------------------------------------------------------------------
// SetInputArrayToProcess(0, ...) picks the array written (ParaView's "Scalars"); without it the
// active scalars are written; a name that is not a point array is an error and writes nothing.
TEST(OpenEXRWriter, WritesTheChosenArray)
{
  auto image = vtkBloomTest::MakeImage(
    TestExtent, 1, VTK_FLOAT, [](int i, int j, int, int) { return 0.25 * i - 0.5 * j; });
  vtkNew<vtkFloatArray> rgb;
  rgb->SetName("rgb");
  rgb->SetNumberOfComponents(3);
  rgb->SetNumberOfTuples(image->GetNumberOfPoints());
  for (vtkIdType p = 0; p < image->GetNumberOfPoints(); ++p)
  {
    rgb->SetTuple3(p, p * 1.5, -p * 0.25, 7.0);
  }
  image->GetPointData()->AddArray(rgb);

  const std::string chosenPath = vtkBloomTest::OutputPath("ChosenArray.exr");
  const WriteResult chosen = Write(image, chosenPath,
    [](vtkOpenEXRWriter* w)
    { w->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "rgb"); });
  ASSERT_EQ(chosen.Returned, 1) << chosen.Message;
  const auto read = vtkOpenEXRTest::Read(chosenPath);
  ASSERT_EQ(read.Errors, 0) << read.Message;
  ASSERT_EQ(read.Image->GetNumberOfScalarComponents(), 3);
  int extent[6];
  image->GetExtent(extent);
  for (int j = extent[2]; j <= extent[3]; ++j)
  {
    for (int i = extent[0]; i <= extent[1]; ++i)
    {
      const vtkIdType p = image->ComputePointId(std::array<int, 3>{ i, j, extent[4] }.data());
      for (int c = 0; c < 3; ++c)
      {
        EXPECT_EQ(vtkOpenEXRTest::FloatAt(read.Image, i, j, c),
          static_cast<float>(rgb->GetComponent(p, c)));
      }
    }
  }

  const std::string activePath = vtkBloomTest::OutputPath("ActiveArray.exr");
  ASSERT_EQ(Write(image, activePath).Returned, 1);
  EXPECT_EQ(vtkOpenEXRTest::Read(activePath).Image->GetNumberOfScalarComponents(), 1);

  const std::string missingPath = vtkBloomTest::OutputPath("MissingArray.exr");
  std::remove(missingPath.c_str());
  const WriteResult missing = Write(image, missingPath,
    [](vtkOpenEXRWriter* w)
    { w->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "nope"); });
  EXPECT_GT(missing.Errors, 0);
  EXPECT_NE(missing.Message.find("chosen array"), std::string::npos) << missing.Message;
  EXPECT_FALSE(std::filesystem::exists(missingPath));
}

//------------------------------------------------------------------------------
TEST(OpenEXRWriter, UnsignedIntIsLossless)
{
  auto image = vtkBloomTest::MakeImage(TestExtent, 3, VTK_UNSIGNED_INT,
    [](int i, int j, int, int c)
    { return 4294967295.0 - (c * 1000003.0 + (j + 50) * 97 + i + 7); });
  const std::string path = vtkBloomTest::OutputPath("UnsignedInt.exr");
  // PixelType does not apply to integers.
  const WriteResult written =
    Write(image, path, [](vtkOpenEXRWriter* w) { w->SetPixelTypeToHalf(); });
  ASSERT_EQ(written.Returned, 1) << written.Message;
  Imf::InputFile file(path.c_str());
  EXPECT_EQ(file.header().channels().findChannel("R")->type, Imf::UINT);
  const auto read = vtkOpenEXRTest::Read(path);
  ASSERT_EQ(read.Errors, 0) << read.Message;
  EXPECT_EQ(read.Image->GetScalarType(), VTK_UNSIGNED_INT);
  EXPECT_TRUE(SameExtent(read.Image, image));
  EXPECT_TRUE(vtkBloomTest::BitIdentical(read.Image, image));
}

//------------------------------------------------------------------------------
TEST(OpenEXRWriter, DisplayWindow)
{
  std::mt19937 random(7);
  auto image = MakeFloatImage(3, random);
  const std::string path = vtkBloomTest::OutputPath("DisplayWindow.exr");
  ASSERT_EQ(
    Write(image, path, [](vtkOpenEXRWriter* w) { w->SetDisplayWindow(-10, 99, 0, 49); }).Returned,
    1);
  vtkNew<vtkOpenEXRReader> reader;
  reader->SetFileName(path.c_str());
  reader->UpdateInformation();
  const int* display = reader->GetDisplayWindow();
  EXPECT_EQ(display[0], -10);
  EXPECT_EQ(display[1], 99);
  EXPECT_EQ(display[2], 0);
  EXPECT_EQ(display[3], 49);
  const int* data = reader->GetDataWindow();
  EXPECT_EQ(data[0], TestExtent[0]);
  EXPECT_EQ(data[1], TestExtent[1]);
  EXPECT_EQ(data[2], TestExtent[2]);
  EXPECT_EQ(data[3], TestExtent[3]);
}

//------------------------------------------------------------------------------
TEST(OpenEXRWriter, OverwritesExistingFile)
{
  std::mt19937 random(11);
  const std::string path = vtkBloomTest::OutputPath("Overwrite.exr");
  auto first = MakeFloatImage(1, random);
  auto second = MakeFloatImage(4, random);
  ASSERT_EQ(Write(first, path).Returned, 1);
  // The replacement keeps the permissions of the file it replaces.
  const fs::perms permissions =
    fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read;
  fs::permissions(path, permissions);
  ASSERT_EQ(Write(second, path).Returned, 1);
  EXPECT_EQ(fs::status(path).permissions(), permissions);
  const auto read = vtkOpenEXRTest::Read(path);
  EXPECT_TRUE(vtkBloomTest::BitIdentical(read.Image, second));
  EXPECT_EQ(CountTemporaries(vtkBloomTest::OutputDirectory()), 0);
}

//------------------------------------------------------------------------------
class OpenEXRWriterErrors : public ::testing::Test
{
protected:
  void SetUp() override
  {
    std::mt19937 random(3);
    this->Good = MakeFloatImage(3, random);
    this->Existing = vtkBloomTest::OutputPath("WriterErrorsExisting.exr");
    ASSERT_EQ(Write(this->Good, this->Existing).Returned, 1);
    this->ExistingBytes = vtkOpenEXRTest::FileBytes(this->Existing);
    ASSERT_FALSE(this->ExistingBytes.empty());
  }

  // A failed write: Write() returned 0, one error event, an error code, the existing file
  // untouched and no temporary file left behind.
  void ExpectCleanFailure(const WriteResult& result)
  {
    EXPECT_EQ(result.Returned, 0);
    EXPECT_EQ(result.Errors, 1) << result.Message;
    EXPECT_NE(result.ErrorCode, vtkErrorCode::NoError);
    EXPECT_EQ(vtkOpenEXRTest::FileBytes(this->Existing), this->ExistingBytes);
    EXPECT_EQ(CountTemporaries(vtkBloomTest::OutputDirectory()), 0);
  }

  vtkSmartPointer<vtkImageData> Good;
  std::string Existing;
  std::string ExistingBytes;
};

TEST_F(OpenEXRWriterErrors, UnsupportedScalarType)
{
  auto shorts = vtkBloomTest::MakeImage(
    TestExtent, 3, VTK_SHORT, [](int i, int j, int, int c) { return i + j + c; });
  const WriteResult result = Write(shorts, this->Existing);
  this->ExpectCleanFailure(result);
  EXPECT_NE(result.Message.find("short"), std::string::npos) << result.Message;
}

TEST_F(OpenEXRWriterErrors, EmptyInput)
{
  vtkNew<vtkImageData> empty;
  this->ExpectCleanFailure(Write(empty, this->Existing));
  // Points but no scalars.
  vtkNew<vtkImageData> noScalars;
  noScalars->SetExtent(0, 3, 0, 3, 0, 0);
  this->ExpectCleanFailure(Write(noScalars, this->Existing));
}

TEST_F(OpenEXRWriterErrors, VolumeAndTooManyComponents)
{
  const int volume[6] = { 0, 3, 0, 3, 0, 1 };
  auto image = vtkBloomTest::MakeImage(volume, 1, VTK_FLOAT, [](int, int, int, int) { return 1; });
  this->ExpectCleanFailure(Write(image, this->Existing));
  auto five =
    vtkBloomTest::MakeImage(TestExtent, 5, VTK_FLOAT, [](int, int, int, int) { return 1; });
  this->ExpectCleanFailure(Write(five, this->Existing));
}

TEST_F(OpenEXRWriterErrors, BadTileSize)
{
  this->ExpectCleanFailure(Write(this->Good, this->Existing,
    [](vtkOpenEXRWriter* w)
    {
      w->TiledOn();
      w->SetTileSize(0, 16);
    }));
}

TEST_F(OpenEXRWriterErrors, MissingDirectory)
{
  const std::string path = vtkBloomTest::OutputPath("no_such_directory/out.exr");
  const WriteResult result = Write(this->Good, path);
  this->ExpectCleanFailure(result);
  EXPECT_EQ(result.ErrorCode, vtkErrorCode::CannotOpenFileError);
  EXPECT_FALSE(fs::exists(path));
}

TEST_F(OpenEXRWriterErrors, TargetIsDirectory)
{
  const std::string path = vtkBloomTest::OutputPath("a_directory.exr");
  fs::create_directories(path);
  this->ExpectCleanFailure(Write(this->Good, path));
  EXPECT_TRUE(fs::is_directory(path));
}

TEST_F(OpenEXRWriterErrors, NoFileName)
{
  vtkNew<vtkOpenEXRWriter> writer;
  vtkNew<vtkOpenEXRTest::ErrorObserver> observer;
  writer->AddObserver(vtkCommand::ErrorEvent, observer);
  writer->SetInputData(this->Good);
  EXPECT_EQ(writer->Write(), 0);
  EXPECT_EQ(observer->Errors, 1);
  EXPECT_EQ(writer->GetErrorCode(), vtkErrorCode::NoFileNameError);
}

#ifndef _WIN32
// Write `image` to `path` as the unprivileged user "nobody" (65534) where this process is root,
// for whom directory permissions are not enforced: in a child process that drops its
// privileges, whose result comes back as its exit status. Otherwise in this process.
WriteResult WriteAsAnUnprivilegedUser(vtkImageData* image, const std::string& path)
{
  if (::geteuid() != 0)
  {
    return Write(image, path);
  }
  std::fflush(nullptr);
  const pid_t child = ::fork();
  if (child == 0)
  {
    const bool dropped = ::setgroups(0, nullptr) == 0 && ::setgid(65534) == 0 &&
      ::setuid(65534) == 0 && ::geteuid() == 65534;
    if (!dropped)
    {
      ::_exit(100);
    }
    const WriteResult result = Write(image, path);
    // Returned (0 or 1), then the number of errors reported (at most 9), then the code's
    // class: 1 when CannotOpenFileError.
    ::_exit(result.Returned * 100 + std::min(result.Errors, 9) * 10 +
      (result.ErrorCode == vtkErrorCode::CannotOpenFileError ? 1 : 0));
  }
  int status = 0;
  WriteResult result;
  if (child < 0 || ::waitpid(child, &status, 0) != child || !WIFEXITED(status) ||
    WEXITSTATUS(status) == 100)
  {
    ADD_FAILURE() << "no child process could write as the user nobody";
    result.Returned = -1;
    return result;
  }
  const int code = WEXITSTATUS(status);
  result.Returned = code / 100;
  result.Errors = (code / 10) % 10;
  result.ErrorCode =
    code % 10 == 1 ? vtkErrorCode::CannotOpenFileError : vtkErrorCode::UnknownError;
  return result;
}

// Limits the size of any file this process writes (RLIMIT_FSIZE, which binds root too) for
// its lifetime; a write past it fails with EFBIG instead of raising SIGXFSZ.
class FileSizeLimit
{
public:
  explicit FileSizeLimit(rlim_t bytes)
  {
    this->Previous = std::signal(SIGXFSZ, SIG_IGN);
    ::getrlimit(RLIMIT_FSIZE, &this->Saved);
    struct rlimit limit = this->Saved;
    limit.rlim_cur = bytes;
    this->Set = ::setrlimit(RLIMIT_FSIZE, &limit) == 0;
  }
  ~FileSizeLimit()
  {
    ::setrlimit(RLIMIT_FSIZE, &this->Saved);
    std::signal(SIGXFSZ, this->Previous);
  }
  FileSizeLimit(const FileSizeLimit&) = delete;
  FileSizeLimit& operator=(const FileSizeLimit&) = delete;
  bool Set = false;

private:
  struct rlimit Saved = {};
  void (*Previous)(int) = SIG_DFL;
};
#endif

// A directory the user cannot write to: the write fails before any byte, and the file there
// is kept. Run as root (every CI leg), it runs as the user nobody.
TEST_F(OpenEXRWriterErrors, UnwritableDirectory)
{
#ifdef _WIN32
  GTEST_SKIP() << "POSIX permissions";
#else
  const std::string directory = vtkBloomTest::OutputPath("read_only");
  fs::create_directories(directory);
  const std::string path = directory + "/kept.exr";
  fs::permissions(directory, fs::perms::owner_all);
  ASSERT_EQ(Write(this->Good, path).Returned, 1);
  const std::string before = vtkOpenEXRTest::FileBytes(path);
  // Readable and searchable by all, writable by none.
  fs::permissions(directory,
    fs::perms::owner_read | fs::perms::owner_exec | fs::perms::group_read | fs::perms::group_exec |
      fs::perms::others_read | fs::perms::others_exec);
  std::mt19937 random(5);
  auto other = MakeFloatImage(1, random);
  const WriteResult result = WriteAsAnUnprivilegedUser(other, path);
  fs::permissions(directory, fs::perms::owner_all);
  EXPECT_EQ(result.Returned, 0);
  EXPECT_EQ(result.Errors, 1);
  EXPECT_EQ(result.ErrorCode, vtkErrorCode::CannotOpenFileError);
  EXPECT_EQ(vtkOpenEXRTest::FileBytes(path), before);
  EXPECT_EQ(CountTemporaries(directory), 0);
#endif
}

// The disk fills up halfway through the file: the write fails, the file that was there is
// kept byte for byte, and the partial temporary file is removed. Root cannot bypass the
// limit, so this runs in every leg.
TEST_F(OpenEXRWriterErrors, DiskFullHalfwayKeepsTheOldFile)
{
#ifdef _WIN32
  GTEST_SKIP() << "POSIX resource limits";
#else
  std::mt19937 random(6);
  auto other = MakeFloatImage(3, random);
  WriteResult result;
  {
    // Half of what the same image takes: the header and part of the pixels fit.
    FileSizeLimit limit(static_cast<rlim_t>(this->ExistingBytes.size() / 2));
    ASSERT_TRUE(limit.Set);
    result = Write(other, this->Existing, [](vtkOpenEXRWriter* w) { w->SetNumberOfThreads(1); });
  }
  this->ExpectCleanFailure(result);
  EXPECT_EQ(result.ErrorCode, vtkErrorCode::OutOfDiskSpaceError) << result.Message;
#endif
}

//------------------------------------------------------------------------------
TEST(OpenEXRWriter, PrintSelfShowsParameters)
{
  vtkNew<vtkOpenEXRWriter> writer;
  writer->SetFileName("y.exr");
  writer->SetPixelTypeToHalf();
  writer->SetCompressionToPiz();
  writer->SetDisplayWindow(1, 2, 3, 4);
  writer->TiledOn();
  writer->SetTileSize(32, 16);
  std::ostringstream os;
  writer->Print(os);
  const std::string text = os.str();
  for (const char* expected : { "FileName: y.exr", "PixelType: Half", "Compression: PIZ",
         "DisplayWindow: 1 2 3 4", "Tiled: On", "TileSize: 32 16" })
  {
    EXPECT_NE(text.find(expected), std::string::npos) << expected;
  }
  // The defaults: float, ZIP.
  vtkNew<vtkOpenEXRWriter> defaults;
  EXPECT_EQ(defaults->GetPixelType(), vtkOpenEXRWriter::PIXEL_TYPE_FLOAT);
  EXPECT_EQ(defaults->GetCompression(), vtkOpenEXRWriter::COMPRESSION_ZIP);
}
}
