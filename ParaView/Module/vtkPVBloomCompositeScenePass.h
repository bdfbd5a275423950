// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkPVBloomCompositeScenePass
 * @brief   The render pass IceT runs on every rank when the bloom view composites float colour.
 *
 * vtkIceTCompositePass composites 8-bit colour read back from whatever its render pass drew,
 * so under MPI a bloom on the composited image sees HDR values clamped to [0, 1]. Its one
 * float path (SetEnableFloatValuePass, ICET_IMAGE_COLOR_RGBA_FLOAT) reads colour and depth
 * with vtkValuePass::GetFloatImageData from a vtkValuePass's RGBA32F framebuffer, and accepts
 * no other pass (vtkIceTCompositePass::Draw, ParaView 5.11 and 6.1). This pass is that
 * vtkValuePass in name only: it binds the value pass's float framebuffer, clears it as IceT
 * clears its own (transparent black, depth 1), and renders its delegate (ParaView's default
 * pass) there with the props' own colours, unclamped. None of vtkValuePass's shader
 * replacements apply, because this pass never registers itself with the props (no PreRender).
 *
 * vtkPVBloomRenderView sets it as the IceT render pass on every rank while bloom is on; the
 * composited float image reaches the bloom on the displaying rank through vtkPVBloomPass.
 */
#ifndef vtkPVBloomCompositeScenePass_h
#define vtkPVBloomCompositeScenePass_h

#include "vtkParaViewBloomModule.h" // For export macro
#include "vtkValuePass.h"

class vtkRenderPass;

class VTKPARAVIEWBLOOM_EXPORT vtkPVBloomCompositeScenePass : public vtkValuePass
{
public:
  static vtkPVBloomCompositeScenePass* New();
  vtkTypeMacro(vtkPVBloomCompositeScenePass, vtkValuePass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Render the delegate into the float framebuffer that IceT reads.
  void Render(const vtkRenderState* s) override;

  void ReleaseGraphicsResources(vtkWindow* window) override;

protected:
  vtkPVBloomCompositeScenePass();
  ~vtkPVBloomCompositeScenePass() override;

  vtkRenderPass* Delegate;

private:
  vtkPVBloomCompositeScenePass(const vtkPVBloomCompositeScenePass&) = delete;
  void operator=(const vtkPVBloomCompositeScenePass&) = delete;
};

#endif
