//VTK::System::Dec
// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
//BLOOM::Extensions

/*=========================================================================
  vtkBloomPassFS.glsl: one full-screen pass of vtkBloomPass.

  A pass applies up to two banded linear operators (vtkBloomLinearOperator, computed on the CPU
  by the same code as the vtkImageBloom filters), one along x and one along y, then one
  point-wise step:

    sum(p) = sum_ky Wy[p.y][ky] * ( sum_kx Wx[p.x][kx] * source[Fx[p.x] + kx, Fy[p.y] + ky] )

  which is the separable x pass followed by the y pass, summed in the same order. Each axis is
  evaluated in one of three ways, chosen per program by vtkBloomPass (no run-time branch on a
  uniform: llvmpipe would execute both sides):

  - OP_IDENTITY: the axis is not resampled (one tap of weight 1);
  - OP_TABLE: row j of the texture `xRows`/`yRows` holds First[j] in texel 0 and the band's
    weights in texels 1..width (any operator, any output sample);
  - OP_PERIODIC: the operator's interior, where First[j + PERIOD] = First[j] + STRIDE and the
    rows repeat with period PERIOD (1 for a convolution or a 2:1 resample, 2 for a 1:2
    resample); First is computed from the interior's first rows and the weights are the
    operator's own rows, both uniforms (not constants: the compiler would factor equal
    constant weights, w a + w b -> w (a + b), which overflows where the CPU chain does not).
    The border samples are drawn separately with OP_TABLE.

  Every fetch is an exact texelFetch of the RGBA float source: bilinear interpolation and
  border clamping are already folded into the weights, so no hardware filtering is involved
  and odd sizes behave exactly as on the CPU. Zero weights are skipped, so 0 * Inf never makes
  a NaN.

  ZERO_BLOOM: the composite where the content-aware chain knows the bloom is zero; the bloom
  is a uniform zero (not a constant, which the compiler could fold), so the result is the
  full composite's bit for bit.

  TILE (compute only, both axes OP_TABLE): the x half of the pass computed once per row. A 2D
  pass re-sums a source row for every output row that reads it; a separable pair of passes
  writes the rows to a target and reads them back in a second dispatch. Here each 16 x 16 work
  group first sums the at most TILE_ROWS source rows its outputs read, for its 16 columns, into
  shared memory, then each output sums its column's rows through the y operator: the same sums
  in the same order as the separable pair (vtkBloomPassTesting::SetFuseSeparablePasses), kept in 32-bit
  floats as the exact mode's targets keep them: the same bits.

  TILE2: a second separable term of the same output, from its own source and operators (both
  by table, X2_WIDTH and Y2_WIDTH taps), its x sums shared the same way (TILE2_ROWS rows): with TILE2_ADDEND it is the ADD
  step's addend (the upsample's blurred level, which a pass of its own would have written),
  else weight2 times it is added to the result (the downsample's other term, which a pass of its
  own would have written before this one blended over it).

  SAMPLE_THRESHOLD (the bright pass of a multisampled scene, vtkBloomPass::ThresholdSamples):
  each of the SAMPLE_THRESHOLD samples of a source pixel goes through the bright pass, and the
  pixel is their mean, before the resample; the step then thresholds nothing more. A thin line
  or a point that covers part of a pixel then brings light in proportion to its coverage, as
  the scene does, rather than nothing until its resolved colour crosses the threshold.

  COMPOSITE_SAMPLES (a second composite into a framebuffer with as many samples as the
  multisampled scene, after the composite of the resolved scene into all its samples): each
  sample whose scene sample differs from the resolved scene (an anti-aliased edge) becomes the
  composite of its own scene sample (gl_SampleID: the shader runs once per sample; the others
  are discarded before any tap). The framebuffer then holds the samples the renderer would have
  drawn and resolves as it resolves them without the pass: VTK presents a multisampled window
  through a gamma 2.2 average of its samples, where every sample holding the linear average
  was up to 72 levels off at the edges of thin lines on white. The bloom is the pixel's, the
  same for each of its samples. Where the samples' excess above 1 (light, which an 8-bit
  framebuffer clips sample by sample) would take more than half a level off their mean, the
  pixel keeps the resolved composite (discarded): the float resolve keeps the light's excess at
  its edges, as before.

  COMPUTE: the same pass as a compute shader (OpenGL 4.3; vtkBloomPass::UseComputeShaders),
  one invocation per output sample of the draw's region, written with imageStore into the
  target bound as image unit 0 (IMAGE_FORMAT) at targetOffset (the composite's origin in the
  framebuffer's colour texture, else 0); BLEND adds to what the target holds, as the fragment
  pass's GL_ONE, GL_ONE blending does. Into GL_RGBA8 the store clamps and rounds as a fragment
  output does.
=========================================================================*/

