// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// The gallery's scene pieces and frame metrics (see vtkBloomGallery.h).
#include "vtkBloomGallery.h"

#include "vtkActor.h"
#include "vtkBloomParameters.h"
#include "vtkBloomVTKCompat.h" // For OpenGL
#include "vtkCamera.h"
#include "vtkCornerAnnotation.h"
#include "vtkDataArray.h"
#include "vtkElevationFilter.h"
#include "vtkFramebufferPass.h"
#include "vtkImageBloomThreshold.h"
#include "vtkLegendBoxActor.h"
#include "vtkLookupTable.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPolyDataMapper.h"
#include "vtkPropCollection.h"
#include "vtkProperty.h"
#include "vtkRenderStepsPass.h"
#include "vtkRendererCollection.h"
#include "vtkScalarBarActor.h"
#include "vtkSphereSource.h"
#include "vtkTextActor.h"
#include "vtkTextProperty.h"
#include "vtkTextureObject.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWindowToImageFilter.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

namespace vtkBloomGallery
{
//------------------------------------------------------------------------------
vtkSmartPointer<vtkRenderWindow> MakeWindow(int width, int height, int samples)
{
  auto window = vtkSmartPointer<vtkRenderWindow>::New();
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(samples);
  window->SetSize(width, height);
  return window;
}

//------------------------------------------------------------------------------
View& AddBloomView(Scene& scene, vtkRenderer* renderer)
{
  if (!renderer->GetRenderWindow())
  {
    scene.Window->AddRenderer(renderer);
  }
  View view;
  view.Renderer = renderer;
  view.Bloom = vtkSmartPointer<vtkBloomPass>::New();
  vtkNew<vtkRenderStepsPass> steps;
  view.Bloom->SetDelegatePass(steps);
  renderer->SetPass(view.Bloom);
  // Plain: no pass at all, the renderer's own rendering, as before the user added the bloom.
  vtkSmartPointer<vtkRenderer> r = renderer;
  vtkSmartPointer<vtkBloomPass> bloom = view.Bloom;
  view.Use = [r, bloom](bool on) { r->SetPass(on ? bloom.GetPointer() : nullptr); };
  scene.Views.push_back(view);
  return scene.Views.back();
}

//------------------------------------------------------------------------------
namespace
{
vtkSmartPointer<vtkActor> ActorOf(vtkAlgorithmOutput* port, bool scalars)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(port);
  mapper->SetScalarVisibility(scalars);
  mapper->SetScalarRange(0.0, 1.0);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  // VTK's defaults, written out: the headlight's diffuse term only, so nothing exceeds 1.
  actor->GetProperty()->SetAmbient(0.0);
  actor->GetProperty()->SetDiffuse(1.0);
  actor->GetProperty()->SetSpecular(0.0);
  return actor;
}
}

vtkSmartPointer<vtkActor> LitSphere(const double centre[3], double radius, const double rgb[3])
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(centre[0], centre[1], centre[2]);
  sphere->SetRadius(radius);
  sphere->SetThetaResolution(48);
  sphere->SetPhiResolution(32);
  auto actor = ActorOf(sphere->GetOutputPort(), false);
  actor->GetProperty()->SetColor(rgb[0], rgb[1], rgb[2]);
  return actor;
}

vtkSmartPointer<vtkActor> ColourMappedSphere(const double centre[3], double radius)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(centre[0], centre[1], centre[2]);
  sphere->SetRadius(radius);
  sphere->SetThetaResolution(48);
  sphere->SetPhiResolution(32);
  vtkNew<vtkElevationFilter> elevation;
  elevation->SetInputConnection(sphere->GetOutputPort());
  elevation->SetLowPoint(centre[0], centre[1] - radius, centre[2]);
  elevation->SetHighPoint(centre[0], centre[1] + radius, centre[2]);
  return ActorOf(elevation->GetOutputPort(), true);
}

