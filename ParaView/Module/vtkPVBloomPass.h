// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkPVBloomPass
 * @brief   vtkBloomPass fed with the float colour that IceT composited from every rank.
 *
 * Under MPI, the bloom view's pass runs around ParaView's IceT composite. With
 * SetCompositePass set (vtkPVBloomRenderView does it while IceT composites float colour, see
 * vtkPVBloomCompositeScenePass), the scene the chain reads is the composited RGBA32F image,
 * blended over the view's background (SetCompositeBackground) as ParaView blends its 8-bit
 * composite: colour + (1 - alpha) * background. HDR values above 1
 * thus bloom under MPI as they do in serial; an interactive render's reduced composite (an image
 * reduction factor) is enlarged to the frame, as ParaView enlarges its 8-bit one. Without a
 * composite pass, or where IceT gave no float image on this process, it is vtkBloomPass.
 */
#ifndef vtkPVBloomPass_h
#define vtkPVBloomPass_h

#include "vtkBloomPass.h"
#include "vtkParaViewBloomModule.h" // For export macro
#include "vtkWeakPointer.h"         // For the composite pass

#include <vector> // For the upload buffer

class vtkIceTCompositePass;

class VTKPARAVIEWBLOOM_EXPORT vtkPVBloomPass : public vtkBloomPass
{
public:
  static vtkPVBloomPass* New();
  vtkTypeMacro(vtkPVBloomPass, vtkBloomPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The IceT pass whose float composite replaces the scene (nullptr: the scene as rendered).
  void SetCompositePass(vtkIceTCompositePass* pass);

  /// The background the composite goes over: the renderer's own, which ParaView replaces by
  /// transparent black while it composites (vtkSynchronizedRenderers' FixBackground).
  void SetCompositeBackground(const double rgb[3], double alpha);

  /// Whether the last render bloomed IceT's float composite.
  vtkGetMacro(LastSceneWasComposited, bool);

  ///@{
  /// The kept frame (vtkBloomPass::KeptFrameModes), through which the view serves each tile of
  /// a screenshot larger than the window from one bloomed frame (vtkPVBloomRenderView).
  using vtkBloomPass::GetKeptFrameMode;
  using vtkBloomPass::GetKeptFrameSize;
  using vtkBloomPass::KEPT_FRAME_KEEP;
  using vtkBloomPass::KEPT_FRAME_OFF;
  using vtkBloomPass::KEPT_FRAME_SERVE;
  using vtkBloomPass::ReleaseKeptFrame;
  using vtkBloomPass::SetKeptFrameMode;
  ///@}

protected:
  vtkPVBloomPass();
  ~vtkPVBloomPass() override;

  void SceneRendered(const vtkRenderState* s, vtkTextureObject* sceneColor) override;
  /// `image` (size[0] x size[1] RGBA) enlarged to width x height in Pixels, each pixel the
  /// sample under its centre; returns Pixels.
  const float* Enlarge(const float* image, const int size[2], int width, int height);

  vtkWeakPointer<vtkIceTCompositePass> CompositePass;
  bool LastSceneWasComposited = false;
  float CompositeBackground[4] = { 0.0f, 0.0f, 0.0f, 0.0f };
  std::vector<float> Pixels;

private:
  vtkPVBloomPass(const vtkPVBloomPass&) = delete;
  void operator=(const vtkPVBloomPass&) = delete;
};

#endif
