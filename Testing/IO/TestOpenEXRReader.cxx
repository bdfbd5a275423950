// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// vtkOpenEXRReader on the real files of ../shared/data/exr and on small files written here
// with the OpenEXR C++ library. Expectations come from the file headers (read with the C++
// library) and pixels are compared with the C++ library's own decoder, which shares no
// decoding code with the reader's core-library path.
#include "vtkBloomTestSupport.h"
#include "vtkOpenEXRReader.h"
#include "vtkOpenEXRTestHelpers.h"

#include <vtkDataArray.h>
#include <vtkErrorCode.h>
#include <vtkImageData.h>
#include <vtkInformation.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkStreamingDemandDrivenPipeline.h>
#include <vtkStringArray.h>

#include <Imath/half.h>
#include <ImfChannelList.h>
#include <ImfDeepFrameBuffer.h>
#include <ImfDeepScanLineOutputFile.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfInputPart.h>
#include <ImfMultiPartInputFile.h>
#include <ImfOutputFile.h>
#include <ImfPartType.h>
#include <ImfRgbaFile.h>

#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <functional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using vtkOpenEXRTest::Bits;
using vtkOpenEXRTest::Read;

//------------------------------------------------------------------------------
// The channels of part `part`, decoded as float by the OpenEXR C++ library, interleaved in the
// given order, rows from the data window's first row.
std::vector<float> ReferencePixels(
  const std::string& path, int part, const std::vector<std::string>& names, Imath::Box2i& window)
{
  Imf::MultiPartInputFile file(path.c_str());
  Imf::InputPart input(file, part);
  window = input.header().dataWindow();
  const size_t width = static_cast<size_t>(window.max.x - window.min.x + 1);
  const size_t height = static_cast<size_t>(window.max.y - window.min.y + 1);
  const size_t n = names.size();
  std::vector<float> pixels(width * height * n);
  Imf::FrameBuffer frameBuffer;
  for (size_t c = 0; c < n; ++c)
  {
    frameBuffer.insert(names[c],
      Imf::Slice::Make(
        Imf::FLOAT, pixels.data() + c, window, n * sizeof(float), n * sizeof(float) * width));
  }
  input.setFrameBuffer(frameBuffer);
  input.readPixels(window.min.y, window.max.y);
  return pixels;
}

//------------------------------------------------------------------------------
// Number of scalar values whose bits differ between the reader's output and `expected`.
size_t CountBitDifferences(vtkImageData* image, const std::vector<float>& expected)
{
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  if (!scalars || scalars->GetDataType() != VTK_FLOAT ||
    static_cast<size_t>(scalars->GetNumberOfValues()) != expected.size())
  {
    return expected.size() + 1;
  }
  const float* data = static_cast<const float*>(scalars->GetVoidPointer(0));
  size_t differences = 0;
  for (size_t v = 0; v < expected.size(); ++v)
  {
    differences += Bits(data[v]) != Bits(expected[v]) ? 1 : 0;
  }
  return differences;
}

//------------------------------------------------------------------------------
std::vector<std::string> ComponentNames(vtkOpenEXRReader* reader)
{
  std::vector<std::string> names;
  vtkStringArray* array = reader->GetComponentNames();
  for (vtkIdType i = 0; i < array->GetNumberOfValues(); ++i)
  {
    names.push_back(array->GetValue(i));
  }
  return names;
}

//------------------------------------------------------------------------------
// One real file: its data window and the channels the reader must pick, from its header.
struct RealFile
{
  const char* Name;
  int Window[4]; // xmin, xmax, ymin, ymax
  std::vector<std::string> Channels;
};

void PrintTo(const RealFile& file, std::ostream* os)
{
  *os << file.Name;
}

class OpenEXRReaderRealFile : public ::testing::TestWithParam<RealFile>
{
};