vtkSmartPointer<vtkActor> GroundPlane(double size, double y, const double rgb[3])
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-size, y, size);
  plane->SetPoint1(size, y, size);
  plane->SetPoint2(-size, y, -size);
  auto actor = ActorOf(plane->GetOutputPort(), false);
  actor->GetProperty()->SetColor(rgb[0], rgb[1], rgb[2]);
  return actor;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkProp> TextLabel(const char* text, double x, double y, const double rgb[3])
{
  auto label = vtkSmartPointer<vtkTextActor>::New();
  label->SetInput(text);
  label->GetTextProperty()->SetFontSize(20);
  label->GetTextProperty()->BoldOn();
  label->GetTextProperty()->SetColor(rgb[0], rgb[1], rgb[2]);
  label->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  label->GetPositionCoordinate()->SetValue(x, y);
  return label;
}

vtkSmartPointer<vtkProp> ScalarBar(const double rgb[3])
{
  vtkNew<vtkLookupTable> table;
  table->SetRange(0.0, 1.0);
  table->Build();
  auto bar = vtkSmartPointer<vtkScalarBarActor>::New();
  bar->SetLookupTable(table);
  bar->SetTitle("Elevation");
  bar->SetNumberOfLabels(3);
  bar->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  bar->GetPositionCoordinate()->SetValue(0.86, 0.1);
  bar->SetWidth(0.12);
  bar->SetHeight(0.8);
  for (vtkTextProperty* text : { bar->GetLabelTextProperty(), bar->GetTitleTextProperty() })
  {
    text->SetColor(rgb[0], rgb[1], rgb[2]);
    text->ShadowOff();
  }
  return bar;
}

vtkSmartPointer<vtkProp> CornerText(const double rgb[3])
{
  auto corner = vtkSmartPointer<vtkCornerAnnotation>::New();
  corner->SetText(0, "lower left");
  corner->SetText(3, "upper right");
  corner->SetMaximumFontSize(18);
  corner->GetTextProperty()->SetColor(rgb[0], rgb[1], rgb[2]);
  corner->GetTextProperty()->BoldOn();
  return corner;
}

vtkSmartPointer<vtkProp> Legend(const double rgb[3])
{
  vtkNew<vtkSphereSource> symbol;
  symbol->Update();
  auto legend = vtkSmartPointer<vtkLegendBoxActor>::New();
  legend->SetNumberOfEntries(3);
  const char* names[3] = { "grey", "copper", "teal" };
  const double colours[3][3] = { { 0.6, 0.6, 0.6 }, { 0.8, 0.45, 0.2 }, { 0.1, 0.6, 0.6 } };
  for (int i = 0; i < 3; ++i)
  {
    legend->SetEntry(i, symbol->GetOutput(), names[i], const_cast<double*>(colours[i]));
  }
  legend->GetEntryTextProperty()->SetColor(rgb[0], rgb[1], rgb[2]);
  legend->BorderOn();
  legend->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  legend->GetPositionCoordinate()->SetValue(0.02, 0.72);
  legend->GetPosition2Coordinate()->SetValue(0.26, 0.25);
  return legend;
}

