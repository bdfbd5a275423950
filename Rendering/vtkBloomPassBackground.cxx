// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// The renderer's background kept out of the bloom (see vtkBloomPassBackground.h).
#include "vtkBloomPassBackground.h"

#include "vtkBloomPassResources.h"
#include "vtkBloomVTKCompat.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkRenderer.h"

#include <algorithm>

//------------------------------------------------------------------------------
vtkBloomPassHiddenBackground::vtkBloomPassHiddenBackground(vtkRenderer* renderer, bool hide)
  : Renderer(renderer)
  , Hidden(hide)
{
  renderer->GetBackground(this->Color);
  renderer->GetBackground2(this->Color2);
  this->Alpha = renderer->GetBackgroundAlpha();
  this->Gradient = renderer->GetGradientBackground();
  this->Textured = renderer->GetTexturedBackground();
  if (hide)
  {
    renderer->SetBackground(0.0, 0.0, 0.0);
    renderer->SetBackgroundAlpha(0.0);
    renderer->SetGradientBackground(false);
    renderer->SetTexturedBackground(false);
  }
}

//------------------------------------------------------------------------------
vtkBloomPassHiddenBackground::~vtkBloomPassHiddenBackground()
{
  if (this->Hidden)
  {
    this->Renderer->SetBackground(this->Color);
    this->Renderer->SetBackground2(this->Color2);
    this->Renderer->SetBackgroundAlpha(this->Alpha);
    this->Renderer->SetGradientBackground(this->Gradient);
    this->Renderer->SetTexturedBackground(this->Textured);
  }
}

//------------------------------------------------------------------------------
void vtkBloomPassBackground::Plan(
  vtkBloomPassResources& resources, vtkRenderer* renderer, bool bloomBackground)
{
  // A layer drawn over others clears nothing: what lies below it is not its background, and
  // the composite goes over it instead (vtkBloomPassChainRunner::Output::Over).
  if (bloomBackground || renderer->Transparent())
  {
    resources.BackgroundMode = vtkBloomPassResources::BACKGROUND_IN_SCENE;
    resources.Background.Release(resources.Context);
    return;
  }
  const bool drawn = renderer->GetGradientBackground() ||
    (renderer->GetTexturedBackground() && renderer->GetBackgroundTexture());
  resources.BackgroundMode =
    drawn ? vtkBloomPassResources::BACKGROUND_TEXTURE : vtkBloomPassResources::BACKGROUND_COLOR;
  double rgb[3];
  renderer->GetBackground(rgb);
  std::copy(rgb, rgb + 3, resources.BackgroundColor);
  resources.BackgroundColor[3] = static_cast<float>(renderer->GetBackgroundAlpha());
  if (!drawn)
  {
    resources.Background.Release(resources.Context);
  }
}

//------------------------------------------------------------------------------
void vtkBloomPassBackground::Draw(
  vtkBloomPassResources& resources, vtkRenderer* renderer, int x, int y, int width, int height)
{
  vtkOpenGLRenderWindow* context = resources.Context;
  vtkBloomPassTarget& target = resources.Background;
  x = std::max(x, 0);
  y = std::max(y, 0);
  target.Allocate(context, x + width, y + height, resources.Format);
  resources.BackgroundOrigin[0] = x;
  resources.BackgroundOrigin[1] = y;
  vtkOpenGLState* state = context->GetState();
  state->PushFramebufferBindings();
  target.FBO->Bind();
  target.FBO->ActivateDrawBuffer(0);
  state->vtkglViewport(x, y, width, height);
  state->vtkglScissor(x, y, width, height);
  // The renderer's own drawing of its gradient or texture, as its camera pass would clear.
  renderer->Clear();
  state->PopFramebufferBindings();
}

//------------------------------------------------------------------------------
void vtkBloomPassBackground::PutOver(vtkBloomPassResources& resources, vtkImageData* scene)
{
  const int mode = resources.BackgroundMode;
  if (mode == vtkBloomPassResources::BACKGROUND_IN_SCENE)
  {
    return;
  }
  vtkNew<vtkImageData> drawn;
  if (mode == vtkBloomPassResources::BACKGROUND_TEXTURE &&
    !resources.Background.Read(resources.Context, drawn))
  {
    return;
  }
  const bool texture = mode == vtkBloomPassResources::BACKGROUND_TEXTURE;
  int size[3];
  scene->GetDimensions(size);
  float* rgba = static_cast<float*>(scene->GetScalarPointer());
  for (int j = 0; j < size[1]; ++j)
  {
    // The background target holds the renderer's pixels at its window position.
    const float* behind = texture
      ? static_cast<const float*>(drawn->GetScalarPointer(
          resources.BackgroundOrigin[0], j + resources.BackgroundOrigin[1], 0))
      : resources.BackgroundColor;
    const int step = texture ? 4 : 0;
    for (int i = 0; i < size[0]; ++i, rgba += 4, behind += step)
    {
      const float uncovered = std::max(1.0f - std::min(rgba[3], 1.0f), 0.0f);
      for (int c = 0; c < 4; ++c)
      {
        rgba[c] += uncovered * behind[c];
      }
    }
  }
}