//------------------------------------------------------------------------------
TEST_P(OpenEXRReaderRealFile, MatchesHeaderAndReferenceDecoder)
{
  const RealFile& expected = GetParam();
  VTKBLOOM_REQUIRE_DATA(path, std::string("exr/") + expected.Name);

  // The table above must agree with the header itself.
  Imf::MultiPartInputFile file(path.c_str());
  const Imath::Box2i headerWindow = file.header(0).dataWindow();
  ASSERT_EQ(headerWindow.min.x, expected.Window[0]);
  ASSERT_EQ(headerWindow.max.x, expected.Window[1]);
  ASSERT_EQ(headerWindow.min.y, expected.Window[2]);
  ASSERT_EQ(headerWindow.max.y, expected.Window[3]);
  for (const std::string& channel : expected.Channels)
  {
    ASSERT_NE(file.header(0).channels().findChannel(channel), nullptr) << channel;
  }

  vtkNew<vtkOpenEXRReader> reader;
  vtkNew<vtkOpenEXRTest::ErrorObserver> observer;
  reader->AddObserver(vtkCommand::ErrorEvent, observer);
  reader->SetFileName(path.c_str());
  reader->Update();
  ASSERT_EQ(observer->Errors, 0) << observer->Message;
  EXPECT_EQ(reader->GetErrorCode(), vtkErrorCode::NoError);

  vtkImageData* image = reader->GetOutput();
  int extent[6];
  image->GetExtent(extent);
  EXPECT_EQ(extent[0], expected.Window[0]);
  EXPECT_EQ(extent[1], expected.Window[1]);
  EXPECT_EQ(extent[2], expected.Window[2]);
  EXPECT_EQ(extent[3], expected.Window[3]);
  EXPECT_EQ(extent[4], 0);
  EXPECT_EQ(extent[5], 0);
  ASSERT_EQ(image->GetNumberOfScalarComponents(), static_cast<int>(expected.Channels.size()));
  ASSERT_EQ(image->GetScalarType(), VTK_FLOAT);
  EXPECT_EQ(ComponentNames(reader), expected.Channels);
  EXPECT_STREQ(
    image->GetPointData()->GetScalars()->GetComponentName(0), expected.Channels[0].c_str());

  Imath::Box2i window;
  const std::vector<float> reference = ReferencePixels(path, 0, expected.Channels, window);
  EXPECT_EQ(CountBitDifferences(image, reference), 0u);
}

// Windows and channels as the OpenEXR headers state them (exrheader-style inspection).
INSTANTIATE_TEST_SUITE_P(SharedData, OpenEXRReaderRealFile,
  ::testing::Values(RealFile{ "ScanLines_Desk.exr", { 0, 643, 0, 873 }, { "R", "G", "B", "A" } },
    RealFile{ "ScanLines_CandleGlass.exr", { 0, 999, 0, 809 }, { "R", "G", "B", "A" } },
    RealFile{ "Tiles_GoldenGate.exr", { 0, 1261, 0, 859 }, { "R", "G", "B" } },
    RealFile{ "DisplayWindow_t08.exr", { 30, 429, 40, 339 }, { "R", "G", "B" } },
    RealFile{ "MultiResolution_ColorCodedLevels.exr", { 0, 511, 0, 511 }, { "R", "G", "B", "A" } },
    RealFile{ "Beachball_multipart.0001.exr", { 654, 1530, 245, 1120 }, { "R", "G", "B", "A" } },
    RealFile{ "TestImages_AllHalfValues.exr", { 0, 255, 0, 255 }, { "R", "G", "B" } },
    RealFile{ "TestImages_BrightRings.exr", { 0, 799, 0, 799 }, { "R", "G", "B" } },
    RealFile{ "TestImages_BrightRingsNanInf.exr", { 0, 799, 0, 799 }, { "R", "G", "B" } },
    RealFile{ "TestImages_GrayRampsHorizontal.exr", { 0, 799, 0, 799 }, { "Y" } },
    RealFile{ "TestImages_WideFloatRange.exr", { 0, 499, 0, 499 }, { "G" } },
    RealFile{ "TestImages_stripes.exr", { 0, 99, 0, 49 }, { "R", "G", "B", "A" } }),
  [](const ::testing::TestParamInfo<RealFile>& info)
  {
    std::string name = info.param.Name;
    name = name.substr(0, name.find('.'));
    for (char& c : name)
    {
      c = std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
    }
    return name;
  });

