// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// vtkBloomPass blooms light, not the frame (issue 35): at its defaults a frame with nothing above
// 1 is the renderer's own, the background never blooms and the glow goes over it
// (premultiplied), the annotations are drawn over the bloom, and an emitter glows whatever its
// colour. Each test also runs the switch that brings the earlier behaviour back, so that it
// fails where the feature is missing. The gallery of users' configurations is
// TestBloomPassGallery.cxx.
#include "vtkBloomPass.h"
#include "vtkBloomPassTestSphere.h"
#include "vtkBloomPassTestWindow.h"
#include "vtkBloomPassThroughRenderer.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCameraPass.h"
#include "vtkCoordinate.h"
#include "vtkDataArray.h"
#include "vtkDefaultPass.h"
#include "vtkImageBloomThreshold.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderState.h"
#include "vtkSphereSource.h"
#include "vtkTextActor.h"
#include "vtkTextProperty.h"
#include "vtkWindowToImageFilter.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace
{
// The window's frame as 8-bit RGB.
std::vector<int> Grab(vtkRenderWindow* window)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  grab->ShouldRerenderOff();
  grab->Update();
  vtkDataArray* rgb = grab->GetOutput()->GetPointData()->GetScalars();
  std::vector<int> values(static_cast<size_t>(rgb->GetNumberOfTuples()) * 3);
  for (vtkIdType p = 0; p < rgb->GetNumberOfTuples(); ++p)
  {
    for (int c = 0; c < 3; ++c)
    {
      values[3 * p + c] = static_cast<int>(rgb->GetComponent(p, c));
    }
  }
  return values;
}

int LargestDifference(const std::vector<int>& a, const std::vector<int>& b)
{
  if (a.empty() || a.size() != b.size())
  {
    ADD_FAILURE() << "frames of " << a.size() << " and " << b.size() << " values compared";
    return std::numeric_limits<int>::max();
  }
  int largest = 0;
  for (size_t i = 0; i < a.size(); ++i)
  {
    largest = std::max(largest, std::abs(a[i] - b[i]));
  }
  return largest;
}

// A white-background figure as users make them: a lit grey sphere and a dark label; with
// `lamp`, an orange HDR lamp beside it.
struct Figure
{
  BloomWindow W{ 240, 180 };
  vtkNew<vtkTextActor> Label;

  Figure(const double background[3], bool lamp)
  {
    this->W.Bloom->BloomBackgroundOff(); // the default (BloomWindow turns it on)
    const double grey[3] = { 0.8, 0.8, 0.8 }, orange[3] = { 1.0, 0.5, 0.2 };
    const double centre[3] = { -0.6, 0.0, 0.0 }, lampCentre[3] = { 1.1, 0.3, 0.0 };
    this->W.Renderer->AddActor(vtkBloomPassTestSphere(centre, 0.8, grey));
    if (lamp)
    {
      this->W.Renderer->AddActor(vtkBloomPassTestSphere(lampCentre, 0.15, orange, 4.0));
    }
    this->W.Renderer->SetBackground(background[0], background[1], background[2]);
    this->Label->SetInput("T = 300 K");
    this->Label->GetTextProperty()->SetFontSize(18);
    this->Label->GetTextProperty()->SetColor(0.1, 0.1, 0.1);
    this->Label->SetDisplayPosition(10, 150);
    this->W.Renderer->AddViewProp(this->Label);
    this->W.Renderer->ResetCamera();
    this->W.Renderer->GetActiveCamera()->SetPosition(0.0, 0.0, 6.0);
    this->W.Renderer->GetActiveCamera()->SetFocalPoint(0.0, 0.0, 0.0);
    this->W.Renderer->ResetCameraClippingRange();
  }

  std::vector<int> Render(bool bloom)
  {
    this->W.Renderer->SetPass(bloom ? static_cast<vtkRenderPass*>(this->W.Bloom) : nullptr);
    this->W.Window->Render();
    return Grab(this->W.Window);
  }

  /// The lamp's centre and radius on screen, in pixels (row 0 at the bottom).
  void Lamp(double centre[2], double& radius)
  {
    vtkNew<vtkCoordinate> at;
    at->SetCoordinateSystemToWorld();
    at->SetValue(1.1, 0.3, 0.0);
    const double* c = at->GetComputedDoubleDisplayValue(this->W.Renderer);
    centre[0] = c[0];
    centre[1] = c[1];
    at->SetValue(1.25, 0.3, 0.0);
    radius = at->GetComputedDoubleDisplayValue(this->W.Renderer)[0] - centre[0];
  }

