# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
# Frame time of an example scene with and without vtkBloomPass, by GPU timer and wall clock,
# and the per-pass GPU profile of the bloom frame:
#   BloomPassFrameTime [--profile] [SCENE [WIDTH HEIGHT [FRAMES [PRESET]]]]
if (NOT VTKBLOOM_ENABLE_RENDERING)
  return ()
endif ()
add_executable(BloomPassFrameTime BloomPassFrameTime.cxx)
target_link_libraries(BloomPassFrameTime PRIVATE vtkbloom_scenes VTKBloom::RenderingBloom
  VTK::RenderingOpenGL2 VTK::RenderingCore VTK::CommonCore ${vtkbloom_opengl_modules} vtkbloom_build_flags)
vtk_module_autoinit(TARGETS BloomPassFrameTime MODULES VTK::RenderingOpenGL2)

# The same full-screen pass as a fragment shader and as a compute shader (OpenGL 4.3):
#   ShaderStageThroughput [WIDTH HEIGHT [FRAMES]]
set(stage_shaders)
foreach (stage IN ITEMS VS FS CS)
  vtk_encode_string(
    INPUT         "${CMAKE_CURRENT_LIST_DIR}/glsl/StageThroughput${stage}.glsl"
    HEADER_OUTPUT header
    SOURCE_OUTPUT source)
  list(APPEND stage_shaders "${source}")
endforeach ()
add_executable(ShaderStageThroughput ShaderStageThroughput.cxx ${stage_shaders})
target_include_directories(ShaderStageThroughput PRIVATE "${CMAKE_CURRENT_BINARY_DIR}")
target_link_libraries(ShaderStageThroughput PRIVATE VTKBloom::RenderingBloom VTK::RenderingOpenGL2 VTK::RenderingCore
  VTK::CommonCore ${vtkbloom_opengl_modules} vtkbloom_build_flags)
vtk_module_autoinit(TARGETS ShaderStageThroughput MODULES VTK::RenderingOpenGL2)
