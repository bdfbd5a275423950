# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
# CMakeLists.txt for ThirdParty/glew/vtkglew in Debian's VTK 9.1 source, which strips the bundled
# glew. scripts/lib/build-debian-vtk.sh (the OSMesa and the EGL builds) copies glew 2.2's src/glew.c
# and include/GL/*.h beside it. GLEW_OSMESA makes glew resolve entry points with
# OSMesaGetProcAddress, GLEW_EGL with eglGetProcAddress, so neither build needs GLX.
file(GLOB vtkglew_headers RELATIVE "${CMAKE_CURRENT_SOURCE_DIR}" include/GL/*.h)

vtk_module_add_module(VTK::glew
  SOURCES src/glew.c
  HEADERS ${vtkglew_headers}
  HEADERS_SUBDIR "vtkglew/include/GL")
target_compile_definitions(glew PRIVATE GLEW_NO_GLU)
target_include_directories(glew PRIVATE "${CMAKE_CURRENT_SOURCE_DIR}/include")

if (VTK_OPENGL_HAS_OSMESA AND UNIX)
  target_compile_definitions(glew PRIVATE GLEW_OSMESA)
  target_link_libraries(glew PRIVATE ${CMAKE_DL_LIBS})
endif ()
if (VTK_OPENGL_HAS_EGL)
  target_compile_definitions(glew PRIVATE GLEW_EGL)
endif ()
if (NOT BUILD_SHARED_LIBS)
  target_compile_definitions(glew PUBLIC GLEW_STATIC)
endif ()
