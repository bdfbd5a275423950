// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkBloomPassProfiler.h"

#include "vtkBloomVTKCompat.h"

//------------------------------------------------------------------------------
void vtkBloomPassProfiler::StartFrame(bool on)
{
  this->On = on;
  this->Entries.clear();
}

//------------------------------------------------------------------------------
void vtkBloomPassProfiler::Begin()
{
  if (!this->On)
  {
    return;
  }
  const size_t first = 2 * this->Entries.size();
  if (this->Queries.size() < first + 2)
  {
    const size_t old = this->Queries.size();
    this->Queries.resize(first + 2);
    glGenQueries(static_cast<GLsizei>(first + 2 - old), this->Queries.data() + old);
  }
  glQueryCounter(this->Queries[first], GL_TIMESTAMP);
}

//------------------------------------------------------------------------------
void vtkBloomPassProfiler::End(const std::string& name, int width, int height, double bytes)
{
  if (!this->On)
  {
    return;
  }
  glQueryCounter(this->Queries[2 * this->Entries.size() + 1], GL_TIMESTAMP);
  vtkBloomPassProfiledPass entry;
  entry.Name = name;
  entry.Size[0] = width;
  entry.Size[1] = height;
  entry.Bytes = bytes;
  this->Entries.push_back(entry);
}

//------------------------------------------------------------------------------
void vtkBloomPassProfiler::Resolve()
{
  for (size_t i = 0; i < this->Entries.size(); ++i)
  {
    GLuint64 start = 0, end = 0;
    glGetQueryObjectui64v(this->Queries[2 * i], GL_QUERY_RESULT, &start);
    glGetQueryObjectui64v(this->Queries[2 * i + 1], GL_QUERY_RESULT, &end);
    this->Entries[i].Milliseconds = end >= start ? 1e-6 * static_cast<double>(end - start) : 0.0;
  }
}

//------------------------------------------------------------------------------
void vtkBloomPassProfiler::ReleaseGraphicsResources()
{
  if (!this->Queries.empty())
  {
    glDeleteQueries(static_cast<GLsizei>(this->Queries.size()), this->Queries.data());
    this->Queries.clear();
  }
  this->Entries.clear();
}
