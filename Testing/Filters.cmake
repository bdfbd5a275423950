# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
# GoogleTest suites of the FiltersBloom module; included by Testing/CMakeLists.txt.
# Every gtest suite here is named Filters*, so `ctest -R ^Filters` runs them all.

# The tests read the shared calibration EXRs with OpenEXR's own C++ API (float slices, never
# the half-precision RGBA interface).
find_package(OpenEXR 3 REQUIRED)

set(vtkbloom_filters_test_libraries
  vtkbloom_reference
  VTKBloom::FiltersBloom
  VTK::ImagingCore
  VTK::CommonDataModel
  VTK::CommonExecutionModel
  VTK::CommonCore)

set(vtkbloom_filters_tests
  TestBloomReference
  TestBloomCalibration
  TestImageBloomPresets
  TestBloomParameters
  TestImageSeparableGaussian
  TestImagePyramidDown
  TestImagePyramidUp
  TestImageBloomThreshold
  TestBloomStreaming
  TestBloomErrors
  TestBloomLinearOperator
  TestBloomChainCut
  TestBloomFFTConvolution
  TestImageBloomPSF
  TestImageBloomPSFSplit)

foreach (test IN LISTS vtkbloom_filters_tests)
  set(extra)
  if (test STREQUAL "TestBloomCalibration")
    set(extra OpenEXR::OpenEXR)
  endif ()
  vtkbloom_add_gtest(${test}
    SOURCES "${CMAKE_CURRENT_LIST_DIR}/Filters/${test}.cxx"
    LIBRARIES ${vtkbloom_filters_test_libraries} ${extra})
endforeach ()