//------------------------------------------------------------------------------
TEST(OpenEXRReader, DataWindowAndDisplayWindow)
{
  VTKBLOOM_REQUIRE_DATA(path, "exr/DisplayWindow_t08.exr");
  Imf::InputFile file(path.c_str());
  const Imath::Box2i data = file.header().dataWindow();
  const Imath::Box2i display = file.header().displayWindow();
  // The point of this file: the two windows differ.
  ASSERT_NE(data, display);

  vtkNew<vtkOpenEXRReader> reader;
  reader->SetFileName(path.c_str());
  reader->UpdateInformation();
  const int* dw = reader->GetDataWindow();
  const int* dsp = reader->GetDisplayWindow();
  EXPECT_EQ(dw[0], data.min.x);
  EXPECT_EQ(dw[1], data.max.x);
  EXPECT_EQ(dw[2], data.min.y);
  EXPECT_EQ(dw[3], data.max.y);
  EXPECT_EQ(dsp[0], display.min.x);
  EXPECT_EQ(dsp[1], display.max.x);
  EXPECT_EQ(dsp[2], display.min.y);
  EXPECT_EQ(dsp[3], display.max.y);

  // WHOLE_EXTENT is the data window, with unit spacing and zero origin, so a point's index
  // is its EXR pixel coordinate.
  vtkInformation* info = reader->GetOutputInformation(0);
  int whole[6];
  info->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), whole);
  EXPECT_EQ(whole[0], data.min.x);
  EXPECT_EQ(whole[1], data.max.x);
  EXPECT_EQ(whole[2], data.min.y);
  EXPECT_EQ(whole[3], data.max.y);
  EXPECT_EQ(whole[4], 0);
  EXPECT_EQ(whole[5], 0);

  reader->Update();
  vtkImageData* image = reader->GetOutput();
  double spacing[3], origin[3];
  image->GetSpacing(spacing);
  image->GetOrigin(origin);
  EXPECT_EQ(spacing[0], 1.0);
  EXPECT_EQ(spacing[1], 1.0);
  EXPECT_EQ(origin[0], 0.0);
  EXPECT_EQ(origin[1], 0.0);

  // No flip: the file's first row (y = ymin) is at structured index j = ymin, and the bottom
  // right pixel is at (xmax, ymax).
  Imath::Box2i window;
  const std::vector<float> reference = ReferencePixels(path, 0, { "R", "G", "B" }, window);
  const size_t width = static_cast<size_t>(window.max.x - window.min.x + 1);
  for (int c = 0; c < 3; ++c)
  {
    EXPECT_EQ(Bits(vtkOpenEXRTest::FloatAt(image, data.min.x, data.min.y, c)), Bits(reference[c]));
    const size_t last = (static_cast<size_t>(data.max.y - data.min.y) * width +
                          static_cast<size_t>(data.max.x - data.min.x)) *
        3 +
      c;
    EXPECT_EQ(
      Bits(vtkOpenEXRTest::FloatAt(image, data.max.x, data.max.y, c)), Bits(reference[last]));
  }
}

//------------------------------------------------------------------------------
TEST(OpenEXRReader, MultiPartSelectionByIndexAndName)
{
  VTKBLOOM_REQUIRE_DATA(path, "exr/Beachball_multipart.0001.exr");
  Imf::MultiPartInputFile file(path.c_str());
  ASSERT_GT(file.parts(), 1);

  vtkNew<vtkOpenEXRReader> reader;
  reader->SetFileName(path.c_str());
  reader->UpdateInformation();
  ASSERT_EQ(reader->GetNumberOfParts(), file.parts());
  for (int p = 0; p < file.parts(); ++p)
  {
    EXPECT_EQ(std::string(reader->GetPartName(p)), file.header(p).name()) << p;
  }
  EXPECT_EQ(reader->GetPartName(-1), nullptr);
  EXPECT_EQ(reader->GetPartName(file.parts()), nullptr);

  // Every part, by index, against the C++ decoder. The channels follow the documented rule:
  // RGBA when present, else the first channels of the (only) layer in name order.
  for (int p = 0; p < file.parts(); ++p)
  {
    const Imf::Header& header = file.header(p);
    std::vector<std::string> channels;
    if (header.channels().findChannel("R"))
    {
      channels = { "R", "G", "B", "A" };
    }
    else
    {
      for (auto it = header.channels().begin(); it != header.channels().end(); ++it)
      {
        channels.emplace_back(it.name());
      }
    }
    const auto result = Read(path, [p](vtkOpenEXRReader* r) { r->SetPartIndex(p); });
    ASSERT_EQ(result.Errors, 0) << "part " << p << ": " << result.Message;
    ASSERT_EQ(result.Image->GetNumberOfScalarComponents(), static_cast<int>(channels.size()));
    const Imath::Box2i window = header.dataWindow();
    int extent[6];
    result.Image->GetExtent(extent);
    EXPECT_EQ(extent[0], window.min.x) << p;
    EXPECT_EQ(extent[3], window.max.y) << p;
    Imath::Box2i unused;
    EXPECT_EQ(CountBitDifferences(result.Image, ReferencePixels(path, p, channels, unused)), 0u)
      << "part " << p << " (" << header.name() << ")";
  }

  // By name: "depth_left" is a Z-only part; the name wins over the index.
  int depthIndex = -1;
  for (int p = 0; p < file.parts(); ++p)
  {
    depthIndex = file.header(p).name() == "depth_left" ? p : depthIndex;
  }
  ASSERT_GT(depthIndex, 0);
  reader->SetPartIndex(0);
  reader->SetPartName("depth_left");
  reader->Update();
  EXPECT_EQ(reader->GetSelectedPartIndex(), depthIndex);
  EXPECT_EQ(reader->GetOutput()->GetNumberOfScalarComponents(), 1);
  EXPECT_EQ(ComponentNames(reader), std::vector<std::string>{ "Z" });

  // Different parts give different images: rgba_right (part 0) and rgba_left.
  const auto right = Read(path, [](vtkOpenEXRReader* r) { r->SetPartName("rgba_right"); });
  const auto left = Read(path, [](vtkOpenEXRReader* r) { r->SetPartName("rgba_left"); });
  const auto first = Read(path, [](vtkOpenEXRReader* r) { r->SetPartIndex(0); });
  ASSERT_EQ(right.Errors + left.Errors + first.Errors, 0);
  EXPECT_TRUE(vtkBloomTest::BitIdentical(right.Image, first.Image));
  EXPECT_NE(right.Image->GetExtent()[0], left.Image->GetExtent()[0]);
  EXPECT_FALSE(vtkBloomTest::BitIdentical(right.Image, left.Image));
}

