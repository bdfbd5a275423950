// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkBloomPassTesting.h
 * @brief  (private to vtk-bloom's tests and benchmarks) switches of vtkBloomPass that no user
 *         sets, kept out of its public header.
 *
 * As VTK's own tests reach internals through private headers: not installed, not wrapped.
 */

#ifndef vtkBloomPassTesting_h
#define vtkBloomPassTesting_h

#include "vtkRenderingBloomModule.h" // For export macro

class vtkBloomPass;

class VTKRENDERINGBLOOM_EXPORT vtkBloomPassTesting
{
public:
  /**
   * On (the default), the scene renders into the depth buffer of the framebuffer the pass was
   * called with where the two match (vtkBloomPassDepth::Share); off, the pass always draws the
   * depth after the composite, as it did before: the frame-cost check shows that its counts
   * see that draw, and the benchmarks measure what it cost.
   */
  static void SetShareWindowDepth(vtkBloomPass* pass, bool share);
  static bool GetShareWindowDepth(vtkBloomPass* pass);
};

#endif
// VTK-HeaderTest-Exclude: vtkBloomPassTesting.h
