# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
# The accuracy-versus-time study (issue 4): a plain harness, run by scripts/accuracy-study.sh.
# vtkImageGaussianSmooth (VTK::ImagingGeneral) is its comparison row.
find_package(VTK 9.1 QUIET COMPONENTS ImagingGeneral)
add_executable(BloomAccuracyStudy "${CMAKE_CURRENT_LIST_DIR}/BloomAccuracyStudy.cxx")
target_link_libraries(BloomAccuracyStudy PRIVATE VTKBloom::FiltersBloom VTK::ImagingGeneral
  VTK::ImagingCore VTK::CommonExecutionModel VTK::CommonDataModel VTK::CommonCore
  vtkbloom_build_flags)
# With rendering, the GPU rows: vtkBloomPass::ApplyToImage against the CPU filter.
if (VTKBLOOM_ENABLE_RENDERING)
  target_link_libraries(BloomAccuracyStudy PRIVATE VTKBloom::RenderingBloom
    VTK::RenderingOpenGL2 VTK::RenderingCore)
  target_compile_definitions(BloomAccuracyStudy PRIVATE VTKBLOOM_ACCURACY_WITH_GPU)
  vtk_module_autoinit(TARGETS BloomAccuracyStudy MODULES VTK::RenderingOpenGL2)
endif ()