//------------------------------------------------------------------------------
TEST(OpenEXRReader, BadPartSelectionIsAnError)
{
  VTKBLOOM_REQUIRE_DATA(path, "exr/Beachball_multipart.0001.exr");
  const auto byName = Read(path, [](vtkOpenEXRReader* r) { r->SetPartName("no_such_part"); });
  EXPECT_EQ(byName.Errors, 1);
  EXPECT_TRUE(byName.Empty());
  EXPECT_EQ(byName.ErrorCode, vtkErrorCode::UserError);
  // The message helps: it lists the parts that exist.
  EXPECT_NE(byName.Message.find("rgba_left"), std::string::npos) << byName.Message;

  const auto byIndex = Read(path, [](vtkOpenEXRReader* r) { r->SetPartIndex(10); });
  EXPECT_EQ(byIndex.Errors, 1);
  EXPECT_TRUE(byIndex.Empty());
  EXPECT_NE(byIndex.ErrorCode, vtkErrorCode::NoError);
}

//------------------------------------------------------------------------------
TEST(OpenEXRReader, LuminanceChromaBecomesRGB)
{
  VTKBLOOM_REQUIRE_DATA(path, "exr/LuminanceChroma_StarField.exr");
  // The file really is subsampled luminance/chroma.
  Imf::InputFile file(path.c_str());
  const Imf::Channel* ry = file.header().channels().findChannel("RY");
  ASSERT_NE(ry, nullptr);
  ASSERT_EQ(ry->xSampling, 2);
  ASSERT_EQ(file.header().channels().findChannel("R"), nullptr);

  vtkNew<vtkOpenEXRReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  ASSERT_EQ(reader->GetErrorCode(), vtkErrorCode::NoError);
  vtkImageData* image = reader->GetOutput();
  ASSERT_EQ(image->GetNumberOfScalarComponents(), 3);
  EXPECT_EQ(ComponentNames(reader), (std::vector<std::string>{ "R", "G", "B" }));

  // Same values as the library's RGBA interface.
  Imf::RgbaInputFile rgba(path.c_str());
  const Imath::Box2i window = rgba.dataWindow();
  const int width = window.max.x - window.min.x + 1;
  const int height = window.max.y - window.min.y + 1;
  std::vector<Imf::Rgba> pixels(static_cast<size_t>(width) * height);
  rgba.setFrameBuffer(pixels.data() - window.min.x - window.min.y * width, 1, width);
  rgba.readPixels(window.min.y, window.max.y);
  size_t differences = 0, finite = 0, coloured = 0;
  double sum = 0.0;
  for (int y = 0; y < height; ++y)
  {
    for (int x = 0; x < width; ++x)
    {
      const Imf::Rgba& p = pixels[static_cast<size_t>(y) * width + x];
      const float r = vtkOpenEXRTest::FloatAt(image, x + window.min.x, y + window.min.y, 0);
      const float g = vtkOpenEXRTest::FloatAt(image, x + window.min.x, y + window.min.y, 1);
      const float b = vtkOpenEXRTest::FloatAt(image, x + window.min.x, y + window.min.y, 2);
      differences +=
        (Bits(r) != Bits(float(p.r)) || Bits(g) != Bits(float(p.g)) || Bits(b) != Bits(float(p.b)))
        ? 1
        : 0;
      finite += std::isfinite(r) && std::isfinite(g) && std::isfinite(b) ? 1 : 0;
      coloured += (r != g || g != b) ? 1 : 0;
      sum += r + g + b;
    }
  }
  EXPECT_EQ(differences, 0u);
  // Plausible colour: all finite, a positive mean, and the chroma makes R, G, B differ.
  EXPECT_EQ(finite, pixels.size());
  EXPECT_GT(sum, 0.0);
  EXPECT_GT(coloured, pixels.size() / 100);
}

