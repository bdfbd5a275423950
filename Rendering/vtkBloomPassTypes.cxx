// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// The boxes of samples that the content-aware chain computes (vtkBloomPassRegion.cxx).
#include "vtkBloomPassTypes.h"

#include <algorithm>

//------------------------------------------------------------------------------
vtkBloomPassBox vtkBloomPassBox::Union(const vtkBloomPassBox& o) const
{
  if (this->Empty())
  {
    return o;
  }
  if (o.Empty())
  {
    return *this;
  }
  return { std::min(this->X0, o.X0), std::max(this->X1, o.X1), std::min(this->Y0, o.Y0),
    std::max(this->Y1, o.Y1) };
}

//------------------------------------------------------------------------------
vtkBloomPassBox vtkBloomPassBox::Intersection(const vtkBloomPassBox& o) const
{
  return { std::max(this->X0, o.X0), std::min(this->X1, o.X1), std::max(this->Y0, o.Y0),
    std::min(this->Y1, o.Y1) };
}

//------------------------------------------------------------------------------
vtkBloomPassBox vtkBloomPassBox::Window(const int window[4], int width, int height)
{
  const bool whole = window[0] == 0 && window[1] == 0 && window[2] == 0 && window[3] == 0;
  return whole ? Whole(width, height)
               : vtkBloomPassBox{ window[0], window[1], window[2], window[3] };
}
