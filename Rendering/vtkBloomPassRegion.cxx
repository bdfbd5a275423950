// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// Content-aware evaluation of vtkBloomPass's chain (vtkBloomParameters::RestrictToBrightRegion):
// the bright pass is reduced to the bounding box of its non-zero samples, and every later pass
// computes only the box of output samples that read any sample of its input's box. Outside
// those boxes the full chain computes zeros (sums of zero samples), and the targets are kept
// zero there, so the restricted chain computes every sample it does compute from the same
// inputs as the full chain, and the output is the same bit for bit.
#include "vtkBloomPassChainRunner.h"

#include "vtkBloomLinearOperator.h"
#include "vtkBloomPassPrograms.h"
#include "vtkBloomPassReduceCS.h"
#include "vtkBloomPassResources.h"
#include "vtkBloomVTKCompat.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include <algorithm>
#include <vector>

namespace
{
// The samples [lo, hi) of the output of `op` whose band reads any input sample in [in0, in1).
void ReachAxis(const vtkBloomLinearOperator* op, int in0, int in1, int size, int& lo, int& hi)
{
  if (!op)
  {
    lo = std::max(in0, 0);
    hi = std::min(in1, size);
    return;
  }
  lo = op->OutputSize;
  hi = 0;
  for (int j = 0; j < op->OutputSize; ++j)
  {
    if (op->First[j] < in1 && op->First[j] + op->Width > in0)
    {
      lo = std::min(lo, j);
      hi = j + 1;
    }
  }
}

// Output tiles of one reduction step: each covers Tile x Tile input samples.
const int Tile = 8;
}

//------------------------------------------------------------------------------
vtkBloomPassChainRunner::Box vtkBloomPassChainRunner::Reach(const vtkBloomLinearOperator* x,
  const vtkBloomLinearOperator* y, const Box& in, int width, int height)
{
  Box out;
  if (in.Empty())
  {
    return out;
  }
  ReachAxis(x, in.X0, in.X1, width, out.X0, out.X1);
  ReachAxis(y, in.Y0, in.Y1, height, out.Y0, out.Y1);
  return out.Empty() ? Box() : out;
}

//------------------------------------------------------------------------------
void vtkBloomPassChainRunner::PrepareTarget(
  vtkBloomPassTarget& target, const Box* region, int width, int height)
{
  const Box whole = Box::Whole(width, height);
  const Box dirty = { target.Dirty[0], target.Dirty[1], target.Dirty[2], target.Dirty[3] };
  Box held = whole;
  if (region &&
    !(region->X0 <= 0 && region->X1 >= width && region->Y0 <= 0 && region->Y1 >= height))
  {
    held = region->Intersection(whole);
    if (held.Empty())
    {
      held = Box();
    }
    // The pass replaces `held`; whatever else the target holds must become zero.
    const bool covered = dirty.Empty() ||
      (!held.Empty() && held.X0 <= dirty.X0 && held.X1 >= dirty.X1 && held.Y0 <= dirty.Y0 &&
        held.Y1 >= dirty.Y1);
    if (!covered)
    {
      this->FlushComputeWrites();
      vtkOpenGLState* state = this->Resources.Context->GetState();
      target.FBO->Bind();
      target.FBO->ActivateDrawBuffer(0);
      state->vtkglEnable(GL_SCISSOR_TEST);
      state->vtkglScissor(dirty.X0, dirty.Y0, dirty.X1 - dirty.X0, dirty.Y1 - dirty.Y0);
      state->vtkglClearColor(0.0, 0.0, 0.0, 0.0);
      state->vtkglClear(GL_COLOR_BUFFER_BIT);
      state->vtkglDisable(GL_SCISSOR_TEST);
    }
  }
  else
  {
    // The pass replaces all of width x height; the texture may be larger (Temp).
    held = dirty.Union(whole);
  }
  target.Dirty[0] = held.X0;
  target.Dirty[1] = held.X1;
  target.Dirty[2] = held.Y0;
  target.Dirty[3] = held.Y1;
}

