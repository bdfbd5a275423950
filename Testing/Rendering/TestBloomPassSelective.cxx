// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// Selective bloom in one render (issue 30, part 7): the emission written by the scene's own
// shaders into a second attachment gives the image the emitters' second render gives, a scalar
// range glows exactly where its scalar lies, and the pass falls back to the second render where
// the scene's shaders cannot write the emission.
#include "vtkBloomExampleScenes.h"
#include "vtkBloomPass.h"
#include "vtkBloomPassTestWindow.h"
#include "vtkBloomTestSupport.h"

#include "vtkActor.h"
#include "vtkActor2D.h"
#include "vtkBloomVTKCompat.h"
#include "vtkCamera.h"
#include "vtkDoubleArray.h"
#include "vtkFollower.h"
#include "vtkImageData.h"
#include "vtkLookupTable.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkPolyDataMapper2D.h"
#include "vtkProperty.h"
#include "vtkSphereSource.h"

#include <gtest/gtest.h>

#include <cmath>

namespace
{
// The bloomed result of `w` rendered once, with the emission in the scene's render or not.
vtkSmartPointer<vtkImageData> RenderSelective(BloomWindow& w, bool inScene, bool expectInScene)
{
  w.Bloom->SetEmitInSceneRender(inScene);
  w.Bloom->SetFloatPrecisionTo32Bit();
  w.Bloom->CaptureResultOn();
  w.Window->Render();
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_EQ(w.Bloom->GetLastFrame()->GetEmissionInSceneRender(), expectInScene);
  auto result = vtkSmartPointer<vtkImageData>::New();
  EXPECT_TRUE(w.Bloom->ReadResultImage(result));
  return result;
}

// A glowing sphere (the emitter) beside and partly behind a grey one.
void LampAndWall(BloomWindow& w, vtkActor* lamp, vtkActor* wall)
{
  vtkNew<vtkSphereSource> wallSource, lampSource;
  wallSource->SetRadius(2.0);
  wallSource->SetCenter(1.5, 0.0, 1.0);
  lampSource->SetRadius(1.5);
  lampSource->SetCenter(-0.5, 0.3, -1.0);
  for (auto* source : { wallSource.Get(), lampSource.Get() })
  {
    source->SetThetaResolution(48);
    source->SetPhiResolution(24);
  }
  vtkNew<vtkPolyDataMapper> wallMapper, lampMapper;
  wallMapper->SetInputConnection(wallSource->GetOutputPort());
  lampMapper->SetInputConnection(lampSource->GetOutputPort());
  wall->SetMapper(wallMapper);
  wall->GetProperty()->SetColor(0.6, 0.6, 0.6);
  lamp->SetMapper(lampMapper);
  lamp->GetProperty()->SetAmbient(1.0);
  lamp->GetProperty()->SetDiffuse(0.0);
  lamp->GetProperty()->SetAmbientColor(8.0, 4.0, 2.0);
  w.Renderer->AddActor(wall);
  w.Renderer->AddActor(lamp);
  w.Renderer->SetBackground(0.1, 0.1, 0.2);
  w.Renderer->GetActiveCamera()->SetPosition(0.0, 0.0, 20.0);
  w.Renderer->ResetCamera();
  w.Bloom->SetPreset("webgpu-market");
  w.Bloom->AddEmitter(lamp);
  w.Bloom->SetEmissionSourceToEmitters();
}
}

