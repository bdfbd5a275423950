// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// The tests' switches of vtkBloomPass and its profile (see vtkBloomPassTesting.h).
#include "vtkBloomPassTesting.h"

#include "vtkBloomPassInternals.h"

#include <algorithm>

//------------------------------------------------------------------------------
void vtkBloomPassTesting::SetShareWindowDepth(vtkBloomPass* pass, bool share)
{
  pass->Internals->Switches.ShareWindowDepth = share;
  pass->Modified();
}

//------------------------------------------------------------------------------
bool vtkBloomPassTesting::GetShareWindowDepth(vtkBloomPass* pass)
{
  return pass->Internals->Switches.ShareWindowDepth;
}

//------------------------------------------------------------------------------
void vtkBloomPassTesting::SetSimulateComputeShaderFailure(vtkBloomPass* pass, bool fail)
{
  pass->Internals->Switches.SimulateComputeShaderFailure = fail;
  pass->Modified();
}

//------------------------------------------------------------------------------
void vtkBloomPassTesting::SetSingleDrawSamples(vtkBloomPass* pass, int samples)
{
  pass->Internals->Switches.SingleDrawSamples = std::max(-1, samples);
  pass->Modified();
}

//------------------------------------------------------------------------------
void vtkBloomPassTesting::SetFuseSeparablePasses(vtkBloomPass* pass, bool fuse)
{
  pass->Internals->Switches.FuseSeparablePasses = fuse;
  pass->Modified();
}

//------------------------------------------------------------------------------
void vtkBloomPassTesting::SetProfilePasses(vtkBloomPass* pass, bool profile)
{
  pass->Internals->Switches.ProfilePasses = profile;
  pass->Modified();
}

//------------------------------------------------------------------------------
void vtkBloomPassTesting::SetTimeChains(vtkBloomPass* pass, bool time)
{
  pass->Internals->Runner.SetTimeEveryChain(time);
}

//------------------------------------------------------------------------------
std::vector<vtkBloomPassTesting::ProfiledPass> vtkBloomPassTesting::GetProfile(vtkBloomPass* pass)
{
  return pass->Internals->Profiler.GetEntries();
}
