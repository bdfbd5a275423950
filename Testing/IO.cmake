# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
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

# Crafted files (Support/vtkBloomCraftedEXR.cxx): streams that decode short of the channel
# list, refused; the valid files they are made from, read as OpenEXR decodes them. The
# committed copies in Data/EXR/Crafted are written by MakeCraftedEXR.
vtkbloom_add_gtest(TestOpenEXRCrafted
  SOURCES IO/TestOpenEXRCrafted.cxx
  LIBRARIES ${vtkbloom_io_test_libraries})
target_include_directories(TestOpenEXRCrafted PRIVATE "${CMAKE_CURRENT_SOURCE_DIR}/IO")
add_executable(MakeCraftedEXR IO/MakeCraftedEXR.cxx)
target_link_libraries(MakeCraftedEXR PRIVATE vtkbloom_testing)
# The hostile headers as files, for scripts/valgrind.sh (the fuzz project builds its own).
add_executable(MakeHostileEXR Fuzz/MakeHostileEXR.cxx)
target_link_libraries(MakeHostileEXR PRIVATE vtkbloom_testing)
