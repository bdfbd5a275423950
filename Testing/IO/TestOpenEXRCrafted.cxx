// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// vtkOpenEXRReader on crafted files (Support/vtkBloomCraftedEXR.h): chunks whose streams
// decode short of what the header and channel list require, in every layout the reader
// accepts. OpenEXR 3.1 accepts the DWA ones and copies unset heap bytes into the image; the
// reader must refuse each with one line naming the chunk. The valid files they are made from
// must read exactly as OpenEXR's C++ library decodes them, so that the checks refuse nothing
// sound. Run under valgrind by scripts/test.sh (the hostile-file leg).
#include "vtkBloomCraftedEXR.h"
#include "vtkBloomTestSupport.h"
#include "vtkOpenEXRReader.h"
#include "vtkOpenEXRTestHelpers.h"

#include <ImfFrameBuffer.h>
#include <ImfInputFile.h>
#include <ImfRgbaFile.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <vector>

namespace
{
namespace fs = std::filesystem;

//------------------------------------------------------------------------------
void ExpectRefused(const std::string& path, const std::string& what)
{
  const vtkOpenEXRTest::ReadResult result = vtkOpenEXRTest::Read(path);
  EXPECT_EQ(result.Errors, 1) << what;
  EXPECT_TRUE(result.Empty()) << what;
  // After VTK's own prefix, one line that names the chunk and its sizes.
  const size_t start = result.Message.find("Cannot read OpenEXR file");
  ASSERT_NE(start, std::string::npos) << what << ": " << result.Message;
  const std::string line =
    result.Message.substr(start, result.Message.find_last_not_of('\n') + 1 - start);
  EXPECT_EQ(line.find('\n'), std::string::npos) << what << ": " << line;
  EXPECT_NE(line.find(" chunk of pixels ("), std::string::npos) << what << ": " << line;
  EXPECT_NE(line.find(" bytes"), std::string::npos) << what << ": " << line;
}

//------------------------------------------------------------------------------
// The channels `names` of every pixel, interleaved, as OpenEXR's C++ library decodes them
// (luminance/chroma: R, G, B, A through Imf::RgbaInputFile).
std::vector<float> LibraryPixels(
  const std::string& path, bool luminanceChroma, const std::vector<std::string>& names)
{
  std::vector<float> values;
  if (luminanceChroma)
  {
    Imf::RgbaInputFile in(path.c_str());
    const Imath::Box2i window = in.dataWindow();
    const int width = window.max.x - window.min.x + 1;
    const int height = window.max.y - window.min.y + 1;
    std::vector<Imf::Rgba> pixels(static_cast<size_t>(width) * height);
    in.setFrameBuffer(pixels.data(), 1, width);
    in.readPixels(window.min.y, window.max.y);
    for (const Imf::Rgba& p : pixels)
    {
      values.insert(values.end(), { float(p.r), float(p.g), float(p.b), float(p.a) });
    }
    return values;
  }
  Imf::InputFile in(path.c_str());
  const Imath::Box2i window = in.header().dataWindow();
  const size_t width = static_cast<size_t>(window.max.x - window.min.x + 1);
  const size_t height = static_cast<size_t>(window.max.y - window.min.y + 1);
  const size_t n = names.size();
  values.assign(width * height * n, 0.0f);
  Imf::FrameBuffer frame;
  for (size_t c = 0; c < n; ++c)
  {
    frame.insert(names[c],
      Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(values.data() + c), n * sizeof(float),
        n * sizeof(float) * width));
  }
  in.setFrameBuffer(frame);
  in.readPixels(window.min.y, window.max.y);
  return values;
}

//------------------------------------------------------------------------------
TEST(OpenEXRCrafted, ValidFilesReadAsOpenEXRDecodesThem)
{
  const std::string scratch = vtkBloomTest::OutputPath("crafted-valid");
  const auto files = vtkBloomCraftedEXR::MakeValid(scratch + "-writer");
  const auto paths = vtkBloomCraftedEXR::WriteAll(files, scratch);
  ASSERT_GE(paths.size(), 8u);
  for (const std::string& path : paths)
  {
    const std::string name = fs::path(path).filename().string();
    const vtkOpenEXRTest::ReadResult result = vtkOpenEXRTest::Read(path);
    ASSERT_EQ(result.Errors, 0) << name << ": " << result.Message;
    vtkDataArray* scalars = result.Image->GetPointData()->GetScalars();
    ASSERT_NE(scalars, nullptr) << name;
    std::vector<std::string> names;
    for (int c = 0; c < scalars->GetNumberOfComponents(); ++c)
    {
      names.emplace_back(scalars->GetComponentName(c));
    }
    const std::vector<float> expected =
      LibraryPixels(path, name.find("yca") != std::string::npos, names);
    ASSERT_EQ(static_cast<size_t>(scalars->GetNumberOfValues()), expected.size()) << name;
    const float* values = static_cast<const float*>(scalars->GetVoidPointer(0));
    size_t differing = 0;
    for (size_t i = 0; i < expected.size(); ++i)
    {
      differing += vtkOpenEXRTest::Bits(values[i]) != vtkOpenEXRTest::Bits(expected[i]) ? 1 : 0;
    }
    EXPECT_EQ(differing, 0u) << name;
  }
}

//------------------------------------------------------------------------------
TEST(OpenEXRCrafted, CraftedFilesOfThisOpenEXRAreRefused)
{
  const std::string scratch = vtkBloomTest::OutputPath("crafted");
  const auto files = vtkBloomCraftedEXR::MakeAll(scratch + "-writer");
  const auto paths = vtkBloomCraftedEXR::WriteAll(files, scratch);
  ASSERT_EQ(paths.size(), files.size());
  ASSERT_GE(paths.size(), 20u);
  for (size_t i = 0; i < paths.size(); ++i)
  {
    ExpectRefused(paths[i], files[i].Name + " (" + files[i].Description + ")");
  }
}

//------------------------------------------------------------------------------
// The committed set, written against OpenEXR 3.1.5: the same bytes on every OpenEXR version.
TEST(OpenEXRCrafted, CommittedCraftedFilesAreRefused)
{
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(VTKBLOOM_CRAFTED_EXR_DIR))
  {
    if (entry.path().extension() == ".exr")
    {
      files.push_back(entry.path());
    }
  }
  ASSERT_GE(files.size(), 20u);
  for (const fs::path& file : files)
  {
    ExpectRefused(file.string(), file.filename().string());
  }
}
}
