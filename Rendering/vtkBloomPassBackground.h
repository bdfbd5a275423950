// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkBloomPassBackground.h
 * @brief  (private to vtkBloomPass) keeps the renderer's background out of the bloom: the scene
 *         renders over transparent black, and the composite puts it over the background.
 *
 * A background is not light. Where vtkBloomPass::BloomBackground is off (the default) and the
 * renderer clears its viewport (it is not a layer that draws over others), the delegate renders
 * the scene with the renderer's background hidden (transparent black, no gradient, no texture),
 * so that the bright pass sees the scene alone, premultiplied by its coverage. The composite
 * then puts the scene over the background as the renderer would have drawn it: a solid colour
 * as a uniform, a gradient or a texture drawn by the renderer itself (vtkRenderer::Clear) into
 * a target of its own. Since the colour is premultiplied, the scene over the background equals
 * the renderer's own render wherever nothing glows: at anti-aliased and translucent edges too.
 */

#ifndef vtkBloomPassBackground_h
#define vtkBloomPassBackground_h

class vtkBloomPassResources;
class vtkImageData;
class vtkRenderer;

/// While alive, `renderer` clears to transparent black with no gradient or texture (when
/// `hide` is true); its background settings are restored when it goes out of scope.
class vtkBloomPassHiddenBackground
{
public:
  vtkBloomPassHiddenBackground(vtkRenderer* renderer, bool hide);
  ~vtkBloomPassHiddenBackground();
  vtkBloomPassHiddenBackground(const vtkBloomPassHiddenBackground&) = delete;
  vtkBloomPassHiddenBackground& operator=(const vtkBloomPassHiddenBackground&) = delete;

private:
  vtkRenderer* Renderer;
  bool Hidden;
  double Color[3];
  double Color2[3];
  double Alpha;
  bool Gradient;
  bool Textured;
};

namespace vtkBloomPassBackground
{
/**
 * Decide where the composite finds `renderer`'s background (resources' BackgroundMode):
 * in the scene when `bloomBackground` is on or the renderer clears nothing (a layer), else a
 * solid colour, or for a gradient or textured background a target drawn by Draw().
 */
void Plan(vtkBloomPassResources& resources, vtkRenderer* renderer, bool bloomBackground);

/**
 * BACKGROUND_TEXTURE: draw `renderer`'s background into the resources' Background target, at
 * the renderer's place in its window, (x, y) to (x + width, y + height): VTK 9.3 and later
 * dither gradients by window position, so the target's pixels are the window's.
 */
void Draw(
  vtkBloomPassResources& resources, vtkRenderer* renderer, int x, int y, int width, int height);

/**
 * Put a float RGBA scene read back from the scene target (premultiplied, over transparent
 * black) over the background, as the composite does where nothing glows: S + (1 - a) B.
 * Nothing changes when the background is in the scene.
 */
void PutOver(vtkBloomPassResources& resources, vtkImageData* scene);
}

#endif
// VTK-HeaderTest-Exclude: vtkBloomPassBackground.h