//------------------------------------------------------------------------------
// The scalar-field scene (a scalar-range emitter of a texture-coloured slice) and an emitter
// prop half hidden behind another: one render gives the two renders' image.
TEST(RenderingBloomPassSelective, OneRenderGivesTheImageOfTwo)
{
  {
    BloomWindow w(320, 240);
    ASSERT_TRUE(vtkBloomBuildExampleScene("scalar-field", w.Renderer, w.Bloom));
    auto two = RenderSelective(w, false, false);
    auto one = RenderSelective(w, true, true);
    vtkNew<vtkImageData> scene;
    ASSERT_TRUE(w.Bloom->ReadSceneImage(scene));
    const double error = vtkBloomTest::ColourRelativeL2(one, two);
    std::cout << "scalar-field: one render vs two, relative L2 " << error << "\n";
    EXPECT_LE(error, 1e-6);
    EXPECT_GT(vtkBloomTest::ColourRelativeL2(one, scene), 1e-2) << "the range must glow";
  }
  {
    BloomWindow w(240, 180);
    vtkNew<vtkActor> lamp, wall;
    LampAndWall(w, lamp, wall);
    auto two = RenderSelective(w, false, false);
    auto one = RenderSelective(w, true, true);
    vtkNew<vtkImageData> scene;
    ASSERT_TRUE(w.Bloom->ReadSceneImage(scene));
    const double error = vtkBloomTest::ColourRelativeL2(one, two);
    std::cout << "lamp and wall: one render vs two, relative L2 " << error << "\n";
    EXPECT_LE(error, 1e-6);
    EXPECT_GT(vtkBloomTest::ColourRelativeL2(one, scene), 1e-2) << "the lamp must glow";
  }
  {
    // Multisampled, the resolve averages the colour and the emission's weight separately:
    // along the lamp's silhouette the one render's emission is the average colour times the
    // average weight (vtkBloomPassEmission.h), not exactly the second render's (whose depth
    // mask is one sample's): 2.0 % relative L2 on llvmpipe, all of it along the silhouette.
    BloomWindow w(240, 180);
    w.Window->SetMultiSamples(4);
    vtkNew<vtkActor> lamp, wall;
    LampAndWall(w, lamp, wall);
    auto two = RenderSelective(w, false, false);
    auto one = RenderSelective(w, true, true);
    const double error = vtkBloomTest::ColourRelativeL2(one, two);
    std::cout << "lamp and wall, 4 samples: one render vs two, relative L2 " << error << "\n";
    EXPECT_LE(error, 3e-2);
  }
}

//------------------------------------------------------------------------------
// A plane whose scalar is x / 2, seen so that pixel column i has x = i + 1/2: the range
// [40, 60] emits in columns 80 to 119 exactly, with the plane's own colour, in one render and
// through the emitter's own render.
TEST(RenderingBloomPassSelective, ScalarRangeEmitsExactlyWhereItsScalarLies)
{
  const int width = 200, height = 40;
  for (const bool inScene : { true, false })
  {
    BloomWindow w(width, height);
    vtkNew<vtkPlaneSource> plane;
    plane->SetOrigin(0.0, 0.0, 0.0);
    plane->SetPoint1(width, 0.0, 0.0);
    plane->SetPoint2(0.0, height, 0.0);
    plane->SetResolution(7, 3);
    plane->Update();
    vtkNew<vtkDoubleArray> scalar;
    scalar->SetName("s");
    vtkPoints* points = plane->GetOutput()->GetPoints();
    for (vtkIdType p = 0; p < points->GetNumberOfPoints(); ++p)
    {
      scalar->InsertNextValue(points->GetPoint(p)[0] / 2.0);
    }
    plane->GetOutput()->GetPointData()->SetScalars(scalar);
    vtkNew<vtkLookupTable> table;
    table->SetTableRange(0.0, 100.0);
    // Few colours: the texture's padding (one colour, 10 units of scalar, each side) is wide.
    table->SetNumberOfTableValues(10);
    table->SetHueRange(0.0, 0.7);
    table->Build();
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(plane->GetOutput());
    mapper->SetLookupTable(table);
    mapper->SetScalarRange(0.0, 100.0);
    mapper->SetInterpolateScalarsBeforeMapping(true);
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->GetProperty()->SetAmbient(1.0);
    actor->GetProperty()->SetDiffuse(0.0);
    w.Renderer->AddActor(actor);
    vtkCamera* camera = w.Renderer->GetActiveCamera();
    camera->ParallelProjectionOn();
    camera->SetFocalPoint(width / 2.0, height / 2.0, 0.0);
    camera->SetPosition(width / 2.0, height / 2.0, 100.0);
    camera->SetParallelScale(height / 2.0);
    w.Renderer->ResetCameraClippingRange();

    const double range[2] = { 40.0, 60.0 };
    auto emitter = vtkBloomPass::CreateScalarRangeEmitter(actor, range);
    ASSERT_NE(emitter, nullptr);
    w.Bloom->AddEmitter(emitter);
    w.Bloom->SetEmissionSourceToEmitters();
    RenderSelective(w, inScene, inScene);
    vtkNew<vtkImageData> scene, emission;
    ASSERT_TRUE(w.Bloom->ReadSceneImage(scene));
    ASSERT_TRUE(w.Bloom->ReadEmissionImage(emission));
    int wrong = 0;
    for (int j = 0; j < height; ++j)
    {
      for (int i = 0; i < width; ++i)
      {
        const vtkIdType p = static_cast<vtkIdType>(j) * width + i;
        const bool in = i >= 80 && i <= 119;
        for (int c = 0; c < 3; ++c)
        {
          const double expected = in ? scene->GetPointData()->GetScalars()->GetComponent(p, c) : 0;
          const double got = emission->GetPointData()->GetScalars()->GetComponent(p, c);
          wrong += std::abs(got - expected) > 1e-6 ? 1 : 0;
        }
      }
    }
    EXPECT_EQ(wrong, 0) << (inScene ? "in one render" : "in the emitter's render");
  }
}

