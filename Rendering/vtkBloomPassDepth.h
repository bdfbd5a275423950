// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkBloomPassDepth.h
 * @brief  (private to vtkBloomPass) puts the scene's depth where the frame is composited.
 *
 * The delegate renders the scene into the pass's own float target, so the framebuffer the pass
 * was called with would hold the composited colour and none of the scene's depth. What reads
 * that depth afterwards would then see an empty scene: the annotations drawn over the bloom (a
 * label mapper that hides the labels of occluded points reads the depth buffer), a pass around
 * this one (depth of field, eye-dome lighting, ParaView's compositing), a picker, a renderer
 * layered above. Two ways, the first where it applies:
 * - Share(): the scene's render writes the called framebuffer's own depth buffer, attached to
 *   the pass's target in place of the target's depth for that render, as the plain frame would
 *   have written it. It costs nothing: no draw, no copy.
 * - Write(): a full-screen draw of the scene's depth texture into the bound framebuffer, its
 *   colour untouched, as vtkSSAOPass writes gl_FragDepth in its final draw. On a GPU whose
 *   fragment shading runs on part of the chip (an NVIDIA H200) that draw costs 0.56 ms at
 *   3840x2160 (docs/gpu.md): it is the fallback, where the depth buffers differ in size or
 *   samples (a renderer in part of the window, a tile with a guard band), or where the pass
 *   needs the scene's depth as a texture of its own (the emitters' second render).
 */

#ifndef vtkBloomPassDepth_h
#define vtkBloomPassDepth_h

#include <memory>

class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkTextureObject;
class vtkWindow;

class vtkBloomPassDepth
{
public:
  vtkBloomPassDepth();
  ~vtkBloomPassDepth();
  vtkBloomPassDepth(const vtkBloomPassDepth&) = delete;
  vtkBloomPassDepth& operator=(const vtkBloomPassDepth&) = delete;

  /**
   * Write `depth` (a depth texture of the scene) into the bound framebuffer's depth over the
   * viewport (x, y, width, height): the viewport's pixel (i, j) takes the texture's texel
   * (i + offset[0], j + offset[1]). Colour, blending and the depth test are as they were after.
   */
  void Write(vtkOpenGLRenderWindow* window, vtkTextureObject* depth, int x, int y, int width,
    int height, const int offset[2]);

  /**
   * Before the scene's render into the framebuffer object `target` (its GL name): where the
   * framebuffer `called` (the one the pass was called with, a framebuffer object) has a depth
   * buffer of the same size and samples as `target`'s, attach it to `target` in place of
   * `target`'s own until EndShare(). Returns whether it did; the window's depth then needs no
   * Write().
   */
  bool Share(unsigned int called, unsigned int target);

  /// After the scene's render: `target` gets its own depth back (nothing if Share() did not).
  void EndShare();

  void ReleaseGraphicsResources(vtkWindow* window);

private:
  /// A framebuffer's depth attachment, as glGetFramebufferAttachmentParameteriv gives it.
  struct Attachment
  {
    int Type = 0; ///< GL_NONE, GL_RENDERBUFFER or GL_TEXTURE
    unsigned int Name = 0;
    int Level = 0;
    int Size[3] = { 0, 0, 0 }; ///< width, height, samples
    bool Describe(unsigned int framebuffer);
    void AttachTo(unsigned int framebuffer) const;
  };

  std::unique_ptr<vtkOpenGLQuadHelper> Quad;
  unsigned int SharedTarget = 0; ///< the target whose depth Share() replaced, until EndShare()
  Attachment Own;                ///< that target's own depth
};

#endif
// VTK-HeaderTest-Exclude: vtkBloomPassDepth.h
