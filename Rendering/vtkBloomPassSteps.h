// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkBloomPassSteps.h
 * @brief  (private to vtkBloomPass) the steps of the delegate that the pass adjusts while it
 *         renders: its overlay, drawn over the bloom, and its translucency, drawn as the renderer
 *         draws it.
 *
 * The steps are found through the delegate: the OverlayPass and TranslucentPass of a
 * vtkRenderStepsPass, or a vtkOverlayPass in a vtkSequencePass, through the delegates of
 * vtkCameraPass and of image-processing passes (vtkSSAOPass, vtkToneMappingPass, ...).
 *
 * Overlay. Annotations are not light: text, scalar bars, corner annotations, legends, logos and
 * 2D widget representations are the props' overlay, which the delegate draws in its overlay step
 * (vtkOverlayPass). DetachOverlay() takes that step out before the scene renders, and
 * RenderOverlay() draws it after the composite, over the bloom, then puts it back. A delegate with
 * no overlay step of its own (ParaView's, whose annotations a renderer of their own draws above
 * the bloom) has nothing to detach.
 *
 * Translucency. vtkOpenGLRenderer draws translucent geometry through depth peeling
 * (UseDepthPeeling: dual depth peeling where supported) or order-independent transparency; a
 * vtkRenderStepsPass draws it with a plain vtkTranslucentPass, which blends in the props' order.
 * WrapTranslucency() wraps such a plain step as the renderer wraps its own while the scene renders
 * (with the renderer's peels and occlusion ratio), so that the bloomed frame's translucency is the
 * frame the renderer draws without a pass. A step the user set up otherwise is left as it is.
 *
 * Hidden lines. vtkOpenGLRenderer removes the hidden lines of wireframe actors
 * (UseHiddenLineRemoval) with a vtkHiddenLineRemovalPass in place of its opaque geometry; a
 * vtkRenderStepsPass's plain vtkOpaquePass draws every line. RemoveHiddenLines() puts the
 * renderer's step in its place while the scene renders.
 *
 * FXAA. The renderer's own FXAA runs inside its geometry step; RendererFXAAOff keeps it out of
 * the scene render.
 */

#ifndef vtkBloomPassSteps_h
#define vtkBloomPassSteps_h

#include "vtkSmartPointer.h" // For the detached steps

#include <vector>

class vtkHiddenLineRemovalPass;
class vtkRenderPass;
class vtkRenderState;
class vtkRenderer;
class vtkRenderStepsPass;
class vtkSequencePass;
class vtkTranslucentPass;
class vtkWindow;

class vtkBloomPassSteps
{
public:
  vtkBloomPassSteps();
  ~vtkBloomPassSteps();
  vtkBloomPassSteps(const vtkBloomPassSteps&) = delete;
  vtkBloomPassSteps& operator=(const vtkBloomPassSteps&) = delete;

  /// Take the overlay steps out of `delegate`; returns how many were found.
  int DetachOverlay(vtkRenderPass* delegate);

  /**
   * Render the detached overlay steps for `s` into the bound framebuffer at the viewport
   * (x, y, width, height), over what it holds, then put them back. Returns the props rendered.
   */
  int RenderOverlay(const vtkRenderState* s, int x, int y, int width, int height);

  /**
   * Where `s` has translucent geometry, wrap the first plain translucent step of `delegate` in
   * the renderer's depth peeling or order-independent transparency; returns which (none where
   * nothing was wrapped). Order-independent transparency's last blend leaves an alpha that is
   * not the scene's coverage (it multiplies the transmittance by its complement), so a scene
   * drawn with it cannot be put over its background afterwards.
   */
  enum Translucency
  {
    NO_TRANSLUCENCY,
    ORDER_INDEPENDENT,
    DEPTH_PEELING
  };
  Translucency WrapTranslucency(const vtkRenderState* s, vtkRenderPass* delegate);

  /**
   * Where the renderer removes hidden lines and `s` has a wireframe actor, draw the first plain
   * opaque step of `delegate` as the renderer draws its own opaque geometry then (a
   * vtkHiddenLineRemovalPass); true where it did.
   */
  bool RemoveHiddenLines(const vtkRenderState* s, vtkRenderPass* delegate);

  /**
   * The first image-processing pass among the delegate's steps (vtkSSAOPass, vtkToneMappingPass,
   * ...), or null: it processes the frame, background included, so that the background cannot
   * be put under the scene afterwards.
   */
  static vtkRenderPass* FindImageProcessing(vtkRenderPass* delegate);

  /**
   * The renderer's FXAA switched off while the delegate renders the scene, restored after. A
   * delegate that renders through the renderer (vtkDefaultPass, ParaView's vtkPVDefaultPass)
   * ends in vtkOpenGLRenderer::UpdateGeometry, which applies the renderer's FXAA to the
   * framebuffer it drew: the float scene, over the hidden background, through an 8-bit
   * texture, which clamped light to 1 before the bright pass and darkened edges over a light
   * background. The pass applies FXAA to the finished frame instead.
   */
  class RendererFXAAOff
  {
  public:
    explicit RendererFXAAOff(vtkRenderer* renderer);
    ~RendererFXAAOff();
    RendererFXAAOff(const RendererFXAAOff&) = delete;
    RendererFXAAOff& operator=(const RendererFXAAOff&) = delete;

  private:
    vtkRenderer* Renderer;
    bool UseFXAA;
  };

  /// Put every detached or wrapped step back.
  void Restore();

  /// Free the wrappers' textures and framebuffers.
  void ReleaseGraphicsResources(vtkWindow* window);

private:
  /// Calls `visit` on each pass reachable from `pass` (with its sequence and index, if any).
  template <typename Visit>
  static void Walk(
    vtkRenderPass* pass, vtkSequencePass* sequence, int index, int depth, const Visit& visit);

  /// The first vtkRenderStepsPass reachable from `delegate` whose step `get` is of the class
  /// `className` exactly (VTK's plain step), or null.
  static vtkRenderStepsPass* FindPlainStep(
    vtkRenderPass* delegate, vtkRenderPass* (vtkRenderStepsPass::*get)(), const char* className);

  struct Slot
  {
    vtkRenderStepsPass* Steps = nullptr; ///< its OverlayPass or TranslucentPass, or
    vtkSequencePass* Sequence = nullptr; ///< item Index of its passes
    int Index = -1;
    vtkSmartPointer<vtkRenderPass> Pass; ///< the original step
  };
  std::vector<Slot> Overlays;
  std::vector<Slot> Translucents;
  std::vector<Slot> Opaques;
  vtkSmartPointer<vtkHiddenLineRemovalPass> HiddenLines; ///< the renderer's opaque step with HLR
  vtkSmartPointer<vtkSequencePass> Empty; ///< stands in for an overlay taken from a sequence
  /// The renderer's kind of translucency around the first plain translucent step, kept while
  /// the kind (Peeling: depth peeling, else OIT) and the step stay the same.
  vtkSmartPointer<vtkRenderPass> Wrapper;
  vtkRenderPass* Wrapped = nullptr;
  bool Peeling = false;
};

#endif
// VTK-HeaderTest-Exclude: vtkBloomPassSteps.h
