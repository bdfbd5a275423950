# Frame time of an example scene with and without vtkBloomPass:
#   BloomPassFrameTime [SCENE] [WIDTH HEIGHT] [FRAMES]
if (NOT VTKBLOOM_ENABLE_RENDERING)
  return ()
endif ()
add_executable(BloomPassFrameTime BloomPassFrameTime.cxx)
target_link_libraries(BloomPassFrameTime PRIVATE vtkbloom_scenes VTKBloom::RenderingBloom
  VTK::RenderingOpenGL2 VTK::RenderingCore VTK::CommonCore vtkbloom_build_flags)
vtk_module_autoinit(TARGETS BloomPassFrameTime MODULES VTK::RenderingOpenGL2)
