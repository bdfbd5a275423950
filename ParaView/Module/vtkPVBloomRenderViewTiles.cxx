// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// vtkPVBloomRenderView's screenshots in tiles under IceT: the whole frame rendered first, at the
// window resized to it, and the tiles served from it (see the class documentation and Render).
#include "vtkPVBloomRenderView.h"

#include "vtkCamera.h"
#include "vtkIceTSynchronizedRenderers.h"
#include "vtkPVSynchronizedRenderer.h"
#include "vtkProcessModule.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSynchronizedRenderers.h"

#include <algorithm>
#include <cmath>

namespace
{
/**
 * The camera of the first (lower left) tile of a frame `scale` times the window, as
 * vtkWindowToImageFilter sets it in a renderer that fills the window: window centre
 * + (1 - scale), view angle 2 atan(tan(angle / 2) / scale y), parallel scale / scale y. A
 * camera here is those four numbers: window centre x and y, view angle, parallel scale.
 */
struct vtkFirstTileCamera
{
  static void Get(vtkCamera* camera, double c[4])
  {
    camera->GetWindowCenter(c);
    c[2] = camera->GetViewAngle();
    c[3] = camera->GetParallelScale();
  }
  static void Set(vtkCamera* camera, const double c[4])
  {
    camera->SetWindowCenter(c[0], c[1]);
    camera->SetViewAngle(c[2]);
    camera->SetParallelScale(c[3]);
  }
  static double Angle(double degrees, double factor)
  {
    const double half = degrees * std::acos(-1.0) / 360.0;
    return std::atan(std::tan(half) * factor) * 360.0 / std::acos(-1.0);
  }
  /// The frame's camera to its first tile's.
  static void Do(const double frame[4], const int scale[2], double tile[4])
  {
    tile[0] = frame[0] + (1.0 - scale[0]);
    tile[1] = frame[1] + (1.0 - scale[1]);
    tile[2] = Angle(frame[2], 1.0 / scale[1]);
    tile[3] = frame[3] / scale[1];
  }
  /// The first tile's camera to the frame's.
  static void Undo(const double tile[4], const int scale[2], double frame[4])
  {
    frame[0] = tile[0] - (1.0 - scale[0]);
    frame[1] = tile[1] - (1.0 - scale[1]);
    frame[2] = Angle(tile[2], scale[1]);
    frame[3] = tile[3] * scale[1];
  }
};
}

//------------------------------------------------------------------------------
bool vtkPVBloomRenderView::TilesFromWholeFrame()
{
  // pvbatch, Catalyst and a parallel server (RenderWholeFrame says where each finds the whole
  // frame's camera). The view's renderer fills the window, as vtkWindowToImageFilter's camera
  // shift is undone here.
  const double* viewport = this->GetRenderer()->GetViewport();
  const int process = vtkProcessModule::GetProcessType();
  const bool batchOrServer = process == vtkProcessModule::PROCESS_BATCH ||
    process == vtkProcessModule::PROCESS_SERVER ||
    process == vtkProcessModule::PROCESS_RENDER_SERVER;
  return this->TiledInParallel() && batchOrServer && viewport[0] == 0.0 && viewport[1] == 0.0 &&
    viewport[2] == 1.0 && viewport[3] == 1.0;
}

//------------------------------------------------------------------------------
void vtkPVBloomRenderView::Render(bool interactive, bool skip_rendering)
{
  // Every rank takes the same branch: the window's tiling (ParaView sets it on every rank before
  // the render), the view's properties and the process type agree across ranks.
  const bool served = this->UseBloom && !interactive && !skip_rendering &&
    !this->GetMakingSelection() && this->TilesFromWholeFrame();
  double tile[4] = { 0.0, 0.0, 1.0, 1.0 };
  this->GetRenderWindow()->GetTileViewport(tile);
  if (served && tile[0] == 0.0 && tile[1] == 0.0)
  {
    this->RenderWholeFrame(interactive);
  }
  this->BloomPass->SetKeptFrameMode(
    served ? vtkPVBloomPass::KEPT_FRAME_SERVE : vtkPVBloomPass::KEPT_FRAME_OFF);
  this->Superclass::Render(interactive, skip_rendering);
  this->CheckFirstTileCamera();
  // The last tile (vtkWindowToImageFilter renders the top right one last), or any other render:
  // the kept frame goes.
  const bool last = tile[2] >= 1.0 - 1e-9 && tile[3] >= 1.0 - 1e-9;
  if (!skip_rendering && (!served || last))
  {
    this->BloomPass->ReleaseKeptFrame();
  }
}

