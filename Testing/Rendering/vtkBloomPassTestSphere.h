// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// A sphere as users add one to a scene, lit or a lamp, for the rendering suites
// (TestBloomPassLight.cxx, TestBloomPassTiles.cxx).
#ifndef vtkBloomPassTestSphere_h
#define vtkBloomPassTestSphere_h

#include "vtkActor.h"
#include "vtkNew.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"

// A lit sphere of `colour` at `centre` with `radius`; `emission` > 0 makes it a lamp (unlit,
// its ambient colour `emission` times `colour`: HDR above 1, as users make emissive props;
// vtkProperty clamps the ambient coefficient to 1, not the colour).
inline vtkSmartPointer<vtkActor> vtkBloomPassTestSphere(
  const double centre[3], double radius, const double colour[3], double emission = 0.0)
{
  vtkNew<vtkSphereSource> source;
  source->SetCenter(centre[0], centre[1], centre[2]);
  source->SetRadius(radius);
  source->SetThetaResolution(48);
  source->SetPhiResolution(24);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(colour[0], colour[1], colour[2]);
  if (emission > 0.0)
  {
    actor->GetProperty()->SetAmbient(1.0);
    actor->GetProperty()->SetDiffuse(0.0);
    actor->GetProperty()->SetAmbientColor(
      emission * colour[0], emission * colour[1], emission * colour[2]);
  }
  return actor;
}

#endif