//------------------------------------------------------------------------------
TEST(OpenEXRReader, AllHalfValuesAreExact)
{
  VTKBLOOM_REQUIRE_DATA(path, "exr/TestImages_AllHalfValues.exr");
  // The raw half bit patterns, through the C++ library.
  Imf::InputFile file(path.c_str());
  const Imath::Box2i window = file.header().dataWindow();
  const size_t width = static_cast<size_t>(window.max.x - window.min.x + 1);
  const size_t count = width * static_cast<size_t>(window.max.y - window.min.y + 1);
  ASSERT_EQ(count, 65536u);
  std::vector<Imath::half> halves(count * 3);
  Imf::FrameBuffer frameBuffer;
  const char* names[3] = { "R", "G", "B" };
  for (int c = 0; c < 3; ++c)
  {
    frameBuffer.insert(names[c],
      Imf::Slice::Make(Imf::HALF, halves.data() + c, window, 3 * sizeof(Imath::half),
        3 * sizeof(Imath::half) * width));
  }
  file.setFrameBuffer(frameBuffer);
  file.readPixels(window.min.y, window.max.y);

  const auto result = Read(path);
  ASSERT_EQ(result.Errors, 0) << result.Message;
  const float* data =
    static_cast<const float*>(result.Image->GetPointData()->GetScalars()->GetVoidPointer(0));
  for (int c = 0; c < 3; ++c)
  {
    std::set<uint16_t> patterns;
    size_t mismatches = 0, nans = 0, infinities = 0;
    for (size_t p = 0; p < count; ++p)
    {
      const Imath::half h = halves[p * 3 + c];
      patterns.insert(h.bits());
      const float expected = h; // Imath's exact widening, NaN payload included.
      mismatches += Bits(data[p * 3 + c]) != Bits(expected) ? 1 : 0;
      nans += std::isnan(data[p * 3 + c]) ? 1 : 0;
      infinities += std::isinf(data[p * 3 + c]) ? 1 : 0;
    }
    EXPECT_EQ(patterns.size(), 65536u) << "channel " << names[c];
    EXPECT_EQ(mismatches, 0u) << "channel " << names[c];
    // 2 signs x 1023 non-zero mantissas with an all-ones exponent; +Inf and -Inf.
    EXPECT_EQ(nans, 2046u);
    EXPECT_EQ(infinities, 2u);
  }
}

//------------------------------------------------------------------------------
TEST(OpenEXRReader, TiledMipMapReadsFullResolutionLevel)
{
  VTKBLOOM_REQUIRE_DATA(path, "exr/MultiResolution_ColorCodedLevels.exr");
  Imf::MultiPartInputFile file(path.c_str());
  ASSERT_TRUE(file.header(0).hasTileDescription());
  ASSERT_EQ(file.header(0).tileDescription().mode, Imf::MIPMAP_LEVELS);
  const auto result = Read(path);
  ASSERT_EQ(result.Errors, 0) << result.Message;
  int dims[3];
  result.Image->GetDimensions(dims);
  EXPECT_EQ(dims[0], 512);
  EXPECT_EQ(dims[1], 512);
}

//------------------------------------------------------------------------------
TEST(OpenEXRReader, CanReadFile)
{
  VTKBLOOM_REQUIRE_DATA(path, "exr/ScanLines_Desk.exr");
  vtkNew<vtkOpenEXRReader> reader;
  EXPECT_EQ(reader->CanReadFile(path.c_str()), 3);
  EXPECT_EQ(reader->CanReadFile(nullptr), 0);
  EXPECT_EQ(reader->CanReadFile("/nonexistent/file.exr"), 0);
  const std::string text = vtkBloomTest::OutputPath("CanReadFile.txt");
  vtkOpenEXRTest::WriteBytes(text, "not an image\n");
  EXPECT_EQ(reader->CanReadFile(text.c_str()), 0);
  EXPECT_STREQ(reader->GetFileExtensions(), ".exr");
}

