// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkBloomToolData.h"

#include "vtkBloomPass.h"
#include "vtkBloomVTKCompat.h"
#include "vtkImageBloom.h"
#include "vtkImageBloomThreshold.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellData.h>
#include <vtkCellDataToPointData.h>
#include <vtkColorTransferFunction.h>
#include <vtkCompositeDataSet.h>
#include <vtkContourFilter.h>
#include <vtkDataSet.h>
#include <vtkDataSetMapper.h>
#include <vtkDataSetSurfaceFilter.h>
#include <vtkImageData.h>
#include <vtkLookupTable.h>
#include <vtkMath.h>
#include <vtkNew.h>
#include <vtkPiecewiseFunction.h>
#include <vtkPointData.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkShaderProperty.h>
#include <vtkSmartVolumeMapper.h>
#include <vtkTrivialProducer.h>
#include <vtkVolume.h>
#include <vtkVolumeProperty.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <sstream>

namespace vtkBloomTool
{
namespace
{
//------------------------------------------------------------------------------
// The arrays of a dataset, for messages: "point: Temperature, Velocity (3); cell: Id".
std::string DescribeArrays(vtkDataObject* data)
{
  std::map<std::string, int> point, cell;
  ForEachDataSet(data,
    [&](vtkDataSet* dataset)
    {
      for (int a = 0; a < dataset->GetPointData()->GetNumberOfArrays(); ++a)
      {
        if (vtkDataArray* array = dataset->GetPointData()->GetArray(a))
        {
          point[array->GetName() ? array->GetName() : "(unnamed)"] = array->GetNumberOfComponents();
        }
      }
      for (int a = 0; a < dataset->GetCellData()->GetNumberOfArrays(); ++a)
      {
        if (vtkDataArray* array = dataset->GetCellData()->GetArray(a))
        {
          cell[array->GetName() ? array->GetName() : "(unnamed)"] = array->GetNumberOfComponents();
        }
      }
    });
  auto list = [](const std::map<std::string, int>& arrays)
  {
    std::string text;
    for (const auto& entry : arrays)
    {
      text += (text.empty() ? "" : ", ") + entry.first +
        (entry.second > 1 ? " (" + std::to_string(entry.second) + " components)" : "");
    }
    return text.empty() ? std::string("none") : text;
  };
  return "point arrays: " + list(point) + "; cell arrays: " + list(cell);
}

//------------------------------------------------------------------------------
struct ArrayChoice
{
  std::string Name;
  bool OnCells = false;
  int Components = 1;
};

// The array to colour by: the named one (points first, then cells), else the active point
// scalars, else the first point array, else the first cell array; Name "" when there is none.
ArrayChoice ChooseArray(vtkDataObject* data, const std::string& requested)
{
  ArrayChoice choice;
  ForEachDataSet(data,
    [&](vtkDataSet* dataset)
    {
      if (!choice.Name.empty())
      {
        return;
      }
      vtkPointData* pd = dataset->GetPointData();
      vtkCellData* cd = dataset->GetCellData();
      vtkDataArray* array = nullptr;
      bool onCells = false;
      if (!requested.empty())
      {
        array = pd->GetArray(requested.c_str());
        if (!array && (array = cd->GetArray(requested.c_str())))
        {
          onCells = true;
        }
      }
      else if ((array = pd->GetScalars()) || (pd->GetNumberOfArrays() && (array = pd->GetArray(0))))
      {
      }
      else if (cd->GetNumberOfArrays() && (array = cd->GetArray(0)))
      {
        onCells = true;
      }
      if (array && array->GetName())
      {
        choice.Name = array->GetName();
        choice.OnCells = onCells;
        choice.Components = array->GetNumberOfComponents();
      }
    });
  return choice;
}

//------------------------------------------------------------------------------
// Range of the chosen array (a component, or the magnitude with component -1) over every leaf,
// and how many of its values lie in [lo, hi].
void ArrayRange(vtkDataObject* data, const ArrayChoice& choice, int component, double range[2],
  const double* within = nullptr, vtkIdType* count = nullptr)
{
  range[0] = VTK_DOUBLE_MAX;
  range[1] = VTK_DOUBLE_MIN;
  if (count)
  {
    *count = 0;
  }
  ForEachDataSet(data,
    [&](vtkDataSet* dataset)
    {
      vtkDataArray* array = choice.OnCells ? dataset->GetCellData()->GetArray(choice.Name.c_str())
                                           : dataset->GetPointData()->GetArray(choice.Name.c_str());
      if (!array || array->GetNumberOfTuples() == 0)
      {
        return;
      }
      const int c = array->GetNumberOfComponents() == 1 ? 0 : component;
      double r[2];
      array->GetRange(r, c);
      range[0] = std::min(range[0], r[0]);
      range[1] = std::max(range[1], r[1]);
      if (within && count)
      {
        for (vtkIdType t = 0; t < array->GetNumberOfTuples(); ++t)
        {
          double v;
          if (c >= 0)
          {
            v = array->GetComponent(t, c);
          }
          else
          {
            double sum = 0.0;
            for (int k = 0; k < array->GetNumberOfComponents(); ++k)
            {
              sum += array->GetComponent(t, k) * array->GetComponent(t, k);
            }
            v = std::sqrt(sum);
          }
          *count += (v >= within[0] && v <= within[1]) ? 1 : 0;
        }
      }
    });
  if (range[0] > range[1])
  {
    range[0] = 0.0;
    range[1] = 1.0;
  }
}

//------------------------------------------------------------------------------
// The colour maps, as control points (t, r, g, b): viridis and inferno sampled at nine points
// from matplotlib's tables (van der Walt and Smith), coolwarm Moreland's diverging map,
// grayscale a linear ramp.
void FillColorMap(const std::string& name, vtkColorTransferFunction* colours, double lo, double hi)
{
  static const std::map<std::string, std::vector<std::array<double, 4>>> maps = {
    { "viridis",
      { { 0.0, 0.267004, 0.004874, 0.329415 }, { 0.125, 0.275191, 0.194905, 0.496005 },
        { 0.25, 0.229739, 0.322361, 0.545706 }, { 0.375, 0.172719, 0.448791, 0.557885 },
        { 0.5, 0.127568, 0.566949, 0.550556 }, { 0.625, 0.157851, 0.683765, 0.501686 },
        { 0.75, 0.369214, 0.788888, 0.382914 }, { 0.875, 0.678489, 0.863742, 0.189503 },
        { 1.0, 0.993248, 0.906157, 0.143936 } } },
    { "inferno",
      { { 0.0, 0.001462, 0.000466, 0.013866 }, { 0.125, 0.087411, 0.044556, 0.224813 },
        { 0.25, 0.258234, 0.038571, 0.406485 }, { 0.375, 0.416331, 0.090203, 0.432943 },
        { 0.5, 0.578304, 0.148039, 0.404411 }, { 0.625, 0.735683, 0.215906, 0.330245 },
        { 0.75, 0.865006, 0.316822, 0.226055 }, { 0.875, 0.954506, 0.468744, 0.099874 },
        { 1.0, 0.988362, 0.998364, 0.644924 } } },
    { "coolwarm", { { 0.0, 0.230, 0.299, 0.754 }, { 1.0, 0.706, 0.016, 0.150 } } },
    { "grayscale", { { 0.0, 0.0, 0.0, 0.0 }, { 1.0, 1.0, 1.0, 1.0 } } },
  };
  const auto& points = maps.at(name);
  colours->RemoveAllPoints();
  if (name == "coolwarm")
  {
    colours->SetColorSpaceToDiverging();
  }
  else if (name == "grayscale")
  {
    colours->SetColorSpaceToRGB();
  }
  else
  {
    colours->SetColorSpaceToLab();
  }
  const double span = hi > lo ? hi - lo : 1.0;
  for (const auto& p : points)
  {
    colours->AddRGBPoint(lo + p[0] * span, p[1], p[2], p[3]);
  }
}

//------------------------------------------------------------------------------
// The background, and the camera looking along the chosen axis (iso: along -1,-1,-1), z up (y
// up for +-z), then turned and zoomed by TurnCamera.
void PlaceCamera(vtkRenderer* renderer, const DataSceneOptions& options)
{
  if (options.HasBackground)
  {
    renderer->SetBackground(options.Background);
  }
  else
  {
    renderer->SetBackground(0.02, 0.02, 0.03);
  }
  static const std::map<std::string, std::array<double, 3>> directions = {
    { "iso", { -1, -1, -1 } }, { "+x", { 1, 0, 0 } }, { "-x", { -1, 0, 0 } }, { "+y", { 0, 1, 0 } },
    { "-y", { 0, -1, 0 } }, { "+z", { 0, 0, 1 } }, { "-z", { 0, 0, -1 } }
  };
  const auto direction = directions.at(options.View);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetPosition(-direction[0], -direction[1], -direction[2]);
  if (options.View == "+z" || options.View == "-z")
  {
    camera->SetViewUp(0.0, 1.0, 0.0);
  }
  else
  {
    camera->SetViewUp(0.0, 0.0, 1.0);
  }
  renderer->ResetCamera();
  TurnCamera(renderer, options);
}
}

//------------------------------------------------------------------------------
void ParseDataOption(const std::string& option, const std::string& value, DataSceneOptions& o)
{
  auto pair = [&](double out[2])
  {
    const auto colon = value.find(':');
    if (colon == std::string::npos)
    {
      throw UsageError{ option + " expects LO:HI, got '" + value + "'" };
    }
    out[0] = ParseDouble(option, value.substr(0, colon));
    out[1] = ParseDouble(option, value.substr(colon + 1));
    if (!(out[0] <= out[1]))
    {
      throw UsageError{ option + " expects LO <= HI, got '" + value + "'" };
    }
  };
  if (option == "--color-by")
  {
    const auto colon = value.rfind(':');
    o.ColorBy = value.substr(0, colon);
    o.ColorComponent = colon == std::string::npos
      ? -1
      : ParseInt(option + " component", value.substr(colon + 1), 0, 1 << 20);
    if (o.ColorBy.empty())
    {
      throw UsageError{ "--color-by expects NAME or NAME:COMPONENT" };
    }
  }
  else if (option == "--range")
  {
    pair(o.Range);
    o.HasRange = true;
  }
  else if (option == "--emit-range")
  {
    pair(o.EmitRange);
    o.HasEmitRange = true;
  }
  else if (option == "--contour")
  {
    o.Contours = ParseList(option, value);
  }
  else if (option == "--background")
  {
    const auto rgb = ParseList(option, value);
    if (rgb.size() != 3)
    {
      throw UsageError{ "--background expects R,G,B" };
    }
    std::copy(rgb.begin(), rgb.end(), o.Background);
    o.HasBackground = true;
  }
}

//------------------------------------------------------------------------------
struct DataScene::vtkInternals
{
  DataSceneOptions Options;
  std::string FileName;
  ArrayChoice Array;
  double ColorRange[2] = { 0.0, 1.0 };
  vtkNew<vtkTrivialProducer> Producer;
  vtkNew<vtkCellDataToPointData> ToPoints;
  vtkNew<vtkContourFilter> Contour;
  vtkNew<vtkDataSetSurfaceFilter> Surface;
  vtkSmartPointer<vtkMapper> Mapper;
  vtkNew<vtkActor> Actor;
  vtkSmartPointer<vtkActor> Emitter;
  vtkNew<vtkLookupTable> Table;
  vtkNew<vtkColorTransferFunction> Colours;
  vtkNew<vtkSmartVolumeMapper> VolumeMapper;
  vtkNew<vtkVolume> Volume;
  vtkSmartPointer<vtkDataObject> Data;
  bool IsVolume = false;
  bool IsComposite = false;

