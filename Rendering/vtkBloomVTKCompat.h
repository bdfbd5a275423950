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
 *   crash of a missing OSMesa into a message.
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
#include <dlfcn.h>
#else
#include "vtk_glew.h" // IWYU pragma: export
#endif

#if VTKBLOOM_VTK_AT_LEAST(9, 3)
#include "vtkCompositePolyDataMapper.h"
using vtkBloomCompositePolyDataMapper = vtkCompositePolyDataMapper;
#else
#include "vtkCompositePolyDataMapper2.h"
using vtkBloomCompositePolyDataMapper = vtkCompositePolyDataMapper2;
#endif

#if VTKBLOOM_VTK_AT_LEAST(9, 4)
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
#endif

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
 * VTK 9.1 fixes the window when it is built, so there is nothing to check there.
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
  (void)why;
#endif
  return true;
}

#endif
