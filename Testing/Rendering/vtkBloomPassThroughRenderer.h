// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// A delegate that renders the scene through the renderer (ClearLights, UpdateLights,
// UpdateGeometry: the renderer's own culled props), as ParaView's vtkPVDefaultPass does under
// its camera pass; for the rendering suites that must behave as in ParaView
// (TestBloomPassLight.cxx, TestBloomPassTiles.cxx).
#ifndef vtkBloomPassThroughRenderer_h
#define vtkBloomPassThroughRenderer_h

#include "vtkDefaultPass.h"
#include "vtkObjectFactory.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"

class vtkBloomPassThroughRenderer : public vtkDefaultPass
{
public:
  static vtkBloomPassThroughRenderer* New() { VTK_STANDARD_NEW_BODY(vtkBloomPassThroughRenderer); }
  vtkTypeMacro(vtkBloomPassThroughRenderer, vtkDefaultPass);
  void Render(const vtkRenderState* s) override
  {
    vtkRenderer* renderer = s->GetRenderer();
    this->ClearLights(renderer);
    this->UpdateLightGeometry(renderer);
    this->UpdateLights(renderer);
    this->UpdateGeometry(renderer, s->GetFrameBuffer());
  }
};

#endif
