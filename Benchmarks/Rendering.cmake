# Frame time of an example scene with and without vtkBloomPass, by GPU timer and wall clock,
# and the per-pass GPU profile of the bloom frame:
#   BloomPassFrameTime [--profile] [SCENE [WIDTH HEIGHT [FRAMES [PRESET]]]]
if (NOT VTKBLOOM_ENABLE_RENDERING)
  return ()
endif ()
add_executable(BloomPassFrameTime BloomPassFrameTime.cxx)
target_link_libraries(BloomPassFrameTime PRIVATE vtkbloom_scenes VTKBloom::RenderingBloom
  VTK::RenderingOpenGL2 VTK::RenderingCore VTK::CommonCore VTK::opengl vtkbloom_build_flags)
vtk_module_autoinit(TARGETS BloomPassFrameTime MODULES VTK::RenderingOpenGL2)
