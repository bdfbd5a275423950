// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// Tiled frames bloom as one frame (issue 36, part 2): vtkWindowToImageFilter with a scale renders
// a screenshot larger than the window in tiles, and ParaView's screenshots do the same. Each
// tile renders with a guard band and the frame's chain cut to it (vtkBloomPassTile), so the
// tiled screenshot is the larger window's frame: its bloom term (the frame with the pass minus
// the frame without it) within 1 % relative L2, and no step at a tile edge larger than the
// steps beside it. Every comparison also runs with SeamlessTiles off, each tile blooming alone,
// which must fail it. The scenes are built as users build them: lit and emissive props across
// the tile edges, a light background, two viewports side by side.
#include "vtkBloomPass.h"
#include "vtkBloomPassTestSphere.h"
#include "vtkBloomPassThroughRenderer.h"
#include "vtkBloomTestSupport.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCameraPass.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDefaultPass.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderState.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkWindowToImageFilter.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <vector>

namespace
{
// An RGB frame, row 0 at the bottom.
struct Frame
{
  int Width = 0;
  int Height = 0;
  std::vector<double> Values;
  std::vector<bool> Covered; ///< a prop covers the pixel (the frame without the pass)
  double At(int i, int j, int c) const { return this->Values[3 * (j * this->Width + i) + c]; }
};

void AddSphere(
  vtkRenderer* renderer, double x, double y, double radius, const double colour[3], double emission)
{
  const double centre[3] = { x, y, 0.0 };
  renderer->AddActor(vtkBloomPassTestSphere(centre, radius, colour, emission));
}

// Lamps across the middle of the frame (where 2 x 2 and 4 x 4 tiles meet) and near its edges,
// a lit grey sphere, over `background`.
void Populate(vtkRenderer* renderer, const double background[3])
{
  const double warm[3] = { 1.0, 0.7, 0.3 }, cold[3] = { 0.3, 0.7, 1.0 }, red[3] = { 1.0, 0.2, 0.2 };
  const double grey[3] = { 0.8, 0.8, 0.8 };
  AddSphere(renderer, 0.02, 0.03, 0.2, warm, 5.0);
  AddSphere(renderer, 0.9, 0.45, 0.15, cold, 6.0);
  AddSphere(renderer, -1.35, -0.6, 0.12, red, 8.0);
  AddSphere(renderer, -0.5, 0.7, 0.25, grey, 0.0);
  renderer->SetBackground(background[0], background[1], background[2]);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0.0, 0.0, 6.0);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetViewUp(0.0, 1.0, 0.0);
  renderer->ResetCameraClippingRange();
}

// The window's frame, as vtkWindowToImageFilter reads it at `scale` times the window's size.
Frame Grab(vtkRenderWindow* window, int scale)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetScale(scale);
  grab->ReadFrontBufferOff();
  grab->Update();
  vtkImageData* image = grab->GetOutput();
  Frame frame;
  frame.Width = image->GetDimensions()[0];
  frame.Height = image->GetDimensions()[1];
  vtkDataArray* rgb = image->GetPointData()->GetScalars();
  for (vtkIdType p = 0; p < rgb->GetNumberOfTuples(); ++p)
  {
    for (int c = 0; c < 3; ++c)
    {
      frame.Values.push_back(rgb->GetComponent(p, c));
    }
  }
  return frame;
}

// A window of width x height with `viewports` renderers side by side, each with the pass
// (SeamlessTiles as given) or none; the frame captured at `scale` times the window's size.
Frame Render(int width, int height, int scale, bool bloom, bool seamless, int viewports = 1,
  vtkBloomPass* inspect = nullptr, bool throughRenderer = false)
{
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(width, height);
  std::vector<vtkSmartPointer<vtkBloomPass>> passes;
  for (int v = 0; v < viewports; ++v)
  {
    vtkNew<vtkRenderer> renderer;
    renderer->SetViewport(static_cast<double>(v) / viewports, 0.0, (v + 1.0) / viewports, 1.0);
    const double dark[3] = { 0.05, 0.05, 0.08 }, light[3] = { 0.92, 0.93, 0.95 };
    Populate(renderer, v == 1 ? light : dark);
    if (bloom)
    {
      auto pass = inspect && v == 0 ? vtkSmartPointer<vtkBloomPass>(inspect)
                                    : vtkSmartPointer<vtkBloomPass>::New();
      vtkNew<vtkRenderStepsPass> steps;
      vtkNew<vtkCameraPass> camera;
      vtkNew<vtkBloomPassThroughRenderer> through;
      camera->SetDelegatePass(through);
      pass->SetDelegatePass(throughRenderer ? static_cast<vtkRenderPass*>(camera) : steps);
      pass->SetSeamlessTiles(seamless);
      renderer->SetPass(pass);
      passes.push_back(pass);
    }
    window->AddRenderer(renderer);
  }
  window->Render();
  Frame frame = Grab(window, scale);
  for (auto& pass : passes)
  {
    pass->ReleaseGraphicsResources(window);
  }
  return frame;
}

