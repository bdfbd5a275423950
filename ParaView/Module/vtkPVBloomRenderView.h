// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkPVBloomRenderView
 * @brief   ParaView's render view with vtkBloomPass applied to the composited image.
 *
 * The view puts vtkBloomPass in the image-processing slot of its vtkPVSynchronizedRenderer,
 * the slot ParaView's own tone mapping and vtkPVRenderViewWithEDL use. Where that slot sits
 * is what makes the bloom correct in parallel:
 *
 * - Serial (builtin, pvpython, pvbatch with one rank): the pass's delegate is the camera pass,
 *   so the scene renders straight into the pass's float target and HDR values above 1 bloom.
 * - Parallel (pvbatch or pvserver with N > 1 ranks, through vtkIceTSynchronizedRenderers):
 *   the pass's delegate is the camera pass around vtkIceTCompositePass, which renders each
 *   rank's geometry, composites all ranks, and pastes the composited image into the pass's
 *   target. The bloom therefore runs on the whole composited image, never on one rank's
 *   partial image, so there are no seams at the ranks' boundaries. It runs on the rank that
 *   displays the image (rank 0). Tile displays are refused: the view renders without bloom
 *   there, with one warning, since each display would bloom its tile alone.
 * - HDR under MPI: IceT composites 8-bit colour, which would clamp the scene to [0, 1]. In
 *   pvbatch and pvserver (CompositeFloatColor on, the default) every rank renders through
 *   vtkPVBloomCompositeScenePass into a float target, IceT composites RGBA32F, and
 *   vtkPVBloomPass blooms that float image, over the renderer's single background colour (a
 *   server's: over transparent black, which its client blends over its own background): the
 *   bloom under MPI is the serial one. IceT then leaves no 8-bit image; a server's root sends
 *   its client the frame the bloom wrote instead (a capture relay in the client-server
 *   synchronizer, which still drives IceT). An interactive render with an image reduction
 *   factor composites float colour at the reduced size, enlarged to the frame before the bloom
 *   (vtkPVBloomPass); selection renders keep the 8-bit composite.
 *
 * Screenshots larger than the view render in tiles; where this process renders the whole scene
 * (no IceT), each tile blooms with the whole frame's chain and a guard band
 * (vtkBloomPass::SeamlessTiles), and the renderer culls nothing while the window is tiled, so
 * the screenshot has no seams. Under IceT (several ranks) IceT composites the window's size, one
 * tile at a time, so a tile cannot have a guard band: at the first
 * tile every rank renders the whole frame once, at the window resized to it, and the root keeps
 * its bloomed frame; each tile then writes its part of it (vtkPVBloomPass::SetKeptFrameMode). A
 * parallel server does the same, with its client's last camera (see RenderWholeFrame).
 *
 * With ParaView's tone mapping on (UseToneMapping), the tone mapping pass stays outermost and
 * bloom becomes its delegate: bloom in linear HDR, then tone mapping. During a selection
 * render the view leaves the slot empty, as ParaView does.
 *
 * The pass's vtkBloomParameters are SetBloomPreset ("custom" or a preset name) over the
 * hand-set parameters of SetBloomCustomParameters, resolved as the Bloom filter resolves them
 * (a vtkPVImageBloom used for that only; it never executes).
 */

#ifndef vtkPVBloomRenderView_h
#define vtkPVBloomRenderView_h

#include "vtkCullerCollection.h"          // For the cullers kept aside while tiled
#include "vtkNew.h"                       // For the pass and its parameters
#include "vtkPVBloomCompositeScenePass.h" // For the float composite
#include "vtkPVBloomPass.h"               // For the pass
#include "vtkPVRenderView.h"
#include "vtkParaViewBloomModule.h" // For export macro
#include "vtkSmartPointer.h"        // For the server's capture relay

class vtkBloomParameters;
class vtkPVImageBloom;
class vtkSynchronizedRenderers;

class VTKPARAVIEWBLOOM_EXPORT vtkPVBloomRenderView : public vtkPVRenderView
{
public:
  static vtkPVBloomRenderView* New();
  vtkTypeMacro(vtkPVBloomRenderView, vtkPVRenderView);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Bloom on (default) or off; off, the view renders as ParaView's render view.
  void SetUseBloom(bool use);
  vtkGetMacro(UseBloom, bool);
  ///@}

