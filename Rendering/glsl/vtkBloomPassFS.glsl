//VTK::System::Dec

/*=========================================================================
  vtkBloomPassFS.glsl: one full-screen pass of vtkBloomPass.

  A pass applies one banded linear operator (vtkBloomLinearOperator, computed on the CPU by the
  same code as the vtkImageBloom filters) along one axis, then one point-wise step. Row j of
  `operatorRows` holds the index of the first input sample in texel 0 and the band's weights in
  texels 1..bandWidth. Every fetch is an exact texelFetch: bilinear interpolation and border
  clamping are already folded into the weights, so no hardware filtering is involved and odd
  sizes behave exactly as on the CPU.
=========================================================================*/

//VTK::Output::Dec

in vec2 texCoord;

//BLOOM::Constants

uniform sampler2D source;       // the operator's input
uniform sampler2D operatorRows; // First and Weights of the operator, one row per output sample
uniform int bandWidth;          // vtkBloomLinearOperator::Width
uniform int axis;               // AXIS_X, AXIS_Y or AXIS_NONE (point-wise pass)
uniform vec2 outputSize;        // samples of the output, the size of the viewport
uniform int step;               // the point-wise step after the operator
uniform float weight;           // SCALE, KARIS_TERM and ADD weight

// Selective bloom: source samples count only where the emitter is the visible surface.
uniform int maskByDepth;
uniform sampler2D emitterDepth;
uniform sampler2D sceneDepth;

// Bright pass (vtkImageBloomThreshold::BrightPass).
uniform int thresholdMode;
uniform float threshold;
uniform float knee;
uniform float clampLuminance;
uniform float ceiling; // min(clampLuminance, largest float)
uniform vec3 lumaWeights;

// ADD and COMPOSITE.
uniform sampler2D addend;
uniform sampler2D scene;
uniform float keep;
uniform vec3 strengthTint;
uniform int sanitize;
uniform float largest; // largest finite value of the output target

// The chain's source as vtkImageBloom reads its input: with SanitizeNonFinite, NaN becomes 0
// and +-Inf the largest finite float, before any resampling.
uniform int sanitizeSource;

vec4 fetchSource(ivec2 q)
{
  vec4 value = texelFetch(source, q, 0);
  if (sanitizeSource != 0)
  {
    for (int i = 0; i < 4; ++i)
    {
      value[i] = isnan(value[i]) ? 0.0 : clamp(value[i], -FLOAT_MAX, FLOAT_MAX);
    }
  }
  if (maskByDepth != 0 && texelFetch(emitterDepth, q, 0).r > texelFetch(sceneDepth, q, 0).r)
  {
    value = vec4(0.0);
  }
  return value;
}

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
  if (thresholdMode == MODE_NONE)
  {
    return c;
  }
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
  if (thresholdMode == MODE_SMOOTHSTEP_KNEE)
  {
    // knee 0 is the step lum >= threshold; smoothstep(t, t, x) is undefined.
    factor = k > 0.0 ? smoothstep(threshold - k, threshold + k, lum)
                     : (lum >= threshold ? 1.0 : 0.0);
  }
  else if (thresholdMode == MODE_QUADRATIC_KNEE)
  {
    float brightness = max(c.r, max(c.g, c.b));
    float q = clamp(brightness - threshold + k, 0.0, 2.0 * k);
    q = q * q / (4.0 * k + 1e-5);
    factor = max(q, brightness - threshold) / max(brightness, 1e-5);
  }
  else if (thresholdMode == MODE_HARD_LUMINANCE)
  {
    factor = lum > threshold ? 1.0 : 0.0;
  }
  else if (thresholdMode == MODE_PER_CHANNEL)
  {
    return max(c - vec3(threshold), vec3(0.0));
  }
  return max(c * factor, vec3(0.0));
}

vec4 finite(vec4 v)
{
  for (int i = 0; i < 4; ++i)
  {
    v[i] = isnan(v[i]) ? 0.0 : clamp(v[i], -largest, largest);
  }
  return v;
}

void main()
{
  // The output sample this fragment computes; texCoord spans the viewport.
  ivec2 p = ivec2(floor(texCoord * outputSize));
  vec4 sum = vec4(0.0);
  if (axis == AXIS_NONE)
  {
    sum = fetchSource(p);
  }
  else
  {
    int j = axis == AXIS_X ? p.x : p.y;
    int first = int(texelFetch(operatorRows, ivec2(0, j), 0).r);
    for (int k = 0; k < bandWidth; ++k)
    {
      float w = texelFetch(operatorRows, ivec2(k + 1, j), 0).r;
      // The band's padding has zero weights; skipping them keeps 0 * Inf from making a NaN.
      if (w != 0.0)
      {
        ivec2 q = axis == AXIS_X ? ivec2(first + k, p.y) : ivec2(p.x, first + k);
        sum += w * fetchSource(q);
      }
    }
  }

  vec4 result;
  if (step == STEP_SCALE)
  {
    result = weight * sum;
  }
  else if (step == STEP_THRESHOLD)
  {
    result = vec4(brightPass(sum.rgb), 0.0);
  }
  else if (step == STEP_KARIS_TERM)
  {
    // Karis 2014: weight each term by 1 / (1 + luma); alpha carries the weights' sum.
    float k = weight / (1.0 + max(dot(sum.rgb, lumaWeights), 0.0));
    result = vec4(k * sum.rgb, k);
  }
  else if (step == STEP_KARIS_NORMALIZE)
  {
    result = vec4(sum.rgb / sum.a, 0.0);
  }
  else if (step == STEP_ADD)
  {
    result = sum + weight * texelFetch(addend, p, 0);
  }
  else // STEP_COMPOSITE
  {
    vec4 base = texelFetch(scene, p, 0);
    if (sanitize != 0)
    {
      base = finite(base);
    }
    result = vec4(keep * base.rgb + strengthTint * sum.rgb, base.a);
    if (sanitize != 0)
    {
      result = finite(result);
    }
  }
  gl_FragData[0] = result;
}
