// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * What the OpenGL context of this test run gives the bloom pass, found once before any test
 * by vtkBloomOpenGLEnvironment.cxx (linked into every vtkbloom_add_gtest OPENGL test).
 */
#ifndef vtkBloomOpenGLEnvironment_h
#define vtkBloomOpenGLEnvironment_h

/**
 * Whether vtkBloomPass runs its chain as compute passes here (OpenGL 4.3, or an older context
 * with the compute extensions): the pass's own decision, seen as GetLastFrame()->GetComputePasses()
 * of a frame with light. Where the CI leg says it must (VTKBLOOM_EXPECT_COMPUTE=1), a context
 * without them fails the whole suite before its first test, so a compute test cannot pass by
 * skipping there.
 */
bool vtkBloomTestComputePassesRun();

#endif