//VTK::Output::Dec

#ifdef COMPUTE
layout(local_size_x = 16, local_size_y = 16) in;
layout(IMAGE_FORMAT, binding = 0) uniform image2D target;
uniform ivec2 targetOffset; // where the output sample (0, 0) lies in the target
#else
in vec2 texCoord;
#endif

//BLOOM::Constants

//BLOOM::Variant

uniform sampler2D source; // the operators' input
uniform ivec2 regionOffset; // the first output sample this draw computes
uniform vec2 regionSize;    // the samples this draw computes, the size of the viewport
uniform float weight;       // SCALE, KARIS_TERM and ADD weight

#ifndef ZERO_BLOOM
#define ZERO_BLOOM 0
#endif
#ifndef TILE
#define TILE 0
#endif
#ifndef SAMPLE_THRESHOLD
#define SAMPLE_THRESHOLD 0
#endif
#ifndef COMPOSITE_SAMPLES
#define COMPOSITE_SAMPLES 0
#endif
#if SAMPLE_THRESHOLD
uniform sampler2DMS sourceSamples; // the scene before its resolve
vec3 brightPass(vec3 c);
#endif
#if TILE && defined(COMPUTE)
shared vec4 tileRows[TILE_ROWS * 16]; // the x sums of the group's rows, 16 columns a row
#endif
#ifndef TILE2
#define TILE2 0
#endif
#ifndef TILE2_ADDEND
#define TILE2_ADDEND 0
#endif
#if TILE2 && defined(COMPUTE)
uniform sampler2D source2;
uniform sampler2D x2Rows;
uniform sampler2D y2Rows;
uniform float weight2;
shared vec4 tileRows2[TILE2_ROWS * 16];
#endif

#if X_MODE == OP_TABLE
uniform sampler2D xRows;
#define X_COUNT X_TABLE_WIDTH // a constant: the taps' loop unrolls, their fetches overlap
#define X_ANY 0xffffffffu
#define X_ALL 0u
#elif X_MODE == OP_PERIODIC
uniform int xInterior[3]; // first interior output sample, First of its first two rows
uniform float xWeights[X_PERIOD * X_TAPS];
#define X_COUNT X_TAPS
#else
#define X_COUNT 1
#define X_ANY 1u
#define X_ALL 1u
#endif

#if Y_MODE == OP_TABLE
uniform sampler2D yRows;
#define Y_COUNT Y_TABLE_WIDTH
#define Y_ANY 0xffffffffu
#define Y_ALL 0u
#elif Y_MODE == OP_PERIODIC
uniform int yInterior[3];
uniform float yWeights[Y_PERIOD * Y_TAPS];
#define Y_COUNT Y_TAPS
#else
#define Y_COUNT 1
#define Y_ANY 1u
#define Y_ALL 1u
#endif

#if MASK_BY_DEPTH
// Selective bloom: source samples count only where the emitter is the visible surface.
uniform sampler2D emitterDepth;
uniform sampler2D sceneDepth;
#endif

#if STEP == STEP_THRESHOLD
// Bright pass (vtkImageBloomThreshold::BrightPass).
uniform float threshold;
uniform float knee;
uniform float clampLuminance;
uniform float ceiling; // min(clampLuminance, largest float)
#endif
#if STEP == STEP_THRESHOLD || STEP == STEP_KARIS_TERM
uniform vec3 lumaWeights;
#endif