//------------------------------------------------------------------------------
bool vtkBloomPassChainRunner::MeasureBrightRegionByCompute(Box& box)
{
  if (!this->Frame.UseCompute || this->ComputeState < 0 || !this->ComputeSupported())
  {
    return false;
  }
  if (this->ComputeState == 0)
  {
    this->ComputeState = -1;
    const GLuint program = vtkBloomPassPrograms::BuildComputeProgram(vtkBloomPassReduceCS, nullptr);
    if (!program)
    {
      return false; // the fragment passes then
    }
    this->ReduceProgram = program;
    glGenBuffers(1, &this->ReduceBuffer);
    this->ComputeState = 1;
  }
  vtkBloomPassTarget& level = this->Resources.Levels[0];
  const GLint init[4] = { 1 << 30, 1 << 30, -1, -1 };
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->ReduceBuffer);
  glBufferData(GL_SHADER_STORAGE_BUFFER, sizeof(init), init, GL_DYNAMIC_READ);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, this->ReduceBuffer);
  glUseProgram(this->ReduceProgram);
  level.Color->Activate();
  glUniform1i(glGetUniformLocation(this->ReduceProgram, "source"), level.Color->GetTextureUnit());
  glUniform2i(
    glGetUniformLocation(this->ReduceProgram, "sourceSize"), level.Size[0], level.Size[1]);
  glDispatchCompute((level.Size[0] + 15) / 16, (level.Size[1] + 15) / 16, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  if (this->Profiler.IsOn())
  {
    // The dispatch alone; the read-back's wait is no GPU work (BloomPassFrameTime --sync).
    this->Profiler.End("reduce (compute)", 1, 1,
      16.0 * this->Resources.Levels[0].Size[0] * this->Resources.Levels[0].Size[1]);
  }
  GLint result[4] = { 0, 0, -1, -1 };
  glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof(result), result);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, 0);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
  level.Color->Deactivate();
  // VTK's shader cache must know that its last program is no longer bound.
  this->Resources.Context->GetShaderCache()->ReleaseCurrentShader();
  box = result[2] >= 0 ? Box{ result[0], result[2] + 1, result[1], result[3] + 1 } : Box();
  ++this->Passes;
  ++this->ComputePasses;
  return true;
}

//------------------------------------------------------------------------------
void vtkBloomPassChainRunner::ReleaseCompute()
{
  if (this->ReduceProgram)
  {
    glDeleteProgram(this->ReduceProgram);
  }
  if (this->ReduceBuffer)
  {
    glDeleteBuffers(1, &this->ReduceBuffer);
  }
  this->ReduceProgram = this->ReduceBuffer = 0;
  this->ComputeState = 0;
  this->ComputePrograms.Clear(
    [](ComputeProgram& program)
    {
      if (program.Id)
      {
        glDeleteProgram(program.Id);
      }
    });
  this->Variants.clear();      // they point at the programs
  this->FailedCompute.clear(); // a new context builds them afresh
  this->ComputeSupport = 0;
  this->Software = 0;
}

//------------------------------------------------------------------------------
bool vtkBloomPassChainRunner::CostTimingSupported()
{
  if (this->CostTimingSupport == 0)
  {
    GLint bits = 0;
    if (glQueryCounter && glGetQueryiv)
    {
      glGetQueryiv(GL_TIMESTAMP, GL_QUERY_COUNTER_BITS, &bits);
    }
    this->CostTimingSupport = bits > 0 ? 1 : -1;
  }
  return this->CostTimingSupport > 0;
}

//------------------------------------------------------------------------------
void vtkBloomPassChainRunner::BeginCostTiming(bool measured)
{
  // Timestamps rather than GL_TIME_ELAPSED, which cannot nest: a caller may time the frame.
  if (!this->CostTimingSupported())
  {
    return;
  }
  CostSlot& slot = this->CostTimings[this->NextCostSlot]; // collected by Run()
  if (slot.Pending)
  {
    return; // every slot still in flight: this evaluation goes untimed rather than wait
  }
  if (!slot.Queries[0])
  {
    glGenQueries(2, slot.Queries);
  }
  glQueryCounter(slot.Queries[0], GL_TIMESTAMP);
  slot.Measured = measured;
  slot.ContentAware = this->Frame.Restrict;
  this->CostTimingOpen = true;
  this->CompiledProgram = false;
}

//------------------------------------------------------------------------------
void vtkBloomPassChainRunner::EndCostTiming()
{
  if (!this->CostTimingOpen)
  {
    return;
  }
  CostSlot& slot = this->CostTimings[this->NextCostSlot];
  if (this->CompiledProgram)
  {
    // Compiling a program stalls the GPU far longer than the chain runs: not a sample. The
    // first full chain compiles the programs of the operators' borders the region had left
    // out; time the next one instead.
    this->CostTimingOpen = false;
    if (!slot.Measured && slot.ContentAware)
    {
      this->FramesUntilExplore = 1;
    }
    return;
  }
  glQueryCounter(slot.Queries[1], GL_TIMESTAMP);
  slot.Pending = true;
  this->NextCostSlot = (this->NextCostSlot + 1) % CostSlots;
  this->CostTimingOpen = false;
}

//------------------------------------------------------------------------------
void vtkBloomPassChainRunner::CollectCostTimings()
{
  for (CostSlot& slot : this->CostTimings)
  {
    GLint available = 0;
    if (slot.Pending)
    {
      glGetQueryObjectiv(slot.Queries[1], GL_QUERY_RESULT_AVAILABLE, &available);
    }
    if (!available)
    {
      continue;
    }
    GLuint64 start = 0, end = 0;
    glGetQueryObjectui64v(slot.Queries[0], GL_QUERY_RESULT, &start);
    glGetQueryObjectui64v(slot.Queries[1], GL_QUERY_RESULT, &end);
    slot.Pending = false;
    const double ms = end >= start ? 1e-6 * static_cast<double>(end - start) : 0.0;
    this->LastChainMilliseconds = ms;
    if (slot.ContentAware)
    {
      double& average = slot.Measured ? this->RegionCost : this->FullCost;
      average = average < 0.0 ? ms : 0.5 * (average + ms);
    }
  }
}