//------------------------------------------------------------------------------
TEST(OpenEXRReader, MaximumImageBytesRefusesLargeImages)
{
  VTKBLOOM_REQUIRE_DATA(path, "exr/ScanLines_Desk.exr");
  // 644 x 874 pixels x 4 float components.
  static constexpr vtkTypeUInt64 bytes = 644u * 874u * 4u * 4u;
  const auto refused = Read(path, [](vtkOpenEXRReader* r) { r->SetMaximumImageBytes(bytes - 1); });
  EXPECT_EQ(refused.Errors, 1);
  EXPECT_TRUE(refused.Empty());
  EXPECT_NE(refused.Message.find("MaximumImageBytes"), std::string::npos) << refused.Message;
  const auto accepted = Read(path, [](vtkOpenEXRReader* r) { r->SetMaximumImageBytes(bytes); });
  EXPECT_EQ(accepted.Errors, 0) << accepted.Message;
  EXPECT_EQ(accepted.Image->GetNumberOfPoints(), 644 * 874);
}

//------------------------------------------------------------------------------
TEST(OpenEXRReader, FailureClearsPreviousOutput)
{
  VTKBLOOM_REQUIRE_DATA(good, "exr/ScanLines_Desk.exr");
  vtkNew<vtkOpenEXRReader> reader;
  vtkNew<vtkOpenEXRTest::ErrorObserver> observer;
  reader->AddObserver(vtkCommand::ErrorEvent, observer);
  reader->SetFileName(good.c_str());
  reader->Update();
  ASSERT_GT(reader->GetOutput()->GetNumberOfPoints(), 0);

  const std::string bad = vtkBloomTest::OutputPath("FailureClearsPreviousOutput.exr");
  vtkOpenEXRTest::WriteBytes(bad, vtkOpenEXRTest::FileBytes(good).substr(0, 2000));
  reader->SetFileName(bad.c_str());
  reader->Update();
  EXPECT_EQ(observer->Errors, 1);
  EXPECT_NE(reader->GetErrorCode(), vtkErrorCode::NoError);
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 0);
  EXPECT_EQ(reader->GetOutput()->GetPointData()->GetScalars(), nullptr);
  EXPECT_EQ(reader->GetNumberOfParts(), 1); // the header itself is intact

  // And the reader recovers: the error code is reset by the next successful read.
  reader->SetFileName(good.c_str());
  reader->Update();
  EXPECT_EQ(observer->Errors, 1);
  EXPECT_EQ(reader->GetErrorCode(), vtkErrorCode::NoError);
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 644 * 874);
}

//------------------------------------------------------------------------------
// Write a small scanline file with the C++ library: channel name -> (type, value(x, y)).
struct TestChannel
{
  std::string Name;
  Imf::PixelType Type;
  int Sampling;
};

void WriteTestFile(const std::string& path, int width, int height,
  const std::vector<TestChannel>& channels, const std::function<double(int, int, int)>& value)
{
  Imf::Header header(width, height);
  Imf::FrameBuffer frameBuffer;
  std::vector<std::vector<char>> storage;
  const Imath::Box2i window = header.dataWindow();
  for (size_t c = 0; c < channels.size(); ++c)
  {
    const TestChannel& channel = channels[c];
    header.channels().insert(
      channel.Name, Imf::Channel(channel.Type, channel.Sampling, channel.Sampling));
    const int w = width / channel.Sampling, h = height / channel.Sampling;
    storage.emplace_back(static_cast<size_t>(w) * h * 4);
    char* data = storage.back().data();
    for (int y = 0; y < h; ++y)
    {
      for (int x = 0; x < w; ++x)
      {
        const double v = value(static_cast<int>(c), x, y);
        char* out = data + (static_cast<size_t>(y) * w + x) * 4;
        if (channel.Type == Imf::UINT)
        {
          *reinterpret_cast<uint32_t*>(out) = static_cast<uint32_t>(v);
        }
        else if (channel.Type == Imf::HALF)
        {
          *reinterpret_cast<Imath::half*>(out) = Imath::half(static_cast<float>(v));
        }
        else
        {
          *reinterpret_cast<float*>(out) = static_cast<float>(v);
        }
      }
    }
    // Every value sits in a 4-byte cell, whatever its type, to keep the strides uniform.
    frameBuffer.insert(channel.Name,
      Imf::Slice(
        channel.Type, data, 4, static_cast<size_t>(w) * 4, channel.Sampling, channel.Sampling));
  }
  Imf::OutputFile out(path.c_str(), header);
  out.setFrameBuffer(frameBuffer);
  out.writePixels(window.max.y - window.min.y + 1);
}

