// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkBloomExampleScenes.h"

#include "vtkActor.h"
#include "vtkBloomPass.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkImageBloom.h"
#include "vtkImageBloomThreshold.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkLookupTable.h"
#include "vtkMath.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRTAnalyticSource.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"

#include <cmath>

namespace
{
// The height the scenes' bloom parameters were chosen at (vtk-bloom render's default size);
// other heights get the same look, scaled (vtkBloomParameters::ReferenceHeight).
constexpr int SceneHeight = 540;

// The scenes' bloom: the webgpu-market chain with the scene's own levels and strength, sized
// for SceneHeight so that it looks the same at every resolution. Returns the parameters for
// the scene's bright pass.
vtkBloomParameters* SceneBloom(vtkBloomPass* pass, int levels, double strength)
{
  pass->SetPreset("webgpu-market");
  vtkBloomParameters* p = pass->GetParameters();
  p->SetReferenceHeight(SceneHeight);
  p->SetNumberOfLevels(levels);
  p->SetStrength(strength);
  return p;
}

// A camera at `position` looking at `focus`, z up or y up.
vtkCamera* SceneCamera(
  vtkRenderer* renderer, const double position[3], const double focus[3], bool zUp)
{
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(position[0], position[1], position[2]);
  camera->SetFocalPoint(focus[0], focus[1], focus[2]);
  camera->SetViewUp(0.0, zUp ? 0.0 : 1.0, zUp ? 1.0 : 0.0);
  return camera;
}
// A perceptual "hot" table: black-red-yellow-white over the wavelet's range.
void HotTable(vtkLookupTable* table, double lo, double hi)
{
  const int n = 256;
  table->SetNumberOfTableValues(n);
  table->SetTableRange(lo, hi);
  for (int i = 0; i < n; ++i)
  {
    const double t = i / (n - 1.0);
    const double r = std::min(1.0, 0.1 + 1.6 * t);
    const double g = std::min(1.0, std::max(0.0, 1.8 * t - 0.45));
    const double b = std::min(1.0, std::max(0.0, 3.0 * t - 2.0) + 0.25 * (1.0 - t));
    table->SetTableValue(i, 0.7 * r, 0.7 * g, 0.7 * b, 1.0);
  }
  table->Build();
}

// The wavelet's z = 0 slice coloured by its scalar, with contours above it; only the
// hottest range of the slice glows (selective bloom through a scalar-range emitter).
void ScalarField(vtkRenderer* renderer, vtkBloomPass* pass)
{
  vtkNew<vtkRTAnalyticSource> wavelet;
  wavelet->SetWholeExtent(-60, 60, -60, 60, 0, 0);
  wavelet->SetMaximum(255.0);
  wavelet->SetCenter(8.0, -6.0, 0.0);
  wavelet->Update();
  // The slice as a plane with the same grid, carrying the wavelet's scalars (both order their
  // points x fastest).
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-60.0, -60.0, 0.0);
  plane->SetPoint1(60.0, -60.0, 0.0);
  plane->SetPoint2(-60.0, 60.0, 0.0);
  plane->SetResolution(120, 120);
  plane->Update();
  vtkNew<vtkPolyData> surface;
  surface->ShallowCopy(plane->GetOutput());
  surface->GetPointData()->SetScalars(wavelet->GetOutput()->GetPointData()->GetScalars());
  vtkNew<vtkLookupTable> table;
  HotTable(table, 37.0, 277.0);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(surface);
  mapper->SetLookupTable(table);
  mapper->SetScalarRange(37.0, 277.0);
  mapper->SetInterpolateScalarsBeforeMapping(true);
  vtkNew<vtkActor> slice;
  slice->SetMapper(mapper);
  slice->GetProperty()->SetAmbient(1.0);
  slice->GetProperty()->SetDiffuse(0.0);
  renderer->AddActor(slice);

  const double hot[2] = { 245.0, 277.0 };
  auto emitter = vtkBloomPass::CreateScalarRangeEmitter(slice, hot);
  pass->AddEmitter(emitter);
  pass->SetEmissionSourceToEmitters();
  SceneBloom(pass, 6, 1.5)->SetThresholdMode(vtkImageBloomThreshold::NONE);

  renderer->SetBackground(0.02, 0.02, 0.03);
  const double position[3] = { 0.0, 0.0, 300.0 }, focus[3] = { 0.0, 0.0, 0.0 };
  vtkCamera* camera = SceneCamera(renderer, position, focus, false);
  renderer->ResetCamera();
  camera->Zoom(1.9);
}

