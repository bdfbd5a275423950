//VTK::System::Dec
// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/*=========================================================================
  vtkBloomPassPSFSplitCS.glsl: the split PSF's compute shaders (vtkBloomPassPSFSplit; the
  split itself is vtkBloomPSFSplit's, in FiltersBloom). One stage per program, chosen by a
  #define; `scale` is the tail's grid spacing f, `imageSize` the image's, `coarseSize` the
  grid's nodes (ceil(imageSize / f)). Pixel i of an axis reads (and is spread onto) the nodes
  j0 and j1 with weights 1 - t and t, vtkBloomPSFSplit::TentWeights' table (`tents`): the
  shaders compute no weight of their own.

  - SPLIT_DOWN_X, then SPLIT_DOWN_Y: node (jx, jy) of `target` = the sum of the pixels of
    the bright pass that reach it, each times its weight for that node on both axes (Down: the
    transpose of the bilinear interpolation, so the sum and the centroid are kept), one axis a
    stage (x into a coarseSize.x x imageSize.y image, then y). A node gathers from the pixels
    [f j - f, f j + 2 f) of its axis, which hold every pixel with a weight for it.
  - SPLIT_CORE: target(p) = sum_d core(d) source(p - d) over the core's offsets
    |d| <= CORE_RADIUS (each channel its own kernel: `weights` (2 R + 1)^2 vec4, row-major,
    entry (dy + R) (2 R + 1) + dx + R for offset (dx, dy)), the source extended by half-sample
    reflection (REFLECT) or zeros, plus the coarse tail `tail` (the tail's convolution)
    interpolated bilinearly at p. A work group of CORE_LANES x CORE_ROWS invocations makes
    4 CORE_LANES x CORE_ROWS outputs, four adjacent ones an invocation: the source rows the
    group needs pass through shared memory one at a time (each read once from the texture),
    and every weight read serves four outputs (the loop over a kernel row unrolled where the
    compiler can, so that each shared sample is read once for the four). With zeros this gather
    is the scatter-and-drop of the CPU's core; with reflection it equals the CPU's
    scatter-and-fold for point-symmetric kernels (Airy, Gaussians).
=========================================================================*/

uniform ivec2 imageSize;
uniform ivec2 coarseSize;
uniform int scale;
uniform sampler2D source;

// Each pixel's tent weights, from vtkBloomPSFSplit::TentWeights: (j0, j1, t, 0) for the
// columns x, then the rows y (at imageSize.x + y).
layout(std430, binding = 1) readonly buffer Tents
{
  vec4 tents[];
};

void Tent(int i, int axis, out int j0, out int j1, out float t)
{
  const vec4 e = tents[axis == 0 ? i : imageSize.x + i];
  j0 = int(e.x);
  j1 = int(e.y);
  t = e.z;
}

#if defined(SPLIT_DOWN_X) || defined(SPLIT_DOWN_Y)
layout(local_size_x = 16, local_size_y = 16) in;
layout(rgba32f, binding = 0) uniform writeonly image2D target;

float NodeWeight(int i, int node, int axis)
{
  int j0, j1;
  float t;
  Tent(i, axis, j0, j1, t);
  return (j0 == node ? 1.0 - t : 0.0) + (j1 == node ? t : 0.0);
}

// SPLIT_DOWN_X: (node x, pixel row y) = the weighted sum along x of `source` (the bright pass);
// SPLIT_DOWN_Y: (node x, node y) = the weighted sum along y of `source` (the first stage's).
void main()
{
  const ivec2 at = ivec2(gl_GlobalInvocationID.xy);
#ifdef SPLIT_DOWN_X
  const int axis = 0;
  const ivec2 size = ivec2(coarseSize.x, imageSize.y);
#else
  const int axis = 1;
  const ivec2 size = coarseSize;
#endif
  if (any(greaterThanEqual(at, size)))
  {
    return;
  }
  const int node = at[axis];
  const int lo = max(node * scale - scale, 0);
  const int hi = min(node * scale + 2 * scale, imageSize[axis]);
  vec3 sum = vec3(0.0);
  ivec2 from = at;
  for (int i = lo; i < hi; ++i)
  {
    from[axis] = i;
    sum += NodeWeight(i, node, axis) * texelFetch(source, from, 0).rgb;
  }
  imageStore(target, at, vec4(sum, 0.0));
}
#endif

#ifdef SPLIT_CORE
// CORE_LANES x CORE_ROWS invocations; each makes CORE_OUTPUTS adjacent outputs of its row.
layout(local_size_x = CORE_LANES, local_size_y = CORE_ROWS) in;
layout(rgba32f, binding = 0) uniform writeonly image2D target;
const int R = CORE_RADIUS;
const int K = 2 * CORE_RADIUS + 1;
layout(std430, binding = 0) readonly buffer CoreWeights
{
  vec4 weights[];
};
uniform sampler2D tail;

const int P = CORE_OUTPUTS;
const int WIDTH = P * CORE_LANES;
const int SPAN = WIDTH + 2 * CORE_RADIUS;
// One source row, a plane per channel, one float of padding every 32: invocation l reads
// sample P l + j, and the padding puts the 32 lanes' reads in 32 different banks.
const int PADDED = SPAN + SPAN / 32 + 1;
shared float red[PADDED];
shared float green[PADDED];
shared float blue[PADDED];

int Slot(int i)
{
  return i + i / 32;
}

vec3 Sample(int i)
{
  const int at = Slot(i);
  return vec3(red[at], green[at], blue[at]);
}

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

// The tail's bilinear interpolation at pixel (x, y).
vec3 Tail(int x, int y)
{
  int i0, i1, j0, j1;
  float tx, ty;
  Tent(x, 0, i0, i1, tx);
  Tent(y, 1, j0, j1, ty);
  const vec3 top = (1.0 - tx) * texelFetch(tail, ivec2(i0, j0), 0).rgb +
    tx * texelFetch(tail, ivec2(i1, j0), 0).rgb;
  const vec3 bottom = (1.0 - tx) * texelFetch(tail, ivec2(i0, j1), 0).rgb +
    tx * texelFetch(tail, ivec2(i1, j1), 0).rgb;
  return (1.0 - ty) * top + ty * bottom;
}

void main()
{
  const int x0 = int(gl_WorkGroupID.x) * WIDTH;
  const int top = int(gl_WorkGroupID.y) * CORE_ROWS;
  const int y = top + int(gl_LocalInvocationID.y);
  const int lane = int(gl_LocalInvocationID.x);
  const int first = int(gl_LocalInvocationID.y) * CORE_LANES + lane;
  vec3 acc[P];
  for (int p = 0; p < P; ++p)
  {
    acc[p] = vec3(0.0);
  }
  // The rows the work group's outputs read, each through shared memory once; row y reads
  // source row yy with kernel row dy = y - yy.
  for (int yy = top - R; yy < top + CORE_ROWS + R; ++yy)
  {
    const int sy = Extend(yy, imageSize.y);
    for (int k = first; k < SPAN; k += CORE_LANES * CORE_ROWS)
    {
      const int sx = Extend(x0 - R + k, imageSize.x);
      const vec3 v = sx < 0 || sy < 0 ? vec3(0.0) : texelFetch(source, ivec2(sx, sy), 0).rgb;
      const int at = Slot(k);
      red[at] = v.r;
      green[at] = v.g;
      blue[at] = v.b;
    }
    barrier();
    const int dy = y - yy;
    if (dy >= -R && dy <= R)
    {
      // Output P lane + p gathers sample P lane + p + 2 R - k with weight (dx = k - R, dy);
      // unrolled, each sample is read once for the P outputs.
      const int base = (dy + R) * K;
#pragma optionNV(unroll all)
      for (int k = 0; k < K; ++k)
      {
        const vec3 w = weights[base + k].rgb;
        for (int p = 0; p < P; ++p)
        {
          acc[p] += w * Sample(P * lane + p + 2 * R - k);
        }
      }
    }
    barrier();
  }
  for (int p = 0; p < P; ++p)
  {
    const int x = x0 + P * lane + p;
    if (x < imageSize.x && y < imageSize.y)
    {
      imageStore(target, ivec2(x, y), vec4(acc[p] + Tail(x, y), 0.0));
    }
  }
}
#endif