//------------------------------------------------------------------------------
TEST(OpenEXRReader, UnsignedIntChannels)
{
  const std::string path = vtkBloomTest::OutputPath("UnsignedIntChannels.exr");
  auto value = [](int c, int x, int y)
  { return static_cast<double>(4294967295u - static_cast<uint32_t>(c * 1000003 + y * 97 + x)); };
  WriteTestFile(
    path, 13, 7, { { "B", Imf::UINT, 1 }, { "G", Imf::UINT, 1 }, { "R", Imf::UINT, 1 } }, value);
  const auto result = Read(path);
  ASSERT_EQ(result.Errors, 0) << result.Message;
  ASSERT_EQ(result.Image->GetScalarType(), VTK_UNSIGNED_INT);
  ASSERT_EQ(result.Image->GetNumberOfScalarComponents(), 3);
  // Components are R, G, B; the file stores them as channels 2, 1, 0 of WriteTestFile.
  const unsigned int* data =
    static_cast<const unsigned int*>(result.Image->GetPointData()->GetScalars()->GetVoidPointer(0));
  size_t mismatches = 0;
  for (int y = 0; y < 7; ++y)
  {
    for (int x = 0; x < 13; ++x)
    {
      for (int c = 0; c < 3; ++c)
      {
        mismatches += data[(y * 13 + x) * 3 + c] != static_cast<uint32_t>(value(2 - c, x, y));
      }
    }
  }
  EXPECT_EQ(mismatches, 0u);

  // One UINT channel among float ones: everything becomes float.
  const std::string mixed = vtkBloomTest::OutputPath("MixedChannels.exr");
  WriteTestFile(mixed, 5, 4,
    { { "B", Imf::HALF, 1 }, { "G", Imf::FLOAT, 1 }, { "R", Imf::UINT, 1 } },
    [](int c, int x, int y) { return c == 2 ? 1000000.0 + x + 10 * y : 0.25 * (x - y); });
  const auto mixedResult = Read(mixed);
  ASSERT_EQ(mixedResult.Errors, 0) << mixedResult.Message;
  ASSERT_EQ(mixedResult.Image->GetScalarType(), VTK_FLOAT);
  EXPECT_EQ(vtkOpenEXRTest::FloatAt(mixedResult.Image, 3, 2, 0), 1000023.0f);
  EXPECT_EQ(vtkOpenEXRTest::FloatAt(mixedResult.Image, 3, 2, 1), 0.25f);
  EXPECT_EQ(vtkOpenEXRTest::FloatAt(mixedResult.Image, 3, 2, 2), 0.25f);
}

//------------------------------------------------------------------------------
TEST(OpenEXRReader, LayersAndChannelNames)
{
  const std::string path = vtkBloomTest::OutputPath("Layers.exr");
  const std::vector<TestChannel> channels = { { "Z", Imf::FLOAT, 1 }, { "diffuse.B", Imf::HALF, 1 },
    { "diffuse.G", Imf::HALF, 1 }, { "diffuse.R", Imf::HALF, 1 }, { "specular.B", Imf::FLOAT, 1 },
    { "specular.G", Imf::FLOAT, 1 }, { "specular.R", Imf::FLOAT, 1 } };
  WriteTestFile(path, 6, 4, channels, [](int c, int x, int y) { return c * 100 + y * 10 + x; });

  vtkNew<vtkOpenEXRReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  ASSERT_EQ(reader->GetErrorCode(), vtkErrorCode::NoError);
  // All channels are listed, in file (name) order.
  vtkStringArray* names = reader->GetChannelNames();
  ASSERT_EQ(names->GetNumberOfValues(), 7);
  EXPECT_EQ(names->GetValue(0), "Z");
  EXPECT_EQ(names->GetValue(6), "specular.R");
  // The unnamed layer holds only Z.
  EXPECT_EQ(ComponentNames(reader), std::vector<std::string>{ "Z" });
  EXPECT_EQ(vtkOpenEXRTest::FloatAt(reader->GetOutput(), 5, 3, 0), 35.0f);

  reader->SetLayer("specular");
  reader->Update();
  ASSERT_EQ(reader->GetErrorCode(), vtkErrorCode::NoError);
  EXPECT_EQ(
    ComponentNames(reader), (std::vector<std::string>{ "specular.R", "specular.G", "specular.B" }));
  // specular.R was channel 6 of WriteTestFile, specular.B channel 4.
  EXPECT_EQ(vtkOpenEXRTest::FloatAt(reader->GetOutput(), 5, 3, 0), 635.0f);
  EXPECT_EQ(vtkOpenEXRTest::FloatAt(reader->GetOutput(), 5, 3, 2), 435.0f);

  const auto missing = Read(path, [](vtkOpenEXRReader* r) { r->SetLayer("nope"); });
  EXPECT_EQ(missing.Errors, 1);
  EXPECT_TRUE(missing.Empty());
  EXPECT_NE(missing.Message.find("diffuse"), std::string::npos) << missing.Message;

  // Without an unnamed layer, the layer of the first channel is used; u, v is no known
  // layout, so both channels are read in name order.
  const std::string layered = vtkBloomTest::OutputPath("LayerOnly.exr");
  WriteTestFile(layered, 4, 4,
    { { "forward.u", Imf::HALF, 1 }, { "forward.v", Imf::HALF, 1 }, { "mask.m", Imf::HALF, 1 } },
    [](int c, int, int) { return c + 1.0; });
  const auto layerResult = Read(layered);
  ASSERT_EQ(layerResult.Errors, 0) << layerResult.Message;
  ASSERT_EQ(layerResult.Image->GetNumberOfScalarComponents(), 2);
  EXPECT_EQ(vtkOpenEXRTest::FloatAt(layerResult.Image, 0, 0, 0), 1.0f);
  EXPECT_EQ(vtkOpenEXRTest::FloatAt(layerResult.Image, 0, 0, 1), 2.0f);
}

