//VTK::System::Dec
// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/*=========================================================================
  vtkBloomPassFFTBlurCS.glsl: vtkBloomPassFFTBlur's compute shaders (OpenGL 4.3), a wide
  same-size operator M = T + D (vtkBloomFFTConvolution) applied along every line (a row,
  FFT_AXIS 0, or a column, 1) of `lines` lines of n samples of an RGBA texture:

    (M x)[j] = (k * E x)[PadLeft + j] + sum_k U_k[j - Row0] t_k,   t_k = sum_q V_q,k x[Col0 + q]

  Two stages, chosen by a #define:

  - FFT_BLUR_CONVOLVE: appended to vtkBloomPassFFTCS.glsl compiled with FFT_TRANSFORM and
    FFT_LIBRARY, whose TransformLine() is the DFT of the shared `line` of FFT_N samples. One
    work group per line and signal (signal 0 = R + i G, signal 1 = B + i A: the kernel is
    real, so one complex convolution filters two channels). It reads the extended line E x
    (sample m of the buffer is x[extension[m]], zero where it is -1: the border mode and the
    zero padding, from vtkBloomLinearOperator::FoldIndex on the CPU), finds the range of its
    non-zero samples and the corrections' coefficients t_k, then the circular convolution with
    the kernel as conj(DFT(conj(DFT(z) K))), K the kernel's spectrum divided by N: the inverse
    transform through the forward one, so that one program with direction -1 runs both. It
    writes the n samples of the line (PadLeft + j) to `signal` (line l of signal s at
    (s lines + l) n). An all-zero line is not transformed: its range is empty.
  - FFT_BLUR_FINISH: one invocation per output sample: both signals, plus the corrections
    sum_k U_k[j - Row0] t_k on the rows of D's blocks, times `weight`, into the image `target`;
    exact zeros where no non-zero input sample of the line reaches (reachLo, reachHi: the
    float32 weights' non-zeros, the direct pass's zero set), and no negative output from a
    non-negative operator (nonNegative) on a line with no negative sample.

  The tables (int): extension[FFT_N], then reachLo[n] and reachHi[n]. The factors (float):
  each block's V (Cols x Rank) at blockV, its U (Rank x Rows) at blockU.
=========================================================================*/

uniform int lineLength; // n
uniform int lines;
uniform ivec4 blocks[2]; // Row0, Rows, Col0, Cols of D's blocks (Rows 0: none)
uniform ivec2 blockRank;
uniform ivec2 blockV; // where each block's V starts in `factors`
uniform ivec2 blockU; // where each block's U starts in `factors`
uniform int nonNegative; // every weight of M is >= 0

layout(std430, binding = 3) readonly buffer Tables
{
  int tables[];
};

layout(std430, binding = 4) readonly buffer Factors
{
  float factors[];
};

layout(std430, binding = 6) buffer LineRanges
{
  ivec4 lineRange[]; // per signal and line: its first and last non-zero sample, any negative
};

#if defined(FFT_BLUR_CONVOLVE)

layout(std430, binding = 2) readonly buffer Spectrum
{
  vec2 spectrum[]; // FFT_N values: the kernel's spectrum divided by FFT_N
};

layout(std430, binding = 5) writeonly buffer Coefficients
{
  vec2 coefficients[]; // per signal and line: the blocks' t_k
};

uniform sampler2D source;
uniform int padLeft;

shared int firstNonZero;
shared int lastNonZero;
shared int anyNegative;