// Field lines of a magnetic dipole, traced with RK4, drawn as HDR emissive lines, with
// a few hundred glowing particles scattered along them.
void FieldLines(vtkRenderer* renderer, vtkBloomPass* pass)
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> lines;
  vtkNew<vtkDoubleArray> speed;
  speed->SetName("Strength");
  auto field = [](const double x[3], double b[3])
  {
    // Dipole along z: B = (3 (m.r) r - m r^2) / r^5.
    const double r2 = vtkMath::Dot(x, x) + 1e-6;
    const double r = std::sqrt(r2);
    const double mr = x[2];
    for (int i = 0; i < 3; ++i)
    {
      b[i] = (3.0 * mr * x[i] - (i == 2 ? r2 : 0.0)) / (r2 * r2 * r);
    }
  };
  // Each line starts on the equator (z = 0) and follows the field away from it, up through the
  // northern half-space until it nears the dipole; the southern half is its mirror image. At
  // the equator the dipole's field points to -z, so the tracer follows -B there.
  const int seedsAround = 12;
  for (int s = 0; s < seedsAround; ++s)
  {
    for (int shell = 0; shell < 3; ++shell)
    {
      const double phi = 2.0 * vtkMath::Pi() * (s + 0.5 * shell) / seedsAround;
      const double rho = 0.5 + 0.45 * shell;
      double x[3] = { rho * std::cos(phi), rho * std::sin(phi), 0.0 };
      double b0[3];
      field(x, b0);
      const double sense = b0[2] < 0.0 ? -1.0 : 1.0; // the direction that leaves z = 0 upwards
      std::vector<vtkIdType> ids;
      for (int step = 0; step < 900 && vtkMath::Norm(x) > 0.12 && x[2] >= 0.0; ++step)
      {
        ids.push_back(points->InsertNextPoint(x));
        double k1[3], k2[3], k3[3], k4[3], y[3];
        auto unit = [&](const double p[3], double out[3])
        {
          field(p, out);
          vtkMath::Normalize(out);
          vtkMath::MultiplyScalar(out, sense);
        };
        const double h = 0.02;
        unit(x, k1);
        for (int i = 0; i < 3; ++i)
          y[i] = x[i] + 0.5 * h * k1[i];
        unit(y, k2);
        for (int i = 0; i < 3; ++i)
          y[i] = x[i] + 0.5 * h * k2[i];
        unit(y, k3);
        for (int i = 0; i < 3; ++i)
          y[i] = x[i] + h * k3[i];
        unit(y, k4);
        double b[3];
        field(x, b);
        speed->InsertNextValue(std::log10(vtkMath::Norm(b) + 1e-12));
        for (int i = 0; i < 3; ++i)
        {
          x[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
        }
      }
      // Mirror the line below the equator.
      std::vector<vtkIdType> mirrored;
      for (vtkIdType id : ids)
      {
        double p[3];
        points->GetPoint(id, p);
        p[2] = -p[2];
        mirrored.push_back(points->InsertNextPoint(p));
        speed->InsertNextValue(speed->GetValue(id));
      }
      lines->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
      lines->InsertNextCell(static_cast<vtkIdType>(mirrored.size()), mirrored.data());
    }
  }
  vtkNew<vtkPolyData> polyData;
  polyData->SetPoints(points);
  polyData->SetLines(lines);
  vtkNew<vtkPolyDataMapper> lineMapper;
  lineMapper->SetInputData(polyData);
  lineMapper->ScalarVisibilityOff();
  vtkNew<vtkActor> fieldLines;
  fieldLines->SetMapper(lineMapper);
  // Emissive HDR colour: ambient only, with an ambient colour above 1.
  fieldLines->GetProperty()->SetAmbient(1.0);
  fieldLines->GetProperty()->SetDiffuse(0.0);
  fieldLines->GetProperty()->SetAmbientColor(0.4, 1.0, 2.4);
  fieldLines->GetProperty()->SetLineWidth(3.0);
  renderer->AddActor(fieldLines);

  // Particles: small spheres along the lines, hotter near the poles.
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(7);
  for (int i = 0; i < 40; ++i)
  {
    random->Next();
    const vtkIdType id = static_cast<vtkIdType>(random->GetValue() * points->GetNumberOfPoints());
    double p[3];
    points->GetPoint(std::min(id, points->GetNumberOfPoints() - 1), p);
    vtkNew<vtkSphereSource> sphere;
    sphere->SetCenter(p);
    sphere->SetRadius(0.035);
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(sphere->GetOutputPort());
    vtkNew<vtkActor> particle;
    particle->SetMapper(mapper);
    particle->GetProperty()->SetAmbient(1.0);
    particle->GetProperty()->SetDiffuse(0.0);
    particle->GetProperty()->SetAmbientColor(6.0, 3.0, 1.0);
    renderer->AddActor(particle);
  }

  SceneBloom(pass, 6, 0.5)->SetThreshold(1.0);

  renderer->SetBackground(0.0, 0.0, 0.0);
  const double position[3] = { 0.0, -9.0, 2.5 }, focus[3] = { 0.0, 0.0, 0.0 };
  vtkCamera* camera = SceneCamera(renderer, position, focus, true);
  renderer->ResetCamera();
  camera->Zoom(1.9);
}