//------------------------------------------------------------------------------
TEST(OpenEXRReader, SubsampledChannelIsAnError)
{
  const std::string path = vtkBloomTest::OutputPath("Subsampled.exr");
  WriteTestFile(path, 8, 8, { { "Z", Imf::HALF, 2 } }, [](int, int x, int) { return x; });
  const auto result = Read(path);
  EXPECT_EQ(result.Errors, 1);
  EXPECT_TRUE(result.Empty());
  EXPECT_NE(result.Message.find("subsampled"), std::string::npos) << result.Message;
}

//------------------------------------------------------------------------------
TEST(OpenEXRReader, DeepPartIsAnError)
{
  const std::string path = vtkBloomTest::OutputPath("Deep.exr");
  {
    Imf::Header header(4, 4);
    header.channels().insert("Z", Imf::Channel(Imf::FLOAT));
    header.setType(Imf::DEEPSCANLINE);
    header.compression() = Imf::ZIPS_COMPRESSION;
    std::vector<unsigned int> counts(16, 1);
    std::vector<float> depth(16, 2.0f);
    std::vector<float*> pointers(16);
    for (size_t i = 0; i < 16; ++i)
    {
      pointers[i] = &depth[i];
    }
    Imf::DeepFrameBuffer frameBuffer;
    frameBuffer.insertSampleCountSlice(Imf::Slice(Imf::UINT, reinterpret_cast<char*>(counts.data()),
      sizeof(unsigned int), 4 * sizeof(unsigned int)));
    frameBuffer.insert("Z",
      Imf::DeepSlice(Imf::FLOAT, reinterpret_cast<char*>(pointers.data()), sizeof(float*),
        4 * sizeof(float*), sizeof(float)));
    Imf::DeepScanLineOutputFile out(path.c_str(), header);
    out.setFrameBuffer(frameBuffer);
    out.writePixels(4);
  }
  const auto result = Read(path);
  EXPECT_EQ(result.Errors, 1);
  EXPECT_TRUE(result.Empty());
  EXPECT_EQ(result.ErrorCode, vtkErrorCode::FileFormatError);
  EXPECT_NE(result.Message.find("deep"), std::string::npos) << result.Message;
}

//------------------------------------------------------------------------------
TEST(OpenEXRReader, PrintSelfShowsParameters)
{
  vtkNew<vtkOpenEXRReader> reader;
  reader->SetFileName("x.exr");
  reader->SetPartName("beauty");
  reader->SetLayer("diffuse");
  reader->SetMaximumImageBytes(12345);
  std::ostringstream os;
  reader->Print(os);
  const std::string text = os.str();
  for (const char* expected : { "FileName: x.exr", "PartIndex: 0", "PartName: beauty",
         "Layer: diffuse", "MaximumImageBytes: 12345", "DataWindow: 0 -1 0 -1",
         "DisplayWindow: 0 -1 0 -1", "NumberOfParts: 0" })
  {
    EXPECT_NE(text.find(expected), std::string::npos) << expected;
  }
}
}