// The bloom term of a frame: with the pass, minus without it.
Frame BloomTerm(
  int width, int height, int scale, bool seamless, int viewports = 1, bool throughRenderer = false)
{
  Frame with = Render(width, height, scale, true, seamless, viewports, nullptr, throughRenderer);
  const Frame without = Render(width, height, scale, false, seamless, viewports);
  if (with.Values.size() != without.Values.size())
  {
    ADD_FAILURE() << "the frames with and without the pass differ in size: " << with.Width << "x"
                  << with.Height << " and " << without.Width << "x" << without.Height;
    return Frame();
  }
  for (size_t k = 0; k < with.Values.size(); ++k)
  {
    with.Values[k] -= without.Values[k];
  }
  // Where a prop covers the pixel the frame with the pass saturates: its bloom term has the
  // prop's edges. The background is the corner's colour.
  with.Covered.resize(with.Values.size() / 3);
  for (size_t p = 0; p < with.Covered.size(); ++p)
  {
    for (int c = 0; c < 3; ++c)
    {
      with.Covered[p] = with.Covered[p] || without.Values[3 * p + c] != without.Values[c];
    }
  }
  return with;
}

double RelativeL2(const Frame& a, const Frame& reference)
{
  if (a.Values.size() != reference.Values.size() || a.Values.empty())
  {
    ADD_FAILURE() << "frames of " << a.Values.size() << " and " << reference.Values.size()
                  << " values cannot be compared";
    return std::numeric_limits<double>::infinity();
  }
  double error = 0.0, norm = 0.0;
  for (size_t k = 0; k < a.Values.size(); ++k)
  {
    const double d = a.Values[k] - reference.Values[k];
    error += d * d;
    norm += reference.Values[k] * reference.Values[k];
  }
  return std::sqrt(error / std::max(norm, 1e-30));
}

// The bloom term's step between pixels k - 1 and k of line l (a row, or a column with
// `columns`), channel c; negative where a prop covers either pixel.
double Step(const Frame& f, int l, int k, int c, bool columns)
{
  const int i = columns ? l : k, j = columns ? k : l;
  const int i0 = columns ? i : i - 1, j0 = columns ? j - 1 : j;
  if (f.Covered[j * f.Width + i] || f.Covered[j0 * f.Width + i0])
  {
    return -1.0;
  }
  return std::abs(f.At(i, j, c) - f.At(i0, j0, c));
}

// The largest amount by which a step of the bloom term across a tile edge (every `tile[0]`
// columns and `tile[1]` rows) exceeds the larger of the steps beside it on the same line, one
// pixel either side: a glow cut at the edge jumps there, a smooth glow does not.
double Seam(const Frame& f, const int tile[2])
{
  double seam = 0.0;
  for (int columns = 0; columns < 2; ++columns)
  {
    const int lines = columns ? f.Width : f.Height;
    const int length = columns ? f.Height : f.Width;
    for (int k = tile[columns]; k + 1 < length; k += tile[columns])
    {
      for (int l = 0; l < lines; ++l)
      {
        for (int c = 0; c < 3; ++c)
        {
          const double across = Step(f, l, k, c, columns);
          const double beside =
            std::max(Step(f, l, k - 1, c, columns), Step(f, l, k + 1, c, columns));
          if (across >= 0.0 && beside >= 0.0)
          {
            seam = std::max(seam, across - beside);
          }
        }
      }
    }
  }
  return seam;
}
}