#if STEP == STEP_ADD
uniform sampler2D addend;
#endif
#if STEP == STEP_COMPOSITE
uniform sampler2D scene;
#if COMPOSITE_SAMPLES
uniform sampler2DMS sceneSamples; // the scene before its resolve
#endif
uniform float keep;
uniform vec3 strengthTint;
uniform float glowAlpha; // 1: the glow raises a transparent scene's alpha; 0: alpha is kept
uniform float largest; // largest finite value of the output target
#if SCENE_BACKGROUND == BACKGROUND_TEXTURE
uniform sampler2D background; // the renderer's gradient or textured background
uniform ivec2 backgroundOrigin; // where the renderer's pixel (0, 0) lies in it
#elif SCENE_BACKGROUND == BACKGROUND_COLOR
uniform vec4 backgroundColor; // the renderer's solid background
#endif
#if ZERO_BLOOM
uniform float zeroBloom;
#endif
#endif

// First sample and phase of the output sample j along each axis.
int xFirst;
int xPhase;
int yFirst;
int yPhase;

void setUpX(int j)
{
#if X_MODE == OP_TABLE
  xFirst = int(texelFetch(xRows, ivec2(0, j), 0).r);
#elif X_MODE == OP_PERIODIC
  int m = (j - xInterior[0]) / X_PERIOD;
  xPhase = j - xInterior[0] - m * X_PERIOD;
  xFirst = (xPhase == 0 ? xInterior[1] : xInterior[2]) + X_STRIDE * m;
#else
  xFirst = j;
#endif
}

float weightX(int j, int k)
{
#if X_MODE == OP_TABLE
  return texelFetch(xRows, ivec2(k + 1, j), 0).r;
#elif X_MODE == OP_PERIODIC
#if X_PERIOD == 1
  return xWeights[k];
#else
  return xPhase == 0 ? xWeights[k] : xWeights[X_TAPS + k];
#endif
#else
  return 1.0;
#endif
}

void setUpY(int j)
{
#if Y_MODE == OP_TABLE
  yFirst = int(texelFetch(yRows, ivec2(0, j), 0).r);
#elif Y_MODE == OP_PERIODIC
  int m = (j - yInterior[0]) / Y_PERIOD;
  yPhase = j - yInterior[0] - m * Y_PERIOD;
  yFirst = (yPhase == 0 ? yInterior[1] : yInterior[2]) + Y_STRIDE * m;
#else
  yFirst = j;
#endif
}

float weightY(int j, int k)
{
#if Y_MODE == OP_TABLE
  return texelFetch(yRows, ivec2(k + 1, j), 0).r;
#elif Y_MODE == OP_PERIODIC
#if Y_PERIOD == 1
  return yWeights[k];
#else
  return yPhase == 0 ? yWeights[k] : yWeights[Y_TAPS + k];
#endif
#else
  return 1.0;
#endif
}

// The chain's source as vtkImageBloom reads its input: with SanitizeNonFinite, NaN becomes 0
// and +-Inf the largest finite float, before any resampling.
vec4 fetchSource(ivec2 q)
{
#if SAMPLE_THRESHOLD
  vec3 bright = vec3(0.0);
  for (int s = 0; s < SAMPLE_THRESHOLD; ++s)
  {
    vec4 one = texelFetch(sourceSamples, q, s);
#if SANITIZE_SOURCE
    for (int i = 0; i < 3; ++i)
    {
      one[i] = isnan(one[i]) ? 0.0 : clamp(one[i], -FLOAT_MAX, FLOAT_MAX);
    }
#endif
    bright += brightPass(one.rgb);
  }
  return vec4(bright / float(SAMPLE_THRESHOLD), 0.0);
#endif
  vec4 value = texelFetch(source, q, 0);
#if SANITIZE_SOURCE
  for (int i = 0; i < 4; ++i)
  {
    value[i] = isnan(value[i]) ? 0.0 : clamp(value[i], -FLOAT_MAX, FLOAT_MAX);
  }
#endif
#if MASK_BY_DEPTH
  if (texelFetch(emitterDepth, q, 0).r > texelFetch(sceneDepth, q, 0).r)
  {
    value = vec4(0.0);
  }
#endif
#if EMISSION_IN_ALPHA
  // Selective bloom in one render: an emitting fragment's alpha is 1 + its weight
  // (vtkBloomPassEmission.h).
  value = vec4(value.rgb * clamp(value.a - 1.0, 0.0, 1.0), 0.0);
#endif
  return value;
}

