// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkOpenEXRThreadPool.h"

#include "vtkSMPTools.h"

#include <ImfThreading.h>

#include <algorithm>
#include <mutex>

//------------------------------------------------------------------------------
int vtkOpenEXRUseThreadPool(int requested)
{
  const int threads =
    requested > 0 ? requested : std::max(1, vtkSMPTools::GetEstimatedNumberOfThreads());
  if (threads <= 1)
  {
    return 0;
  }
  static std::mutex lock;
  std::lock_guard<std::mutex> guard(lock);
  if (Imf::globalThreadCount() < threads)
  {
    Imf::setGlobalThreadCount(threads);
  }
  return threads;
}
