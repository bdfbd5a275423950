// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// Blooms a constant image with an installed vtk-bloom and checks the documented result:
// webgpu-market turns a constant 0.5 into 0.607421875 (PRESETS.md).
#include <vtkImageBloom.h>
#include <vtkOpenEXRReader.h>

#include <vtkImageData.h>
#include <vtkNew.h>

#include <cmath>
#include <iostream>

int main()
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(16, 9, 1);
  image->AllocateScalars(VTK_FLOAT, 4);
  float* p = static_cast<float*>(image->GetScalarPointer());
  for (int i = 0; i < 16 * 9 * 4; ++i)
  {
    p[i] = 0.5f;
  }
  vtkNew<vtkImageBloom> bloom;
  bloom->SetPreset("webgpu-market");
  bloom->SetInputData(image);
  bloom->Update();
  const double v = bloom->GetOutput()->GetScalarComponentAsDouble(3, 4, 0, 1);
  vtkNew<vtkOpenEXRReader> reader; // the IO module links too
  std::cout << "bloomed constant 0.5 -> " << v << "\n";
  return std::abs(v - 0.607421875) < 1e-6 ? 0 : 1;
}
