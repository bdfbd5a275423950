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
  // the composite goes over it instead (vtkBloomPassChainRunner::CompositeOver).
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
  vtkBloomPassResources& resources, vtkRenderer* renderer, int width, int height)
{
  vtkOpenGLRenderWindow* context = resources.Context;
  vtkBloomPassTarget& target = resources.Background;
  target.Allocate(context, width, height, resources.Format);
  vtkOpenGLState* state = context->GetState();
  state->PushFramebufferBindings();
  target.FBO->Bind();
  target.FBO->ActivateDrawBuffer(0);
  state->vtkglViewport(0, 0, width, height);
  state->vtkglScissor(0, 0, width, height);
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
  float* rgba = static_cast<float*>(scene->GetScalarPointer());
  const float* behind = mode == vtkBloomPassResources::BACKGROUND_TEXTURE
    ? static_cast<const float*>(drawn->GetScalarPointer())
    : resources.BackgroundColor;
  const int step = mode == vtkBloomPassResources::BACKGROUND_TEXTURE ? 4 : 0;
  for (vtkIdType p = 0; p < scene->GetNumberOfPoints(); ++p, rgba += 4, behind += step)
  {
    const float uncovered = std::max(1.0f - std::min(rgba[3], 1.0f), 0.0f);
    for (int c = 0; c < 4; ++c)
    {
      rgba[c] += uncovered * behind[c];
    }
  }
}
