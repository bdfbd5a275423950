//VTK::System::Dec
// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause

/*=========================================================================
  vtkBloomPassReduceFS.glsl: one step of vtkBloomPass's bright-region reduction.

  Each output texel covers a TILE x TILE block of the input and writes the bounding box of what
  the block holds, (x0, y0, x1, y1) in level-0 samples with x1, y1 inclusive, or (BIG, BIG, -1,
  -1) when the block holds nothing:
  - FIRST_STEP 1: the input is the bright level; a sample counts when any channel is non-zero
    (the box of the samples from which the rest of the chain can be non-zero).
  - FIRST_STEP 0: the input is the previous step's boxes; their union.
  The coordinates are integers below 2^24, exact in float.
=========================================================================*/

//VTK::Output::Dec

in vec2 texCoord;

//BLOOM::Variant

uniform sampler2D source;
uniform ivec2 sourceSize; // the input's samples; the texture may be larger
uniform vec2 regionSize;  // the output's texels, the size of the viewport

void main()
{
  ivec2 tile = ivec2(floor(texCoord * regionSize));
  ivec2 first = tile * TILE;
  ivec2 last = min(first + ivec2(TILE), sourceSize);
  const float big = 1.0e9;
  vec4 box = vec4(big, big, -1.0, -1.0);
  for (int y = first.y; y < last.y; ++y)
  {
    for (int x = first.x; x < last.x; ++x)
    {
      vec4 v = texelFetch(source, ivec2(x, y), 0);
#if FIRST_STEP
      if (any(notEqual(v, vec4(0.0))))
      {
        box = vec4(min(box.xy, vec2(x, y)), max(box.zw, vec2(x, y)));
      }
#else
      box = vec4(min(box.xy, v.xy), max(box.zw, v.zw));
#endif
    }
  }
  gl_FragData[0] = box;
}