//------------------------------------------------------------------------------
// The emitter is placed in display coordinates, so that the cases can put it near their
// annotations, and drawn nearer the camera than the focal plane so that it is not buried in the
// geometry, but inside the clipping range the camera was reset to (it is not reset again: the
// frames with and without the emitter must see the rest of the scene at the same depths).
vtkSmartPointer<vtkActor> Emitter(
  vtkRenderer* renderer, const double at[2], double pixels, double towardCamera)
{
  vtkCamera* camera = renderer->GetActiveCamera();
  const int* origin = renderer->GetOrigin();
  const int* size = renderer->GetSize();
  const double x = origin[0] + at[0] * size[0], y = origin[1] + at[1] * size[1];
  double focal[3], position[3], p[4], q[4];
  camera->GetFocalPoint(focal);
  camera->GetPosition(position);
  const double distance = camera->GetDistance();
  const double* range = camera->GetClippingRange();
  const double most = 1.0 - (range[0] + 0.1 * distance) / distance;
  const double f = std::max(0.0, std::min(towardCamera, most));
  auto toWorld = [renderer](double dx, double dy, double dz, double out[4])
  {
    renderer->SetDisplayPoint(dx, dy, dz);
    renderer->DisplayToWorld();
    renderer->GetWorldPoint(out);
    for (int c = 0; c < 3; ++c)
    {
      out[c] /= out[3];
    }
  };
  renderer->SetWorldPoint(focal[0], focal[1], focal[2], 1.0);
  renderer->WorldToDisplay();
  toWorld(x, y, renderer->GetDisplayPoint()[2], p);
  for (int c = 0; c < 3; ++c)
  {
    p[c] += f * (position[c] - p[c]);
  }
  renderer->SetWorldPoint(p[0], p[1], p[2], 1.0);
  renderer->WorldToDisplay();
  toWorld(x + pixels, y, renderer->GetDisplayPoint()[2], q);
  const double centre[3] = { p[0], p[1], p[2] };
  const double white[3] = { 1.0, 1.0, 1.0 };
  auto emitter = LitSphere(centre, std::sqrt(vtkMath::Distance2BetweenPoints(p, q)), white);
  // Unlit and bright: its float colour is 6 (1, 0.4, 0.1), light by any threshold at 1. The
  // gain goes in the ambient colour: vtkProperty clamps the ambient coefficient to 1.
  emitter->GetProperty()->SetAmbient(1.0);
  emitter->GetProperty()->SetDiffuse(0.0);
  emitter->GetProperty()->SetAmbientColor(6.0, 2.4, 0.6);
  return emitter;
}

//------------------------------------------------------------------------------
void UseOldDefaults(vtkBloomPass* pass, bool old)
{
  pass->GetParameters()->SetThresholdMode(
    old ? vtkImageBloomThreshold::SMOOTHSTEP_KNEE : vtkImageBloomThreshold::EXCESS_KNEE);
  pass->SetBloomBackground(old);
  pass->SetBloomAnnotations(old);
  pass->SetThresholdEmitters(old);
}

void UseBloom(Scene& scene, bool bloom)
{
  for (View& view : scene.Views)
  {
    view.Use(bloom);
  }
}

void UseOldDefaults(Scene& scene, bool old)
{
  for (View& view : scene.Views)
  {
    UseOldDefaults(view.Bloom, old);
  }
}

Frame GrabFloatPlain(Scene& scene)
{
  vtkNew<vtkRenderStepsPass> steps;
  vtkNew<vtkFramebufferPass> floatFrame;
  floatFrame->SetDelegatePass(steps);
  floatFrame->SetColorFormat(vtkTextureObject::Float32);
  floatFrame->SetDepthFormat(vtkTextureObject::Fixed32);
  for (View& view : scene.Views)
  {
    view.Renderer->SetPass(floatFrame);
  }
  Frame frame = Grab(scene.Window);
  floatFrame->ReleaseGraphicsResources(scene.Window);
  UseBloom(scene, true);
  return frame;
}

//------------------------------------------------------------------------------
namespace
{
Frame ReadBuffer(vtkRenderWindow* window, bool front)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->SetReadFrontBuffer(front);
  grab->ShouldRerenderOff();
  grab->Update();
  auto frame = Frame::New();
  frame->DeepCopy(grab->GetOutput());
  return frame;
}
}

Frame Grab(vtkRenderWindow* window, int* errors, Frame* presented)
{
  window->MakeCurrent();
  for (int i = 0; i < 64 && glGetError() != GL_NO_ERROR; ++i)
  {
  }
  window->Render();
  for (int i = 0; errors && i < 64 && glGetError() != GL_NO_ERROR; ++i)
  {
    ++*errors;
  }
  if (presented)
  {
    *presented = ReadBuffer(window, true);
  }
  return ReadBuffer(window, false);
}

