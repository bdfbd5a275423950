# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
# End-to-end tests of the vtk-bloom command-line tool, run exactly as users call it.
find_package(OpenEXR 3 REQUIRED)
vtkbloom_add_gtest(TestCommandLine OPENGL
  SOURCES Tools/TestCommandLine.cxx
  LIBRARIES OpenEXR::OpenEXR VTK::IOImage)
target_compile_definitions(TestCommandLine PRIVATE
  VTKBLOOM_TOOL="$<TARGET_FILE:vtk-bloom>")
add_dependencies(TestCommandLine vtk-bloom)
if (VTKBLOOM_ENABLE_RENDERING)
  target_compile_definitions(TestCommandLine PRIVATE VTKBLOOM_HAS_RENDERING)
endif ()

# The tool on many files: hostile inputs, --exact, batch mode, --stats, --max-pixels.
vtkbloom_add_gtest(TestCommandLineFiles
  SOURCES Tools/TestCommandLineFiles.cxx
  LIBRARIES OpenEXR::OpenEXR)
target_compile_definitions(TestCommandLineFiles PRIVATE VTKBLOOM_TOOL="$<TARGET_FILE:vtk-bloom>")
add_dependencies(TestCommandLineFiles vtk-bloom)

# render FILE and view, on datasets the test writes with VTK's writers.
if (VTKBLOOM_ENABLE_RENDERING)
  vtkbloom_add_gtest(TestCommandLineData OPENGL
    SOURCES Tools/TestCommandLineData.cxx
    LIBRARIES OpenEXR::OpenEXR VTK::IOXML VTK::IOLegacy VTK::FiltersCore VTK::FiltersGeneral
      VTK::FiltersSources VTK::ImagingCore)
  target_compile_definitions(TestCommandLineData PRIVATE VTKBLOOM_TOOL="$<TARGET_FILE:vtk-bloom>")
  if (TARGET VTK::InteractionWidgets AND TARGET VTK::RenderingFreeType)
    target_compile_definitions(TestCommandLineData PRIVATE VTKBLOOM_TEST_INTERACTIVE)
  endif ()
  add_dependencies(TestCommandLineData vtk-bloom)
endif ()
