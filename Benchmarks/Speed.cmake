# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
# The chain speed suite (issue 5): Google Benchmark, run by scripts/benchmark.sh. OpenCV (Debian's
# libopencv-imgproc-dev) is optional and benchmark-only: without it the OpenCV rows are skipped.
find_package(benchmark QUIET)
if (NOT benchmark_FOUND)
  message(STATUS "Google Benchmark not found: BloomChainSpeed is not built")
  return ()
endif ()
find_package(VTK 9.1 QUIET COMPONENTS ImagingCore ImagingGeneral ImagingMath)
find_package(OpenCV QUIET COMPONENTS core imgproc)
if (NOT OpenCV_FOUND)
  # libopencv-imgproc-dev ships the headers and libraries but not OpenCVConfig.cmake (that comes
  # with the much larger libopencv-dev), so look for them directly.
  find_path(VTKBLOOM_OPENCV_INCLUDE_DIR opencv2/imgproc.hpp PATH_SUFFIXES opencv4)
  find_library(VTKBLOOM_OPENCV_CORE opencv_core)
  find_library(VTKBLOOM_OPENCV_IMGPROC opencv_imgproc)
  if (VTKBLOOM_OPENCV_INCLUDE_DIR AND VTKBLOOM_OPENCV_CORE AND VTKBLOOM_OPENCV_IMGPROC)
    set(OpenCV_FOUND TRUE)
    set(OpenCV_INCLUDE_DIRS "${VTKBLOOM_OPENCV_INCLUDE_DIR}")
    set(OpenCV_LIBS "${VTKBLOOM_OPENCV_IMGPROC}" "${VTKBLOOM_OPENCV_CORE}")
    set(OpenCV_VERSION "(Debian libraries)")
  endif ()
endif ()

add_executable(BloomChainSpeed "${CMAKE_CURRENT_LIST_DIR}/Speed/ChainSpeed.cxx")
target_link_libraries(BloomChainSpeed PRIVATE benchmark::benchmark VTKBloom::FiltersBloom
  VTK::ImagingMath VTK::ImagingGeneral VTK::ImagingCore VTK::CommonExecutionModel
  VTK::CommonDataModel VTK::CommonCore vtkbloom_build_flags)
target_include_directories(BloomChainSpeed PRIVATE "${CMAKE_CURRENT_LIST_DIR}")
if (OpenCV_FOUND)
  target_compile_definitions(BloomChainSpeed PRIVATE VTKBLOOM_HAVE_OPENCV=1)
  target_include_directories(BloomChainSpeed SYSTEM PRIVATE ${OpenCV_INCLUDE_DIRS})
  target_link_libraries(BloomChainSpeed PRIVATE ${OpenCV_LIBS})
  message(STATUS "BloomChainSpeed: OpenCV ${OpenCV_VERSION} rows enabled")
else ()
  message(STATUS "BloomChainSpeed: OpenCV not found, its rows are skipped")
endif ()
# Hook for the GPU row (the render pass on OSMesa): a source that defines
# vtkBloomRegisterGPUBenchmarks() is linked in when it exists.
if (EXISTS "${CMAKE_CURRENT_LIST_DIR}/Speed/ChainSpeedGPU.cxx" AND TARGET VTKBloom::RenderingBloom)
  target_sources(BloomChainSpeed PRIVATE "${CMAKE_CURRENT_LIST_DIR}/Speed/ChainSpeedGPU.cxx")
  target_link_libraries(BloomChainSpeed PRIVATE VTKBloom::RenderingBloom vtkbloom_scenes
    VTK::RenderingOpenGL2 VTK::RenderingCore ${vtkbloom_opengl_modules})
endif ()