namespace
{
// The largest channel difference of pixel p, in levels.
inline double PixelDifference(vtkDataArray* a, vtkDataArray* b, vtkIdType p)
{
  double d = 0.0;
  for (int c = 0; c < 3; ++c)
  {
    d = std::max(d, std::abs(a->GetComponent(p, c) - b->GetComponent(p, c)));
  }
  return d;
}

bool SameSize(vtkImageData* a, vtkImageData* b)
{
  int da[3], db[3];
  a->GetDimensions(da);
  b->GetDimensions(db);
  return da[0] == db[0] && da[1] == db[1] && da[2] == db[2];
}

// Frames of different sizes are as far apart as frames can be: every pixel differs, by more
// than any level.
constexpr double NotComparable = 256.0;
}

double Difference(vtkImageData* a, vtkImageData* b, vtkIdType p)
{
  return PixelDifference(a->GetPointData()->GetScalars(), b->GetPointData()->GetScalars(), p);
}

double MaxLevels(vtkImageData* a, vtkImageData* b)
{
  return MaxOver(a, b, std::vector<char>(a->GetNumberOfPoints(), 1));
}

double PercentOver(vtkImageData* a, vtkImageData* b, double levels)
{
  const std::vector<char> over = DifferenceMask(a, b, levels);
  return over.empty() ? 0.0 : 100.0 * Count(over) / static_cast<double>(over.size());
}

std::vector<char> DifferenceMask(vtkImageData* a, vtkImageData* b, double levels)
{
  vtkDataArray* sa = a->GetPointData()->GetScalars();
  vtkDataArray* sb = b->GetPointData()->GetScalars();
  std::vector<char> mask(a->GetNumberOfPoints(), SameSize(a, b) ? 0 : 1);
  for (vtkIdType p = 0; p < static_cast<vtkIdType>(mask.size()) && SameSize(a, b); ++p)
  {
    mask[p] = PixelDifference(sa, sb, p) > levels ? 1 : 0;
  }
  return mask;
}

//------------------------------------------------------------------------------
std::vector<char> Ring(
  const std::vector<char>& footprint, int width, int height, double inner, double outer)
{
  // Brute force over the footprint's bounding box grown by `outer`: footprints are small.
  std::vector<int> xs, ys;
  for (int j = 0; j < height; ++j)
  {
    for (int i = 0; i < width; ++i)
    {
      if (footprint[static_cast<size_t>(j) * width + i])
      {
        xs.push_back(i);
        ys.push_back(j);
      }
    }
  }
  std::vector<char> ring(footprint.size(), 0);
  if (xs.empty())
  {
    return ring;
  }
  const int pad = static_cast<int>(std::ceil(outer));
  const int i0 = std::max(0, *std::min_element(xs.begin(), xs.end()) - pad);
  const int i1 = std::min(width - 1, *std::max_element(xs.begin(), xs.end()) + pad);
  const int j0 = std::max(0, *std::min_element(ys.begin(), ys.end()) - pad);
  const int j1 = std::min(height - 1, *std::max_element(ys.begin(), ys.end()) + pad);
  for (int j = j0; j <= j1; ++j)
  {
    for (int i = i0; i <= i1; ++i)
    {
      double nearest = 1e30;
      for (size_t k = 0; k < xs.size(); ++k)
      {
        const double dx = xs[k] - i, dy = ys[k] - j;
        nearest = std::min(nearest, dx * dx + dy * dy);
      }
      nearest = std::sqrt(nearest);
      ring[static_cast<size_t>(j) * width + i] = nearest > inner && nearest <= outer ? 1 : 0;
    }
  }
  return ring;
}

