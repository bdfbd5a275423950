# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
# Numerical hard cases and accuracy bounds (issue 4); included by Testing/CMakeLists.txt.
# Every suite here is named Numerics*, so `ctest -R ^Numerics` runs them all.

find_package(OpenEXR 3 REQUIRED)

# The hard cases' inputs and expectations, shared with the GPU suites (no library code in it).
add_library(vtkbloom_hardcases STATIC "${CMAKE_CURRENT_LIST_DIR}/Support/vtkBloomHardCases.cxx")
target_include_directories(vtkbloom_hardcases PUBLIC "${CMAKE_CURRENT_LIST_DIR}/Support")
target_link_libraries(vtkbloom_hardcases PUBLIC VTK::CommonCore VTK::CommonDataModel
  vtkbloom_build_flags)

foreach (test IN ITEMS TestNumericsGaussian TestNumericsHardCases)
  vtkbloom_add_gtest(${test}
    SOURCES "${CMAKE_CURRENT_LIST_DIR}/Numerics/${test}.cxx"
    LIBRARIES vtkbloom_hardcases vtkbloom_reference VTKBloom::FiltersBloom VTKBloom::IOOpenEXR
      OpenEXR::OpenEXR VTK::CommonExecutionModel VTK::CommonDataModel VTK::CommonCore)
endforeach ()

# The exact summation behind the energy statistics, compiled in (it is internal to the module).
vtkbloom_add_gtest(TestNumericsExactSum
  SOURCES "${CMAKE_CURRENT_LIST_DIR}/Numerics/TestNumericsExactSum.cxx"
    "${CMAKE_SOURCE_DIR}/Filters/vtkBloomExactSum.cxx")
target_include_directories(TestNumericsExactSum PRIVATE "${CMAKE_SOURCE_DIR}/Filters")
