#version 430
// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/*=========================================================================
  vtkBloomPassReduceCS.glsl: vtkBloomPass's bright-region reduction as one compute dispatch
  (OpenGL 4.3), where the context has compute shaders; vtkBloomPassReduceFS.glsl otherwise.

  One invocation per sample of the bright level; a sample counts when any channel is non-zero.
  Each work group reduces its 16 x 16 samples in shared memory, and one invocation per group
  merges the group's box into the buffer's (x0, y0, x1, y1), x1 and y1 inclusive, which the
  caller initializes to (2^30, 2^30, -1, -1). Integer atomics: the result does not depend on
  the order of the groups.

  Compute invocations run on every multiprocessor of the GPU; on an NVIDIA H100 fragment
  shaders run on a few only (see docs/gpu.md).
=========================================================================*/

layout(local_size_x = 16, local_size_y = 16) in;

uniform sampler2D source;
uniform ivec2 sourceSize;

layout(std430, binding = 0) buffer BrightBox
{
  int box[4];
};

shared int groupBox[4];

void main()
{
  if (gl_LocalInvocationIndex == 0u)
  {
    groupBox[0] = 1 << 30;
    groupBox[1] = 1 << 30;
    groupBox[2] = -1;
    groupBox[3] = -1;
  }
  barrier();
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (all(lessThan(p, sourceSize)) && any(notEqual(texelFetch(source, p, 0), vec4(0.0))))
  {
    atomicMin(groupBox[0], p.x);
    atomicMin(groupBox[1], p.y);
    atomicMax(groupBox[2], p.x);
    atomicMax(groupBox[3], p.y);
  }
  barrier();
  if (gl_LocalInvocationIndex == 0u && groupBox[2] >= 0)
  {
    atomicMin(box[0], groupBox[0]);
    atomicMin(box[1], groupBox[1]);
    atomicMax(box[2], groupBox[2]);
    atomicMax(box[3], groupBox[3]);
  }
}