#if STEP == STEP_THRESHOLD
// vtkBloomBrightPass.h: non-finite colours are mapped in every mode (vtkBloomMapNonFinite),
// then the threshold (vtkBloomBrightPass).
vec3 brightPass(vec3 c)
{
  for (int i = 0; i < 3; ++i)
  {
    if (isnan(c[i]))
    {
      c[i] = 0.0;
    }
    else if (isinf(c[i]))
    {
      c[i] = c[i] > 0.0 ? ceiling : 0.0;
    }
  }
#if THRESHOLD_MODE == MODE_NONE
  return c;
#else
  float lum = dot(c, lumaWeights);
  // Firefly guard: scale the colour so that its luminance does not exceed the clamp.
  if (lum > clampLuminance)
  {
    // In float32 the luminance of colours near the largest float overflows to Inf (double, on
    // the CPU, does not); take the ratio on scaled values then.
    const float s = 5.421010862e-20; // 2^-64
    c *= isinf(lum) ? (clampLuminance * s) / dot(c * s, lumaWeights) : clampLuminance / lum;
    lum = dot(c, lumaWeights);
  }
  float k = threshold * knee;
  float factor = 1.0;
#if THRESHOLD_MODE == MODE_SMOOTHSTEP_KNEE
  // knee 0 is the step lum >= threshold; smoothstep(t, t, x) is undefined.
  factor =
    k > 0.0 ? smoothstep(threshold - k, threshold + k, lum) : (lum >= threshold ? 1.0 : 0.0);
#elif THRESHOLD_MODE == MODE_QUADRATIC_KNEE
  float brightness = max(c.r, max(c.g, c.b));
  float q = clamp(brightness - threshold + k, 0.0, 2.0 * k);
  q = q * q / (4.0 * k + 1e-5);
  factor = max(q, brightness - threshold) / max(brightness, 1e-5);
#elif THRESHOLD_MODE == MODE_HARD_LUMINANCE
  factor = lum > threshold ? 1.0 : 0.0;
#elif THRESHOLD_MODE == MODE_EXCESS_KNEE
  // The excess of the brightest channel over the threshold, its first 2k softened by a
  // quadratic that starts at the threshold: nothing at or below it glows.
  float brightness = max(c.r, max(c.g, c.b));
  float excess = brightness - threshold;
  float soft = 0.0;
  if (excess > 0.0)
  {
    soft = excess < 2.0 * k ? excess * excess / (4.0 * k) : excess - k;
  }
  factor = brightness > 0.0 ? soft / brightness : 0.0;
#elif THRESHOLD_MODE == MODE_PER_CHANNEL
  return max(c - vec3(threshold), vec3(0.0));
#endif
  return max(c * factor, vec3(0.0));
#endif
}
#endif

