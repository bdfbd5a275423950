// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkOpenEXRThreadPool.h
 * @brief  (private to the OpenEXR reader and writer) OpenEXR's C++ library runs its per-file
 *         compression and decompression tasks on one global thread pool, which has no threads
 *         unless an application asks for them.
 */
#ifndef vtkOpenEXRThreadPool_h
#define vtkOpenEXRThreadPool_h

/**
 * Make the global pool at least `requested` threads large (0: as many as vtkSMPTools would
 * use) and return the count to pass to OpenEXR's file classes (0 when one thread: the calling
 * thread does the work). The pool is never shrunk, so an application's own larger setting
 * stands.
 */
int vtkOpenEXRUseThreadPool(int requested);

#endif
// VTK-HeaderTest-Exclude: vtkOpenEXRThreadPool.h