void main()
{
  const int l = int(gl_WorkGroupID.x);
  const int s = int(gl_WorkGroupID.y);
  const int id = int(gl_LocalInvocationID.x);
  if (id == 0)
  {
    firstNonZero = lineLength;
    lastNonZero = -1;
    anyNegative = 0;
  }
  barrier();
  for (int m = id; m < FFT_N; m += FFT_THREADS)
  {
    const int i = tables[m];
    vec2 v = vec2(0.0);
    if (i >= 0)
    {
      const vec4 texel = texelFetch(source, FFT_AXIS == 0 ? ivec2(i, l) : ivec2(l, i), 0);
      v = s == 0 ? texel.rg : texel.ba;
    }
    line[m] = v;
    const int j = m - padLeft;
    if (j >= 0 && j < lineLength && any(notEqual(v, vec2(0.0))))
    {
      atomicMin(firstNonZero, j);
      atomicMax(lastNonZero, j);
      if (any(lessThan(v, vec2(0.0))))
      {
        atomicOr(anyNegative, 1);
      }
    }
  }
  barrier();
  const int ranks = blockRank.x + blockRank.y;
  for (int c = id; c < ranks; c += FFT_THREADS)
  {
    const int b = c < blockRank.x ? 0 : 1;
    const int k = c - (b == 0 ? 0 : blockRank.x);
    const int rank = blockRank[b];
    const int first = padLeft + blocks[b].z;
    vec2 t = vec2(0.0);
    for (int q = 0; q < blocks[b].w; ++q)
    {
      t += factors[blockV[b] + q * rank + k] * line[first + q];
    }
    coefficients[(s * lines + l) * ranks + c] = t;
  }
  const ivec2 range = ivec2(firstNonZero, lastNonZero);
  if (id == 0)
  {
    lineRange[s * lines + l] = ivec4(range, anyNegative, 0);
  }
  if (range.y < range.x)
  {
    return; // the whole work group: the range is shared
  }
  TransformLine();
  for (int m = id; m < FFT_N; m += FFT_THREADS)
  {
    const vec2 y = ComplexMultiply(line[m], spectrum[m]);
    line[m] = vec2(y.x, -y.y);
  }
  barrier();
  TransformLine();
  const int base = (s * lines + l) * lineLength;
  for (int j = id; j < lineLength; j += FFT_THREADS)
  {
    const vec2 y = line[padLeft + j];
    signal[base + j] = vec2(y.x, -y.y);
  }
}

#elif defined(FFT_BLUR_FINISH)

layout(local_size_x = 16, local_size_y = 16) in;

layout(std430, binding = 0) readonly buffer Signal
{
  vec2 signal[];
};

layout(std430, binding = 5) readonly buffer Coefficients
{
  vec2 coefficients[];
};

layout(FFT_BLUR_FORMAT, binding = 0) writeonly uniform image2D target;
uniform int transformLength; // FFT_N of the convolution: where reachLo starts in `tables`
uniform float weight;

void main()
{
  const ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  const int j = FFT_AXIS == 0 ? p.x : p.y;
  const int l = FFT_AXIS == 0 ? p.y : p.x;
  if (j >= lineLength || l >= lines)
  {
    return;
  }
  vec4 sum = vec4(0.0);
  const ivec4 range[2] = ivec4[](lineRange[l], lineRange[lines + l]);
  const int a = min(range[0].x, range[1].x);
  const int b = max(range[0].y, range[1].y);
  if (a <= b && j >= tables[transformLength + a] &&
    j <= tables[transformLength + lineLength + b])
  {
    // A signal whose line is all zero was not transformed: its part is zero.
    const vec2 rg = range[0].x <= range[0].y ? signal[l * lineLength + j] : vec2(0.0);
    const vec2 ba = range[1].x <= range[1].y ? signal[(lines + l) * lineLength + j] : vec2(0.0);
    sum = vec4(rg, ba);
    const int ranks = blockRank.x + blockRank.y;
    for (int bl = 0; bl < 2; ++bl)
    {
      const int r = j - blocks[bl].x;
      if (r < 0 || r >= blocks[bl].y)
      {
        continue;
      }
      const int c0 = bl == 0 ? 0 : blockRank.x;
      for (int k = 0; k < blockRank[bl]; ++k)
      {
        const float u = factors[blockU[bl] + k * blocks[bl].y + r];
        sum += u *
          vec4(coefficients[l * ranks + c0 + k], coefficients[(lines + l) * ranks + c0 + k]);
      }
    }
    // M >= 0 and x >= 0 give M x >= 0 exactly: what is below zero is the transforms' rounding
    // (a bloom term must not darken; the direct path's sums of non-negative terms never do).
    if (nonNegative != 0)
    {
      sum.xy = range[0].z == 0 ? max(sum.xy, vec2(0.0)) : sum.xy;
      sum.zw = range[1].z == 0 ? max(sum.zw, vec2(0.0)) : sum.zw;
    }
  }
  imageStore(target, p, weight * sum);
}

#endif
