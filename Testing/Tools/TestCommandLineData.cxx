// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// End-to-end tests of `vtk-bloom render FILE` and `vtk-bloom view` on datasets that the test
// writes itself with VTK's writers, in every format the tool reads: each renders; selective
// bloom lands where the hot data is; a time series gives one differing frame per step; bad
// input fails with its message and no output; the interactive view, driven by recorded
// events, responds to its slider (X builds only).
#include "vtkBloomTestSupport.h"
#include "vtkBloomToolTestHelpers.h"

#include <vtkAppendFilter.h>
#include <vtkCellArray.h>
#include <vtkDataSetWriter.h>
#include <vtkDoubleArray.h>
#include <vtkImageData.h>
#include <vtkImageDataToPointSet.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPlaneSource.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkRTAnalyticSource.h>
#include <vtkRectilinearGrid.h>
#include <vtkSphereSource.h>
#include <vtkStructuredGrid.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLImageDataWriter.h>
#include <vtkXMLMultiBlockDataWriter.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLRectilinearGridWriter.h>
#include <vtkXMLStructuredGridWriter.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <half.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace vtkBloomToolTest;

namespace
{
std::string Directory()
{
  const std::string directory = vtkBloomTest::OutputPath("cli-data");
  fs::create_directories(directory);
  return directory;
}

// The wavelet, 21^3 points, with its scalar RTData (about 37 to 277).
vtkSmartPointer<vtkImageData> Wavelet()
{
  vtkNew<vtkRTAnalyticSource> source;
  source->SetWholeExtent(-10, 10, -10, 10, -10, 10);
  source->Update();
  vtkSmartPointer<vtkImageData> image = source->GetOutput();
  return image;
}

// Write the wavelet in `extension`'s format; returns the path.
std::string WriteWavelet(const std::string& extension)
{
  const std::string path = Directory() + "/wavelet" + extension;
  auto image = Wavelet();
  if (extension == ".vti")
  {
    vtkNew<vtkXMLImageDataWriter> writer;
    writer->SetInputData(image);
    writer->SetFileName(path.c_str());
    writer->Write();
  }
  else if (extension == ".vtu" || extension == ".vtk")
  {
    vtkNew<vtkAppendFilter> append;
    append->SetInputData(image);
    append->Update();
    if (extension == ".vtu")
    {
      vtkNew<vtkXMLUnstructuredGridWriter> writer;
      writer->SetInputData(append->GetOutput());
      writer->SetFileName(path.c_str());
      writer->Write();
    }
    else
    {
      vtkNew<vtkDataSetWriter> writer;
      writer->SetInputData(append->GetOutput());
      writer->SetFileName(path.c_str());
      writer->Write();
    }
  }
  else if (extension == ".vts")
  {
    vtkNew<vtkImageDataToPointSet> toPoints;
    toPoints->SetInputData(image);
    toPoints->Update();
    vtkNew<vtkXMLStructuredGridWriter> writer;
    writer->SetInputData(toPoints->GetOutput());
    writer->SetFileName(path.c_str());
    writer->Write();
  }
  else if (extension == ".vtr")
  {
    vtkNew<vtkRectilinearGrid> grid;
    grid->SetDimensions(21, 21, 21);
    for (int axis = 0; axis < 3; ++axis)
    {
      vtkNew<vtkDoubleArray> coordinates;
      for (int i = -10; i <= 10; ++i)
      {
        coordinates->InsertNextValue(i);
      }
      axis == 0
        ? grid->SetXCoordinates(coordinates)
        : (axis == 1 ? grid->SetYCoordinates(coordinates) : grid->SetZCoordinates(coordinates));
    }
    grid->GetPointData()->ShallowCopy(image->GetPointData());
    vtkNew<vtkXMLRectilinearGridWriter> writer;
    writer->SetInputData(grid);
    writer->SetFileName(path.c_str());
    writer->Write();
  }
  else if (extension == ".vtp" || extension == ".vtm")
  {
    vtkNew<vtkSphereSource> sphere;
    sphere->SetRadius(10.0);
    sphere->SetThetaResolution(40);
    sphere->SetPhiResolution(40);
    sphere->Update();
    vtkPolyData* polydata = sphere->GetOutput();
    vtkNew<vtkDoubleArray> values;
    values->SetName("RTData");
    for (vtkIdType p = 0; p < polydata->GetNumberOfPoints(); ++p)
    {
      double x[3];
      polydata->GetPoint(p, x);
      values->InsertNextValue(157.0 + 12.0 * x[2]); // 37 at the bottom, 277 at the top
    }
    polydata->GetPointData()->AddArray(values);
    if (extension == ".vtp")
    {
      vtkNew<vtkXMLPolyDataWriter> writer;
      writer->SetInputData(polydata);
      writer->SetFileName(path.c_str());
      writer->Write();
    }
    else
    {
      vtkNew<vtkMultiBlockDataSet> blocks;
      blocks->SetBlock(0, polydata);
      blocks->SetBlock(1, image);
      vtkNew<vtkXMLMultiBlockDataWriter> writer;
      writer->SetInputData(blocks);
      writer->SetFileName(path.c_str());
      writer->Write();
    }
  }
  return path;
}

// Sum of the colour channels of an EXR image, and their centroid (x, y; row 0 at the top).
struct Energy
{
  double Total = 0.0;
  double X = 0.0;
  double Y = 0.0;
};

Energy Difference(const Pixels& a, const Pixels& b)
{
  Energy e;
  for (int y = 0; y < a.Height; ++y)
  {
    for (int x = 0; x < a.Width; ++x)
    {
      const size_t i = (static_cast<size_t>(y) * a.Width + x) * 4;
      double d = 0.0;
      for (int c = 0; c < 3; ++c)
      {
        d += a.Rgba[i + c] - b.Rgba[i + c];
      }
      e.Total += d;
      e.X += d * x;
      e.Y += d * y;
    }
  }
  if (e.Total != 0.0)
  {
    e.X /= e.Total;
    e.Y /= e.Total;
  }
  return e;
}

double Sum(const Pixels& p)
{
  double sum = 0.0;
  for (size_t i = 0; i < p.Rgba.size(); ++i)
  {
    sum += (i % 4 == 3) ? 0.0 : p.Rgba[i];
  }
  return sum;
}
}

