// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkBloomFrameReport
 * @brief   What vtkBloomPass's last frame did, read-only: vtkBloomPass::GetLastFrame().
 *
 * The pass writes it at the end of each Render() and ApplyToImage(); nothing a caller does
 * with it changes the pass. GPU times arrive frames later: GetLastFrame() takes those that have
 * arrived, without waiting, where the pass's chains are timed (GetChainMilliseconds).
 *
 * The scalar getters are defined in the library, not inline, so that a script without the
 * Python wrapping (ParaView's timing script, through ctypes) can call them.
 */

#ifndef vtkBloomFrameReport_h
#define vtkBloomFrameReport_h

#include "vtkObject.h"
#include "vtkRenderingBloomModule.h" // For export macro

class VTKRENDERINGBLOOM_EXPORT vtkBloomFrameReport : public vtkObject
{
public:
  static vtkBloomFrameReport* New();
  vtkTypeMacro(vtkBloomFrameReport, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The precision of the scene's targets: 16 or 32 (vtkBloomPass::SetFloatPrecision).
  int GetFloatPrecision() const;

  /**
   * The GPU passes the chain ran, the composite included (a pass may be drawn as several
   * rectangles: the operators' interiors and their borders). Where nothing passed the bright
   * pass, only the passes up to that test and the composite ran: 2 to 4 (the bright pass, the
   * bright region's reduction, the composite and its multisampled edges, the result's copy).
   */
  int GetNumberOfPasses() const;

  /// Those of GetNumberOfPasses() that ran as compute shaders.
  int GetComputePasses() const;

  /**
   * Whether the bloom chain was skipped, as vtkImageBloom::GetLastBloomSkipped: no level fits
   * the image, the effect is off (SkipDisabledEffects) or nothing passed the bright pass
   * (SkipEmptyBloom; on the GPU an occlusion query counts the bright pass's non-zero samples).
   * The output is then keep * scene, bit for bit as the chain would give.
   */
  bool GetBloomSkipped() const;

  /**
   * With RestrictToBrightRegion on: the bounding box of the bright pass's non-zero samples, in
   * samples of the first pyramid level, as x0 x1 y0 y1 (x1 and y1 past the end). All zero when
   * nothing was bright, when the region was not measured (RestrictToBrightRegion off, or a
   * frame between two measurements of a region that covered much of the chain) or when the
   * bloom was skipped otherwise.
   */
  vtkGetVector4Macro(BrightRegion, int);

  /// The samples the chain's passes (after the bright pass, before the composite) computed,
  /// over those the full chain computes: 1 unless restricted to the bright region.
  double GetChainCoverage() const;

  /// In PSF mode, the padded FFT grid (NX, NY; a split PSF: its tail's grid); (0, 0) when the
  /// frame did not run the convolution (pyramid mode, or PSF mode refused).
  vtkGetVector2Macro(PSFGrid, int);

  /// With EMISSION_EMITTERS, whether the emission was written in the scene's own render.
  bool GetEmissionInSceneRender() const;

  /// Whether the delegate's annotations were drawn over the bloom.
  bool GetAnnotationsOverBloom() const;

  /// The guard band added to the renderer's tile, in samples along x and y (0 untiled); the
  /// scene and emission read-backs hold the tile and its band.
  vtkGetVector2Macro(TileGuardBand, int);

  /// Whether the frame was a tile served from a kept frame (ParaView's vtkPVBloomPass).
  bool GetTileFromKeptFrame() const;

  /**
   * The GPU milliseconds of the bloom in the latest frame whose GPU timestamps have arrived:
   * from the bright pass to the end of the composite, the scene's render excluded; negative
   * until one has. After a frame has completed (glFinish), it is that frame's. For benchmarks:
   * the chains are timed (two GL timestamp queries each) only where the private
   * vtkBloomPassTesting::SetTimeChains turned it on, and while the bright region's cost is being
   * learned; a frame that nobody times issues no query.
   */
  double GetChainMilliseconds() const;

  /**
   * What the content-aware chain has measured of its own cost: the average GPU milliseconds of
   * a chain, from its start to the end of the composite, with the bright region measured (its
   * read-back's wait included) and with the full chain; negative until timed. Where the full
   * chain is the cheaper, the region is not measured again on this context (docs/rendering.md).
   */
  double GetRegionCost() const;
  double GetFullCost() const;

protected:
  vtkBloomFrameReport() = default;
  ~vtkBloomFrameReport() override = default;

private:
  vtkBloomFrameReport(const vtkBloomFrameReport&) = delete;
  void operator=(const vtkBloomFrameReport&) = delete;

  friend class vtkBloomPass; // the only writer
  int FloatPrecision = 16;
  int NumberOfPasses = 0;
  int ComputePasses = 0;
  bool BloomSkipped = false;
  int BrightRegion[4] = { 0, 0, 0, 0 };
  double ChainCoverage = 1.0;
  int PSFGrid[2] = { 0, 0 };
  bool EmissionInSceneRender = false;
  bool AnnotationsOverBloom = false;
  int TileGuardBand[2] = { 0, 0 };
  bool TileFromKeptFrame = false;
  double ChainMilliseconds = -1.0;
  double RegionCost = -1.0;
  double FullCost = -1.0;
};

#endif