#if STEP == STEP_COMPOSITE
// SCENE_BACKGROUND: the scene was rendered over transparent black (the background is not
// light), premultiplied. It goes over the background, and the glow, whose largest channel
// `coverage` is, goes over the background too (Mol*'s premultiplied-over): on a light
// background the halo shows as colour where added light would saturate. Without it, or with
// no glow (coverage 0), this is the scene as the renderer would have drawn it over its
// background, and over black or transparent black the glow is added as before.
vec4 overBackground(vec4 base, float coverage, ivec2 p)
{
#if SCENE_BACKGROUND == BACKGROUND_TEXTURE
  vec4 behind = texelFetch(background, p + backgroundOrigin, 0);
#elif SCENE_BACKGROUND == BACKGROUND_COLOR
  vec4 behind = backgroundColor;
#endif
#if SCENE_BACKGROUND
  float uncovered = max(1.0 - base.a, 0.0);
  base = vec4(base.rgb + uncovered * (1.0 - coverage) * behind.rgb, base.a + uncovered * behind.a);
#endif
  return base;
}

vec4 finite(vec4 v)
{
  for (int i = 0; i < 4; ++i)
  {
    v[i] = isnan(v[i]) ? 0.0 : clamp(v[i], -largest, largest);
  }
  return v;
}

// The composite of one scene colour `base` (the resolved scene's, or one of its samples') with
// the bloom term `sum` at p.
vec4 compositeOf(vec4 base, vec3 sum, ivec2 p)
{
#if SCENE_ALPHA_CLAMPED
  base.a = min(base.a, 1.0); // selective bloom's weight rode above 1 (EMISSION_IN_ALPHA)
#endif
#if SANITIZE_OUTPUT
  base = finite(base);
#endif
#if COMPOSITE_BLOOM
  // The bloom is clamped to the float range first (NaN 0), as vtkImageBloom's composite does,
  // so a zero strength or tint channel adds nothing even where the float32 bloom overflowed.
  vec3 bloom = sum;
  for (int i = 0; i < 3; ++i)
  {
    bloom[i] = isnan(bloom[i]) ? 0.0 : clamp(bloom[i], -FLOAT_MAX, FLOAT_MAX);
  }
  // The glow carries alpha (a rendered frame): over a transparent background (alpha < 1) the
  // colour stays premultiplied and alpha rises by the glow's largest channel, so that the halo
  // shows over any backdrop. Where the scene is opaque (alpha >= 1), or with glowAlpha 0 (an
  // image, as vtkImageBloom), alpha is the scene's exactly.
  vec3 glow = strengthTint * bloom;
  float coverage = clamp(max(max(glow.r, glow.g), glow.b), 0.0, 1.0);
  base = overBackground(base, coverage, p);
  vec4 result =
    vec4(keep * base.rgb + glow, base.a + glowAlpha * max(1.0 - base.a, 0.0) * coverage);
#else
  // No bloom (nothing passed the bright pass, or the effect is off): keep * in + 0, as
  // vtkImageBloom composites a skipped bloom.
  base = overBackground(base, 0.0, p);
  vec4 result = vec4(keep * base.rgb + vec3(0.0), base.a);
#endif
#if SANITIZE_OUTPUT
  result = finite(result);
#endif
  return result;
}
#endif

// Whether tap k of weight w contributes. Bit k of `any`: the tap is non-zero in some phase
// (else it is compiled out); of `all`: in every phase (no run-time test of its weight). The
// masks hold the first 32 taps only (GLSL leaves a shift by 32 or more undefined); a wider
// operator's further taps are tested by their weight.
bool tapIsOn(uint any, uint all, int k, float w)
{
  if (k >= 32)
  {
    return w != 0.0;
  }
  return ((any >> uint(k)) & 1u) != 0u && (((all >> uint(k)) & 1u) != 0u || w != 0.0);
}

// The x half of output column p.x on source row r.
vec4 rowSum(int px, int r)
{
  vec4 row = vec4(0.0);
  for (int kx = 0; kx < X_COUNT; ++kx)
  {
    float wx = weightX(px, kx);
    if (tapIsOn(X_ANY, X_ALL, kx, wx))
    {
      row += wx * fetchSource(ivec2(xFirst + kx, r));
    }
  }
  return row;
}

