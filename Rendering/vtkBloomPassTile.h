// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkBloomPassTile
 * @brief   The part of a tiled frame that vtkBloomPass renders: the tile and its guard band.
 *
 * vtkWindowToImageFilter with a scale, and ParaView's screenshots larger than their view, render
 * a frame larger than the window in tiles: the window's TileScale and TileViewport say which
 * part of the frame the coming render is, and each renderer's camera is shifted to that part.
 * A tile that bloomed alone would cut every glow at its edges, and its bloom would have the
 * sizes of a frame the tile's size. So, where the window is tiled, the pass renders the tile with
 * a guard band around it: the samples of the frame that the tile's bloom reads, found through
 * the frame's chain (vtkBloomChain::GetInputRange; in PSF mode, the PSF's radius), never past
 * the frame's edges. Its camera's projection is widened to the band for the scene's render
 * (vtkBloomPassTileCamera), its chain is the frame's chain cut to the band (vtkBloomChain::Cut:
 * the frame's levels and operators, row for row), and the composite writes the tile only. A
 * tiled image is then the frame's image to float rounding, and a screenshot has no seams.
 *
 * Untiled, the part is the renderer's viewport itself and nothing changes.
 */

#ifndef vtkBloomPassTile_h
#define vtkBloomPassTile_h

#include "vtkBloomChain.h"   // For the frame's chain
#include "vtkSmartPointer.h" // For the camera's transform
#include "vtkType.h"         // For vtkMTimeType

class vtkBloomParameters;
class vtkCamera;
class vtkHomogeneousTransform;
class vtkRenderer;

struct vtkBloomPassTile
{
  bool Tiled = false;
  int Frame[2] = { 0, 0 };    ///< the renderer's whole frame, over all tiles
  int TileSize[2] = { 0, 0 }; ///< the tile: the renderer's tiled size
  int Size[2] = { 0, 0 };     ///< the part rendered: the tile and its guard band
  int Inner[2] = { 0, 0 };    ///< where the tile starts in the part rendered
  bool Capped = false;        ///< the band was cut to the largest target the context allows

  /**
   * The tile of `renderer` (tiled size w x h): untiled, the part is the tile. Tiled, Frame and
   * where the tile lies in it; Plan() then sets the band.
   */
  void Locate(vtkRenderer* renderer, int w, int h);

  /**
   * The guard band: the samples [first[a], last[a]) of the frame that the tile's bloom reads
   * along x and y (cut to the frame), at most `largest` samples a side.
   */
  void Plan(const int first[2], const int last[2], int largest);

  /// Where the tile starts in the frame, and the part rendered (x0 x1 y0 y1 in the frame).
  const int* GetPosition() const { return this->Position; }
  void GetPart(int part[4]) const;

private:
  int Position[2] = { 0, 0 }; ///< where the tile starts in the frame
  int Start[2] = { 0, 0 };    ///< where the part starts in the frame
};

/**
 * The chain of a parameter set over a whole frame, remade when the parameters or the frame
 * change: the chain the tiles' chains are cut from, and what tells a tile's guard band.
 */
class vtkBloomPassTileFrame
{
public:
  void Update(vtkBloomParameters* parameters, const int frame[2]);
  vtkBloomChain Chain;

private:
  const vtkBloomParameters* Parameters = nullptr; // compared only
  vtkMTimeType Time = 0;
};

/**
 * For its lifetime, the renderer's active camera projects the part of vtkBloomPassTile: the
 * tile's projection, followed by the scale and shift in normalized device coordinates that put
 * the tile's pixels where the part has them (vtkCamera's user transform, which applies after
 * the projection). The viewport is the part's target (vtkCameraPass takes the viewport from
 * the render state's framebuffer). Nothing changes untiled.
 */
class vtkBloomPassTileCamera
{
public:
  vtkBloomPassTileCamera(vtkRenderer* renderer, const vtkBloomPassTile& tile);
  ~vtkBloomPassTileCamera();
  vtkBloomPassTileCamera(const vtkBloomPassTileCamera&) = delete;
  vtkBloomPassTileCamera& operator=(const vtkBloomPassTileCamera&) = delete;

private:
  vtkCamera* Camera = nullptr;
  vtkSmartPointer<vtkHomogeneousTransform> Saved;
};

#endif
// VTK-HeaderTest-Exclude: vtkBloomPassTile.h