//------------------------------------------------------------------------------
// 2x and 4x screenshots of a 160 x 120 window against a 320 x 240 and a 640 x 480 window.
TEST(RenderingBloomPassTiles, AScreenshotInTilesIsTheLargerWindowsFrame)
{
  const int w = 160, h = 120;
  for (int scale : { 2, 4 })
  {
    SCOPED_TRACE(scale);
    const Frame reference = BloomTerm(w * scale, h * scale, 1, true);
    const Frame tiled = BloomTerm(w, h, scale, true);
    const Frame alone = BloomTerm(w, h, scale, false);
    ASSERT_EQ(tiled.Values.size(), reference.Values.size());
    const double seamless = RelativeL2(tiled, reference);
    const double cut = RelativeL2(alone, reference);
    std::printf("scale %d: bloom term %.2e relative L2 off the larger window's (%.4f with each "
                "tile alone)\n",
      scale, seamless, cut);
    EXPECT_LT(seamless, 1e-3); // the frame's to 8-bit rounding
    EXPECT_GT(cut, 0.2);       // the test can fail: tiles that bloom alone are far off
    // A step across a tile edge beyond its neighbours': no larger than the larger window's
    // own at the same places (a steep glow can sit on an edge), to 8-bit rounding.
    const int tile[2] = { w, h };
    const double own = Seam(reference, tile);
    std::printf("  seam %g levels (%g alone, %g in the larger window)\n", Seam(tiled, tile),
      Seam(alone, tile), own);
    EXPECT_LE(Seam(tiled, tile), own + 1.0);
    EXPECT_GT(Seam(alone, tile), own + 8.0);
  }
}

//------------------------------------------------------------------------------
// Two renderers side by side (a dark and a light background), each with its pass: each
// renderer's frame is its viewport's part of the larger frame, wherever the tiles cut it.
TEST(RenderingBloomPassTiles, ViewportsSideBySideTileAsTheirFrames)
{
  const int w = 240, h = 100, scale = 3;
  const Frame reference = BloomTerm(w * scale, h * scale, 1, true, 2);
  const Frame tiled = BloomTerm(w, h, scale, true, 2);
  const Frame alone = BloomTerm(w, h, scale, false, 2);
  const double seamless = RelativeL2(tiled, reference);
  std::printf("two viewports, scale 3: %.2e relative L2 (%.4f with each tile alone)\n", seamless,
    RelativeL2(alone, reference));
  EXPECT_LT(seamless, 1e-3);
  EXPECT_GT(RelativeL2(alone, reference), 0.2);
}

//------------------------------------------------------------------------------
// The guard band: none untiled; in a tile, the samples the frame's bloom reads, cut at the
// frame's edges (a corner tile has a band on two sides only).
TEST(RenderingBloomPassTiles, TheGuardBandIsWhatTheTilesGlowReads)
{
  vtkNew<vtkBloomPass> pass;
  Render(160, 120, 1, true, true, 1, pass);
  int band[2];
  pass->GetLastFrame()->GetTileGuardBand(band);
  EXPECT_EQ(band[0], 0);
  EXPECT_EQ(band[1], 0);
  // The last tile vtkWindowToImageFilter renders is the top right one.
  Render(160, 120, 2, true, true, 1, pass);
  pass->GetLastFrame()->GetTileGuardBand(band);
  EXPECT_GT(band[0], 8);
  EXPECT_GT(band[1], 8);
  EXPECT_LE(band[0], 160);
  EXPECT_LE(band[1], 120);
}

//------------------------------------------------------------------------------
// A delegate that renders through the renderer, as ParaView's does: the renderer culled its
// props against the tile, and sets the viewport from its tiled size.
TEST(RenderingBloomPassTiles, ADelegatevtkBloomPassThroughRendererTilesAsTheFrame)
{
  const int w = 160, h = 120, scale = 2;
  const Frame reference = BloomTerm(w * scale, h * scale, 1, true, 1, true);
  const Frame tiled = BloomTerm(w, h, scale, true, 1, true);
  const double seamless = RelativeL2(tiled, reference);
  std::printf("through the renderer, scale 2: %.4f relative L2\n", seamless);
  EXPECT_LT(seamless, 0.01);
}

//------------------------------------------------------------------------------
namespace
{
double LargestDifference(const Frame& a, const Frame& b)
{
  double largest = a.Values.size() == b.Values.size() ? 0.0 : 1e30;
  for (size_t k = 0; k < a.Values.size() && k < b.Values.size(); ++k)
  {
    largest = std::max(largest, std::abs(a.Values[k] - b.Values[k]));
  }
  return largest;
}

}

