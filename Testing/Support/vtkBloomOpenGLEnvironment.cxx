// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// Linked into every test that makes a render window (vtkbloom_add_gtest OPENGL): before any
// test runs, the window VTK would choose is checked, so that a missing OSMesa (VTK 9.4 and
// later, VTK_DEFAULT_OPENGL_WINDOW=vtkOSOpenGLRenderWindow) fails the suite with one message
// instead of crashing every test in turn. See vtkBloomVTKCompat.h.
#include "vtkBloomVTKCompat.h"

#include <gtest/gtest.h>

#include <string>

namespace
{
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
  }
};

const ::testing::Environment* const Registered =
  ::testing::AddGlobalTestEnvironment(new OpenGLWindowEnvironment);
}