  /**
   * The mean over the halo's ring (4 to 12 pixels out from the lamp's edge, clear of the sphere
   * and the label) of the largest channel's distance of `frame` from `plain`.
   */
  double HaloContrast(const std::vector<int>& frame, const std::vector<int>& plain)
  {
    double centre[2], radius;
    this->Lamp(centre, radius);
    const int width = this->W.Window->GetSize()[0];
    double sum = 0.0;
    int count = 0;
    for (size_t p = 0; p < frame.size() / 3; ++p)
    {
      const double x = static_cast<double>(p % width), y = static_cast<double>(p / width);
      const double r = std::hypot(x - centre[0], y - centre[1]);
      if (r < radius + 4.0 || r > radius + 12.0)
      {
        continue;
      }
      int distance = 0;
      for (int c = 0; c < 3; ++c)
      {
        distance = std::max(distance, std::abs(frame[3 * p + c] - plain[3 * p + c]));
      }
      sum += distance;
      ++count;
    }
    return count ? sum / count : 0.0;
  }
};
}

//------------------------------------------------------------------------------
// Display white and a white background are not light: at the defaults the figure without a
// lamp is the plain frame within one level; at the earlier defaults (smoothstep knee, the
// background and the label in the bloom) most of it moves.
TEST(RenderingBloomPassLight, AWhiteFigureIsThePlainFrame)
{
  const double white[3] = { 1.0, 1.0, 1.0 };
  Figure figure(white, false);
  const std::vector<int> plain = figure.Render(false);
  EXPECT_LE(LargestDifference(figure.Render(true), plain), 1);
  EXPECT_TRUE(figure.W.Bloom->GetLastFrame()->GetAnnotationsOverBloom());

  figure.W.Bloom->GetParameters()->SetThresholdMode(vtkImageBloomThreshold::SMOOTHSTEP_KNEE);
  figure.W.Bloom->BloomBackgroundOn();
  figure.W.Bloom->BloomAnnotationsOn();
  EXPECT_GT(LargestDifference(figure.Render(true), plain), 8) << "the earlier defaults";
}

//------------------------------------------------------------------------------
// The glow goes over the background: on white its halo shows (premultiplied-over), with a
// contrast at least half of what it has on black; added to white (the background in the
// bloom's frame), it would saturate and show nothing there.
TEST(RenderingBloomPassLight, TheGlowShowsOverALightBackground)
{
  const double white[3] = { 1.0, 1.0, 1.0 }, black[3] = { 0.0, 0.0, 0.0 };
  Figure onWhite(white, true), onBlack(black, true), plainWhite(white, false),
    plainBlack(black, false);
  // The reference for each: the same figure without bloom (the lamp then clamps to its disc).
  const std::vector<int> whiteFrame = onWhite.Render(true), blackFrame = onBlack.Render(true);
  const double contrastWhite = onWhite.HaloContrast(whiteFrame, plainWhite.Render(false));
  const double contrastBlack = onBlack.HaloContrast(blackFrame, plainBlack.Render(false));
  std::cout << "halo contrast (levels): on black " << contrastBlack << ", on white "
            << contrastWhite << "\n";
  EXPECT_GT(contrastBlack, 10.0);
  EXPECT_GE(contrastWhite, 0.5 * contrastBlack);

  // Added to white, as the background in the bloom's frame: nothing shows.
  onWhite.W.Bloom->BloomBackgroundOn();
  const double added = onWhite.HaloContrast(onWhite.Render(true), plainWhite.Render(false));
  EXPECT_LT(added, 0.1 * contrastBlack) << "a glow added to white shows nothing";
}