//------------------------------------------------------------------------------
TEST(CommandLineData, EveryFormatRendersAndBlooms)
{
  for (const std::string extension : { ".vti", ".vtu", ".vtp", ".vts", ".vtr", ".vtm", ".vtk" })
  {
    const std::string input = WriteWavelet(extension);
    const std::string bloom = Directory() + "/bloom" + extension + ".exr";
    const std::string plain = Directory() + "/plain" + extension + ".exr";
    fs::remove(bloom);
    fs::remove(plain);
    const std::string options = " --size 240x160 --color-by RTData --emit-range 120:280 --quiet ";
    std::string errors;
    ASSERT_EQ(RunTool("render" + options + Quote(input) + " " + Quote(bloom), &errors), 0)
      << extension << "\n"
      << errors;
    ASSERT_EQ(RunTool("render --no-bloom" + options + Quote(input) + " " + Quote(plain)), 0);
    const Pixels with = ReadEXR(bloom), without = ReadEXR(plain);
    ASSERT_EQ(with.Width, 240);
    ASSERT_EQ(with.Height, 160);
    EXPECT_GT(Sum(without), 0.0) << extension;
    // The emitted range adds light.
    EXPECT_GT(Difference(with, without).Total, 1e-3 * Sum(without)) << extension;
  }
}

