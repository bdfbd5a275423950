//VTK::System::Dec
// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/*=========================================================================
  vtkBloomPassFFTCS.glsl: vtkBloomPassFFT's compute shaders (OpenGL 4.3), the linear
  convolution of a float RGBA image with one PSF per colour channel through a 2-D FFT of the
  zero-padded NX x NY grid. One stage per program, chosen by a #define:

  - FFT_TRANSFORM: the DFT of every sub-sequence of every line (a row or a column) of the two
    complex signals in the buffer `signal` (signal s at s * signalStride; sample n of line l at
    l * lineStride + n * sampleStride), X[q] = sum_m x[m] exp(direction 2 pi i m q / FFT_N),
    unscaled. Sub-sequence j of a line is its samples j * subOffset + m * subSpacing,
    0 <= m < FFT_N (subCount of them per line); a line transformed in one dispatch (a row of
    N <= 4096 samples, a column of N <= 2048) is one sub-sequence (subOffset 0, subSpacing 1). Only lines lineFirst to lineFirst + lineCount - 1 are
    transformed (the others are zero or not needed), and samples at or past sampleLimit along
    a line are zero: not read. A work group takes FFT_LINES units (a line's sub-sequence)
    adjacent in memory, so that it reads and writes runs of them rather than one sample a row
    (coalesced): adjacent lines of one sub-sequence (columns: lineStride 1), or with
    FFT_BLOCK_SUBS adjacent sub-sequences of one line (a row's four-step transform); with
    FFT_SAMPLES_FASTEST consecutive invocations load consecutive samples of a unit (they are
    adjacent in memory), otherwise a sample of consecutive units. Groups are numbered
    g = (s lineBlocks + lineBlock) subBlocks + subBlock along x, then y (2-D so that the count
    stays within 65535 a dimension; groups and units past the last do nothing). Each unit is
    held in shared memory FFT_STRIDE samples from the next (FFT_LINES FFT_STRIDE <= 4096
    complex samples: 32 KiB; FFT_STRIDE >= FFT_N padded against bank conflicts), transformed
    by the FFT_THREADS invocations of one gl_LocalInvocationID.y in place by mixed-radix Stockham
    stages (radices 4, 2, 3, 5, the calls FFT_STAGE_CALLS lists), so that the
    result is in natural order with no bit reversal. Stage s of radix R, with Ns the product
    of the radices before it, takes butterfly j (0 <= j < N / R, k = j mod Ns) from samples
    j + r N / R, multiplies sample r by w^(k r N / (Ns R)), applies the R-point DFT and writes
    it to (j / Ns) Ns R + k + q Ns (Govindaraju et al. 2008, "High performance discrete
    Fourier transforms on graphics processors"). Each invocation keeps its butterflies'
    results in registers between two barriers, so the stage needs one line of shared memory.
    The roots come from `twiddle`, cos and sin of 2 pi m / N for the whole line's N computed
    in double on the CPU (GLSL's float sin and cos are not accurate enough for large N):
    exp(direction 2 pi i m / FFT_N) is entry m FFT_TWIDDLE_STRIDE (= N / FFT_N).
    FFT_FOUR_STEP_TWIDDLE: output q of sub-sequence j is then multiplied by
    exp(direction 2 pi i j q / N), the twiddle of the four-step (Bailey) transform of a line
    longer than 4096 samples (vtkBloomPassFFT.h gives its two passes and the spectrum's order).
    FFT_FROM_TEXTURE: the first (row) transform reads row l of the RGBA texture `source`
    instead, zero padded beyond sourceSize: signal 0 = R + i G, signal 1 = B + i 0.
  - FFT_SEPARATE: the kernels' spectra from the transform of (kR + i kG, kB): with Z the
    spectrum of z = r + i g (r, g real), R[k] = (Z[k] + conj Z[-k]) / 2 and
    G[k] = (Z[k] - conj Z[-k]) / (2 i). Each is scaled by `scale` = 1 / (NX NY), the inverse
    transform's normalization, and written to `spectra` (red, green, blue, NX HY each, HY =
    NY / 2 + 1). The kernels are real, so their spectra are Hermitian (K[-k] = conj K[k]):
    only the frequencies ky <= NY / 2 along y are kept, at ky NX + px (px the position along
    x). Along an axis transformed in four steps the signal's spectrum is in the order of
    vtkBloomPassFFT.h (position N2 k1 + k2 holds frequency k1 + N1 k2): Frequency and
    Negative map a position to its frequency and to the position of its frequency's negative,
    with `split` = (N2 along x, N2 along y), 1 along a one-pass axis.
  - FFT_MULTIPLY: the image's spectrum times the kernels', in place: Y = R KR + i G KG for
    signal 0 (with R, G separated as above; the inverse of Y is then r * kR + i g * kG, both
    real), B KB for signal 1. One invocation per pair (k, -k): it reads both of the signal and
    the kernels' spectra once, at whichever of the two is kept.
  - FFT_FOLD: the output image from the inverse transform: the full convolution's sample
    (u + radius, v + radius), centred on image pixel (u, v) for -radius <= u < W + radius,
    folded back into the image by half-sample reflection (FFT_REFLECT: u and -1 - u are the
    same pixel, period 2 W) or dropped (ZERO). Every pixel gathers the samples that fold onto
    it, so the sum with REFLECT keeps the energy. Alpha is 0.
=========================================================================*/

#if defined(FFT_TRANSFORM)
#ifndef FFT_LINES
#define FFT_LINES 1
#endif
#ifndef FFT_STRIDE
#define FFT_STRIDE FFT_N
#endif
layout(local_size_x = FFT_THREADS, local_size_y = FFT_LINES) in;
#else
layout(local_size_x = 16, local_size_y = 16) in;
#endif

layout(std430, binding = 0) buffer Signal
{
  vec2 signal[];
};

vec2 ComplexMultiply(vec2 a, vec2 b)
{
  return vec2(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x);
}

#if defined(FFT_TRANSFORM)

layout(std430, binding = 1) readonly buffer Twiddles
{
  vec2 twiddle[]; // (cos, sin) of 2 pi m / N, m < N
};

uniform int sampleStride;
uniform int lineStride;
uniform int signalStride;
uniform int lineFirst;  // the first line transformed
uniform int lineCount;  // lines transformed per signal, from lineFirst
uniform int sampleLimit; // line samples at or past it are zero: not read (the zero padding)
uniform int subCount;   // sub-sequences per line
uniform int subOffset;  // line samples between the starts of two sub-sequences
uniform int subSpacing; // line samples between two samples of a sub-sequence
uniform float direction; // -1: forward, +1: inverse

#ifdef FFT_FROM_TEXTURE
uniform sampler2D source;
uniform ivec2 sourceSize;
#endif

shared vec2 line[FFT_LINES * FFT_STRIDE]; // unit c's samples from c FFT_STRIDE


// exp(direction 2 pi i m / N) for 0 <= m < N, N the whole line's length.
vec2 Twiddle(int m)
{
  vec2 w = twiddle[m];
  return vec2(w.x, direction * w.y);
}

// w^m = exp(direction 2 pi i m / FFT_N), a root of the sub-sequence's transform.
vec2 Root(int m)
{
  return Twiddle(m * FFT_TWIDDLE_STRIDE);
}

// One Stockham stage of radix R (at most 5) after stages whose radices multiply to ns.
void Stage(int R, int ns)
{
  const int butterflies = FFT_N / R;
  const int step = FFT_N / (ns * R);
  const int at = int(gl_LocalInvocationID.y) * FFT_STRIDE; // this invocation's unit
  // A constant trip count, and R and ns literal in each call (FFT_STAGE_CALLS): the compiler
  // unrolls the loops and keeps `results` in registers rather than in local memory.
  vec2 results[FFT_BUTTERFLIES * 5];
  for (int b = 0; b < FFT_BUTTERFLIES; ++b)
  {
    const int j = int(gl_LocalInvocationID.x) + b * FFT_THREADS;
    if (j >= butterflies)
    {
      break;
    }
    const int k = j % ns;
    vec2 v[5];
    v[0] = line[at + j];
    for (int r = 1; r < R; ++r)
    {
      v[r] = ComplexMultiply(line[at + j + r * butterflies], Root(k * r * step));
    }
    if (R == 2)
    {
      results[b * 5] = v[0] + v[1];
      results[b * 5 + 1] = v[0] - v[1];
    }
    else if (R == 4)
    {
      // w^(N / 4) is direction * i: multiplying by it is a swap and a sign.
      const vec2 a = v[0] + v[2], c = v[0] - v[2];
      const vec2 e = v[1] + v[3], d = v[1] - v[3];
      const vec2 id = direction * vec2(-d.y, d.x);
      results[b * 5] = a + e;
      results[b * 5 + 1] = c + id;
      results[b * 5 + 2] = a - e;
      results[b * 5 + 3] = c - id;
    }
    else
    {
      // The R-point DFT, its roots w^(N r q / R) from the same table.
      for (int q = 0; q < R; ++q)
      {
        vec2 sum = v[0];
        for (int r = 1; r < R; ++r)
        {
          sum += ComplexMultiply(v[r], Root(((r * q) % R) * butterflies));
        }
        results[b * 5 + q] = sum;
      }
    }
  }
  barrier();
  for (int b = 0; b < FFT_BUTTERFLIES; ++b)
  {
    const int j = int(gl_LocalInvocationID.x) + b * FFT_THREADS;
    if (j >= butterflies)
    {
      break;
    }
    const int k = j % ns;
    const int first = (j / ns) * ns * R + k;
    for (int q = 0; q < R; ++q)
    {
      line[at + first + q * ns] = results[b * 5 + q];
    }
  }
  barrier();
}

#if defined(FFT_LIBRARY)
// For programs that append their own main() (vtkBloomPassFFTBlur): the DFT of the shared
// `line` in place, the stages main() runs.
void TransformLine()
{
  FFT_STAGE_CALLS
}
#else
// The group's units: FFT_LINES adjacent lines of one sub-sequence or, with FFT_BLOCK_SUBS,
// FFT_LINES adjacent sub-sequences of one line; 2-D numbering (see the top) g = (s lineBlocks +
// lineBlock) subBlocks + subBlock.
struct Group
{
  int SubBlock, LineBlock, Signal;
  bool Live; // groups past the last still reach every barrier, but touch nothing
};

Group ThisGroup()
{
  const int g = int(gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x);
#ifdef FFT_BLOCK_SUBS
  const int subBlocks = (subCount + FFT_LINES - 1) / FFT_LINES, lineBlocks = lineCount;
#else
  const int subBlocks = subCount, lineBlocks = (lineCount + FFT_LINES - 1) / FFT_LINES;
#endif
  Group group;
  group.SubBlock = g % subBlocks;
  group.LineBlock = (g / subBlocks) % lineBlocks;
  group.Signal = g / (subBlocks * lineBlocks);
  group.Live = g < 2 * subBlocks * lineBlocks;
  return group;
}

// Element i of the group's FFT_LINES x FFT_N samples, in the order that gives consecutive
// invocations consecutive addresses of the signal (a unit's samples are adjacent in memory
// with FFT_SAMPLES_FASTEST, the units otherwise): its line, sample along the line,
// sub-sequence and sample within it, and its place in shared memory. False past the last unit.
struct Element
{
  int Line, Sample, Sub, M, Shared;
};

bool Locate(Group group, int i, out Element e)
{
#ifdef FFT_SAMPLES_FASTEST
  const int unit = i / FFT_N, m = i % FFT_N;
#else
  const int unit = i % FFT_LINES, m = i / FFT_LINES;
#endif
#ifdef FFT_BLOCK_SUBS
  e.Line = lineFirst + group.LineBlock;
  e.Sub = group.SubBlock * FFT_LINES + unit;
#else
  e.Line = lineFirst + group.LineBlock * FFT_LINES + unit;
  e.Sub = group.SubBlock;
#endif
  e.M = m;
  e.Sample = e.Sub * subOffset + m * subSpacing;
  e.Shared = unit * FFT_STRIDE + m;
  return e.Line < lineFirst + lineCount && e.Sub < subCount;
}

int Address(Group group, Element e)
{
  return group.Signal * signalStride + e.Line * lineStride + e.Sample * sampleStride;
}

void main()
{
  const Group group = ThisGroup();
  const int invocation = int(gl_LocalInvocationID.y) * FFT_THREADS + int(gl_LocalInvocationID.x);
  const int stride = FFT_LINES * FFT_THREADS;
  Element e;
  for (int i = invocation; group.Live && i < FFT_LINES * FFT_N; i += stride)
  {
    if (!Locate(group, i, e))
    {
      continue;
    }
    vec2 value = vec2(0.0);
#ifdef FFT_FROM_TEXTURE
    if (e.Sample < sourceSize.x && e.Line < sourceSize.y)
    {
      const vec4 texel = texelFetch(source, ivec2(e.Sample, e.Line), 0);
      value = group.Signal == 0 ? texel.rg : vec2(texel.b, 0.0);
    }
#else
    if (e.Sample < sampleLimit)
    {
      value = signal[Address(group, e)];
    }
#endif
    line[e.Shared] = value;
  }
  barrier();
  FFT_STAGE_CALLS
  for (int i = invocation; group.Live && i < FFT_LINES * FFT_N; i += stride)
  {
    if (!Locate(group, i, e))
    {
      continue;
    }
#ifdef FFT_FOUR_STEP_TWIDDLE
    signal[Address(group, e)] = ComplexMultiply(line[e.Shared], Twiddle(e.Sub * e.M));
#else
    signal[Address(group, e)] = line[e.Shared];
#endif
  }
}
#endif // FFT_LIBRARY

#elif defined(FFT_SEPARATE) || defined(FFT_MULTIPLY)

uniform ivec2 size;  // NX, NY
uniform ivec2 split; // N2 of each axis's four-step transform; 1 for a one-pass axis

#ifdef FFT_SEPARATE
layout(std430, binding = 1) writeonly buffer Spectra
{
  vec2 spectra[];
};
uniform float scale;
#else
layout(std430, binding = 1) readonly buffer Spectra
{
  vec2 spectra[];
};
#endif

// The frequency k = p / n2 + n1 (p mod n2) at position p of an axis of n samples split as
// n1 x n2 (n2 = 1: p itself).
int Frequency(int p, int n, int n2)
{
  return p / n2 + (n / n2) * (p % n2);
}

// The position of frequency -k where position p holds frequency k.
int Negative(int p, int n, int n2)
{
  const int n1 = n / n2;
  const int m = (n - Frequency(p, n, n2)) % n;
  return (m % n1) * n2 + m / n1;
}

// Where the kernels' spectra keep the frequency at position (px, py), if they keep it
// (frequency ky <= NY / 2 along y); -1 otherwise.
int Kept(int px, int py)
{
  const int ky = Frequency(py, size.y, split.y);
  return ky <= size.y / 2 ? ky * size.x + px : -1;
}

// The spectra of the real and imaginary parts of a signal whose spectrum is z at k and zm at -k.
void Separate(vec2 z, vec2 zm, out vec2 re, out vec2 im)
{
  const vec2 zc = vec2(zm.x, -zm.y);
  re = 0.5 * (z + zc);
  const vec2 d = 0.5 * (z - zc);
  im = vec2(d.y, -d.x); // d / i
}

void main()
{
  const ivec2 k = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(k, size)))
  {
    return;
  }
  const ivec2 km = ivec2(Negative(k.x, size.x, split.x), Negative(k.y, size.y, split.y));
  const int total = size.x * size.y;
  const int kept = size.x * (size.y / 2 + 1); // a channel's kept spectrum
  const int p = k.y * size.x + k.x;
  const int q = km.y * size.x + km.x;
#ifdef FFT_SEPARATE
  const int at = Kept(k.x, k.y);
  if (at < 0)
  {
    return;
  }
  vec2 re, im;
  Separate(signal[p], signal[q], re, im);
  spectra[at] = scale * re;
  spectra[kept + at] = scale * im;
  spectra[2 * kept + at] = scale * signal[total + p];
#else
  if (q < p)
  {
    return; // the invocation of -k does both
  }
  // The kernels' spectra at k, from k or (conjugated) from -k, whichever is kept.
  const int atP = Kept(k.x, k.y);
  const int at = atP >= 0 ? atP : Kept(km.x, km.y);
  const vec2 flip = atP >= 0 ? vec2(1.0, 1.0) : vec2(1.0, -1.0);
  const vec2 kr = flip * spectra[at], kg = flip * spectra[kept + at];
  const vec2 kb = flip * spectra[2 * kept + at];
  vec2 re, im;
  Separate(signal[p], signal[q], re, im);
  // The separated red and green spectra and the kernels' are Hermitian: at -k they are the
  // conjugates.
  const vec2 gp = ComplexMultiply(im, kg);
  signal[p] = ComplexMultiply(re, kr) + vec2(-gp.y, gp.x);
  signal[total + p] = ComplexMultiply(signal[total + p], kb);
  if (q != p)
  {
    const vec2 gq = ComplexMultiply(vec2(im.x, -im.y), vec2(kg.x, -kg.y));
    signal[q] = ComplexMultiply(vec2(re.x, -re.y), vec2(kr.x, -kr.y)) + vec2(-gq.y, gq.x);
    signal[total + q] = ComplexMultiply(signal[total + q], vec2(kb.x, -kb.y));
  }
#endif
}

#elif defined(FFT_FOLD)

layout(rgba32f, binding = 0) writeonly uniform image2D target;
uniform ivec2 imageSize; // W, H
uniform int radius;
uniform int rowStride;    // NX
uniform int signalStride; // NX NY

void main()
{
  const ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize)))
  {
    return;
  }
  vec3 sum = vec3(0.0);
#ifdef FFT_REFLECT
  // Positions u = p + 2 W m and u = -1 - p + 2 W m within [-radius, W + radius).
  const ivec2 reach = ivec2(radius) / (2 * imageSize) + 1;
  for (int my = -reach.y; my <= reach.y; ++my)
  {
    for (int fy = 0; fy < 2; ++fy)
    {
      const int v = (fy == 0 ? p.y : -1 - p.y) + 2 * imageSize.y * my;
      if (v < -radius || v >= imageSize.y + radius)
      {
        continue;
      }
      for (int mx = -reach.x; mx <= reach.x; ++mx)
      {
        for (int fx = 0; fx < 2; ++fx)
        {
          const int u = (fx == 0 ? p.x : -1 - p.x) + 2 * imageSize.x * mx;
          if (u < -radius || u >= imageSize.x + radius)
          {
            continue;
          }
          const int at = (v + radius) * rowStride + u + radius;
          sum += vec3(signal[at], signal[signalStride + at].x);
        }
      }
    }
  }
#else
  const int at = (p.y + radius) * rowStride + p.x + radius;
  sum = vec3(signal[at], signal[signalStride + at].x);
#endif
  imageStore(target, p, vec4(sum, 0.0));
}

#endif
