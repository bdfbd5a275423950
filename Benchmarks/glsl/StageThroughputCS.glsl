#version 430
// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// The compute-shader side of ShaderStageThroughput: the same work as StageThroughputFS.glsl,
// one invocation per sample, written with imageStore.
layout(local_size_x = 16, local_size_y = 16) in;
uniform sampler2D source;
layout(rgba16f, binding = 0) uniform writeonly image2D target;
void main()
{
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = textureSize(source, 0);
  if (any(greaterThanEqual(p, size)))
  {
    return;
  }
  vec4 sum = vec4(0.0);
  for (int k = 0; k < TAPS; ++k)
  {
    sum += texelFetch(source, ivec2(clamp(p.x + k - TAPS / 2, 0, size.x - 1), p.y), 0);
  }
  imageStore(target, p, sum * (1.0 / float(TAPS)));
}