//------------------------------------------------------------------------------
// A plane hot only in one corner (x, y > 0.6 of [-1, 1]); the camera looks along -z from
// above, so +x is right and +y up. The bloom's added energy is centred in the top right
// corner, and zero when the emit range lies above the data.
TEST(CommandLineData, SelectiveBloomLandsInTheHotCorner)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-1.0, -1.0, 0.0);
  plane->SetPoint1(1.0, -1.0, 0.0);
  plane->SetPoint2(-1.0, 1.0, 0.0);
  plane->SetResolution(100, 100);
  plane->Update();
  vtkPolyData* surface = plane->GetOutput();
  vtkNew<vtkDoubleArray> heat;
  heat->SetName("heat");
  for (vtkIdType p = 0; p < surface->GetNumberOfPoints(); ++p)
  {
    double x[3];
    surface->GetPoint(p, x);
    heat->InsertNextValue(x[0] > 0.6 && x[1] > 0.6 ? 1.0 : 0.1);
  }
  surface->GetPointData()->AddArray(heat);
  const std::string input = Directory() + "/corner.vtp";
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputData(surface);
  writer->SetFileName(input.c_str());
  writer->Write();

  const std::string common =
    " --quiet --size 300x300 --view -z --color-by heat --colormap grayscale " + Quote(input);
  const std::string bloom = Directory() + "/corner-bloom.exr";
  const std::string plain = Directory() + "/corner-plain.exr";
  const std::string cold = Directory() + "/corner-cold.exr";
  ASSERT_EQ(RunTool("render --emit-range 0.9:1" + common + " " + Quote(bloom)), 0);
  ASSERT_EQ(RunTool("render --no-bloom --emit-range 0.9:1" + common + " " + Quote(plain)), 0);
  std::string errors;
  ASSERT_EQ(RunTool("render --emit-range 5:6" + common + " " + Quote(cold), &errors), 0);
  EXPECT_NE(errors.find("selects nothing"), std::string::npos) << errors;

  const Pixels with = ReadEXR(bloom), without = ReadEXR(plain), none = ReadEXR(cold);
  const Energy added = Difference(with, without);
  ASSERT_GT(added.Total, 0.0);
  // The hot corner is x, y in [0.6, 1] of the plane: the top right of the picture.
  EXPECT_GT(added.X, 0.6 * with.Width) << added.X;
  EXPECT_LT(added.Y, 0.4 * with.Height) << added.Y;
  EXPECT_EQ(Difference(none, without).Total, 0.0);
  EXPECT_EQ(RelativeL2(none, without), 0.0);
}

//------------------------------------------------------------------------------
// --emit-gain G as documented. Without --emit-range the whole scene's colours are times G:
// the wavelet's edges (VTK clamps a property's ambient and diffuse to 1, so that this once did
// nothing) rise above 1 and glow, where at G = 1 nothing is light and the frame is the plain
// one. With --emit-range the emitted light, and so the glow, is times G.
TEST(CommandLineData, EmitGainScalesWhatGlows)
{
  // Twenty polylines coloured by x: lines, as the report that found this had.
  const std::string lines = Directory() + "/gain-lines.vtp";
  {
    vtkNew<vtkPoints> points;
    vtkNew<vtkCellArray> cells;
    vtkNew<vtkDoubleArray> x;
    x->SetName("x");
    for (int row = 0; row < 20; ++row)
    {
      cells->InsertNextCell(50);
      for (int i = 0; i < 50; ++i)
      {
        cells->InsertCellPoint(points->InsertNextPoint(i / 49.0, row / 19.0, 0.0));
        x->InsertNextValue(i / 49.0);
      }
    }
    vtkNew<vtkPolyData> polylines;
    polylines->SetPoints(points);
    polylines->SetLines(cells);
    polylines->GetPointData()->AddArray(x);
    vtkNew<vtkXMLPolyDataWriter> writer;
    writer->SetInputData(polylines);
    writer->SetFileName(lines.c_str());
    writer->Write();
  }
  const std::string common = " --quiet --size 160x120 --view -z ";
  auto render = [&](const std::string& options, const std::string& input, const std::string& name)
  {
    const std::string out = Directory() + "/" + name + ".exr";
    std::string errors;
    EXPECT_EQ(
      RunTool("render" + common + options + " " + Quote(input) + " " + Quote(out), &errors), 0)
      << errors;
    return ReadEXR(out);
  };
  auto maximum = [](const Pixels& p) { return *std::max_element(p.Rgba.begin(), p.Rgba.end()); };

  const Pixels plain1 = render("--no-bloom", lines, "gain-plain-1");
  const Pixels bloom1 = render("", lines, "gain-bloom-1");
  const Pixels plain8 = render("--no-bloom --emit-gain 8", lines, "gain-plain-8");
  const Pixels bloom8 = render("--emit-gain 8", lines, "gain-bloom-8");
  EXPECT_LE(maximum(plain1), 1.0f);
  EXPECT_EQ(RelativeL2(bloom1, plain1), 0.0) << "nothing above 1: nothing glows";
  EXPECT_GT(maximum(plain8), 2.0f) << "the colours times 8";
  EXPECT_GT(Difference(bloom8, plain8).Total, 0.0) << "what exceeds 1 glows";

  const std::string wavelet = WriteWavelet(".vtp");
  const std::string range = "--color-by RTData --emit-range 150:300 ";
  const Pixels plain = render("--no-bloom " + range, wavelet, "gain-range-plain");
  const Energy glow1 = Difference(render(range, wavelet, "gain-range-1"), plain);
  const Energy glow8 = Difference(render(range + "--emit-gain 8", wavelet, "gain-range-8"), plain);
  ASSERT_GT(glow1.Total, 0.0);
  EXPECT_NEAR(glow8.Total / glow1.Total, 8.0, 0.08); // float16 targets
}

