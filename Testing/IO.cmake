# GoogleTest suites of VTKBloom::IOOpenEXR. The tests use the OpenEXR C++ library directly to
# write small inputs and to decode reference pixels independently of the reader.
find_package(OpenEXR 3 REQUIRED CONFIG)

set(vtkbloom_io_test_libraries
  VTKBloom::IOOpenEXR
  VTK::CommonCore
  VTK::CommonDataModel
  VTK::CommonExecutionModel
  VTK::CommonMisc
  OpenEXR::OpenEXR)

vtkbloom_add_gtest(TestOpenEXRReader
  SOURCES IO/TestOpenEXRReader.cxx
  LIBRARIES ${vtkbloom_io_test_libraries})
vtkbloom_add_gtest(TestOpenEXRWriter
  SOURCES IO/TestOpenEXRWriter.cxx
  LIBRARIES ${vtkbloom_io_test_libraries})
vtkbloom_add_gtest(TestOpenEXRDamaged
  SOURCES IO/TestOpenEXRDamaged.cxx
  LIBRARIES ${vtkbloom_io_test_libraries})

foreach (test IN ITEMS TestOpenEXRReader TestOpenEXRWriter TestOpenEXRDamaged)
  target_include_directories(${test} PRIVATE "${CMAKE_CURRENT_SOURCE_DIR}/IO")
endforeach ()

# Hostile headers generated in the suite (Support/vtkBloomHostileEXR.cxx).
vtkbloom_add_gtest(TestOpenEXRHostile
  SOURCES IO/TestOpenEXRHostile.cxx
  LIBRARIES ${vtkbloom_io_test_libraries})
target_include_directories(TestOpenEXRHostile PRIVATE "${CMAKE_CURRENT_SOURCE_DIR}/IO")