//------------------------------------------------------------------------------
// Where a prop of the scene cannot write the emission (a 2D actor, translucent geometry),
// or the switch is off, the emitters render again, with the same image.
TEST(RenderingBloomPassSelective, FallsBackToASecondRenderWhereItMust)
{
  for (const int obstacle : { 0, 1 })
  {
    BloomWindow w(200, 150);
    vtkNew<vtkActor> lamp, wall;
    LampAndWall(w, lamp, wall);
    auto one = RenderSelective(w, true, true);
    // A 2D square in the corner, away from the lamp.
    vtkNew<vtkPlaneSource> square;
    square->SetOrigin(2.0, 2.0, 0.0);
    square->SetPoint1(12.0, 2.0, 0.0);
    square->SetPoint2(2.0, 12.0, 0.0);
    vtkNew<vtkPolyDataMapper2D> squareMapper;
    squareMapper->SetInputConnection(square->GetOutputPort());
    vtkNew<vtkActor2D> overlay;
    overlay->SetMapper(squareMapper);
    if (obstacle == 0)
    {
      w.Renderer->AddViewProp(overlay);
    }
    else
    {
      wall->GetProperty()->SetOpacity(0.999);
    }
    auto fallback = RenderSelective(w, true, false);
    auto two = RenderSelective(w, false, false);
    EXPECT_LE(vtkBloomTest::ColourRelativeL2(fallback, two), 1e-6) << obstacle;
    if (obstacle == 0)
    {
      // The square is an annotation, drawn over the bloomed result after the pass: the
      // result is the one-render result, to float rounding (it was 0.2 here, which let a
      // glow half gone pass).
      EXPECT_LE(vtkBloomTest::ColourRelativeL2(fallback, one), 1e-6);
    }
  }
}

//------------------------------------------------------------------------------
// A vtkFollower draws through an actor of its own (vedo 2023's meshes are followers): as an
// emitter it glows as the same lamp made as a plain actor does, through the second render.
TEST(RenderingBloomPassSelective, AFollowerEmitsAsAnActorDoes)
{
  vtkSmartPointer<vtkImageData> images[2];
  for (const int follower : { 0, 1 })
  {
    BloomWindow w(200, 150);
    vtkSmartPointer<vtkActor> lamp = follower
      ? vtkSmartPointer<vtkActor>(vtkSmartPointer<vtkFollower>::New())
      : vtkSmartPointer<vtkActor>::New();
    vtkNew<vtkActor> wall;
    LampAndWall(w, lamp, wall);
    images[follower] = RenderSelective(w, true, follower == 0);
    if (follower)
    {
      vtkNew<vtkImageData> scene;
      ASSERT_TRUE(w.Bloom->ReadSceneImage(scene));
      EXPECT_GT(vtkBloomTest::ColourRelativeL2(images[1], scene), 1e-2) << "the follower must glow";
    }
  }
  EXPECT_LE(vtkBloomTest::ColourRelativeL2(images[1], images[0]), 1e-6);
}
