// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkBloomVTKCompat.h
 * @brief  Where vtk-bloom's C++ meets the differences between the VTK versions it builds
 *         against (9.1 to 9.6). The CMake side is cmake/vtkBloomVTKVersion.cmake.
 *
 * - The OpenGL loader: VTK up to 9.3 ships glew (vtk_glew.h), VTK 9.4 and later glad
 *   (vtk_glad.h), which loads libGL, libEGL or libOSMesa when a window is made.
 * - The composite mapper: vtkCompositePolyDataMapper2 (OpenGL2) became
 *   vtkCompositePolyDataMapper in VTK 9.3.
 * - The window chosen at run time (VTK 9.4 and later): vtkBloomPreferHeadlessWindow() names
 *   the headless one where there is no display, and vtkBloomCheckOpenGLWindow() turns the
 *   crash of a missing OSMesa into a message; with VTK 9.1, the abort of an X window with no
 *   display and of an EGL window with no libEGL.
 *
 * Private: not installed. Include it instead of vtk_glew.h or vtk_glad.h.
 */
#ifndef vtkBloomVTKCompat_h
#define vtkBloomVTKCompat_h

#include "vtkVersionMacros.h"

#include <cstddef>
#include <cstdlib>
#include <string>

#define VTKBLOOM_VTK_AT_LEAST(major, minor)                                                        \
  (VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(major, minor, 0))

#if VTKBLOOM_VTK_AT_LEAST(9, 4)
#include "vtk_glad.h" // IWYU pragma: export
#else
#include "vtk_glew.h" // IWYU pragma: export
#endif
#include "vtkRenderWindow.h"
#include "vtkSmartPointer.h"

#include <dlfcn.h>

#if VTKBLOOM_VTK_AT_LEAST(9, 3)
#include "vtkCompositePolyDataMapper.h"
using vtkBloomCompositePolyDataMapper = vtkCompositePolyDataMapper;
#else
#include "vtkCompositePolyDataMapper2.h"
using vtkBloomCompositePolyDataMapper = vtkCompositePolyDataMapper2;
#endif

/// The libraries VTK 9.4 and later load (dlopen) for the EGL and the OSMesa windows; for
/// OSMesa the names it tries, in its order.
inline constexpr const char* vtkBloomEGLLibraries[] = { "libEGL.so.1" };
inline constexpr const char* vtkBloomOSMesaLibraries[] = { "libOSMesa.so.8", "libOSMesa.so.6",
  "libOSMesa.so" };

/// Whether one of `libraries` can be loaded, as VTK loads the window's GL library.
template <size_t N>
inline bool vtkBloomCanLoad(const char* const (&libraries)[N])
{
  for (const char* library : libraries)
  {
    if (void* handle = dlopen(library, RTLD_LAZY | RTLD_LOCAL))
    {
      dlclose(handle);
      return true;
    }
  }
  return false;
}

/**
 * Whether the X display that DISPLAY names opens. VTK 9.1's X window calls abort() when it
 * does not, with no message; this asks Xlib first (loaded here, so that nothing links it).
 */
inline bool vtkBloomCanOpenXDisplay(std::string& why)
{
  const char* display = std::getenv("DISPLAY");
  if (display == nullptr || *display == '\0')
  {
    why = "DISPLAY is not set";
    return false;
  }
  void* xlib = dlopen("libX11.so.6", RTLD_LAZY | RTLD_LOCAL);
  if (xlib == nullptr)
  {
    why = "libX11.so.6 cannot be loaded";
    return false;
  }
  using OpenDisplay = void* (*)(const char*);
  using CloseDisplay = int (*)(void*);
  auto open = reinterpret_cast<OpenDisplay>(dlsym(xlib, "XOpenDisplay"));
  auto close = reinterpret_cast<CloseDisplay>(dlsym(xlib, "XCloseDisplay"));
  void* connection = open && close ? open(display) : nullptr;
  if (connection)
  {
    close(connection);
  }
  dlclose(xlib);
  if (connection == nullptr)
  {
    why = std::string("DISPLAY=") + display + " cannot be opened";
    return false;
  }
  return true;
}