// A lit ground plane and matte spheres under a strong key light, with small emissive lamps.
void LitScene(vtkRenderer* renderer, vtkBloomPass* pass)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-4.0, -4.0, 0.0);
  plane->SetPoint1(4.0, -4.0, 0.0);
  plane->SetPoint2(-4.0, 4.0, 0.0);
  plane->SetResolution(32, 32);
  vtkNew<vtkPolyDataMapper> planeMapper;
  planeMapper->SetInputConnection(plane->GetOutputPort());
  vtkNew<vtkActor> ground;
  ground->SetMapper(planeMapper);
  ground->GetProperty()->SetColor(0.22, 0.23, 0.26);
  renderer->AddActor(ground);

  const double spheres[3][4] = { { -1.6, 0.4, 0.8, 0.8 }, { 0.6, -0.8, 0.6, 0.6 },
    { 1.8, 1.2, 0.9, 0.9 } };
  const double colours[3][3] = { { 0.8, 0.3, 0.25 }, { 0.3, 0.7, 0.4 }, { 0.3, 0.45, 0.85 } };
  for (int i = 0; i < 3; ++i)
  {
    vtkNew<vtkSphereSource> sphere;
    sphere->SetCenter(spheres[i][0], spheres[i][1], spheres[i][2]);
    sphere->SetRadius(spheres[i][3]);
    sphere->SetThetaResolution(64);
    sphere->SetPhiResolution(32);
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(sphere->GetOutputPort());
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->GetProperty()->SetColor(colours[i][0], colours[i][1], colours[i][2]);
    actor->GetProperty()->SetSpecular(0.6);
    actor->GetProperty()->SetSpecularPower(60.0);
    renderer->AddActor(actor);
  }
  const double lamps[4][3] = { { -0.4, 1.6, 0.25 }, { 2.6, -1.0, 0.25 }, { -2.6, -1.6, 0.25 },
    { 0.0, 0.0, 2.6 } };
  const double lampColours[4][3] = { { 12.0, 7.0, 2.0 }, { 2.0, 6.0, 12.0 }, { 10.0, 2.0, 6.0 },
    { 8.0, 8.0, 8.0 } };
  for (int i = 0; i < 4; ++i)
  {
    vtkNew<vtkSphereSource> sphere;
    sphere->SetCenter(lamps[i][0], lamps[i][1], lamps[i][2]);
    sphere->SetRadius(i == 3 ? 0.12 : 0.18);
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(sphere->GetOutputPort());
    vtkNew<vtkActor> lamp;
    lamp->SetMapper(mapper);
    lamp->GetProperty()->SetAmbient(1.0);
    lamp->GetProperty()->SetDiffuse(0.0);
    lamp->GetProperty()->SetAmbientColor(lampColours[i][0], lampColours[i][1], lampColours[i][2]);
    renderer->AddActor(lamp);
  }

  // A key light above 1: highlights go beyond the displayable range and bloom.
  renderer->AutomaticLightCreationOff();
  vtkNew<vtkLight> key;
  key->SetLightTypeToSceneLight();
  key->SetPosition(-3.0, -4.0, 6.0);
  key->SetFocalPoint(0.0, 0.0, 0.0);
  key->SetIntensity(1.7);
  renderer->AddLight(key);
  vtkNew<vtkLight> fill;
  fill->SetLightTypeToHeadlight();
  fill->SetIntensity(0.35);
  renderer->AddLight(fill);

  SceneBloom(pass, 6, 0.6)->SetThreshold(1.2);

  renderer->SetBackground(0.05, 0.06, 0.08);
  const double position[3] = { 1.0, -8.0, 4.5 }, focus[3] = { 0.2, 0.2, 0.6 };
  SceneCamera(renderer, position, focus, true)->SetViewAngle(35.0);
}

struct Scene
{
  const char* Name;
  const char* Description;
  void (*Build)(vtkRenderer*, vtkBloomPass*);
};

const Scene Scenes[] = {
  { "scalar-field", "a wavelet field slice; only its hottest scalar range glows (selective)",
    ScalarField },
  { "field-lines", "glowing dipole field lines and particles (HDR emissive lines)", FieldLines },
  { "lit-spheres", "spheres under an HDR key light with emissive lamps", LitScene },
};
}

//------------------------------------------------------------------------------
std::vector<std::string> vtkBloomExampleSceneNames()
{
  std::vector<std::string> names;
  for (const Scene& scene : Scenes)
  {
    names.emplace_back(scene.Name);
  }
  return names;
}

//------------------------------------------------------------------------------
std::string vtkBloomExampleSceneDescription(const std::string& name)
{
  for (const Scene& scene : Scenes)
  {
    if (name == scene.Name)
    {
      return scene.Description;
    }
  }
  return std::string();
}

//------------------------------------------------------------------------------
bool vtkBloomBuildExampleScene(const std::string& name, vtkRenderer* renderer, vtkBloomPass* pass)
{
  for (const Scene& scene : Scenes)
  {
    if (name == scene.Name)
    {
      scene.Build(renderer, pass);
      return true;
    }
  }
  return false;
}
