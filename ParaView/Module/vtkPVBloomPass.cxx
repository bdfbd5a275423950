// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkPVBloomPass.h"

#include "vtkBloomVTKCompat.h"
#include "vtkFloatArray.h"
#include "vtkIceTCompositePass.h"
#include "vtkObjectFactory.h"
#include "vtkTextureObject.h"

#include <algorithm>

vtkStandardNewMacro(vtkPVBloomPass);

//------------------------------------------------------------------------------
vtkPVBloomPass::vtkPVBloomPass() = default;

//------------------------------------------------------------------------------
vtkPVBloomPass::~vtkPVBloomPass() = default;

//------------------------------------------------------------------------------
void vtkPVBloomPass::SetCompositePass(vtkIceTCompositePass* pass)
{
  if (this->CompositePass != pass)
  {
    this->CompositePass = pass;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkPVBloomPass::SetCompositeBackground(const double rgb[3], double alpha)
{
  const float rgba[4] = { static_cast<float>(rgb[0]), static_cast<float>(rgb[1]),
    static_cast<float>(rgb[2]), static_cast<float>(alpha) };
  std::copy(rgba, rgba + 4, this->CompositeBackground);
}

//------------------------------------------------------------------------------
void vtkPVBloomPass::SceneRendered(const vtkRenderState*, vtkTextureObject* sceneColor)
{
  this->LastSceneWasComposited = false;
  vtkFloatArray* composite =
    this->CompositePass ? this->CompositePass->GetLastRenderedRGBA32F() : nullptr;
  const int width = static_cast<int>(sceneColor->GetWidth());
  const int height = static_cast<int>(sceneColor->GetHeight());
  // An interactive render with an image reduction factor: IceT composited the window's size
  // divided by it (vtkIceTCompositePass::UpdateTileInformation), which the scene gets enlarged
  // as ParaView enlarges its 8-bit image, each pixel a block; the bloom runs at the frame's size.
  const int factor =
    this->CompositePass ? std::max(1, this->CompositePass->GetImageReductionFactor()) : 1;
  const int reduced[2] = { width / factor, height / factor };
  const vtkIdType tuples = composite ? composite->GetNumberOfTuples() : 0;
  const bool whole = tuples == static_cast<vtkIdType>(width) * height;
  const bool enlarge =
    !whole && factor > 1 && tuples == static_cast<vtkIdType>(reduced[0]) * reduced[1];
  if (!composite || composite->GetNumberOfComponents() != 4 || !(whole || enlarge))
  {
    return; // not the displaying process: the scene as rendered
  }
  // IceT composites over transparent black: the scene without its background, as the pass
  // renders it by default, and the composite puts it over the view's background. Where the
  // background blooms (BloomBackground), it goes behind the scene here, as a serial render
  // clears to it.
  const float* background = this->CompositeBackground;
  const float* top = composite->GetPointer(0);
  if (enlarge)
  {
    top = this->Enlarge(top, reduced, width, height);
  }
  if (this->BloomBackground)
  {
    const size_t count = 4 * static_cast<size_t>(width) * height;
    this->Pixels.resize(count); // top may be Pixels already: each value is read, then written
    for (size_t i = 0; i < count; i += 4)
    {
      const float behind = 1.0f - top[i + 3];
      for (size_t c = 0; c < 4; ++c)
      {
        this->Pixels[i + c] = top[i + c] + behind * background[c];
      }
    }
    top = this->Pixels.data();
  }
  else
  {
    const double rgba[4] = { background[0], background[1], background[2], background[3] };
    this->SetSceneBackground(rgba);
  }
  sceneColor->Activate(); // rows of RGBA floats are 16-byte aligned: any unpack alignment
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width, height, GL_RGBA, GL_FLOAT, top);
  sceneColor->Deactivate();
  this->LastSceneWasComposited = true;
}

//------------------------------------------------------------------------------
const float* vtkPVBloomPass::Enlarge(const float* image, const int size[2], int width, int height)
{
  // The sample under each pixel's centre, as a texture of `size` drawn over the viewport with
  // nearest filtering samples it.
  this->Pixels.resize(4 * static_cast<size_t>(width) * height);
  std::vector<int> columns(width);
  for (int x = 0; x < width; ++x)
  {
    columns[x] = std::min(size[0] - 1, static_cast<int>((x + 0.5) * size[0] / width));
  }
  float* out = this->Pixels.data();
  for (int y = 0; y < height; ++y)
  {
    const int row = std::min(size[1] - 1, static_cast<int>((y + 0.5) * size[1] / height));
    const float* in = image + 4 * static_cast<size_t>(row) * size[0];
    for (int x = 0; x < width; ++x, out += 4)
    {
      std::copy(in + 4 * columns[x], in + 4 * columns[x] + 4, out);
    }
  }
  return this->Pixels.data();
}

//------------------------------------------------------------------------------
void vtkPVBloomPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "CompositePass: " << this->CompositePass.GetPointer() << "\n";
  os << indent << "CompositeBackground: " << this->CompositeBackground[0] << " "
     << this->CompositeBackground[1] << " " << this->CompositeBackground[2] << " "
     << this->CompositeBackground[3] << "\n";
  os << indent << "LastSceneWasComposited: " << this->LastSceneWasComposited << "\n";
}
