# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
# GoogleTest suites of the fast chain and its content-aware work; included by
# Testing/CMakeLists.txt. Every suite is named Performance*, so `ctest -R ^Performance` runs them.
# They assert agreement and exactness only, never timings (the timings are in Benchmarks/).
set(vtkbloom_performance_tests
  TestBloomFastPath
  TestBloomContentAware
  TestBloomFFTBlur)

foreach (test IN LISTS vtkbloom_performance_tests)
  vtkbloom_add_gtest(${test}
    SOURCES "${CMAKE_CURRENT_LIST_DIR}/Performance/${test}.cxx"
    LIBRARIES vtkbloom_reference VTKBloom::FiltersBloom VTK::CommonDataModel VTK::CommonExecutionModel
      VTK::CommonCore)
endforeach ()
