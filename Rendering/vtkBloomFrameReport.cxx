// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkBloomFrameReport.h"

#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkBloomFrameReport);

int vtkBloomFrameReport::GetFloatPrecision() const
{
  return this->FloatPrecision;
}

int vtkBloomFrameReport::GetNumberOfPasses() const
{
  return this->NumberOfPasses;
}

int vtkBloomFrameReport::GetComputePasses() const
{
  return this->ComputePasses;
}

bool vtkBloomFrameReport::GetBloomSkipped() const
{
  return this->BloomSkipped;
}

double vtkBloomFrameReport::GetChainCoverage() const
{
  return this->ChainCoverage;
}

bool vtkBloomFrameReport::GetEmissionInSceneRender() const
{
  return this->EmissionInSceneRender;
}

bool vtkBloomFrameReport::GetAnnotationsOverBloom() const
{
  return this->AnnotationsOverBloom;
}

bool vtkBloomFrameReport::GetTileFromKeptFrame() const
{
  return this->TileFromKeptFrame;
}

double vtkBloomFrameReport::GetChainMilliseconds() const
{
  return this->ChainMilliseconds;
}

double vtkBloomFrameReport::GetRegionCost() const
{
  return this->RegionCost;
}

double vtkBloomFrameReport::GetFullCost() const
{
  return this->FullCost;
}

//------------------------------------------------------------------------------
void vtkBloomFrameReport::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  const auto onOff = [](bool b) { return b ? "On" : "Off"; };
  os << indent << "FloatPrecision: " << this->FloatPrecision << "\n";
  os << indent << "NumberOfPasses: " << this->NumberOfPasses << "\n";
  os << indent << "ComputePasses: " << this->ComputePasses << "\n";
  os << indent << "BloomSkipped: " << onOff(this->BloomSkipped) << "\n";
  os << indent << "BrightRegion: " << this->BrightRegion[0] << " " << this->BrightRegion[1] << " "
     << this->BrightRegion[2] << " " << this->BrightRegion[3] << "\n";
  os << indent << "ChainCoverage: " << this->ChainCoverage << "\n";
  os << indent << "PSFGrid: " << this->PSFGrid[0] << " " << this->PSFGrid[1] << "\n";
  os << indent << "EmissionInSceneRender: " << onOff(this->EmissionInSceneRender) << "\n";
  os << indent << "AnnotationsOverBloom: " << onOff(this->AnnotationsOverBloom) << "\n";
  os << indent << "TileGuardBand: " << this->TileGuardBand[0] << " " << this->TileGuardBand[1]
     << "\n";
  os << indent << "TileFromKeptFrame: " << onOff(this->TileFromKeptFrame) << "\n";
  os << indent << "ChainMilliseconds: " << this->ChainMilliseconds << "\n";
  os << indent << "RegionCost: " << this->RegionCost << "\n";
  os << indent << "FullCost: " << this->FullCost << "\n";
}