//------------------------------------------------------------------------------
// The composite's formula, checked against the scene and the glow read back in float: over a
// background B, out = S + G + (1 - a)(1 - g) B, where S (premultiplied, alpha a) and S + G are
// the same figure's scene and result over transparent black, and g is G's largest channel.
TEST(RenderingBloomPassLight, TheSceneAndItsGlowGoOverTheBackground)
{
  const double background[3] = { 0.9, 0.85, 0.6 }, none[3] = { 0.0, 0.0, 0.0 };
  Figure over(background, true), alone(none, true);
  for (Figure* f : { &over, &alone })
  {
    f->Label->SetVisibility(false);
    f->W.Bloom->CaptureResultOn();
    f->Render(true);
  }
  vtkNew<vtkImageData> scene, glowing, result;
  ASSERT_TRUE(alone.W.Bloom->ReadSceneImage(scene));
  ASSERT_TRUE(alone.W.Bloom->ReadResultImage(glowing));
  ASSERT_TRUE(over.W.Bloom->ReadResultImage(result));
  vtkDataArray* s = scene->GetPointData()->GetScalars();
  vtkDataArray* g = glowing->GetPointData()->GetScalars();
  vtkDataArray* r = result->GetPointData()->GetScalars();
  double error = 0.0, norm = 0.0;
  for (vtkIdType p = 0; p < s->GetNumberOfTuples(); ++p)
  {
    double glow[3], largest = 0.0;
    for (int c = 0; c < 3; ++c)
    {
      glow[c] = g->GetComponent(p, c) - s->GetComponent(p, c);
      largest = std::max(largest, glow[c]);
    }
    const double uncovered = 1.0 - std::min(s->GetComponent(p, 3), 1.0);
    const double behind = uncovered * (1.0 - std::min(std::max(largest, 0.0), 1.0));
    for (int c = 0; c < 3; ++c)
    {
      const double expected = s->GetComponent(p, c) + glow[c] + behind * background[c];
      error += std::pow(r->GetComponent(p, c) - expected, 2);
      norm += expected * expected;
    }
  }
  EXPECT_LE(std::sqrt(error / norm), 1e-3);
}

//------------------------------------------------------------------------------
// Annotations are drawn over the bloom: a label beside the lamp keeps its pixels where the
// glow reaches it; blooming the annotations (the earlier behaviour) washes them.
TEST(RenderingBloomPassLight, AnnotationsAreDrawnOverTheGlow)
{
  const double black[3] = { 0.0, 0.0, 0.0 };
  Figure dark(black, false), lit(black, true);
  for (Figure* f : { &dark, &lit })
  {
    f->Label->GetTextProperty()->SetColor(0.3, 0.6, 1.0);
    f->Label->SetDisplayPosition(196, 100); // beside the lamp, in its glow
  }
  // The label's core: where its blue covers the frame without it almost wholly (the glow
  // shows through a partly covered pixel, as it would through any anti-aliased text).
  const std::vector<int> withLabel = dark.Render(false);
  dark.Label->SetVisibility(false);
  const std::vector<int> withoutLabel = dark.Render(false);
  dark.Label->SetVisibility(true);
  std::vector<size_t> core;
  for (size_t i = 2; i < withLabel.size(); i += 3)
  {
    if (withLabel[i] - withoutLabel[i] >= 245)
    {
      core.insert(core.end(), { i - 2, i - 1, i });
    }
  }
  ASSERT_GT(core.size(), 20u);
  auto coreDifference = [&core](const std::vector<int>& a, const std::vector<int>& b)
  {
    int largest = 0;
    for (size_t i : core)
    {
      largest = std::max(largest, std::abs(a[i] - b[i]));
    }
    return largest;
  };
  const std::vector<int> unlit = dark.Render(true);
  EXPECT_LE(coreDifference(lit.Render(true), unlit), 2) << "the glow must not wash the label";
  lit.W.Bloom->BloomAnnotationsOn();
  dark.W.Bloom->BloomAnnotationsOn();
  EXPECT_GT(coreDifference(lit.Render(true), dark.Render(true)), 8) << "bloomed annotations";
}

