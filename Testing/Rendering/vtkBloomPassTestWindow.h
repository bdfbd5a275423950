// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// The offscreen window the vtkBloomPass suites render in (TestBloomPass.cxx,
// TestBloomPassLiveScenes.cxx).
#ifndef vtkBloomPassTestWindow_h
#define vtkBloomPassTestWindow_h

#include "vtkBloomPass.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

// An offscreen window with one renderer whose pass is bloom(render steps). The suites that use
// it compare the pass with vtkImageBloom applied to the whole float frame, which knows no
// background: here the background is part of that frame and blooms as the filter blooms it
// (BloomBackground on). TestBloomPassLight.cxx and the gallery test the default, where it does
// not.
struct BloomWindow
{
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkBloomPass> Bloom;
  vtkNew<vtkRenderStepsPass> Steps;

  BloomWindow(int width, int height)
  {
    this->Window->SetOffScreenRendering(1);
    this->Window->SetMultiSamples(0);
    this->Window->SetSize(width, height);
    this->Window->AddRenderer(this->Renderer);
    this->Bloom->SetDelegatePass(this->Steps);
    this->Bloom->BloomBackgroundOn();
    this->Renderer->SetPass(this->Bloom);
  }
  ~BloomWindow() { this->Window->ReleaseGraphicsResources(this->Window); }
  vtkOpenGLRenderWindow* GL() { return vtkOpenGLRenderWindow::SafeDownCast(this->Window); }
};

#endif