/**
 * With no X display, VTK 9.4 and later try X first, log a warning to stderr, then fall back
 * to EGL and OSMesa. Where neither DISPLAY nor VTK_DEFAULT_OPENGL_WINDOW says anything, this
 * names the headless window this machine can make (EGL, else OSMesa), so that VTK chooses it
 * without the warning. VTK 9.1 fixes its window when it is built: nothing to do.
 */
inline void vtkBloomPreferHeadlessWindow()
{
#if VTKBLOOM_VTK_AT_LEAST(9, 4)
  const char* display = std::getenv("DISPLAY");
  if (std::getenv("VTK_DEFAULT_OPENGL_WINDOW") || (display && *display))
  {
    return;
  }
  if (vtkBloomCanLoad(vtkBloomEGLLibraries))
  {
    setenv("VTK_DEFAULT_OPENGL_WINDOW", "vtkEGLRenderWindow", 0);
  }
  else if (vtkBloomCanLoad(vtkBloomOSMesaLibraries))
  {
    setenv("VTK_DEFAULT_OPENGL_WINDOW", "vtkOSOpenGLRenderWindow", 0);
  }
#endif
}

/**
 * Whether a render window of the kind VTK will choose can be made; when not, `why` says so
 * in one line. VTK 9.4 and later pick the window at run time, and VTK_DEFAULT_OPENGL_WINDOW
 * names one. Asked for vtkOSOpenGLRenderWindow where no libOSMesa exists (Mesa removed it in
 * 25.1), or set to an empty string, VTK 9.6 warns and then crashes; this check runs first.
 * VTK 9.1 fixes the window when it is built: there, an X window needs a display that opens
 * (else VTK aborts with no word), and an EGL window needs libEGL.
 */
inline bool vtkBloomCheckOpenGLWindow(std::string& why)
{
#if VTKBLOOM_VTK_AT_LEAST(9, 4)
  const char* requested = std::getenv("VTK_DEFAULT_OPENGL_WINDOW");
  if (requested == nullptr)
  {
    return true;
  }
  const std::string name = requested;
  if (name.empty())
  {
    why = "VTK_DEFAULT_OPENGL_WINDOW is set but empty: unset it, or set it to "
          "vtkXOpenGLRenderWindow, vtkEGLRenderWindow or vtkOSOpenGLRenderWindow";
    return false;
  }
  if (name == "vtkOSOpenGLRenderWindow" && !vtkBloomCanLoad(vtkBloomOSMesaLibraries))
  {
    why = "VTK_DEFAULT_OPENGL_WINDOW=vtkOSOpenGLRenderWindow, but libOSMesa is not installed "
          "(Mesa 25.1 removed it): use vtkEGLRenderWindow for headless rendering, or unset "
          "the variable";
    return false;
  }
#else
  // VTK 9.1 builds one window in: an X one aborts where no display opens, an EGL one where
  // there is no libEGL. Making the object opens nothing; only its class is asked.
  const std::string name = vtkSmartPointer<vtkRenderWindow>::New()->GetClassName();
  std::string missing;
  if (name == "vtkXOpenGLRenderWindow" && !vtkBloomCanOpenXDisplay(missing))
  {
    why = "this VTK renders through X and " + missing +
      ": run under xvfb-run -a, set DISPLAY, or build against the OSMesa or EGL VTK "
      "(bash scripts/build-osmesa-vtk.sh; docs/building.md)";
    return false;
  }
  if (name == "vtkEGLRenderWindow" && !vtkBloomCanLoad(vtkBloomEGLLibraries))
  {
    why = "this VTK renders through EGL and libEGL.so.1 cannot be loaded: install libegl1 "
          "and a driver (libegl-mesa0 or NVIDIA's), or use the OSMesa VTK";
    return false;
  }
#endif
  return true;
}

#endif
