// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// The part of a tiled frame that vtkBloomPass renders (see vtkBloomPassTile.h).
#include "vtkBloomPassTile.h"

#include "vtkBloomParameters.h"
#include "vtkCamera.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkRenderer.h"
#include "vtkTransform.h"
#include "vtkWindow.h"

#include <algorithm>

//------------------------------------------------------------------------------
void vtkBloomPassTile::Locate(vtkRenderer* renderer, int w, int h)
{
  *this = vtkBloomPassTile();
  this->TileSize[0] = this->Size[0] = this->Frame[0] = w;
  this->TileSize[1] = this->Size[1] = this->Frame[1] = h;
  vtkWindow* window = renderer->GetVTKWindow();
  int scale[2] = { 1, 1 };
  if (window)
  {
    window->GetTileScale(scale);
  }
  if (scale[0] == 1 && scale[1] == 1)
  {
    return;
  }
  // vtkViewport::GetTiledSizeAndOrigin's pixels: the window's size times its tile scale (the
  // frame of all tiles, vtkWindow::GetSize), the tile and the renderer's viewport in it.
  const int* size = window->GetSize();
  const double* viewport = renderer->GetViewport();
  double tile[4];
  window->GetTileViewport(tile);
  for (int a = 0; a < 2; ++a)
  {
    const int first = static_cast<int>(viewport[a] * size[a] + 0.5);
    const int last = static_cast<int>(viewport[a + 2] * size[a] + 0.5);
    this->Frame[a] = last - first;
    this->Position[a] = static_cast<int>(std::max(viewport[a], tile[a]) * size[a] + 0.5) - first;
  }
  this->Tiled = this->Frame[0] != w || this->Frame[1] != h;
}

//------------------------------------------------------------------------------
void vtkBloomPassTile::Plan(const int first[2], const int last[2], int largest)
{
  if (!this->Tiled)
  {
    return;
  }
  for (int a = 0; a < 2; ++a)
  {
    const int tile0 = this->Position[a];
    const int tile1 = tile0 + this->TileSize[a];
    int lo = std::max(std::min(first[a], tile0), 0);
    int hi = std::min(std::max(last[a], tile1), this->Frame[a]);
    if (hi - lo > largest)
    {
      // The largest target the context has: the band is cut, evenly on both sides.
      this->Capped = true;
      const int room = std::max(largest - this->TileSize[a], 0);
      lo = std::max(lo, tile0 - room / 2);
      hi = std::min(hi, lo + largest);
    }
    this->Start[a] = lo;
    this->Size[a] = hi - lo;
    this->Inner[a] = tile0 - lo;
  }
}

//------------------------------------------------------------------------------
void vtkBloomPassTile::GetPart(int part[4]) const
{
  part[0] = this->Start[0];
  part[1] = this->Start[0] + this->Size[0];
  part[2] = this->Start[1];
  part[3] = this->Start[1] + this->Size[1];
}

//------------------------------------------------------------------------------
void vtkBloomPassTileFrame::Update(vtkBloomParameters* parameters, const int frame[2])
{
  if (parameters == this->Parameters && this->Time >= parameters->GetMTime() &&
    this->Chain.Width == frame[0] && this->Chain.Height == frame[1])
  {
    return;
  }
  this->Parameters = parameters;
  this->Time = parameters->GetMTime();
  this->Chain.Build(parameters, frame[0], frame[1]);
}

//------------------------------------------------------------------------------
vtkBloomPassTileCamera::vtkBloomPassTileCamera(vtkRenderer* renderer, const vtkBloomPassTile& tile)
{
  if (!tile.Tiled || (tile.Size[0] == tile.TileSize[0] && tile.Size[1] == tile.TileSize[1]))
  {
    return;
  }
  this->Camera = renderer->GetActiveCamera();
  this->Saved = this->Camera->GetUserTransform();
  // Normalized device coordinates of the tile to those of the part: x' = x w / W + (w + 2 i)
  // / W - 1 (i: where the tile starts in the part), in clip coordinates (times w_clip).
  vtkNew<vtkMatrix4x4> toPart;
  for (int a = 0; a < 2; ++a)
  {
    const double part = tile.Size[a];
    toPart->SetElement(a, a, tile.TileSize[a] / part);
    toPart->SetElement(a, 3, (tile.TileSize[a] + 2.0 * tile.Inner[a]) / part - 1.0);
  }
  vtkNew<vtkTransform> transform;
  transform->SetMatrix(toPart);
  if (this->Saved)
  {
    transform->Concatenate(this->Saved->GetMatrix()); // the user's, then the part's
  }
  this->Camera->SetUserTransform(transform);
}

//------------------------------------------------------------------------------
vtkBloomPassTileCamera::~vtkBloomPassTileCamera()
{
  if (this->Camera)
  {
    this->Camera->SetUserTransform(this->Saved);
  }
}
