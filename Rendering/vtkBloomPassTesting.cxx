// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// The tests' switches of vtkBloomPass (see vtkBloomPassTesting.h).
#include "vtkBloomPassTesting.h"

#include "vtkBloomPassInternals.h"

//------------------------------------------------------------------------------
void vtkBloomPassTesting::SetShareWindowDepth(vtkBloomPass* pass, bool share)
{
  pass->Internals->ShareWindowDepth = share;
}

//------------------------------------------------------------------------------
bool vtkBloomPassTesting::GetShareWindowDepth(vtkBloomPass* pass)
{
  return pass->Internals->ShareWindowDepth;
}