#if TILE && defined(COMPUTE)
// The x sums of the source rows the work group's outputs read, for the group's columns, into
// tileRows; returns the first of those rows. Every invocation reaches the barrier.
int sumTileRows(ivec2 p, bool column)
{
  int y0 = regionOffset.y + int(gl_WorkGroupID.y) * 16;
  int yLast = min(y0 + 15, regionOffset.y + int(regionSize.y) - 1);
  setUpY(y0);
  int r0 = yFirst;
  setUpY(yLast);
  int r1 = min(min(yFirst + Y_COUNT, r0 + TILE_ROWS), textureSize(source, 0).y);
  if (column)
  {
    setUpX(p.x);
    for (int r = r0 + int(gl_LocalInvocationID.y); r < r1; r += 16)
    {
      tileRows[(r - r0) * 16 + int(gl_LocalInvocationID.x)] = rowSum(p.x, r);
    }
  }
  memoryBarrierShared();
  barrier();
  return r0;
}
#endif

#if TILE2 && defined(COMPUTE)
// The second term's x sums into tileRows2, as sumTileRows does (whose barrier covers them: call
// this first); returns its first row. Its taps are its tables' (a zero weight skipped, as
// tapIsOn skips it for OP_TABLE), its source read as it is.
int sumTileRows2(ivec2 p, bool column)
{
  int y0 = regionOffset.y + int(gl_WorkGroupID.y) * 16;
  int yLast = min(y0 + 15, regionOffset.y + int(regionSize.y) - 1);
  int r0 = int(texelFetch(y2Rows, ivec2(0, y0), 0).r);
  int r1 = int(texelFetch(y2Rows, ivec2(0, yLast), 0).r) + Y2_WIDTH;
  r1 = min(min(r1, r0 + TILE2_ROWS), textureSize(source2, 0).y);
  if (column)
  {
    int first = int(texelFetch(x2Rows, ivec2(0, p.x), 0).r);
    for (int r = r0 + int(gl_LocalInvocationID.y); r < r1; r += 16)
    {
      vec4 row = vec4(0.0);
      for (int kx = 0; kx < X2_WIDTH; ++kx)
      {
        float wx = texelFetch(x2Rows, ivec2(kx + 1, p.x), 0).r;
        if (wx != 0.0)
        {
          row += wx * texelFetch(source2, ivec2(first + kx, r), 0);
        }
      }
      tileRows2[(r - r0) * 16 + int(gl_LocalInvocationID.x)] = row;
    }
  }
  return r0;
}

// The second term at p, from the shared x sums (tileFirst2: the first row they hold).
vec4 sumTerm2(ivec2 p, int tileFirst2)
{
  int first = int(texelFetch(y2Rows, ivec2(0, p.y), 0).r);
  vec4 sum = vec4(0.0);
  for (int ky = 0; ky < Y2_WIDTH; ++ky)
  {
    float wy = texelFetch(y2Rows, ivec2(ky + 1, p.y), 0).r;
    if (wy != 0.0)
    {
      sum += wy * tileRows2[(first + ky - tileFirst2) * 16 + int(gl_LocalInvocationID.x)];
    }
  }
  return sum;
}
#endif

