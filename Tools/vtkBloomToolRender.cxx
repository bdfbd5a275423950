// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkBloomToolRender.h"

#include "vtkBloomExampleScenes.h"
#include "vtkBloomPass.h"
#include "vtkBloomToolImageIO.h"
#include "vtkBloomVTKCompat.h"

#include <vtkDataObject.h>
#include <vtkImageData.h>
#include <vtkImageFlip.h>
#include <vtkNew.h>
#include <vtkRenderStepsPass.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <regex>
#include <unistd.h>

namespace fs = std::filesystem;

namespace vtkBloomTool
{
namespace
{
//------------------------------------------------------------------------------
// An offscreen window with one renderer whose pass is the bloom over the standard steps.
struct Stage
{
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkBloomPass> Pass;
  vtkNew<vtkRenderStepsPass> Steps;

  Stage(const RenderOptions& options, ErrorCollector& errors)
  {
    errors.Watch(this->Window);
    errors.Watch(this->Pass);
    this->Window->SetOffScreenRendering(1);
    // Anti-aliased, as VTK's windows are by default: the pass keeps the samples.
    this->Window->SetMultiSamples(4);
    this->Window->SetSize(options.Size[0], options.Size[1]);
    this->Window->AddRenderer(this->Renderer);
    this->Pass->SetDelegatePass(this->Steps);
    this->Pass->SetFloatPrecision(
      options.Precision == 32 ? vtkBloomPass::FLOAT32 : vtkBloomPass::FLOAT16);
    this->Pass->CaptureResultOn();
    this->Renderer->SetPass(this->Pass);
  }

  // Render and write one frame; throws RunError.
  void Write(const RenderOptions& options, const std::string& output, ErrorCollector& errors,
    ProgressBar& progress)
  {
    this->Window->Render();
    vtkNew<vtkImageData> image;
    if (options.Bloom)
    {
      this->Pass->ReadResultImage(image);
    }
    else
    {
      this->Pass->ReadSceneImage(image);
    }
    errors.ThrowIfAny("render failed:");
    const int displayWindow[4] = { 0, options.Size[0] - 1, 0, options.Size[1] - 1 };
    WriteOutput(TopRowFirst(image), displayWindow, output, options.Exposure, errors, progress);
  }

  ~Stage() { this->Window->ReleaseGraphicsResources(this->Window); }
};

}

//------------------------------------------------------------------------------
void RequireOpenGLWindow()
{
  vtkBloomPreferHeadlessWindow();
  std::string why;
  if (!vtkBloomCheckOpenGLWindow(why))
  {
    throw RunError{ why };
  }
}

namespace
{
void CheckOutput(const std::string& output)
{
  const std::string ext = Extension(output);
  if (ext != ".exr" && ext != ".png")
  {
    throw UsageError{ "output must be .exr or .png: " + output };
  }
  std::error_code ec;
  if (fs::is_directory(output, ec))
  {
    throw RunError{ "output " + output + " is a directory" };
  }
}
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkImageData> TopRowFirst(vtkImageData* rendered)
{
  vtkNew<vtkImageFlip> flip;
  flip->SetFilteredAxis(1);
  flip->SetInputData(rendered);
  flip->Update();
  vtkSmartPointer<vtkImageData> image = flip->GetOutput();
  return image;
}

//------------------------------------------------------------------------------
std::string FrameFileName(const std::string& output, size_t index, size_t count)
{
  const std::regex pattern("%(0[1-9][0-9]*)?d");
  std::smatch match;
  if (std::regex_search(output, match, pattern))
  {
    char number[32];
    std::snprintf(number, sizeof(number), match.str().c_str(), static_cast<int>(index));
    return match.prefix().str() + number + match.suffix().str();
  }
  if (count <= 1)
  {
    return output;
  }
  char number[32];
  std::snprintf(number, sizeof(number), "_%04d", static_cast<int>(index));
  const fs::path path(output);
  return (path.parent_path() / (path.stem().string() + number + path.extension().string()))
    .string();
}

//------------------------------------------------------------------------------
int RenderScene(const std::string& scene, const std::string& output, const RenderOptions& options)
{
  const auto names = vtkBloomExampleSceneNames();
  if (std::find(names.begin(), names.end(), scene) == names.end())
  {
    throw UsageError{ "unknown scene '" + scene +
      "' (see render --list), and not a dataset file (.vti, .vtu, .vtp, .vts, .vtr, .vtm, .vtk, "
      ".pvd)" };
  }
  CheckOutput(output);
  RequireOpenGLWindow();
  ErrorCollector errors;
  ProgressBar progress;
  Stage stage(options, errors);
  vtkBloomBuildExampleScene(scene, stage.Renderer, stage.Pass);
  TurnCamera(stage.Renderer, options.Data);
  options.ConfigureBloom(stage.Pass);
  stage.Write(options, output, errors, progress);
  if (!options.Quiet)
  {
    std::cerr << "vtk-bloom: rendered " << scene << " (" << options.Size[0] << "x"
              << options.Size[1] << ", " << stage.Pass->GetLastFrame()->GetNumberOfPasses()
              << " GPU passes) to " << output << "\n";
  }
  return 0;
}

//------------------------------------------------------------------------------
int RenderData(const std::string& path, const std::string& output, const RenderOptions& options)
{
  CheckOutput(output);
  RequireOpenGLWindow();
  const DatasetFiles files = ResolveDataset(path);
  const size_t count = files.Files.size();
  // Outputs never replace an input, and a series never writes over one of its own frames.
  std::error_code ec;
  for (size_t i = 0; i < count; ++i)
  {
    const std::string frame = FrameFileName(output, i, count);
    for (const std::string& input : files.Files)
    {
      if (fs::exists(frame, ec) && fs::equivalent(frame, input, ec))
      {
        throw UsageError{ "refusing to overwrite the input " + input + " with the output" };
      }
    }
  }

  ErrorCollector errors;
  ProgressBar progress;
  progress.Enabled = !options.Quiet && count > 1 && ::isatty(STDERR_FILENO);
  // Read the first step before making a window: bad input fails without touching OpenGL.
  auto first = ReadDataset(files.Files[0], errors);
  Stage stage(options, errors);
  DataScene scene;
  scene.Build(first, files.Files[0], options.Data, stage.Renderer, stage.Pass);
  options.ConfigureBloom(stage.Pass);
  for (size_t i = 0; i < count; ++i)
  {
    progress.Begin("render " + std::to_string(i + 1) + "/" + std::to_string(count),
      static_cast<double>(i) / count, static_cast<double>(i + 1) / count);
    if (i > 0)
    {
      scene.SetData(ReadDataset(files.Files[i], errors), files.Files[i]);
    }
    const std::string warning = scene.EmitWarning();
    if (!warning.empty())
    {
      progress.Break();
      std::cerr << "vtk-bloom: warning: " << warning << "\n";
    }
    stage.Write(options, FrameFileName(output, i, count), errors, progress);
  }
  progress.Finish();
  if (!options.Quiet)
  {
    std::cerr << "vtk-bloom: rendered " << path << " (" << count
              << (count > 1 ? " steps, " : " step, ") << options.Size[0] << "x" << options.Size[1]
              << ") to " << FrameFileName(output, 0, count) << (count > 1 ? " ..." : "") << "\n";
  }
  return 0;
}
}
