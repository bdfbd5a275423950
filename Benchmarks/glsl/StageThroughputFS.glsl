#version 430
// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// The fragment-shader side of ShaderStageThroughput: TAPS horizontal texel fetches of the
// source (TAPS 1: a scaled copy), one sample per fragment.
uniform sampler2D source;
out vec4 colour;
void main()
{
  ivec2 p = ivec2(gl_FragCoord.xy);
  ivec2 size = textureSize(source, 0);
  vec4 sum = vec4(0.0);
  for (int k = 0; k < TAPS; ++k)
  {
    sum += texelFetch(source, ivec2(clamp(p.x + k - TAPS / 2, 0, size.x - 1), p.y), 0);
  }
  colour = sum * (1.0 / float(TAPS));
}
