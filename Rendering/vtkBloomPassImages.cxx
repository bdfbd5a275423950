// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// vtkBloomPass's image entry points: ApplyToImage (an image bloomed by the pass's chain,
// without a scene), the read-backs of the last render (scene, emission, result) and its
// per-pass profile.
#include "vtkBloomPassInternals.h"

#include "vtkDataArray.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPointData.h"
#include "vtkTextureObject.h"

#include <algorithm>
#include <vector>

namespace
{

// A scene read back from a render that wrote its emission in the alpha (an emitting fragment
// has alpha 1 + weight, vtkBloomPassEmission): the scene, with its alpha at most 1, or
// (`emission`) the emission, the colour times the weight.
void vtkBloomPassDecodeEmission(vtkImageData* image, bool emission)
{
  float* rgba = static_cast<float*>(image->GetScalarPointer());
  for (vtkIdType p = 0; p < image->GetNumberOfPoints(); ++p, rgba += 4)
  {
    const float weight = std::min(std::max(rgba[3] - 1.0f, 0.0f), 1.0f);
    for (int c = 0; emission && c < 3; ++c)
    {
      rgba[c] *= weight;
    }
    rgba[3] = emission ? weight : std::min(rgba[3], 1.0f);
  }
}
}

//------------------------------------------------------------------------------
bool vtkBloomPass::ApplyToImage(
  vtkOpenGLRenderWindow* window, vtkImageData* input, vtkImageData* output)
{
  if (!window || !input || !output)
  {
    vtkErrorMacro(<< "ApplyToImage needs a window, an input and an output.");
    return false;
  }
  vtkDataArray* scalars = input->GetPointData()->GetScalars();
  int dims[3];
  input->GetDimensions(dims);
  const int nc = scalars ? scalars->GetNumberOfComponents() : 0;
  if (!scalars || (input->GetScalarType() != VTK_FLOAT && input->GetScalarType() != VTK_DOUBLE) ||
    nc < 3 || nc > 4)
  {
    vtkErrorMacro(<< "ApplyToImage needs float or double scalars with 3 or 4 components.");
    return false;
  }
  if (dims[0] < 1 || dims[1] < 1 || dims[2] != 1)
  {
    vtkErrorMacro(<< "ApplyToImage needs a non-empty two-dimensional image.");
    return false;
  }
  window->Initialize();
  window->MakeCurrent();
  const int w = dims[0], h = dims[1];
  vtkOpenGLState* state = window->GetState();
  const vtkBloomPassSavedState saved(state);
  vtkInternals& in = *this->Internals;
  vtkBloomPassResources& res = in.Resources;
  // An image is not processed further: automatic precision is the half floats'. It is its
  // own frame, whatever the window's tiling.
  in.Tile = vtkBloomPassTile();
  std::fill(in.Output.Window, in.Output.Window + 4, 0);
  if (!in.Prepare(this, window, w, h, 0, false,
        this->FloatPrecision == FLOAT_AUTOMATIC ? FLOAT16 : this->FloatPrecision))
  {
    return false;
  }
  in.Output.GlowAlpha = false; // an image keeps its alpha, as vtkImageBloom's output does
  res.Result.Allocate(window, w, h, GL_RGBA32F);

  // Upload the image as the scene, in float RGBA (alpha 1 when there is none).
  std::vector<float> pixels(static_cast<size_t>(w) * h * 4);
  for (vtkIdType p = 0; p < static_cast<vtkIdType>(w) * h; ++p)
  {
    for (int c = 0; c < 4; ++c)
    {
      pixels[p * 4 + c] = c < nc ? static_cast<float>(scalars->GetComponent(p, c)) : 1.0f;
    }
  }
  res.Scene.Color->Bind();
  state->vtkglPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, w, h, GL_RGBA, GL_FLOAT, pixels.data());
  res.Scene.Color->Deactivate();

  state->PushFramebufferBindings();
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDisable(GL_SCISSOR_TEST);
  const bool bloom = in.RunBloom(this, res.Scene.Color, false);
  in.Report->BloomSkipped = !bloom;
  const int zero[2] = { 0, 0 };
  in.Runner.Composite(in.Output, &res.Result, zero, bloom);
  in.ReportChain();
  state->PopFramebufferBindings();
  in.Profiler.Resolve();

  const bool ok = this->ReadResultImage(output);
  if (ok)
  {
    int extent[6];
    input->GetExtent(extent);
    output->SetExtent(extent);
    output->SetOrigin(input->GetOrigin());
    output->SetSpacing(input->GetSpacing());
  }
  vtkOpenGLCheckErrorMacro("failed after vtkBloomPass::ApplyToImage");
  return ok;
}

//------------------------------------------------------------------------------
bool vtkBloomPass::ReadSceneImage(vtkImageData* image)
{
  vtkBloomPassResources& res = this->Internals->Resources;
  if (!image || !res.Context || !res.Scene.FBO)
  {
    vtkErrorMacro(<< "There is no rendered scene to read; render first.");
    return false;
  }
  if (!res.Scene.Read(res.Context, image))
  {
    return false;
  }
  if (this->Internals->Light.InAlpha)
  {
    // The emission rode on the alpha (1 + weight); the scene's own alpha is at most 1.
    vtkBloomPassDecodeEmission(image, false);
  }
  // The frame as the renderer would have drawn it: the scene over its background.
  vtkBloomPassBackground::PutOver(res, image);
  return true;
}

//------------------------------------------------------------------------------
void vtkBloomPass::SetSceneBackground(const double rgba[4])
{
  vtkBloomPassResources& res = this->Internals->Resources;
  res.BackgroundMode = vtkBloomPassResources::BACKGROUND_COLOR;
  std::copy(rgba, rgba + 4, res.BackgroundColor);
  res.Background.Release(res.Context);
}

//------------------------------------------------------------------------------
bool vtkBloomPass::ReadEmissionImage(vtkImageData* image)
{
  vtkBloomPassResources& res = this->Internals->Resources;
  const bool inScene = this->Internals->Light.InAlpha;
  if (!image || !res.Context || !(inScene || res.Emitter.FBO))
  {
    vtkErrorMacro(<< "There is no emission to read; render with EMISSION_EMITTERS first.");
    return false;
  }
  if (!inScene)
  {
    return res.Emitter.Read(res.Context, image);
  }
  if (!res.Scene.Read(res.Context, image))
  {
    return false;
  }
  vtkBloomPassDecodeEmission(image, true);
  return true;
}

//------------------------------------------------------------------------------
bool vtkBloomPass::ReadResultImage(vtkImageData* image)
{
  vtkBloomPassResources& res = this->Internals->Resources;
  if (!image || !res.Context || !res.Result.FBO)
  {
    vtkErrorMacro(<< "There is no bloomed result to read; turn CaptureResult on and render.");
    return false;
  }
  return res.Result.Read(res.Context, image);
}