  ///@{
  /// "custom" (default) or a name of vtkBloomParameters::GetPresetNames().
  void SetBloomPreset(const char* name);
  const char* GetBloomPreset();
  ///@}

  /// The hand-set parameters (the plugin's BloomParameters sub-proxy).
  void SetBloomCustomParameters(vtkBloomParameters* parameters);

  ///@{
  /// Precision of the pass's targets: 16 (half floats, default) or 32 (floats).
  void SetBloomFloatPrecision(int bits);
  int GetBloomFloatPrecision();

  /// Whether the view's background blooms like a surface (vtkBloomPass::BloomBackground).
  void SetBloomBackground(bool bloom);
  bool GetBloomBackground();
  ///@}

  ///@{
  /// Composite float colour through IceT in pvbatch, so that HDR values bloom under MPI as in
  /// serial (default on). See the class documentation for where it applies.
  vtkSetMacro(CompositeFloatColor, bool);
  vtkGetMacro(CompositeFloatColor, bool);
  ///@}

  /// Whether the last render bloomed the float image IceT composited (vtkPVBloomPass).
  bool GetBloomLastSceneWasComposited();

  /// The pass, for tests and scripts that read its statistics.
  vtkPVBloomPass* GetBloomPass() { return this->BloomPass; }

protected:
  vtkPVBloomRenderView();
  ~vtkPVBloomRenderView() override;

  /// Insert or remove the pass before each render on a process that renders.
  void AboutToRenderOnLocalProcess(bool interactive) override;

  ///@{
  /**
   * A screenshot in tiles under IceT (TilesFromWholeFrame): at the first tile every rank
   * renders the whole frame first, at the window resized to it (RenderWholeFrame), and the
   * root's pass keeps it; the tiles are served from it (vtkPVBloomPass::SetKeptFrameMode). A
   * server's root renders it without its client (RenderWithoutClient), with the client's last
   * camera, and checks that camera when the first tile's arrives (CheckFirstTileCamera).
   */
  void Render(bool interactive, bool skip_rendering) override;
  void RenderWholeFrame(bool interactive);
  void RenderWithoutClient(bool interactive);
  void CheckFirstTileCamera();
  bool WithoutClient = false;   ///< the render under way leaves the client out
  bool CheckTileCamera = false; ///< the next render is a server's first tile
  double ExpectedTileCamera[4] = { 0.0, 0.0, 0.0, 0.0 }; ///< centre x, y, angle, parallel scale
  ///@}

  /// Whether this process shows the image that the bloom must process.
  bool LocalProcessDisplaysImage();
  /// FXAA once, as in the view without bloom (see the implementation).
  void AvoidSecondFXAA();
  /// No culling while a screenshot renders in tiles, so that each tile's guard band shows
  /// every prop (see the implementation); the cullers come back afterwards.
  void CullWholeFrame(bool bloom);
  vtkNew<vtkCullerCollection> TileCullers;

  /// Whether the coming render is a tile of a screenshot larger than the view, under IceT.
  bool TiledInParallel();
  /// Whether such tiles are served from a whole frame here (see Render).
  bool TilesFromWholeFrame();
  /// On every rank: IceT's render pass and colour format for the coming render.
  void UpdateFloatComposite();
  /// A server's root sends its client the bloomed frame, not IceT's 8-bit composite, while
  /// IceT composites float colour (`icet` non-null); see the implementation.
  void SendBloomedFrame(vtkSynchronizedRenderers* icet);
  vtkSmartPointer<vtkSynchronizedRenderers> FrameCapture;

  bool UseBloom = true;
  bool CompositeFloatColor = true;
  bool TileDisplayRefused = false;     ///< the tile-display warning, said once
  bool TiledScreenshotRefused = false; ///< a tiled screenshot under MPI refused, said once
  vtkNew<vtkPVBloomPass> BloomPass;
  vtkNew<vtkPVBloomCompositeScenePass> CompositeScenePass;
  vtkNew<vtkPVImageBloom> BloomPresetResolver;

private:
  vtkPVBloomRenderView(const vtkPVBloomRenderView&) = delete;
  void operator=(const vtkPVBloomRenderView&) = delete;
};

#endif
