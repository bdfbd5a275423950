// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// Build a small emissive HDR scene directly as vtkImageData, bloom it with vtkImageBloom and
// write the before and after images as OpenEXR. Shows the filter API without any file input:
//
//   EmissiveImage BEFORE.exr AFTER.exr [PRESET]

#include "vtkImageBloom.h"
#include "vtkOpenEXRWriter.h"

#include <vtkImageData.h>
#include <vtkNew.h>

#include <cmath>
#include <iostream>

namespace
{
// A dim blue-grey gradient with a few emissive discs and a hot filament, values up to ~60.
void FillScene(vtkImageData* image, int width, int height)
{
  image->SetDimensions(width, height, 1);
  image->AllocateScalars(VTK_FLOAT, 4);
  float* p = static_cast<float*>(image->GetScalarPointer());
  struct Disc
  {
    double X, Y, R, Colour[3];
  };
  const Disc discs[] = { { 0.22, 0.30, 0.035, { 40.0, 18.0, 4.0 } },
    { 0.70, 0.25, 0.020, { 6.0, 25.0, 60.0 } }, { 0.55, 0.70, 0.050, { 12.0, 10.0, 9.0 } },
    { 0.90, 0.85, 0.012, { 60.0, 60.0, 60.0 } } };
  for (int j = 0; j < height; ++j)
  {
    for (int i = 0; i < width; ++i, p += 4)
    {
      const double u = (i + 0.5) / width, v = (j + 0.5) / height;
      double c[3] = { 0.03 + 0.05 * v, 0.04 + 0.06 * v, 0.08 + 0.10 * v };
      for (const Disc& d : discs)
      {
        const double dx = (u - d.X) * width / height, dy = v - d.Y;
        if (dx * dx + dy * dy < d.R * d.R)
        {
          for (int k = 0; k < 3; ++k)
          {
            c[k] = d.Colour[k];
          }
        }
      }
      // A thin glowing sine filament across the lower third.
      const double curve = 0.82 + 0.05 * std::sin(6.2831853 * 2.0 * u);
      if (std::abs(v - curve) * height < 1.2)
      {
        c[0] += 8.0;
        c[1] += 3.0;
        c[2] += 20.0;
      }
      p[0] = static_cast<float>(c[0]);
      p[1] = static_cast<float>(c[1]);
      p[2] = static_cast<float>(c[2]);
      p[3] = 1.0f;
    }
  }
}
}

int main(int argc, char* argv[])
{
  if (argc < 3)
  {
    std::cerr << "usage: EmissiveImage BEFORE.exr AFTER.exr [PRESET]\n";
    return 2;
  }
  vtkNew<vtkImageData> scene;
  FillScene(scene, 960, 540);

  vtkNew<vtkImageBloom> bloom;
  if (!bloom->SetPreset(argc > 3 ? argv[3] : "webgpu-market"))
  {
    return 2;
  }
  bloom->SetInputData(scene);

  vtkNew<vtkOpenEXRWriter> before;
  before->SetFileName(argv[1]);
  before->SetInputData(scene);
  before->Write();

  vtkNew<vtkOpenEXRWriter> after;
  after->SetFileName(argv[2]);
  after->SetInputConnection(bloom->GetOutputPort());
  after->Write();
  return before->GetErrorCode() || after->GetErrorCode() ? 1 : 0;
}
