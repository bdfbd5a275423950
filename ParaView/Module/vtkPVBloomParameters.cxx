// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkPVBloomParameters.h"

#include "vtkObjectFactory.h"

#include <algorithm>

vtkStandardNewMacro(vtkPVBloomParameters);

//------------------------------------------------------------------------------
void vtkPVBloomParameters::SetNumberOfLevelWeights(int n)
{
  const size_t size = static_cast<size_t>(std::max(n, 0));
  if (size != this->LevelWeights.size())
  {
    this->LevelWeights.resize(size, 1.0);
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkPVBloomParameters::SetNumberOfBlurHalfKernelWeights(int n)
{
  const size_t size = static_cast<size_t>(std::max(n, 0));
  if (size != this->BlurHalfKernel.size())
  {
    this->BlurHalfKernel.resize(size, 0.0);
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkPVBloomParameters::SetBlurHalfKernelWeight(int i, double weight)
{
  if (i < 0 || static_cast<size_t>(i) >= this->BlurHalfKernel.size())
  {
    vtkErrorMacro(<< "Blur half-kernel tap " << i << " is outside 0.."
                  << static_cast<int>(this->BlurHalfKernel.size()) - 1);
    return;
  }
  if (this->BlurHalfKernel[i] != weight)
  {
    this->BlurHalfKernel[i] = weight;
    this->Modified();
  }
}