  void CheckArray(vtkDataObject* data, const std::string& name)
  {
    if (this->Options.ColorBy.empty())
    {
      return;
    }
    const ArrayChoice found = ChooseArray(data, this->Options.ColorBy);
    if (found.Name.empty())
    {
      throw UsageError{ "--color-by: " + name + " has no array '" + this->Options.ColorBy +
        "'; its " + DescribeArrays(data) };
    }
    if (this->Options.ColorComponent >= found.Components)
    {
      throw UsageError{ "--color-by: array '" + found.Name + "' of " + name + " has " +
        std::to_string(found.Components) + " component(s), no component " +
        std::to_string(this->Options.ColorComponent) };
    }
  }

  // The steps of DataScene::Build, defined below.
  void CheckRepresentation(vtkDataObject* data, const std::string& name) const;
  void BuildVolume(vtkRenderer* renderer, int component, double gain);
  void BuildSurface(vtkRenderer* renderer, vtkBloomPass* pass, int component, double gain);
  vtkAlgorithm* SurfaceSource();
  void ColourMapper(int component);
  void AddEmitter(vtkBloomPass* pass, vtkProperty* property);
};

DataScene::DataScene()
  : Internals(new vtkInternals)
{
}

DataScene::~DataScene() = default;

//------------------------------------------------------------------------------
// Refuse what the representation and the chosen array cannot do with this data.
void DataScene::vtkInternals::CheckRepresentation(
  vtkDataObject* data, const std::string& name) const
{
  const DataSceneOptions& options = this->Options;
  if (this->IsVolume && !vtkImageData::SafeDownCast(data))
  {
    throw UsageError{ "--representation volume needs image data (.vti); " + name + " holds " +
      data->GetClassName() };
  }
  if (this->IsVolume && options.HasEmitRange)
  {
    throw UsageError{ "--emit-range applies to surface, points and wireframe; a volume blooms "
                      "as a whole scene (raise --emit-gain)" };
  }
  if ((options.HasEmitRange || !options.Contours.empty() || this->IsVolume) &&
    this->Array.Name.empty())
  {
    throw UsageError{ name +
      " has no point or cell array to contour, emit or render as a "
      "volume by; its " +
      DescribeArrays(data) };
  }
}

//------------------------------------------------------------------------------
// --representation volume: the image through the CPU ray caster, coloured by the colour map
// lifted by the gain, its opacity a ramp over the colour range.
void DataScene::vtkInternals::BuildVolume(vtkRenderer* renderer, int component, double gain)
{
  vtkNew<vtkColorTransferFunction> colours;
  FillColorMap(this->Options.Colormap, colours, this->ColorRange[0], this->ColorRange[1]);
  // HDR colours: the gain lifts the volume above the bright-pass threshold.
  for (int i = 0; i < colours->GetSize(); ++i)
  {
    double node[6];
    colours->GetNodeValue(i, node);
    node[1] *= gain;
    node[2] *= gain;
    node[3] *= gain;
    colours->SetNodeValue(i, node);
  }
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(this->ColorRange[0], 0.0);
  opacity->AddPoint(this->ColorRange[1], 0.3);
  vtkNew<vtkVolumeProperty> property;
  property->SetColor(colours);
  property->SetScalarOpacity(opacity);
  property->SetInterpolationTypeToLinear();
  vtkAlgorithm* source = this->Producer;
  if (this->Array.OnCells)
  {
    this->ToPoints->SetInputConnection(this->Producer->GetOutputPort());
    source = this->ToPoints;
  }
  this->VolumeMapper->SetInputConnection(source->GetOutputPort());
  // CPU ray casting: VTK 9.1's GPU ray caster draws nothing inside a framebuffer render pass
  // (vtkFramebufferPass as much as vtkBloomPass), while the CPU image is composited there.
  this->VolumeMapper->SetRequestedRenderModeToRayCast();
  this->VolumeMapper->SetScalarModeToUsePointFieldData();
  this->VolumeMapper->SelectScalarArray(this->Array.Name.c_str());
  if (this->Array.Components > 1)
  {
    this->VolumeMapper->SetVectorMode(
      component < 0 ? vtkSmartVolumeMapper::MAGNITUDE : vtkSmartVolumeMapper::COMPONENT);
    this->VolumeMapper->SetVectorComponent(std::max(component, 0));
  }
  this->Volume->SetMapper(this->VolumeMapper);
  this->Volume->SetProperty(property);
  renderer->AddVolume(this->Volume);
}

//------------------------------------------------------------------------------
// Surface, points or wireframe: the data (or its contours) through a mapper, coloured by the
// chosen array, and what glows: the emit range through an emitter, else the whole actor.
void DataScene::vtkInternals::BuildSurface(
  vtkRenderer* renderer, vtkBloomPass* pass, int component, double gain)
{
  vtkAlgorithm* source = this->SurfaceSource();
  this->Mapper->SetInputConnection(source->GetOutputPort());
  if (!this->Array.Name.empty())
  {
    this->ColourMapper(component);
  }
  else
  {
    this->Mapper->ScalarVisibilityOff();
  }
  vtkProperty* property = this->Actor->GetProperty();
  // Blocks without the coloured array, and data without arrays, in a neutral grey.
  property->SetColor(0.7, 0.7, 0.7);
  if (this->Options.Representation == "points")
  {
    property->SetRepresentationToPoints();
    property->SetPointSize(3.0);
  }
  else if (this->Options.Representation == "wireframe")
  {
    property->SetRepresentationToWireframe();
  }
  this->Actor->SetMapper(this->Mapper);
  renderer->AddActor(this->Actor);

  if (this->Options.HasEmitRange)
  {
    this->AddEmitter(pass, property);
  }
  else if (gain != 1.0)
  {
    // The whole scene's colours times the gain: HDR, so that what now exceeds 1 glows. Not
    // through the property, whose ambient and diffuse VTK clamps to [0, 1], but on the
    // fragment's final colour (after lighting, textures and scalar colouring).
    std::ostringstream scale;
    scale.precision(17);
    scale << "//VTK::Light::Impl\n  gl_FragData[0].rgb *= " << std::fixed << gain << ";\n";
    this->Actor->GetShaderProperty()->AddFragmentShaderReplacement(
      "//VTK::Light::Impl", true, scale.str(), false);
  }
}

//------------------------------------------------------------------------------
// The pipeline in front of the mapper (the contours when asked, the surface of each block of
// composite data), and the mapper that suits it; returns the last stage.
vtkAlgorithm* DataScene::vtkInternals::SurfaceSource()
{
  vtkAlgorithm* source = this->Producer;
  if (!this->Options.Contours.empty())
  {
    if (this->Array.OnCells)
    {
      this->ToPoints->SetInputConnection(source->GetOutputPort());
      source = this->ToPoints;
    }
    this->Contour->SetInputConnection(source->GetOutputPort());
    this->Contour->SetInputArrayToProcess(
      0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, this->Array.Name.c_str());
    for (size_t i = 0; i < this->Options.Contours.size(); ++i)
    {
      this->Contour->SetValue(static_cast<int>(i), this->Options.Contours[i]);
    }
    source = this->Contour;
  }
  if (this->IsComposite)
  {
    // Block by block (each keeps its own arrays), drawn by the composite mapper.
    this->Surface->SetInputConnection(source->GetOutputPort());
    source = this->Surface;
    this->Mapper = vtkSmartPointer<vtkBloomCompositePolyDataMapper>::New();
  }
  else
  {
    this->Mapper = vtkSmartPointer<vtkDataSetMapper>::New();
  }
  return source;
}

//------------------------------------------------------------------------------
// Colour the mapper by the chosen array (a component, or the magnitude for component -1)
// through a 256-entry table sampled from the colour map.
void DataScene::vtkInternals::ColourMapper(int component)
{
  const bool onCells = this->Array.OnCells && this->Options.Contours.empty();
  this->Table->SetNumberOfTableValues(256);
  this->Table->SetTableRange(this->ColorRange);
  for (int i = 0; i < 256; ++i)
  {
    double rgb[3];
    this->Colours->GetColor(
      this->ColorRange[0] + (this->ColorRange[1] - this->ColorRange[0]) * i / 255.0, rgb);
    this->Table->SetTableValue(i, rgb[0], rgb[1], rgb[2], 1.0);
  }
  if (this->Array.Components > 1)
  {
    if (component < 0)
    {
      this->Table->SetVectorModeToMagnitude();
    }
    else
    {
      this->Table->SetVectorModeToComponent();
      this->Table->SetVectorComponent(component);
    }
  }
  this->Mapper->SetLookupTable(this->Table);
  this->Mapper->SetScalarRange(this->ColorRange);
  if (onCells)
  {
    this->Mapper->SetScalarModeToUseCellFieldData();
  }
  else
  {
    this->Mapper->SetScalarModeToUsePointFieldData();
  }
  this->Mapper->SelectColorArray(this->Array.Name.c_str());
  this->Mapper->ScalarVisibilityOn();
  this->Mapper->SetColorModeToMapScalars();
  this->Mapper->SetInterpolateScalarsBeforeMapping(true);
}

//------------------------------------------------------------------------------
// Only the emit range glows: an emitter copy of the actor, black outside the range, its
// colours unlit (ambient only), as the scalar-field scene. The pass blooms the range's
// colours whatever their level (no threshold); --emit-gain scales that light (the strength).
void DataScene::vtkInternals::AddEmitter(vtkBloomPass* pass, vtkProperty* property)
{
  this->Emitter = vtkBloomPass::CreateScalarRangeEmitter(this->Actor, this->Options.EmitRange);
  if (!this->Emitter)
  {
    throw RunError{ "cannot make the emitter for --emit-range" };
  }
  vtkNew<vtkProperty> glow;
  glow->DeepCopy(property);
  glow->SetAmbient(1.0);
  glow->SetDiffuse(0.0);
  glow->SetSpecular(0.0);
  // Blocks without the array take the property's colour: black, so they do not emit.
  glow->SetColor(0.0, 0.0, 0.0);
  this->Emitter->SetProperty(glow);
  pass->SetEmissionSourceToEmitters();
  pass->AddEmitter(this->Emitter);
  pass->GetParameters()->SetThresholdMode(vtkImageBloomThreshold::NONE);
}

//------------------------------------------------------------------------------
void DataScene::Build(vtkDataObject* data, const std::string& name, const DataSceneOptions& options,
  vtkRenderer* renderer, vtkBloomPass* pass)
{
  vtkInternals& d = *this->Internals;
  d.Options = options;
  d.CheckArray(data, name);
  d.Array = ChooseArray(data, options.ColorBy);
  d.IsComposite = vtkCompositeDataSet::SafeDownCast(data) != nullptr;
  d.IsVolume = options.Representation == "volume";
  d.CheckRepresentation(data, name);
  const int component = d.Array.Components == 1 ? 0 : options.ColorComponent;
  if (options.HasRange)
  {
    d.ColorRange[0] = options.Range[0];
    d.ColorRange[1] = options.Range[1];
  }
  else if (!d.Array.Name.empty())
  {
    ArrayRange(data, d.Array, component, d.ColorRange);
  }
  FillColorMap(options.Colormap, d.Colours, d.ColorRange[0], d.ColorRange[1]);
  // With --emit-range the gain scales the emitted light (the strength, in vtk-bloom.cxx).
  const double gain = options.EmitGain >= 0.0 && !options.HasEmitRange ? options.EmitGain : 1.0;

  d.Producer->SetOutput(data);
  d.Data = data;
  d.FileName = name;
  if (d.IsVolume)
  {
    d.BuildVolume(renderer, component, gain);
  }
  else
  {
    d.BuildSurface(renderer, pass, component, gain);
  }
  PlaceCamera(renderer, options);
}

//------------------------------------------------------------------------------
void TurnCamera(vtkRenderer* renderer, const DataSceneOptions& options)
{
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->Azimuth(options.Azimuth);
  camera->Elevation(options.Elevation);
  camera->OrthogonalizeViewUp();
  camera->Zoom(options.Zoom);
  renderer->ResetCameraClippingRange();
}

//------------------------------------------------------------------------------
void DataScene::SetData(vtkDataObject* data, const std::string& name)
{
  vtkInternals& d = *this->Internals;
  d.CheckArray(data, name);
  d.Producer->SetOutput(data);
  d.Data = data;
  d.FileName = name;
}

//------------------------------------------------------------------------------
std::string DataScene::EmitWarning() const
{
  const vtkInternals& d = *this->Internals;
  if (!d.Options.HasEmitRange || !d.Data)
  {
    return "";
  }
  double range[2];
  vtkIdType count = 0;
  const int component = d.Array.Components == 1 ? 0 : d.Options.ColorComponent;
  ArrayRange(d.Data, d.Array, component, range, d.Options.EmitRange, &count);
  if (count > 0)
  {
    return "";
  }
  std::ostringstream message;
  message << "--emit-range " << d.Options.EmitRange[0] << ":" << d.Options.EmitRange[1]
          << " selects nothing in " << d.FileName << " ('" << d.Array.Name << "' spans ["
          << range[0] << ", " << range[1] << "]); no bloom is added";
  return message.str();
}
}