//------------------------------------------------------------------------------
double MeanOver(vtkImageData* a, vtkImageData* b, const std::vector<char>& mask)
{
  if (!SameSize(a, b))
  {
    return NotComparable;
  }
  vtkDataArray* sa = a->GetPointData()->GetScalars();
  vtkDataArray* sb = b->GetPointData()->GetScalars();
  double sum = 0.0;
  long n = 0;
  for (vtkIdType p = 0; p < static_cast<vtkIdType>(mask.size()) && p < a->GetNumberOfPoints(); ++p)
  {
    if (mask[p])
    {
      sum += PixelDifference(sa, sb, p);
      ++n;
    }
  }
  return n > 0 ? sum / n : 0.0;
}

double MaxOver(vtkImageData* a, vtkImageData* b, const std::vector<char>& mask)
{
  if (!SameSize(a, b))
  {
    return NotComparable;
  }
  vtkDataArray* sa = a->GetPointData()->GetScalars();
  vtkDataArray* sb = b->GetPointData()->GetScalars();
  double most = 0.0;
  for (vtkIdType p = 0; p < static_cast<vtkIdType>(mask.size()) && p < a->GetNumberOfPoints(); ++p)
  {
    most = mask[p] ? std::max(most, PixelDifference(sa, sb, p)) : most;
  }
  return most;
}

std::vector<char> OutsideViewport(vtkImageData* frame, vtkRenderer* renderer)
{
  int dims[3];
  frame->GetDimensions(dims);
  const int* origin = renderer->GetOrigin();
  const int* size = renderer->GetSize();
  std::vector<char> mask(static_cast<size_t>(dims[0]) * dims[1], 0);
  for (int j = 0; j < dims[1]; ++j)
  {
    for (int i = 0; i < dims[0]; ++i)
    {
      const bool inside =
        i >= origin[0] && i < origin[0] + size[0] && j >= origin[1] && j < origin[1] + size[1];
      mask[static_cast<size_t>(j) * dims[0] + i] = inside ? 0 : 1;
    }
  }
  return mask;
}

long Count(const std::vector<char>& mask)
{
  return static_cast<long>(std::count(mask.begin(), mask.end(), 1));
}

double SceneMaximum(vtkBloomPass* pass)
{
  vtkNew<vtkImageData> scene;
  if (!pass->ReadSceneImage(scene))
  {
    return -1.0;
  }
  vtkDataArray* rgba = scene->GetPointData()->GetScalars();
  double most = 0.0;
  for (vtkIdType p = 0; p < rgba->GetNumberOfTuples(); ++p)
  {
    for (int c = 0; c < 3; ++c)
    {
      most = std::max(most, rgba->GetComponent(p, c));
    }
  }
  return most;
}

//------------------------------------------------------------------------------
namespace
{
/// While alive, every renderer of a window has a solid background of one grey and only the
/// annotations are visible; everything is restored when it goes out of scope.
class AnnotationsAlone
{
public:
  AnnotationsAlone(Scene& scene)
    : Window(scene.Window)
  {
    vtkRendererCollection* renderers = scene.Window->GetRenderers();
    vtkCollectionSimpleIterator it;
    renderers->InitTraversal(it);
    while (vtkRenderer* r = renderers->GetNextRenderer(it))
    {
      Saved saved{ r, {}, {}, r->GetGradientBackground(), r->GetTexturedBackground(), {} };
      r->GetBackground(saved.Colour);
      r->GetBackground2(saved.Colour2);
      vtkPropCollection* props = r->GetViewProps();
      vtkCollectionSimpleIterator pit;
      props->InitTraversal(pit);
      while (vtkProp* prop = props->GetNextProp(pit))
      {
        const bool annotation = std::find(scene.Annotations.begin(), scene.Annotations.end(),
                                  prop) != scene.Annotations.end();
        saved.Visibility.emplace_back(prop, prop->GetVisibility());
        prop->SetVisibility(annotation ? prop->GetVisibility() : 0);
      }
      r->GradientBackgroundOff();
      r->TexturedBackgroundOff();
      this->Renderers.push_back(saved);
    }
  }
  ~AnnotationsAlone()
  {
    for (Saved& saved : this->Renderers)
    {
      saved.Renderer->SetBackground(saved.Colour);
      saved.Renderer->SetBackground2(saved.Colour2);
      saved.Renderer->SetGradientBackground(saved.Gradient);
      saved.Renderer->SetTexturedBackground(saved.Textured);
      for (auto& prop : saved.Visibility)
      {
        prop.first->SetVisibility(prop.second);
      }
    }
  }
  Frame Over(double grey)
  {
    for (Saved& saved : this->Renderers)
    {
      saved.Renderer->SetBackground(grey, grey, grey);
    }
    return Grab(this->Window);
  }

private:
  struct Saved
  {
    vtkRenderer* Renderer;
    double Colour[3];
    double Colour2[3];
    bool Gradient;
    bool Textured;
    std::vector<std::pair<vtkProp*, int>> Visibility;
  };
  vtkRenderWindow* Window;
  std::vector<Saved> Renderers;
};
}

