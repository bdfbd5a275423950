// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// Linked into every test that makes a render window (vtkbloom_add_gtest OPENGL): before any
// test runs, the window VTK would choose is checked, so that a missing OSMesa (VTK 9.4 and
// later, VTK_DEFAULT_OPENGL_WINDOW=vtkOSOpenGLRenderWindow) fails the suite with one message
// instead of crashing every test in turn. See vtkBloomVTKCompat.h. Then the bloom pass is
// asked whether it runs compute passes here (vtkBloomOpenGLEnvironment.h).
#include "vtkBloomOpenGLEnvironment.h"

#include "vtkBloomPass.h"
#include "vtkBloomVTKCompat.h"

#include <vtkNew.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkRenderStepsPass.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>

namespace
{
int ComputePasses = -1; // the probe's count; -1 before it ran

// One 32 x 32 frame whose background is light (4, above the threshold), through a pass that
// may use compute shaders: how many of its passes ran as compute passes, and the context.
int ProbeComputePasses(std::string& context)
{
  vtkNew<vtkRenderWindow> window;
  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkBloomPass> bloom;
  vtkNew<vtkRenderStepsPass> steps;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(32, 32);
  window->AddRenderer(renderer);
  renderer->SetBackground(4.0, 4.0, 4.0);
  bloom->SetDelegatePass(steps);
  bloom->BloomBackgroundOn();
  bloom->UseComputeShadersOn();
  renderer->SetPass(bloom);
  window->Render();
  int major = 0, minor = 0;
  if (auto* gl = vtkOpenGLRenderWindow::SafeDownCast(window))
  {
    gl->GetOpenGLVersion(major, minor);
  }
  context = "OpenGL " + std::to_string(major) + "." + std::to_string(minor);
  const int passes = bloom->GetLastFrame()->GetComputePasses();
  window->ReleaseGraphicsResources(window);
  return passes;
}

class OpenGLWindowEnvironment : public ::testing::Environment
{
public:
  void SetUp() override
  {
    vtkBloomPreferHeadlessWindow();
    std::string why;
    if (!vtkBloomCheckOpenGLWindow(why))
    {
      GTEST_FAIL() << "no render window can be made: " << why;
    }
    std::string context;
    ComputePasses = ProbeComputePasses(context);
    const char* expect = std::getenv("VTKBLOOM_EXPECT_COMPUTE");
    if (expect && std::strcmp(expect, "1") == 0 && ComputePasses <= 0)
    {
      // Not GTEST_FAIL: GoogleTest would still run the tests, whose skips then make CTest
      // report the run as skipped (SKIP_REGULAR_EXPRESSION) rather than failed.
      std::cerr << "vtkBloomOpenGLEnvironment: this leg must run the bloom pass's compute "
                << "shaders (VTKBLOOM_EXPECT_COMPUTE=1), and its " << context
                << " context runs none\n";
      std::exit(1);
    }
  }
};

const ::testing::Environment* const Registered =
  ::testing::AddGlobalTestEnvironment(new OpenGLWindowEnvironment);
}

bool vtkBloomTestComputePassesRun()
{
  return ComputePasses > 0;
}