//------------------------------------------------------------------------------
// Each option of docs/cli.md's table for datasets, against the frame without it: the effect the
// table documents, measured on the picture (the plain frame, --no-bloom, so that the bloom does
// not blur what is measured). Each check fails when its option is ignored.
TEST(CommandLineData, EveryDataOptionDoesWhatItsTableRowSays)
{
  const std::string input = WriteWavelet(".vti");
  const std::string base = " --quiet --no-bloom --size 160x120 --color-by RTData ";
  int frame = 0;
  auto render = [&](const std::string& options)
  {
    const std::string out = Directory() + "/option-" + std::to_string(frame++) + ".exr";
    std::string errors;
    const std::string background =
      options.find("--background") == std::string::npos ? "--background 0,0,0 " : "";
    EXPECT_EQ(
      RunTool(
        "render" + base + background + options + " " + Quote(input) + " " + Quote(out), &errors),
      0)
      << options << ": " << errors;
    return ReadEXR(out);
  };
  // Pixels that are not the black background, and their mean value.
  auto covered = [](const Pixels& p)
  {
    size_t n = 0;
    for (size_t i = 0; i < p.Rgba.size(); i += 4)
    {
      n += (p.Rgba[i] > 0.0f || p.Rgba[i + 1] > 0.0f || p.Rgba[i + 2] > 0.0f) ? 1 : 0;
    }
    return n;
  };
  auto mean = [](const Pixels& p)
  {
    double sum = 0.0;
    for (size_t i = 0; i < p.Rgba.size(); i += 4)
    {
      sum += p.Rgba[i] + p.Rgba[i + 1] + p.Rgba[i + 2];
    }
    return sum / static_cast<double>(p.Rgba.size() / 4);
  };
  const Pixels plain = render("");
  const size_t surface = covered(plain);
  ASSERT_GT(surface, 1000u);

  // --background R,G,B: the corner is that colour.
  const Pixels red = render("--background 1,0,0");
  EXPECT_EQ(red.Rgba[0], 1.0f);
  EXPECT_EQ(red.Rgba[1], 0.0f);
  EXPECT_EQ(plain.Rgba[0], 0.0f);

  // --colormap grayscale: white light on grey colours leaves R = G = B; viridis does not.
  auto spread = [](const Pixels& p)
  {
    float most = 0.0f;
    for (size_t i = 0; i < p.Rgba.size(); i += 4)
    {
      most = std::max(most,
        std::max(std::abs(p.Rgba[i] - p.Rgba[i + 1]), std::abs(p.Rgba[i + 1] - p.Rgba[i + 2])));
    }
    return most;
  };
  EXPECT_LT(spread(render("--colormap grayscale")), 1e-3f);
  EXPECT_GT(spread(plain), 0.1f);

  // --range LO:HI: a range above all of the data maps it to the lowest colour, a uniform one.
  EXPECT_LT(spread(render("--colormap grayscale --range 1000:2000")), 1e-3f);
  EXPECT_LT(mean(render("--colormap grayscale --range 1000:2000")),
    0.5 * mean(render("--colormap grayscale")));

  // --representation points and wireframe: the grid's points and edges (all of them, inside
  // too), not its faces: frames of their own.
  const Pixels points = render("--representation points");
  const Pixels wireframe = render("--representation wireframe");
  EXPECT_GT(RelativeL2(points, plain), 0.1);
  EXPECT_GT(RelativeL2(wireframe, plain), 0.1);
  EXPECT_GT(RelativeL2(points, wireframe), 0.1);

  // --contour: iso-surfaces inside the box, not the box's faces: a different frame.
  const Pixels contour = render("--contour 200");
  EXPECT_GT(covered(contour), 0u);
  EXPECT_GT(RelativeL2(contour, plain), 0.1);

  // --view, --azimuth, --elevation: the camera turns; --zoom 2: the object grows.
  EXPECT_GT(RelativeL2(render("--view +x"), plain), 0.05);
  EXPECT_GT(RelativeL2(render("--azimuth 30"), plain), 0.05);
  EXPECT_GT(RelativeL2(render("--elevation 30"), plain), 0.05);
  EXPECT_GT(covered(render("--zoom 2")), surface * 3 / 2);

  // --precision: 16 (default) writes values a half holds exactly, 32 values it does not.
  auto halves = [](const Pixels& p)
  {
    size_t exact = 0;
    for (float v : p.Rgba)
    {
      exact += static_cast<float>(half(v)) == v ? 1 : 0;
    }
    return exact == p.Rgba.size();
  };
  EXPECT_TRUE(halves(plain));
  EXPECT_FALSE(halves(render("--precision 32")));
}