void main()
{
  // The output sample this fragment computes; texCoord spans the draw's region.
#ifdef COMPUTE
  ivec2 p = regionOffset + ivec2(gl_GlobalInvocationID.xy);
#if TILE2
  int tileFirst2 = sumTileRows2(p, float(gl_GlobalInvocationID.x) < regionSize.x);
#endif
#if TILE
  int tileFirst = sumTileRows(p, float(gl_GlobalInvocationID.x) < regionSize.x);
#endif
  if (any(greaterThanEqual(vec2(gl_GlobalInvocationID.xy), regionSize)))
  {
    return;
  }
#else
  ivec2 p = regionOffset + ivec2(floor(texCoord * regionSize));
#endif
#if COMPOSITE_SAMPLES
  // A sample equal to the resolved scene holds its composite already (the composite before).
  vec4 ownSample = texelFetch(sceneSamples, p, gl_SampleID);
  if (ownSample == texelFetch(scene, p, 0))
  {
    discard;
  }
#endif

#if ZERO_BLOOM
  vec4 sum = vec4(zeroBloom);
#elif TILE && defined(COMPUTE)
  setUpY(p.y);
  vec4 sum = vec4(0.0);
  for (int ky = 0; ky < Y_COUNT; ++ky)
  {
    float wy = weightY(p.y, ky);
    if (tapIsOn(Y_ANY, Y_ALL, ky, wy))
    {
      sum += wy * tileRows[(yFirst + ky - tileFirst) * 16 + int(gl_LocalInvocationID.x)];
    }
  }
#elif STEP != STEP_COMPOSITE || COMPOSITE_BLOOM
  setUpX(p.x);
  setUpY(p.y);
  vec4 sum = vec4(0.0);
  for (int ky = 0; ky < Y_COUNT; ++ky)
  {
    // The tap masks are constants except for OP_TABLE: the tests fold at compile time.
    float wy = weightY(p.y, ky);
    if (tapIsOn(Y_ANY, Y_ALL, ky, wy))
    {
      vec4 row = rowSum(p.x, yFirst + ky);
      sum += wy * row;
    }
  }
#endif

  vec4 result;
#if STEP == STEP_SCALE
  result = weight * sum;
#elif STEP == STEP_THRESHOLD && SAMPLE_THRESHOLD
  result = vec4(sum.rgb, 0.0); // thresholded sample by sample (fetchSource)
#elif STEP == STEP_THRESHOLD
  result = vec4(brightPass(sum.rgb), 0.0);
#elif STEP == STEP_KARIS_TERM
  // Karis 2014: weight each term by 1 / (1 + luma); alpha carries the weights' sum.
  float k = weight / (1.0 + max(dot(sum.rgb, lumaWeights), 0.0));
  result = vec4(k * sum.rgb, k);
#elif STEP == STEP_KARIS_NORMALIZE
  result = vec4(sum.rgb / sum.a, 0.0);
#elif STEP == STEP_ADD && TILE2 && TILE2_ADDEND && defined(COMPUTE)
  result = sum + weight * sumTerm2(p, tileFirst2);
#elif STEP == STEP_ADD
  result = sum + weight * texelFetch(addend, p, 0);
#else // STEP_COMPOSITE
#if !COMPOSITE_BLOOM
  vec4 sum = vec4(0.0); // no bloom term
#endif
#if COMPOSITE_SAMPLES
  // Each sample's own composite, which the framebuffer clips to [0, 1] as it clips the
  // renderer's samples, unless the pixel holds light: where the samples' excess above 1 would
  // take more than half a level off their mean, the pixel keeps the resolved composite (the
  // float resolve keeps the light's excess at its edges). Colours a sample interpolates from
  // outside its triangle (multisampling shades at the pixel's centre) stray a little out of
  // [0, 1] at the edges of colour-mapped surfaces: that is not light.
  result = compositeOf(ownSample, sum.rgb, p);
  vec3 excess = vec3(0.0);
  for (int j = 0; j < COMPOSITE_SAMPLES; ++j)
  {
    vec3 c = compositeOf(texelFetch(sceneSamples, p, j), sum.rgb, p).rgb;
    excess += max(c - vec3(1.0), vec3(0.0));
  }
  if (any(greaterThan(excess, vec3(0.5 * float(COMPOSITE_SAMPLES) / 255.0))))
  {
    discard;
  }
#else
  result = compositeOf(texelFetch(scene, p, 0), sum.rgb, p);
#endif
#endif

#if DISCARD_ZERO
  // The target was cleared to zero; an occlusion query counts the samples that are not.
  if (all(equal(result, vec4(0.0))))
  {
#ifdef COMPUTE
    return;
#else
    discard;
#endif
  }
#endif
#ifdef COMPUTE
#if TILE2 && !TILE2_ADDEND
  result += weight2 * sumTerm2(p, tileFirst2);
#endif
#if BLEND
  result += imageLoad(target, targetOffset + p);
#endif
  imageStore(target, targetOffset + p, result);
#else
  gl_FragData[0] = result;
#endif
}
