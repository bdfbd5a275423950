// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// The opt-in per-pass profile of vtkBloomPassChainRunner (vtkBloomPassTesting::SetProfilePasses): a
// timestamp query at each end of a pass, the pass's size and its compulsory memory traffic, and
// the resolution of the queries once the frame is done. The chain itself is in
// vtkBloomPassChainRunner.cxx; Pass() calls in here only when profiling is on.
#include "vtkBloomPassChainRunner.h"

#include "vtkBloomChain.h"
#include "vtkBloomPassResources.h"
#include "vtkBloomVTKCompat.h"

#include <string>

//------------------------------------------------------------------------------
void vtkBloomPassChainRunner::BeginProfiledSpan()
{
  // Timestamps rather than GL_TIME_ELAPSED, which cannot nest: a caller may time the whole
  // frame with a GL_TIME_ELAPSED query around the pass.
  const size_t first = 2 * this->Profile.size();
  if (this->TimestampQueries.size() < first + 2)
  {
    const size_t old = this->TimestampQueries.size();
    this->TimestampQueries.resize(first + 2);
    glGenQueries(static_cast<GLsizei>(first + 2 - old), this->TimestampQueries.data() + old);
  }
  glQueryCounter(this->TimestampQueries[first], GL_TIMESTAMP);
}

//------------------------------------------------------------------------------
void vtkBloomPassChainRunner::EndProfiledSpan(
  const std::string& name, int width, int height, double bytes)
{
  glQueryCounter(this->TimestampQueries[2 * this->Profile.size() + 1], GL_TIMESTAMP);
  ProfiledPass entry;
  entry.Name = name;
  entry.Size[0] = width;
  entry.Size[1] = height;
  entry.Bytes = bytes;
  this->Profile.push_back(entry);
}

//------------------------------------------------------------------------------
void vtkBloomPassChainRunner::EndProfiledPass(const PassSpec& spec)
{
  // Bytes per texel of the chain's targets; the window's framebuffer (the composite's target
  // when it is null) is counted at the same rate.
  const double texel = this->Resources.Format == GL_RGBA32F ? 16.0 : 8.0;
  const double w = spec.X ? spec.X->OutputSize : spec.SourceSize[0];
  const double h = spec.Y ? spec.Y->OutputSize : spec.SourceSize[1];
  double bytes = texel * spec.SourceSize[0] * spec.SourceSize[1] + texel * w * h;
  if (spec.Blend)
  {
    bytes += texel * w * h;
  }
  if (spec.Addend)
  {
    bytes += texel * w * h;
  }
  if (spec.Step == STEP_COMPOSITE)
  {
    bytes += texel * this->Resources.Chain.Width * this->Resources.Chain.Height;
  }
  if (spec.ReadsSource && this->In.Mask)
  {
    bytes += 2.0 * 4.0 * spec.SourceSize[0] * spec.SourceSize[1]; // the two depth textures
  }
  std::string name = spec.Name;
  if (spec.Level >= 0)
  {
    name += " L" + std::to_string(spec.Level);
  }
  this->EndProfiledSpan(name, static_cast<int>(w), static_cast<int>(h), bytes);
}

//------------------------------------------------------------------------------
void vtkBloomPassChainRunner::ResolveProfile()
{
  for (size_t i = 0; i < this->Profile.size(); ++i)
  {
    GLuint64 start = 0, end = 0;
    glGetQueryObjectui64v(this->TimestampQueries[2 * i], GL_QUERY_RESULT, &start);
    glGetQueryObjectui64v(this->TimestampQueries[2 * i + 1], GL_QUERY_RESULT, &end);
    this->Profile[i].Milliseconds = end >= start ? 1e-6 * static_cast<double>(end - start) : 0.0;
  }
}