//------------------------------------------------------------------------------
// An emitter glows whatever its colour: an LDR emitter (colour 0.6, below any threshold)
// blooms at the defaults, and does not once the threshold applies to emitters.
TEST(RenderingBloomPassLight, AnLDREmitterGlows)
{
  const double black[3] = { 0.0, 0.0, 0.0 };
  Figure figure(black, false);
  const double centre[3] = { 1.1, 0.3, 0.0 }, colour[3] = { 0.6, 0.5, 0.2 };
  vtkSmartPointer<vtkActor> emitter = vtkBloomPassTestSphere(centre, 0.15, colour, 1.0);
  figure.W.Renderer->AddActor(emitter);
  figure.W.Bloom->SetEmissionSourceToEmitters();
  figure.W.Bloom->AddEmitter(emitter);
  const std::vector<int> plain = figure.Render(false);
  EXPECT_GT(figure.HaloContrast(figure.Render(true), plain), 5.0);
  EXPECT_FALSE(figure.W.Bloom->GetLastFrame()->GetBloomSkipped());
  figure.W.Bloom->ThresholdEmittersOn();
  EXPECT_LE(LargestDifference(figure.Render(true), plain), 1);
  EXPECT_TRUE(figure.W.Bloom->GetLastFrame()->GetBloomSkipped());
}

//------------------------------------------------------------------------------
// Translucent geometry is drawn as the renderer draws it without a pass (order-independent
// transparency, or depth peeling), over a light background: two overlapping translucent
// spheres in front of an opaque one equal the plain frame within one level, both ways.
TEST(RenderingBloomPassLight, TranslucentGeometryIsThePlainFrame)
{
  for (const bool peeling : { false, true })
  {
    const double background[3] = { 0.95, 0.95, 0.9 };
    Figure figure(background, false);
    const double centres[2][3] = { { 0.2, 0.1, 1.0 }, { 0.7, -0.1, 1.4 } };
    const double colours[2][3] = { { 0.2, 0.5, 0.9 }, { 0.9, 0.3, 0.2 } };
    for (int i = 0; i < 2; ++i)
    {
      vtkSmartPointer<vtkActor> glass = vtkBloomPassTestSphere(centres[i], 0.6, colours[i]);
      glass->GetProperty()->SetOpacity(0.4);
      figure.W.Renderer->AddActor(glass);
    }
    figure.W.Renderer->SetUseDepthPeeling(peeling);
    const std::vector<int> plain = figure.Render(false);
    EXPECT_LE(LargestDifference(figure.Render(true), plain), 1) << "depth peeling " << peeling;
  }
}

//------------------------------------------------------------------------------
// The renderer's FXAA where the delegate renders through the renderer (ParaView's default
// pass): VTK applies it inside UpdateGeometry, on the framebuffer the delegate draws, which
// here is the pass's float scene over its hidden background. The pass keeps it out of the
// scene and applies it to the finished frame: the lamp stays above 1 in the scene and glows,
// and the white figure, rendered first without the pass as users toggle it, is the plain
// frame within one level (an 8-bit FXAA of the scene clamped the lamp to 1 and darkened the
// sphere's edges against the transparent background by about 100 levels).
TEST(RenderingBloomPassLight, TheRenderersFXAAStaysOutOfTheScene)
{
  const double white[3] = { 1.0, 1.0, 1.0 };
  for (bool lamp : { false, true })
  {
    Figure figure(white, lamp);
    // Without the label: a delegate that renders the overlay inside UpdateGeometry keeps the
    // annotations in the scene (GetLastAnnotationsOverBloom), so FXAA reaches them too.
    figure.Label->VisibilityOff();
    figure.W.Renderer->UseFXAAOn();
    vtkNew<vtkCameraPass> camera;
    vtkNew<vtkBloomPassThroughRenderer> through;
    camera->SetDelegatePass(through);
    figure.W.Bloom->SetDelegatePass(camera);
    const std::vector<int> plain = figure.Render(false);
    const std::vector<int> bloomed = figure.Render(true);
    EXPECT_TRUE(figure.W.Renderer->GetUseFXAA()) << "the renderer's switch is restored";
    vtkNew<vtkImageData> scene;
    ASSERT_TRUE(figure.W.Bloom->ReadSceneImage(scene));
    double largest = 0.0;
    vtkDataArray* rgba = scene->GetPointData()->GetScalars();
    for (vtkIdType p = 0; p < rgba->GetNumberOfTuples(); ++p)
    {
      largest = std::max(largest, rgba->GetComponent(p, 0));
    }
    if (lamp)
    {
      EXPECT_GT(largest, 2.0) << "the lamp's colour reaches the scene unclamped";
      EXPECT_GT(figure.HaloContrast(bloomed, plain), 10.0) << "and glows";
    }
    else
    {
      EXPECT_LE(LargestDifference(bloomed, plain), 1) << "FXAA once, on the finished frame";
    }
  }
}
