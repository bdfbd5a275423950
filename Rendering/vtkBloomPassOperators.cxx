// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkBloomPassOperators.h"

#include "vtkBloomLinearOperator.h"
#include "vtkBloomVTKCompat.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkTextureObject.h"

#include <algorithm>
#include <sstream>

//------------------------------------------------------------------------------
vtkBloomPassOperators::Interior vtkBloomPassOperators::Interior::Find(
  const vtkBloomLinearOperator& op)
{
  const int width = op.Width;
  auto weight = [&op, width](int j, int k)
  { return static_cast<float>(op.Weights[static_cast<size_t>(j) * width + k]); };
  // Too short an interior is not worth its own draw. A stride of 0 (an input of one
  // sample) would leave the shader independent of the fragment's position, so
  // FindInvariantRange refuses it and the table evaluates such an operator.
  const int minimum = 8;
  for (int period : { 1, 2 })
  {
    const vtkBloomLinearOperator::InvariantRange range = op.FindInvariantRange(period, minimum);
    if (range.Begin == range.End)
    {
      continue;
    }
    const int begin = range.Begin, end = range.End, stride = range.Stride;
    // Drop the band's zero padding common to every phase.
    int lo = width, hi = 0;
    for (int ph = 0; ph < period; ++ph)
    {
      for (int k = 0; k < width; ++k)
      {
        if (weight(begin + ph, k) != 0.0f)
        {
          lo = std::min(lo, k);
          hi = std::max(hi, k + 1);
        }
      }
    }
    if (hi <= lo || hi - lo > 31) // a bit per tap in Defines()
    {
      continue;
    }
    Interior interior;
    interior.Begin = begin;
    interior.End = end;
    interior.Period = period;
    interior.Stride = stride;
    interior.Taps = hi - lo;
    for (int ph = 0; ph < 2; ++ph)
    {
      interior.First[ph] = op.First[begin + std::min(ph, period - 1)] + lo;
    }
    for (int ph = 0; ph < period; ++ph)
    {
      for (int k = lo; k < hi; ++k)
      {
        interior.Weights.push_back(weight(begin + ph, k));
      }
    }
    return interior;
  }
  return Interior();
}

//------------------------------------------------------------------------------
std::string vtkBloomPassOperators::Interior::Defines(const char* axis) const
{
  // Bit k of ANY: tap k is non-zero in some phase (else it is compiled out); of
  // ALL: in every phase (no run-time test of its weight). Only the first 32 taps have bits (a
  // shift by 32 or more is undefined in C++ and in GLSL); the shader tests the weight of the
  // others (tapIsOn).
  const int masked = std::min(this->Taps, 32);
  unsigned int any = 0, all = masked == 32 ? 0xffffffffu : (1u << masked) - 1u;
  for (int ph = 0; ph < this->Period; ++ph)
  {
    for (int k = 0; k < masked; ++k)
    {
      if (this->Weights[ph * this->Taps + k] != 0.0f)
      {
        any |= 1u << k;
      }
      else
      {
        all &= ~(1u << k);
      }
    }
  }
  std::ostringstream os;
  os << "#define " << axis << "_PERIOD " << this->Period << "\n#define " << axis << "_STRIDE "
     << this->Stride << "\n#define " << axis << "_TAPS " << this->Taps << "\n#define " << axis
     << "_ANY " << any << "u\n#define " << axis << "_ALL " << all << "u\n";
  return os.str();
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkBloomPassOperators::Texture(
  vtkOpenGLRenderWindow* context, const vtkBloomLinearOperator& op)
{
  auto found = this->Textures.find(&op);
  if (found != this->Textures.end())
  {
    return found->second;
  }
  // Row j: First[j] then the band's weights; exact in float for indices below 2^24.
  const int columns = op.Width + 1;
  std::vector<float> rows(static_cast<size_t>(columns) * op.OutputSize);
  for (int j = 0; j < op.OutputSize; ++j)
  {
    float* row = rows.data() + static_cast<size_t>(j) * columns;
    row[0] = static_cast<float>(op.First[j]);
    for (int k = 0; k < op.Width; ++k)
    {
      row[k + 1] = static_cast<float>(op.Weights[static_cast<size_t>(j) * op.Width + k]);
    }
  }
  vtkNew<vtkTextureObject> texture;
  texture->SetContext(context);
  texture->SetInternalFormat(GL_R32F);
  texture->SetMinificationFilter(vtkTextureObject::Nearest);
  texture->SetMagnificationFilter(vtkTextureObject::Nearest);
  texture->Create2DFromRaw(columns, op.OutputSize, 1, VTK_FLOAT, rows.data());
  this->Textures[&op] = texture.Get();
  return texture;
}

//------------------------------------------------------------------------------
const vtkBloomPassOperators::Interior& vtkBloomPassOperators::InteriorOf(
  const vtkBloomLinearOperator& op)
{
  auto found = this->Interiors.find(&op);
  if (found == this->Interiors.end())
  {
    found = this->Interiors.emplace(&op, Interior::Find(op)).first;
  }
  return found->second;
}

//------------------------------------------------------------------------------
int vtkBloomPassOperators::TileRows(const vtkBloomLinearOperator& y)
{
  auto found = this->TileRowCounts.find(&y);
  if (found != this->TileRowCounts.end())
  {
    return found->second;
  }
  // A tile's 16 output rows may start anywhere (a restricted pass starts at its region): the
  // largest span over every 16 consecutive rows, First increasing along the band. Rounded up
  // to 16, so that operators of one shape share a program.
  int rows = 0;
  for (int j = 0; j < y.OutputSize; ++j)
  {
    if (j > 0 && y.First[j] < y.First[j - 1])
    {
      rows = MaximumTileRows + 1; // not a band whose rows advance: never tiled
      break;
    }
    const int last = std::min(j + 15, y.OutputSize - 1);
    rows = std::max(rows, y.First[last] + y.Width - y.First[j]);
  }
  rows = (rows + 15) / 16 * 16;
  this->TileRowCounts[&y] = rows;
  return rows;
}

//------------------------------------------------------------------------------
std::vector<vtkBloomPassSegment> vtkBloomPassOperators::Segments(
  const vtkBloomLinearOperator* op, int size, bool single)
{
  if (!op)
  {
    return { { 0, size, vtkBloomPassShaderValues::OP_IDENTITY } };
  }
  const Interior& interior = this->InteriorOf(*op);
  if (single || interior.End <= interior.Begin)
  {
    return { { 0, op->OutputSize, vtkBloomPassShaderValues::OP_TABLE } };
  }
  std::vector<vtkBloomPassSegment> segments;
  if (interior.Begin > 0)
  {
    segments.push_back({ 0, interior.Begin, vtkBloomPassShaderValues::OP_TABLE });
  }
  segments.push_back({ interior.Begin, interior.End, vtkBloomPassShaderValues::OP_PERIODIC });
  if (interior.End < op->OutputSize)
  {
    segments.push_back({ interior.End, op->OutputSize, vtkBloomPassShaderValues::OP_TABLE });
  }
  return segments;
}

//------------------------------------------------------------------------------
void vtkBloomPassOperators::Release(vtkWindow* w)
{
  for (auto& texture : this->Textures)
  {
    texture.second->ReleaseGraphicsResources(w);
  }
  this->Textures.clear();
  this->Interiors.clear();
  this->TileRowCounts.clear();
}
