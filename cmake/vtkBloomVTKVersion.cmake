# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
# Where vtk-bloom's CMake meets the differences between the VTK versions it builds against
# (9.1 to 9.6); the C++ side is Rendering/vtkBloomVTKCompat.h. Included once, after
# find_package(VTK), by the top-level project and by the ParaView plugin.
#
# vtkbloom_opengl_modules: what code that calls OpenGL itself links.
#   VTK 9.1 to 9.3: the glew loader, and VTK::opengl, the system's libGL (or libOSMesa, or
#   libEGL in the headless builds of scripts/lib/build-debian-vtk.sh).
#   VTK 9.4 and later: the glad loader, which opens libGL, libEGL or libOSMesa when a window is
#   made: there is no VTK::opengl to link, and one VTK holds the X, EGL and OSMesa windows.
if (TARGET VTK::glad)
  set(vtkbloom_opengl_modules VTK::glad)
elseif (TARGET VTK::glew AND TARGET VTK::opengl)
  set(vtkbloom_opengl_modules VTK::glew VTK::opengl)
else ()
  message(FATAL_ERROR "VTK ${VTK_VERSION} offers neither VTK::glad (9.4 and later) nor "
    "VTK::glew and VTK::opengl (9.1 to 9.3): vtk-bloom cannot reach OpenGL through it.")
endif ()

# The render window VTK opens with no display: fixed when VTK is built up to 9.3, chosen at
# run time (X, then EGL, then OSMesa, or VTK_DEFAULT_OPENGL_WINDOW) from 9.4.
if (VTK_VERSION VERSION_LESS "9.4")
  set(vtkbloom_window_choice "fixed when VTK was built")
else ()
  set(vtkbloom_window_choice "chosen at run time (VTK_DEFAULT_OPENGL_WINDOW)")
endif ()
message(STATUS "vtk-bloom: VTK ${VTK_VERSION}, OpenGL through ${vtkbloom_opengl_modules}, "
  "render window ${vtkbloom_window_choice}")
