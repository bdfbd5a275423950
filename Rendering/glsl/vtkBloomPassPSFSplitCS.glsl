//VTK::System::Dec
/*=========================================================================
  vtkBloomPassPSFSplitCS.glsl: the split PSF's compute shaders (vtkBloomPassPSFSplit; the
  split itself is vtkBloomPSFSplit's, in FiltersBloom). One stage per program, chosen by a
  #define; `scale` is the tail's grid spacing f, `imageSize` the image's, `coarseSize` the
  grid's nodes (ceil(imageSize / f)). Pixel i of an axis reads (and is spread onto) the nodes
  j0 = floor(u) and j1 = min(j0 + 1, nodes - 1) with weights 1 - t and t, u = (i + 1/2) / f - 1/2
  clamped to [0, nodes - 1], t = u - j0 (Tent, as vtkBloomPSFSplit::TentWeights).

  - SPLIT_DOWN: node (jx, jy) of `target` = the sum of the pixels of `source` (the bright pass)
    that reach it, each times its weight for that node on both axes (Down: the transpose of
    the bilinear interpolation, so the sum and the centroid are kept). A node gathers from the
    pixels [f j - f, f j + 2 f) of each axis, which hold every pixel with a weight for it.
  - SPLIT_CORE: target(p) = sum_d core(d) source(p - d) over the core's offsets
    |d| <= CORE_RADIUS (each channel its own kernel: `weights` (2 R + 1)^2 vec4, row-major,
    entry (dy + R) (2 R + 1) + dx + R for offset (dx, dy)), the source extended by half-sample
    reflection (REFLECT) or zeros, plus the coarse tail `tail` (the tail's convolution) interpolated
    bilinearly at p. A work group of CORE_COLUMNS invocations makes CORE_COLUMNS x CORE_ROWS
    outputs, one column each: the source's rows it needs pass through shared memory one at a
    time (each read once from the texture), and each sample read from it serves every output
    row it reaches (CORE_ROWS accumulators an invocation). With zeros this gather is the
    scatter-and-drop of the CPU's core; with reflection it equals the CPU's scatter-and-fold for
    point-symmetric kernels (Airy, Gaussians).
=========================================================================*/

uniform ivec2 imageSize;
uniform ivec2 coarseSize;
uniform int scale;
uniform sampler2D source;

void Tent(int i, int nodes, out int j0, out int j1, out float t)
{
  const float u = clamp((float(i) + 0.5) / float(scale) - 0.5, 0.0, float(nodes - 1));
  j0 = int(floor(u));
  j1 = min(j0 + 1, nodes - 1);
  t = u - float(j0);
}

#ifdef SPLIT_DOWN
layout(local_size_x = 16, local_size_y = 16) in;
layout(rgba32f, binding = 0) uniform writeonly image2D target;

float NodeWeight(int i, int node, int nodes)
{
  int j0, j1;
  float t;
  Tent(i, nodes, j0, j1, t);
  return (j0 == node ? 1.0 - t : 0.0) + (j1 == node ? t : 0.0);
}

void main()
{
  const ivec2 node = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(node, coarseSize)))
  {
    return;
  }
  const ivec2 lo = max(node * scale - scale, ivec2(0));
  const ivec2 hi = min(node * scale + 2 * scale, imageSize);
  vec3 sum = vec3(0.0);
  for (int y = lo.y; y < hi.y; ++y)
  {
    const float wy = NodeWeight(y, node.y, coarseSize.y);
    if (wy == 0.0)
    {
      continue;
    }
    vec3 row = vec3(0.0);
    for (int x = lo.x; x < hi.x; ++x)
    {
      row += NodeWeight(x, node.x, coarseSize.x) * texelFetch(source, ivec2(x, y), 0).rgb;
    }
    sum += wy * row;
  }
  imageStore(target, node, vec4(sum, 0.0));
}
#endif

#ifdef SPLIT_CORE
layout(local_size_x = CORE_COLUMNS) in;
layout(rgba32f, binding = 0) uniform writeonly image2D target;
layout(std430, binding = 0) readonly buffer CoreWeights
{
  vec4 weights[];
};
uniform sampler2D tail;

const int R = CORE_RADIUS;
const int SPAN = CORE_COLUMNS + 2 * CORE_RADIUS;
shared vec3 row[SPAN];

// The source pixel at i along an axis of n, or -1 where the extension is zero.
int Extend(int i, int n)
{
#ifdef REFLECT
  // GLSL leaves % of a negative operand undefined: -1 - i for i < 0 is its mirror image.
  const int period = 2 * n;
  const int m = i < 0 ? period - 1 - (-1 - i) % period : i % period;
  return m < n ? m : period - 1 - m;
#else
  return i < 0 || i >= n ? -1 : i;
#endif
}

void main()
{
  const int x0 = int(gl_WorkGroupID.x) * CORE_COLUMNS;
  const int y0 = int(gl_WorkGroupID.y) * CORE_ROWS;
  const int lx = int(gl_LocalInvocationID.x);
  vec3 acc[CORE_ROWS];
  for (int o = 0; o < CORE_ROWS; ++o)
  {
    acc[o] = vec3(0.0);
  }
  for (int yy = y0 - R; yy < y0 + CORE_ROWS + R; ++yy)
  {
    const int sy = Extend(yy, imageSize.y);
    for (int k = lx; k < SPAN; k += CORE_COLUMNS)
    {
      const int sx = Extend(x0 - R + k, imageSize.x);
      row[k] = sx < 0 || sy < 0 ? vec3(0.0) : texelFetch(source, ivec2(sx, sy), 0).rgb;
    }
    barrier();
    // Output row y0 + o reads this row at offset dy = y0 + o - yy; the sample at x + e has
    // offset dx = -e.
    for (int e = -R; e <= R; ++e)
    {
      const vec3 v = row[lx + R + e];
      for (int o = 0; o < CORE_ROWS; ++o)
      {
        const int dy = y0 + o - yy;
        if (dy >= -R && dy <= R)
        {
          acc[o] += weights[(dy + R) * (2 * R + 1) + R - e].rgb * v;
        }
      }
    }
    barrier();
  }
  const int x = x0 + lx;
  if (x >= imageSize.x)
  {
    return;
  }
  int i0, i1;
  float tx;
  Tent(x, coarseSize.x, i0, i1, tx);
  for (int o = 0; o < CORE_ROWS; ++o)
  {
    const int y = y0 + o;
    if (y < imageSize.y)
    {
      vec3 value = acc[o];
      int j0, j1;
      float ty;
      Tent(y, coarseSize.y, j0, j1, ty);
      const vec3 top = (1.0 - tx) * texelFetch(tail, ivec2(i0, j0), 0).rgb +
        tx * texelFetch(tail, ivec2(i1, j0), 0).rgb;
      const vec3 bottom = (1.0 - tx) * texelFetch(tail, ivec2(i0, j1), 0).rgb +
        tx * texelFetch(tail, ivec2(i1, j1), 0).rgb;
      value += (1.0 - ty) * top + ty * bottom;
      imageStore(target, ivec2(x, y), vec4(value, 0.0));
    }
  }
}
#endif
