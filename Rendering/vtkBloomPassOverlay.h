/**
 * @file   vtkBloomPassOverlay.h
 * @brief  (private to vtkBloomPass) draws the delegate's annotations over the bloom instead of
 *         into the frame it blooms.
 *
 * Annotations are not light: text, scalar bars, corner annotations, legends, logos and 2D
 * widget representations are the props' overlay, which the delegate draws in its overlay step
 * (vtkOverlayPass). Before the delegate renders the scene, Detach() takes that step out of it
 * wherever it can be found: the OverlayPass of a vtkRenderStepsPass, or a vtkOverlayPass in a
 * vtkSequencePass, through the delegates of vtkCameraPass and of image-processing passes
 * (vtkSSAOPass, vtkToneMappingPass, ...). After the composite, Render() draws the detached steps
 * into the framebuffer the pass was called with, over the bloom, and puts them back. A delegate
 * with no overlay step of its own (ParaView's, whose annotations are drawn by a renderer of
 * their own above the bloom) has nothing to detach.
 */

#ifndef vtkBloomPassOverlay_h
#define vtkBloomPassOverlay_h

#include "vtkSmartPointer.h" // For the detached steps

#include <vector>

class vtkRenderPass;
class vtkRenderState;
class vtkRenderStepsPass;
class vtkSequencePass;

class vtkBloomPassOverlay
{
public:
  vtkBloomPassOverlay();
  ~vtkBloomPassOverlay();
  vtkBloomPassOverlay(const vtkBloomPassOverlay&) = delete;
  vtkBloomPassOverlay& operator=(const vtkBloomPassOverlay&) = delete;

  /// Take the overlay steps out of `delegate`; returns how many were found.
  int Detach(vtkRenderPass* delegate);

  /**
   * Render the detached steps for `s` into the bound framebuffer at the viewport
   * (x, y, width, height), over what it holds, then put them back. Returns the props rendered.
   */
  int Render(const vtkRenderState* s, int x, int y, int width, int height);

  /// Put the detached steps back without rendering them.
  void Restore();

private:
  void Collect(vtkRenderPass* pass, int depth);

  struct Slot
  {
    vtkRenderStepsPass* Steps = nullptr; ///< its OverlayPass, or
    vtkSequencePass* Sequence = nullptr; ///< item Index of its passes
    int Index = -1;
    vtkSmartPointer<vtkRenderPass> Pass; ///< the overlay step
  };
  std::vector<Slot> Slots;
  vtkSmartPointer<vtkSequencePass> Empty; ///< stands in for a step taken from a sequence
};

#endif
// VTK-HeaderTest-Exclude: vtkBloomPassOverlay.h