//------------------------------------------------------------------------------
TEST(CommandLineData, TimeSeriesGivesOneDifferentFramePerStep)
{
  const std::string directory = Directory() + "/series";
  fs::remove_all(directory);
  fs::create_directories(directory);
  std::ofstream pvd(directory + "/series.pvd");
  pvd << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n";
  for (int step = 0; step < 3; ++step)
  {
    vtkNew<vtkSphereSource> sphere;
    sphere->SetRadius(2.0 + step);
    sphere->Update();
    const std::string name = "step_" + std::to_string(step) + ".vtp";
    vtkNew<vtkXMLPolyDataWriter> writer;
    writer->SetInputData(sphere->GetOutput());
    writer->SetFileName((directory + "/" + name).c_str());
    writer->Write();
    pvd << "<DataSet timestep=\"" << step * 0.25 << "\" file=\"" << name << "\"/>\n";
  }
  pvd << "</Collection>\n</VTKFile>\n";
  pvd.close();

  const std::string out = directory + "/frame.exr";
  std::string errors;
  ASSERT_EQ(RunTool("render --quiet --size 160x120 --emit-gain 3 --threshold 0.5 " +
                Quote(directory + "/series.pvd") + " " + Quote(out),
              &errors),
    0)
    << errors;
  std::vector<Pixels> frames;
  for (int step = 0; step < 3; ++step)
  {
    const std::string frame = directory + "/frame_000" + std::to_string(step) + ".exr";
    ASSERT_TRUE(fs::exists(frame)) << frame;
    frames.push_back(ReadEXR(frame));
  }
  EXPECT_GT(RelativeL2(frames[0], frames[1]), 1e-3);
  EXPECT_GT(RelativeL2(frames[1], frames[2]), 1e-3);
  // A numbered pattern reads the same steps; a %d in OUT names the frames.
  ASSERT_EQ(RunTool("render --quiet --size 160x120 --emit-gain 3 --threshold 0.5 " +
              Quote(directory + "/step_%d.vtp") + " " + Quote(directory + "/p%02d.exr")),
    0);
  for (int step = 0; step < 3; ++step)
  {
    EXPECT_EQ(
      RelativeL2(ReadEXR(directory + "/p0" + std::to_string(step) + ".exr"), frames[step]), 0.0);
  }
}

