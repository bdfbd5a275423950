# GoogleTest suites of the FiltersBloom module; included by Testing/CMakeLists.txt.
# Every gtest suite here is named Filters*, so `ctest -R ^Filters` runs them all.

# The tests read the shared calibration EXRs with OpenEXR's own C++ API (float slices, never
# the half-precision RGBA interface).
find_package(OpenEXR 3 REQUIRED)

# The independent float64 reference the filter suites compare against. It is built once here
# and shares no code with the module under test.
if (NOT TARGET vtkbloom_reference)
  add_library(vtkbloom_reference STATIC
    "${CMAKE_CURRENT_LIST_DIR}/Support/vtkBloomReference.cxx")
  target_include_directories(vtkbloom_reference PUBLIC "${CMAKE_CURRENT_LIST_DIR}/Support")
  target_link_libraries(vtkbloom_reference PUBLIC VTK::CommonCore VTK::CommonDataModel
    vtkbloom_build_flags)
endif ()

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
  TestBloomFFTConvolution
  TestImageBloomPSF)

foreach (test IN LISTS vtkbloom_filters_tests)
  set(extra)
  if (test STREQUAL "TestBloomCalibration")
    set(extra OpenEXR::OpenEXR)
  endif ()
  vtkbloom_add_gtest(${test}
    SOURCES "${CMAKE_CURRENT_LIST_DIR}/Filters/${test}.cxx"
    LIBRARIES ${vtkbloom_filters_test_libraries} ${extra})
endforeach ()
