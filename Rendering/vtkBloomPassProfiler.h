// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkBloomPassProfiler.h
 * @brief  (private to vtkBloomPass) the opt-in per-pass GPU profile of a frame
 *         (vtkBloomPassTesting::SetProfilePasses): a timestamp query at each end of a span of
 *         work, the span's name, size and compulsory memory traffic, and the times once the
 *         frame is done.
 *
 * Timestamps rather than GL_TIME_ELAPSED, which cannot nest: a caller may time the whole frame
 * with a GL_TIME_ELAPSED query around the pass. Off (the default), Begin() and End() do
 * nothing, and the caller may test IsOn() to skip the work of naming a span.
 */

#ifndef vtkBloomPassProfiler_h
#define vtkBloomPassProfiler_h

#include "vtkBloomPassTypes.h" // For the profile's entries

#include <string>
#include <vector>

class vtkBloomPassProfiler
{
public:
  /// Start a frame, profiled or not: the entries start from nothing.
  void StartFrame(bool on);
  bool IsOn() const { return this->On; }

  /// Bracket one span of GPU work, listed as `name`, width x height samples and `bytes`.
  void Begin();
  void End(const std::string& name, int width, int height, double bytes);

  /// Wait for the GPU and fill in the entries' times (the context current).
  void Resolve();
  const std::vector<vtkBloomPassProfiledPass>& GetEntries() const { return this->Entries; }

  /// Free the queries (the context current) and forget the entries.
  void ReleaseGraphicsResources();

private:
  bool On = false;
  std::vector<unsigned int> Queries; ///< two per entry, kept from frame to frame
  std::vector<vtkBloomPassProfiledPass> Entries;
};

#endif
// VTK-HeaderTest-Exclude: vtkBloomPassProfiler.h