//------------------------------------------------------------------------------
TEST(CommandLineData, BadInputFailsWithItsMessageAndNoOutput)
{
  const std::string directory = Directory() + "/bad";
  fs::remove_all(directory);
  fs::create_directories(directory);
  const std::string out = directory + "/out.png";
  auto write = [&](const std::string& name, const std::string& bytes)
  {
    std::ofstream file(directory + "/" + name, std::ios::binary);
    file << bytes;
    return directory + "/" + name;
  };
  const std::string good = WriteWavelet(".vtu");
  const std::string text = Slurp(good);
  vtkNew<vtkPolyData> empty;
  vtkNew<vtkXMLPolyDataWriter> emptyWriter;
  emptyWriter->SetInputData(empty);
  emptyWriter->SetFileName((directory + "/empty.vtp").c_str());
  emptyWriter->Write();
  vtkNew<vtkSphereSource> sphere;
  sphere->Update();
  for (int step : { 0, 1, 3 })
  {
    vtkNew<vtkXMLPolyDataWriter> writer;
    writer->SetInputData(sphere->GetOutput());
    writer->SetFileName((directory + "/gap_" + std::to_string(step) + ".vtp").c_str());
    writer->Write();
  }
  fs::create_directories(directory + "/folder.vti");
  write("missing.pvd",
    "<?xml version=\"1.0\"?><VTKFile type=\"Collection\"><Collection>"
    "<DataSet timestep=\"0\" file=\"gap_0.vtp\"/><DataSet timestep=\"1\" file=\"gap_2.vtp\"/>"
    "</Collection></VTKFile>");

  struct Case
  {
    std::string Arguments;
    int Status;
    std::string Message;
  };
  const std::vector<Case> cases = {
    { Quote(directory + "/nothing.vtu"), 1, "no such file" },
    { Quote(directory), 2, "" }, // a directory has no known extension: not a scene either
    { Quote(directory + "/folder.vti"), 1, "is a directory" },
    { Quote(write("data.xyz", "1 2 3")), 2, "unknown scene" },
    { Quote(write("random.vtu", std::string(3000, '\x7f'))), 1, "cannot read" },
    { Quote(write("random.vtk", "not a vtk file at all\n")), 1, "not a legacy VTK file" },
    { Quote(write("truncated.vtu", text.substr(0, text.size() / 2))), 1, "cannot read" },
    { "--color-by Pressure " + Quote(good), 2, "RTData" },
    { "--color-by RTData:3 " + Quote(good), 2, "component" },
    { Quote(directory + "/empty.vtp"), 1, "empty" },
    { Quote(directory + "/gap_%d.vtp"), 1, "missing step 2" },
    { Quote(directory + "/missing.pvd"), 1, "does not exist" },
    { "--representation volume " + Quote(good), 2, "image data" },
    { "--emit-range 3:1 " + Quote(good), 2, "LO <= HI" },
    { "--view +w " + Quote(good), 2, "--view" },
    { "--colormap jet " + Quote(good), 2, "--colormap" },
  };
  for (const Case& c : cases)
  {
    fs::remove(out);
    std::string errors;
    EXPECT_EQ(
      RunTool("render --quiet --size 64x48 " + c.Arguments + " " + Quote(out), &errors), c.Status)
      << c.Arguments << "\n"
      << errors;
    EXPECT_NE(errors.find(c.Message), std::string::npos) << c.Arguments << "\n" << errors;
    // VTK's own log reaches the message or nowhere: no logger line ("ERR|"), no binary bytes.
    EXPECT_EQ(errors.find("ERR|"), std::string::npos) << c.Arguments << "\n" << errors;
    EXPECT_TRUE(std::all_of(errors.begin(), errors.end(),
      [](char ch) { return ch == '\n' || std::isprint(static_cast<unsigned char>(ch)); }))
      << c.Arguments << "\n"
      << errors;
    EXPECT_FALSE(fs::exists(out)) << c.Arguments;
    EXPECT_FALSE(fs::exists(directory + "/out_0000.png")) << c.Arguments;
  }
}

