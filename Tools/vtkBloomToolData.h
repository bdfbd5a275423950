// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// vtk-bloom command-line tool: the user's own datasets. Which files a path names (one dataset,
// a .pvd time series or a numbered file pattern) and reading them with VTK's own readers
// (vtkBloomToolDataFiles.cxx), and the scene that shows them: colouring, representation,
// contours, what emits, the camera (vtkBloomToolData.cxx).
#ifndef vtkBloomToolData_h
#define vtkBloomToolData_h

#include "vtkBloomToolSupport.h"

#include <vtkSmartPointer.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

class vtkBloomPass;
class vtkDataObject;
class vtkDataSet;
class vtkRenderer;

namespace vtkBloomTool
{
/// Every dataset leaf of a data object (the object itself when it is a dataset).
void ForEachDataSet(vtkDataObject* data, const std::function<void(vtkDataSet*)>& visit);

/// True when `path` names a dataset (by its extension: .vti .vtu .vtp .vts .vtr .vtm .vtk
/// .pvd, or a numbered pattern such as step_%04d.vtu) rather than an example scene.
bool IsDatasetPath(const std::string& path);

/// The files of a dataset path, in time order: one file, the steps of a .pvd collection, or
/// the files a numbered pattern (%d, %0Nd) matches, which must be consecutive. Throws RunError
/// for a missing file or step, a directory, an unknown extension.
struct DatasetFiles
{
  std::vector<std::string> Files;
  std::vector<double> Times;
  bool IsSeries() const { return this->Files.size() > 1; }
};
DatasetFiles ResolveDataset(const std::string& path);

/// Read one file with VTK's readers (XML by vtkXMLGenericDataObjectReader, legacy .vtk by
/// vtkGenericDataObjectReader). A file that is not VTK data, truncated or corrupted XML, and
/// an empty dataset are RunErrors.
vtkSmartPointer<vtkDataObject> ReadDataset(const std::string& file, ErrorCollector& errors);

/// How the data is shown, and what glows.
struct DataSceneOptions
{
  std::string ColorBy;     // array name; "" = the active or first array
  int ColorComponent = -1; // -1 = magnitude for vectors
  bool HasRange = false;
  double Range[2] = { 0.0, 1.0 };
  std::string Colormap = "viridis";       // viridis | inferno | coolwarm | grayscale
  std::string Representation = "surface"; // surface | points | wireframe | volume
  std::vector<double> Contours;
  bool HasEmitRange = false;
  double EmitRange[2] = { 0.0, 0.0 };
  double EmitGain = -1.0;   // < 0: the default, 1 (with --emit-range it scales the strength)
  std::string View = "iso"; // iso | +x | -x | +y | -y | +z | -z
  double Azimuth = 0.0;
  double Elevation = 0.0;
  double Zoom = 1.0;
  bool HasBackground = false;
  double Background[3] = { 0.02, 0.02, 0.03 };
};

/// Turn the renderer's camera by --azimuth and --elevation, then --zoom, about where the scene
/// or dataset set it (datasets after --view), and reset the clipping range.
void TurnCamera(vtkRenderer* renderer, const DataSceneOptions& options);

/// Parse the value of --color-by (NAME or NAME:COMPONENT), --range and --emit-range (LO:HI),
/// --contour (V1,V2,...) and --background (R,G,B) into `options`; UsageError when malformed.
void ParseDataOption(
  const std::string& option, const std::string& value, DataSceneOptions& options);

/// The scene of one dataset or time series: built once from the first step, then fed each
/// later step without rebuilding anything (SetData).
class DataScene
{
public:
  DataScene();
  ~DataScene();

  /// Fill `renderer` and configure `pass` (emitters, threshold mode) for `data`. Throws
  /// UsageError for options the data cannot satisfy (an array it does not have, volume on
  /// non-image data) and RunError for data that cannot be shown.
  void Build(vtkDataObject* data, const std::string& name, const DataSceneOptions& options,
    vtkRenderer* renderer, vtkBloomPass* pass);

  /// Show another step of the series (same kind of data). Throws UsageError when the step
  /// lacks the coloured array.
  void SetData(vtkDataObject* data, const std::string& name);

  /// A warning when the emit range selects nothing in the current step ("" otherwise).
  std::string EmitWarning() const;

private:
  struct vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};
}

#endif
