// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// vtk-bloom command-line tool: `render` (an example scene or the user's dataset, headless, to
// EXR or PNG, every step of a time series) and `view` (the same in an interactive X window).
#ifndef vtkBloomToolRender_h
#define vtkBloomToolRender_h

#include "vtkBloomToolData.h"

#include <functional>
#include <string>

class vtkBloomPass;
class vtkImageData;

namespace vtkBloomTool
{
struct RenderOptions
{
  int Size[2] = { 960, 540 };
  int Precision = 16;
  bool Bloom = true;
  double Exposure = 1.0;
  bool Quiet = false;
  DataSceneOptions Data;
  std::string SnapshotPrefix = "vtk-bloom-view"; // view: where s and e save
  // Applies the command line's bloom options to the pass's parameters, after the scene set
  // its own.
  std::function<void(vtkBloomPass*)> ConfigureBloom;
};

/// Names the headless window where there is no display (vtkBloomPreferHeadlessWindow), then
/// throws RunError where VTK would crash making the window (vtkBloomCheckOpenGLWindow).
void RequireOpenGLWindow();

/// Render the example scene `scene` to `output`. Throws UsageError or RunError.
int RenderScene(const std::string& scene, const std::string& output, const RenderOptions& options);

/// Render the dataset (or every step of the series) `path` to `output` (a series writes
/// OUT_0000.png, OUT_0001.png, ..., or fills a %d / %0Nd pattern in OUT). One window and one
/// pass serve every step. Throws UsageError or RunError.
int RenderData(const std::string& path, const std::string& output, const RenderOptions& options);

/// A rendered image (row 0 at the bottom, as OpenGL reads it) with row 0 at the top, as EXR
/// and PNG files and the rest of the tool store images.
vtkSmartPointer<vtkImageData> TopRowFirst(vtkImageData* rendered);

/// The output file of step `index` of `count` for the output name `output`.
std::string FrameFileName(const std::string& output, size_t index, size_t count);

/// `view`: the dataset or scene in an interactive window with sliders for threshold, strength
/// and levels, keys (b bloom on/off, p next preset, s PNG screenshot, e EXR of the float frame,
/// h help) and the bloom's own time per frame. `events` (for tests) plays a
/// vtkInteractorEventRecorder log and exits. Throws RunError when there is no display.
int View(const std::string& input, const RenderOptions& options, const std::string& events);
}

#endif