//------------------------------------------------------------------------------
bool vtkBloomPassChainRunner::RegionPays() const
{
  return this->RegionCost < 0.0 || this->FullCost < 0.0 || this->RegionCost <= this->FullCost;
}

//------------------------------------------------------------------------------
void vtkBloomPassChainRunner::ReleaseCostTiming()
{
  for (CostSlot& slot : this->CostTimings)
  {
    if (slot.Queries[0])
    {
      glDeleteQueries(2, slot.Queries);
    }
    slot = CostSlot();
  }
  this->NextCostSlot = 0;
  this->CostTimingOpen = false;
  this->CostTimingSupport = 0;
  this->RegionCost = this->FullCost = -1.0;
  this->FramesUntilExplore = FirstExplore;
  this->RegionDeclined = false;
}

//------------------------------------------------------------------------------
vtkBloomPassChainRunner::Box vtkBloomPassChainRunner::MeasureBrightRegion()
{
  this->FlushComputeWrites(); // the bright pass's writes, read by the reduction
  vtkBloomPassResources& res = this->Resources;
  vtkOpenGLState* state = res.Context->GetState();
  this->Profiler.Begin();
  const double levelBytes = 16.0 * res.Levels[0].Size[0] * res.Levels[0].Size[1];
  Box computed;
  if (this->MeasureBrightRegionByCompute(computed))
  {
    return computed;
  }
  vtkBloomPassTarget* source = &res.Levels[0];
  int size[2] = { source->Size[0], source->Size[1] };
  double bytes = 0.0;
  // Steps until at most 32 x 32 boxes are left (at least one); sized first, as `source`
  // points into the list.
  size_t steps = 0;
  for (int w = size[0], h = size[1]; steps == 0 || w * h > 32 * 32; ++steps)
  {
    w = (w + Tile - 1) / Tile;
    h = (h + Tile - 1) / Tile;
  }
  if (res.Reduce.size() < steps)
  {
    res.Reduce.resize(steps);
  }
  for (size_t step = 0; step < steps; ++step)
  {
    const int out[2] = { (size[0] + Tile - 1) / Tile, (size[1] + Tile - 1) / Tile };
    vtkBloomPassTarget& target = res.Reduce[step];
    target.Allocate(res.Context, out[0], out[1], GL_RGBA32F);
    const std::string variant = "#define REDUCE 1\n#define TILE " + std::to_string(Tile) +
      "\n#define FIRST_STEP " + std::string(step == 0 ? "1" : "0") + "\n";
    vtkOpenGLQuadHelper* quad = this->Program(variant);
    if (!quad)
    {
      return Box::Whole(res.Levels[0].Size[0], res.Levels[0].Size[1]);
    }
    target.FBO->Bind();
    target.FBO->ActivateDrawBuffer(0);
    state->vtkglDisable(GL_BLEND);
    state->vtkglViewport(0, 0, out[0], out[1]);
    source->Color->Activate();
    vtkShaderProgram* program = quad->Program;
    program->SetUniformi("source", source->Color->GetTextureUnit());
    program->SetUniform2i("sourceSize", size);
    const float regionSize[2] = { static_cast<float>(out[0]), static_cast<float>(out[1]) };
    program->SetUniform2f("regionSize", regionSize);
    quad->Render();
    source->Color->Deactivate();
    bytes += (step == 0 ? levelBytes : 16.0 * size[0] * size[1]) + 16.0 * out[0] * out[1];
    ++this->Passes;
    source = &target;
    size[0] = out[0];
    size[1] = out[1];
  }
  this->Profiler.End("reduce", size[0], size[1], bytes);

  // A few kilobytes; the wait is for the bright pass, as the occlusion query's would be.
  std::vector<float> boxes(static_cast<size_t>(size[0]) * size[1] * 4);
  state->PushFramebufferBindings();
  source->FBO->Bind(GL_READ_FRAMEBUFFER);
  source->FBO->ActivateReadBuffer(0);
  state->vtkglPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, size[0], size[1], GL_RGBA, GL_FLOAT, boxes.data());
  state->PopFramebufferBindings();
  Box box;
  for (size_t i = 0; i < boxes.size(); i += 4)
  {
    if (boxes[i + 2] >= 0.0f)
    {
      const Box b = { static_cast<int>(boxes[i]), static_cast<int>(boxes[i + 2]) + 1,
        static_cast<int>(boxes[i + 1]), static_cast<int>(boxes[i + 3]) + 1 };
      box = box.Union(b);
    }
  }
  return box;
}
