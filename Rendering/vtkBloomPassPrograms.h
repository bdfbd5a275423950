// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkBloomPassPrograms.h
 * @brief  (private to vtkBloomPass) what the pass asks of the context to build and run its
 *         compute programs: whether it runs them, its extensions, and one program compiled
 *         and linked.
 *
 * Shared by the chain's passes, the region's reduction and the three FFT paths, none of which
 * needs the others for it. docs/architecture.md plans the rest of the programs' service here
 * (their pools, uniforms and dispatch).
 */

#ifndef vtkBloomPassPrograms_h
#define vtkBloomPassPrograms_h

#include <string> // For the compiler's log

class vtkBloomPassPrograms
{
public:
  /**
   * Compile and link one compute shader; 0 when either fails, with the compiler's log in
   * `log` (when given).
   */
  static unsigned int BuildComputeProgram(const char* source, std::string* log);

  /**
   * Whether the current context runs compute shaders as the pass writes them: OpenGL 4.3, or
   * an older context that lists GL_ARB_compute_shader, GL_ARB_shader_image_load_store and
   * GL_ARB_shader_storage_buffer_object; their entry points loaded. `version`: major * 10 +
   * minor.
   */
  static bool ContextRunsCompute(int* version = nullptr);
  /// Whether the current context lists the extension `name` (glGetStringi).
  static bool HasExtension(const char* name);
};

#endif
// VTK-HeaderTest-Exclude: vtkBloomPassPrograms.h