std::vector<double> AnnotationCoverage(Scene& scene)
{
  UseBloom(scene, false);
  Frame black, white;
  {
    AnnotationsAlone alone(scene);
    black = alone.Over(0.0);
    white = alone.Over(1.0);
  }
  vtkDataArray* b = black->GetPointData()->GetScalars();
  vtkDataArray* w = white->GetPointData()->GetScalars();
  // Annotations over black and over white are one window's frames: the same size.
  std::vector<double> coverage(SameSize(black, white) ? black->GetNumberOfPoints() : 0, 0.0);
  double backdrop = 0.0;
  for (size_t p = 0; p < coverage.size(); ++p)
  {
    coverage[p] = PixelDifference(w, b, static_cast<vtkIdType>(p));
    backdrop = std::max(backdrop, coverage[p]);
  }
  for (double& c : coverage)
  {
    c = backdrop > 0.0 ? 1.0 - c / backdrop : 0.0;
  }
  return coverage;
}

//------------------------------------------------------------------------------
void WriteSideBySide(vtkImageData* a, vtkImageData* b, const std::string& path)
{
  int da[3], db[3];
  a->GetDimensions(da);
  b->GetDimensions(db);
  const int height = std::max(da[1], db[1]);
  vtkNew<vtkImageData> both;
  both->SetDimensions(da[0] + db[0], height, 1);
  both->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* out = static_cast<unsigned char*>(both->GetScalarPointer());
  std::fill(out, out + static_cast<size_t>(da[0] + db[0]) * height * 3, 0);
  for (int j = 0; j < height; ++j)
  {
    for (int i = 0; i < da[0] + db[0]; ++i)
    {
      vtkImageData* from = i < da[0] ? a : b;
      const int x = i < da[0] ? i : i - da[0];
      const int* d = i < da[0] ? da : db;
      for (int c = 0; j < d[1] && c < 3; ++c)
      {
        out[(static_cast<size_t>(j) * (da[0] + db[0]) + i) * 3 + c] =
          static_cast<unsigned char>(from->GetScalarComponentAsDouble(x, j, 0, c));
      }
    }
  }
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(both);
  writer->SetFileName(path.c_str());
  writer->Write();
}

void AppendCSV(
  const std::string& path, const std::string& configuration, const std::vector<double>& values)
{
  const bool fresh = !std::ifstream(path).good() || std::ifstream(path).peek() == EOF;
  std::ofstream csv(path, std::ios::app);
  if (fresh)
  {
    csv << "configuration,before_pct_over_8,after_pct_over_8,after_max_levels,glow_ring_levels,"
           "annotations_max_levels\n";
  }
  std::ostringstream line;
  line << configuration;
  for (double v : values)
  {
    line << ",";
    if (!std::isnan(v))
    {
      line << v;
    }
  }
  csv << line.str() << "\n";
}
}