//------------------------------------------------------------------------------
// view: without a display it names render; under X, recorded events that drag the strength
// slider change the saved float frame.
TEST(CommandLineData, ViewRespondsToItsSlider)
{
  const std::string input = WriteWavelet(".vtp");
  std::string errors;
  const std::string noDisplay = "env -u DISPLAY " + std::string(VTKBLOOM_TOOL) + " view " +
    Quote(input) + " >/dev/null 2>" + Quote(Directory() + "/view-errors.txt");
  const int status = std::system(noDisplay.c_str());
  EXPECT_EQ(WIFEXITED(status) ? WEXITSTATUS(status) : -1, 1);
  EXPECT_NE(Slurp(Directory() + "/view-errors.txt").find("render"), std::string::npos);

#ifdef VTKBLOOM_TEST_INTERACTIVE
  if (!std::getenv("DISPLAY"))
  {
    GTEST_SKIP() << "no X display";
  }
  const std::string prefix = Directory() + "/view";
  fs::remove(prefix + "-000.exr");
  fs::remove(prefix + "-001.exr");
  // 400x300 window; the strength slider runs from x 0.70 to 0.95 at y 0.26 (normalized), its
  // handle at the preset's strength. Save (e), drag the handle to the right end, save again.
  const std::string events = Directory() + "/view-events.log";
  {
    const double strength = 1.0; // webgpu-market's, which the data scene keeps
    const int y = static_cast<int>(0.26 * 300);
    const int from = static_cast<int>((0.70 + 0.25 * strength / 3.0) * 400);
    const int to = static_cast<int>(0.95 * 400);
    std::ofstream log(events);
    // vtkInteractorEventRecorder's format (VTK 9.1): event x y modifiers keycode repeat keysym,
    // positions in display coordinates (y up).
    const std::string key = " 10 10 0 101 1 e\n";
    log << "# StreamVersion 1.1\n";
    log << "KeyPressEvent" << key << "CharEvent" << key << "KeyReleaseEvent" << key;
    log << "MouseMoveEvent " << from << " " << y << " 0 0 0 0\n";
    log << "LeftButtonPressEvent " << from << " " << y << " 0 0 0 0\n";
    for (int x = from; x <= to; x += 10)
    {
      log << "MouseMoveEvent " << x << " " << y << " 0 0 0 0\n";
    }
    log << "LeftButtonReleaseEvent " << to << " " << y << " 0 0 0 0\n";
    log << "KeyPressEvent" << key << "CharEvent" << key << "KeyReleaseEvent" << key;
  }
  ASSERT_EQ(RunTool("view --size 400x300 --color-by RTData --emit-range 200:280 --snapshot " +
                Quote(prefix) + " --play-events " + Quote(events) + " " + Quote(input),
              &errors),
    0)
    << errors;
  ASSERT_TRUE(fs::exists(prefix + "-000.exr")) << errors;
  ASSERT_TRUE(fs::exists(prefix + "-001.exr")) << errors;
  const Pixels before = ReadEXR(prefix + "-000.exr"), after = ReadEXR(prefix + "-001.exr");
  EXPECT_GT(Sum(after), Sum(before) * 1.01) << "a stronger bloom adds light";
#endif
}