// The kept frame is protected in vtkBloomPass, for a subclass: this one makes it public as
// ParaView's vtkPVBloomPass does.
class vtkKeepingBloomPass : public vtkBloomPass
{
public:
  static vtkKeepingBloomPass* New();
  vtkTypeMacro(vtkKeepingBloomPass, vtkBloomPass);
  using vtkBloomPass::GetKeptFrameMode;
  using vtkBloomPass::GetKeptFrameSize;
  using vtkBloomPass::KEPT_FRAME_KEEP;
  using vtkBloomPass::KEPT_FRAME_OFF;
  using vtkBloomPass::KEPT_FRAME_SERVE;
  using vtkBloomPass::ReleaseKeptFrame;
  using vtkBloomPass::SetKeptFrameMode;
};
vtkStandardNewMacro(vtkKeepingBloomPass);

//------------------------------------------------------------------------------
// ParaView's way under IceT (vtkPVBloomRenderView), where a tile cannot have a guard band: the
// frame rendered whole at the window resized to it and kept (KEPT_FRAME_KEEP), then the tiles
// at the window's size served from it (KEPT_FRAME_SERVE), with SeamlessTiles off as under IceT.
// The tiled frame is the whole one, byte for byte; served from a kept frame of another size, a
// tile blooms alone (and says so): the check can fail.
TEST(RenderingBloomPassTiles, TilesServedFromAKeptFrameAreThatFrame)
{
  const int w = 160, h = 120;
  for (int scale : { 2, 3 })
  {
    SCOPED_TRACE(scale);
    vtkNew<vtkRenderWindow> window;
    window->SetOffScreenRendering(1);
    window->SetMultiSamples(0);
    vtkNew<vtkRenderer> renderer;
    const double dark[3] = { 0.05, 0.05, 0.08 };
    Populate(renderer, dark);
    vtkNew<vtkKeepingBloomPass> pass;
    vtkNew<vtkRenderStepsPass> steps;
    pass->SetDelegatePass(steps);
    pass->SetSeamlessTiles(false);
    renderer->SetPass(pass);
    window->AddRenderer(renderer);

    window->SetSize(w * scale, h * scale);
    pass->SetKeptFrameMode(vtkKeepingBloomPass::KEPT_FRAME_KEEP);
    window->Render();
    const Frame whole = Grab(window, 1);
    int kept[2];
    pass->GetKeptFrameSize(kept);
    EXPECT_EQ(kept[0], w * scale);
    EXPECT_EQ(kept[1], h * scale);

    window->SetSize(w, h);
    pass->SetKeptFrameMode(vtkKeepingBloomPass::KEPT_FRAME_SERVE);
    const Frame served = Grab(window, scale);
    EXPECT_TRUE(pass->GetLastFrame()->GetTileFromKeptFrame());
    const double off = LargestDifference(served, whole);
    std::printf("scale %d: tiles served from the kept frame, %g levels off it\n", scale, off);
    EXPECT_EQ(off, 0.0);

    // A frame of another size kept: the tiles bloom alone, and the pass says so once.
    vtkNew<vtkBloomTest::EventCounter> warnings;
    pass->AddObserver(vtkCommand::WarningEvent, warnings);
    window->SetSize(w + 1, h);
    const Frame alone = Grab(window, scale);
    EXPECT_EQ(alone.Width, (w + 1) * scale);
    EXPECT_FALSE(pass->GetLastFrame()->GetTileFromKeptFrame());
    EXPECT_EQ(warnings->Count, 1);
    pass->ReleaseKeptFrame();
    pass->GetKeptFrameSize(kept);
    EXPECT_EQ(kept[0], 0);
    pass->ReleaseGraphicsResources(window);
  }
}

//------------------------------------------------------------------------------
TEST(RenderingBloomPassTiles, AnUnknownKeptFrameModeIsRefused)
{
  vtkNew<vtkKeepingBloomPass> pass;
  vtkNew<vtkBloomTest::EventCounter> errors;
  pass->AddObserver(vtkCommand::ErrorEvent, errors);
  pass->SetKeptFrameMode(3);
  pass->SetKeptFrameMode(-1);
  EXPECT_EQ(errors->Count, 2);
  EXPECT_EQ(pass->GetKeptFrameMode(), vtkKeepingBloomPass::KEPT_FRAME_OFF);
}