//------------------------------------------------------------------------------
void vtkPVBloomRenderView::RenderWholeFrame(bool interactive)
{
  vtkRenderWindow* window = this->GetRenderWindow();
  int scale[2] = { 1, 1 };
  window->GetTileScale(scale);
  double tile[4];
  window->GetTileViewport(tile);
  const int size[2] = { window->GetActualSize()[0], window->GetActualSize()[1] };
  vtkCamera* camera = this->GetActiveCamera();
  double saved[4];
  vtkFirstTileCamera::Get(camera, saved);
  // A server's root renders with the camera its client sent with the last render: untiled,
  // since ParaView's screenshot renders the view once before its tiles (checked at the first
  // tile, when the tile's camera arrives). Elsewhere the camera is the first tile's, which
  // vtkWindowToImageFilter shifted and narrowed: undone here.
  vtkSynchronizedRenderers* client = this->SynchronizedRenderers->GetCSSynchronizer();
  double whole[4];
  std::copy(saved, saved + 4, whole);
  if (!client)
  {
    vtkFirstTileCamera::Undo(saved, scale, whole);
    vtkFirstTileCamera::Set(camera, whole);
  }
  vtkFirstTileCamera::Do(whole, scale, this->ExpectedTileCamera);
  this->CheckTileCamera = client != nullptr;
  window->SetTileScale(1, 1);
  window->SetTileViewport(0.0, 0.0, 1.0, 1.0);
  window->SetSize(size[0] * scale[0], size[1] * scale[1]);
  // The root keeps the frame its bloom writes (the composite, before FXAA and annotations);
  // IceT composites it in float, as a view of that size would be.
  this->BloomPass->SetKeptFrameMode(vtkPVBloomPass::KEPT_FRAME_KEEP);
  this->RenderWithoutClient(interactive);
  window->SetSize(size[0], size[1]);
  window->SetTileViewport(tile);
  window->SetTileScale(scale);
  vtkFirstTileCamera::Set(camera, saved);
}

//------------------------------------------------------------------------------
void vtkPVBloomRenderView::CheckFirstTileCamera()
{
  // A server's root: the first tile's camera has arrived from its client with the tile's
  // render; the whole frame was bloomed with the client's camera before it, which must be the
  // one that tile's is made from.
  if (!this->CheckTileCamera)
  {
    return;
  }
  this->CheckTileCamera = false;
  double tile[4];
  vtkFirstTileCamera::Get(this->GetActiveCamera(), tile);
  for (int k = 0; k < 4; ++k)
  {
    const double expected = this->ExpectedTileCamera[k];
    if (std::abs(tile[k] - expected) > 1e-6 * std::max(1.0, std::abs(expected)))
    {
      vtkWarningMacro(<< "This screenshot's tiles were rendered with another camera than the "
                      << "last render's, which the whole frame their bloom comes from had: "
                      << "render the view before saving a screenshot larger than it.");
      return;
    }
  }
}

//------------------------------------------------------------------------------
void vtkPVBloomRenderView::RenderWithoutClient(bool interactive)
{
  // A server's root: its client-server synchronizer would wait for a camera the client sends
  // only with its own renders (vtkSynchronizedRenderers::SlaveStartRender), and send it an
  // image it does not expect. vtkPVRenderView::Render turns the synchronizers on just before
  // AboutToRenderOnLocalProcess, which turns this one off again (WithoutClient): it then only
  // passes the render's start and end on to IceT's synchronizer, its capture delegate. The
  // background it would clear for IceT (the client draws it) is cleared here.
  vtkSynchronizedRenderers* client = this->SynchronizedRenderers->GetCSSynchronizer();
  vtkRenderer* renderer = this->GetRenderer();
  const bool clear = client && client->GetFixBackground();
  double background[3];
  renderer->GetBackground(background);
  const double alpha = renderer->GetBackgroundAlpha();
  const bool gradient = renderer->GetGradientBackground();
  const bool textured = renderer->GetTexturedBackground();
  if (clear)
  {
    renderer->SetBackground(0.0, 0.0, 0.0);
    renderer->SetBackgroundAlpha(0.0);
    renderer->SetGradientBackground(false);
    renderer->SetTexturedBackground(false);
  }
  this->WithoutClient = client != nullptr; // AboutToRenderOnLocalProcess turns it off
  this->Superclass::Render(interactive, false);
  this->WithoutClient = false;
  if (clear)
  {
    renderer->SetBackground(background);
    renderer->SetBackgroundAlpha(alpha);
    renderer->SetGradientBackground(gradient);
    renderer->SetTexturedBackground(textured);
  }
}
