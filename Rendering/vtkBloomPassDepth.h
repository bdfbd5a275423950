// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkBloomPassDepth.h
 * @brief  (private to vtkBloomPass) writes the scene's depth where the frame is composited.
 *
 * The delegate renders the scene into the pass's own target, so the framebuffer the pass was
 * called with holds the composited colour and none of the scene's depth. What reads that depth
 * afterwards then sees an empty scene: the annotations drawn over the bloom (a label mapper that
 * hides the labels of occluded points reads the depth buffer), a pass around this one (depth of
 * field, eye-dome lighting), a renderer layered above. As vtkSSAOPass writes gl_FragDepth in its
 * final draw, Write() draws the scene's depth into the bound framebuffer, its colour untouched.
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

  void ReleaseGraphicsResources(vtkWindow* window);

private:
  std::unique_ptr<vtkOpenGLQuadHelper> Quad;
};

#endif
// VTK-HeaderTest-Exclude: vtkBloomPassDepth.h
