// Runs vtkBloomPass's chain as GLSL passes: the shader variants, the operator textures and
// interiors, the passes of the chain and the composite (see vtkBloomPassChainRunner.h).
#include "vtkBloomPassChainRunner.h"

#include "vtkBloomChain.h"
#include "vtkBloomKernels.h"
#include "vtkBloomPassFS.h"
#include "vtkBloomPassResources.h"
#include "vtkImageBloom.h"
#include "vtkImageBloomThreshold.h"
#include "vtkNew.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderUtilities.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <algorithm>
#include <iomanip>
#include <limits>
#include <sstream>

namespace
{
/**
 * Whether a two-dimensional term costs fewer texel fetches as one pass (Wx Wy per output
 * sample) than as an x pass over the input rows and a y pass; one pass fewer and no
 * intermediate target count for a quarter of the separable cost. The 2:1 box (2 x 2 taps) is
 * one pass, the 2:1 tent (4 x 4) two.
 */
bool TwoDimensional(const vtkBloomChain::Term& term)
{
  const double outputs = static_cast<double>(term.X.OutputSize) * term.Y.OutputSize;
  const double single = static_cast<double>(term.X.Width) * term.Y.Width * outputs;
  const double separable =
    static_cast<double>(term.X.Width) * term.X.OutputSize * term.Y.InputSize +
    static_cast<double>(term.Y.Width) * outputs;
  return single <= 1.25 * separable;
}
}

//------------------------------------------------------------------------------
vtkBloomPassChainRunner::vtkBloomPassChainRunner(vtkObject* owner, vtkBloomPassResources& resources)
  : Owner(owner)
  , Resources(resources)
{
}

//------------------------------------------------------------------------------
vtkBloomPassChainRunner::~vtkBloomPassChainRunner() = default;

//------------------------------------------------------------------------------
void vtkBloomPassChainRunner::ReleaseOperators(vtkWindow* w)
{
  for (auto& op : this->Operators)
  {
    op.second->ReleaseGraphicsResources(w);
  }
  this->Operators.clear();
  this->Interiors.clear();
}

//------------------------------------------------------------------------------
void vtkBloomPassChainRunner::ReleaseGraphicsResources(vtkWindow* w)
{
  this->ReleaseOperators(w);
  for (auto& program : this->Programs)
  {
    program.second->ReleaseGraphicsResources(w);
  }
  this->Programs.clear();
  if (this->Query)
  {
    glDeleteQueries(1, &this->Query);
    this->Query = 0;
  }
  if (!this->TimestampQueries.empty())
  {
    glDeleteQueries(
      static_cast<GLsizei>(this->TimestampQueries.size()), this->TimestampQueries.data());
    this->TimestampQueries.clear();
  }
  this->Profile.clear();
}

//------------------------------------------------------------------------------
std::string vtkBloomPassChainRunner::ShaderConstants()
{
  std::ostringstream os;
  os << "#define OP_IDENTITY " << OP_IDENTITY << "\n#define OP_TABLE " << OP_TABLE
     << "\n#define OP_PERIODIC " << OP_PERIODIC << "\n#define STEP_SCALE " << STEP_SCALE
     << "\n#define STEP_THRESHOLD " << STEP_THRESHOLD << "\n#define STEP_KARIS_TERM "
     << STEP_KARIS_TERM << "\n#define STEP_KARIS_NORMALIZE " << STEP_KARIS_NORMALIZE
     << "\n#define STEP_ADD " << STEP_ADD << "\n#define STEP_COMPOSITE " << STEP_COMPOSITE
     << "\n#define MODE_SMOOTHSTEP_KNEE " << vtkImageBloomThreshold::SMOOTHSTEP_KNEE
     << "\n#define MODE_QUADRATIC_KNEE " << vtkImageBloomThreshold::QUADRATIC_KNEE
     << "\n#define MODE_HARD_LUMINANCE " << vtkImageBloomThreshold::HARD_LUMINANCE
     << "\n#define MODE_PER_CHANNEL " << vtkImageBloomThreshold::PER_CHANNEL
     << "\n#define MODE_NONE " << vtkImageBloomThreshold::NONE << "\n#define FLOAT_MAX "
     << std::scientific << std::setprecision(9) << std::numeric_limits<float>::max() << "\n";
  return os.str();
}

//------------------------------------------------------------------------------
vtkBloomPassChainRunner::Interior vtkBloomPassChainRunner::Interior::Find(
  const vtkBloomLinearOperator& op)
{
  const int width = op.Width;
  auto weight = [&op, width](int j, int k)
  { return static_cast<float>(op.Weights[static_cast<size_t>(j) * width + k]); };
  // Too short an interior is not worth its own draw. A stride of 0 (an input of one
  // sample) would leave the shader independent of the fragment's position, so
  // FindInvariantRange refuses it and the table evaluates such an operator.
  const int minimum = 8;
  for (int period : { 1, 2 })
  {
    const vtkBloomLinearOperator::InvariantRange range = op.FindInvariantRange(period, minimum);
    if (range.Begin == range.End)
    {
      continue;
    }
    const int begin = range.Begin, end = range.End, stride = range.Stride;
    // Drop the band's zero padding common to every phase.
    int lo = width, hi = 0;
    for (int ph = 0; ph < period; ++ph)
    {
      for (int k = 0; k < width; ++k)
      {
        if (weight(begin + ph, k) != 0.0f)
        {
          lo = std::min(lo, k);
          hi = std::max(hi, k + 1);
        }
      }
    }
    if (hi <= lo || hi - lo > 31) // a bit per tap in Defines()
    {
      continue;
    }
    Interior interior;
    interior.Begin = begin;
    interior.End = end;
    interior.Period = period;
    interior.Stride = stride;
    interior.Taps = hi - lo;
    for (int ph = 0; ph < 2; ++ph)
    {
      interior.First[ph] = op.First[begin + std::min(ph, period - 1)] + lo;
    }
    for (int ph = 0; ph < period; ++ph)
    {
      for (int k = lo; k < hi; ++k)
      {
        interior.Weights.push_back(weight(begin + ph, k));
      }
    }
    return interior;
  }
  return Interior();
}

//------------------------------------------------------------------------------
std::string vtkBloomPassChainRunner::Interior::Defines(const char* axis) const
{
  // Bit k of ANY: tap k is non-zero in some phase (else it is compiled out); of ALL: in
  // every phase (no run-time test of its weight).
  unsigned int any = 0, all = (1u << this->Taps) - 1;
  for (int ph = 0; ph < this->Period; ++ph)
  {
    for (int k = 0; k < this->Taps; ++k)
    {
      if (this->Weights[ph * this->Taps + k] != 0.0f)
      {
        any |= 1u << k;
      }
      else
      {
        all &= ~(1u << k);
      }
    }
  }
  std::ostringstream os;
  os << "#define " << axis << "_PERIOD " << this->Period << "\n#define " << axis << "_STRIDE "
     << this->Stride << "\n#define " << axis << "_TAPS " << this->Taps << "\n#define " << axis
     << "_ANY " << any << "u\n#define " << axis << "_ALL " << all << "u\n";
  return os.str();
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkBloomPassChainRunner::OperatorTexture(const vtkBloomLinearOperator& op)
{
  auto found = this->Operators.find(&op);
  if (found != this->Operators.end())
  {
    return found->second;
  }
  // Row j: First[j] then the band's weights; exact in float for indices below 2^24.
  const int columns = op.Width + 1;
  std::vector<float> rows(static_cast<size_t>(columns) * op.OutputSize);
  for (int j = 0; j < op.OutputSize; ++j)
  {
    float* row = rows.data() + static_cast<size_t>(j) * columns;
    row[0] = static_cast<float>(op.First[j]);
    for (int k = 0; k < op.Width; ++k)
    {
      row[k + 1] = static_cast<float>(op.Weights[static_cast<size_t>(j) * op.Width + k]);
    }
  }
  vtkNew<vtkTextureObject> texture;
  texture->SetContext(this->Resources.Context);
  texture->SetInternalFormat(GL_R32F);
  texture->SetMinificationFilter(vtkTextureObject::Nearest);
  texture->SetMagnificationFilter(vtkTextureObject::Nearest);
  texture->Create2DFromRaw(columns, op.OutputSize, 1, VTK_FLOAT, rows.data());
  this->Operators[&op] = texture.Get();
  return texture;
}

//------------------------------------------------------------------------------
const vtkBloomPassChainRunner::Interior& vtkBloomPassChainRunner::InteriorOf(
  const vtkBloomLinearOperator& op)
{
  auto found = this->Interiors.find(&op);
  if (found == this->Interiors.end())
  {
    found = this->Interiors.emplace(&op, Interior::Find(op)).first;
  }
  return found->second;
}

//------------------------------------------------------------------------------
std::vector<vtkBloomPassChainRunner::Segment> vtkBloomPassChainRunner::Segments(
  const vtkBloomLinearOperator* op, int size)
{
  if (!op)
  {
    return { { 0, size, OP_IDENTITY } };
  }
  const Interior& interior = this->InteriorOf(*op);
  if (interior.End <= interior.Begin)
  {
    return { { 0, op->OutputSize, OP_TABLE } };
  }
  std::vector<Segment> segments;
  if (interior.Begin > 0)
  {
    segments.push_back({ 0, interior.Begin, OP_TABLE });
  }
  segments.push_back({ interior.Begin, interior.End, OP_PERIODIC });
  if (interior.End < op->OutputSize)
  {
    segments.push_back({ interior.End, op->OutputSize, OP_TABLE });
  }
  return segments;
}

//------------------------------------------------------------------------------
vtkOpenGLQuadHelper* vtkBloomPassChainRunner::Program(const std::string& variant)
{
  std::unique_ptr<vtkOpenGLQuadHelper>& quad = this->Programs[variant];
  if (!quad)
  {
    std::string fs = vtkBloomPassFS;
    vtkShaderProgram::Substitute(fs, "//BLOOM::Constants", ShaderConstants());
    vtkShaderProgram::Substitute(fs, "//BLOOM::Variant", variant);
    quad.reset(new vtkOpenGLQuadHelper(this->Resources.Context,
      vtkOpenGLRenderUtilities::GetFullScreenQuadVertexShader().c_str(), fs.c_str(), ""));
  }
  else
  {
    this->Resources.Context->GetShaderCache()->ReadyShaderProgram(quad->Program);
  }
  if (!quad->Program || !quad->Program->GetCompiled())
  {
    vtkErrorWithObjectMacro(this->Owner, << "Could not build the bloom shader program:\n"
                                         << variant);
    return nullptr;
  }
  return quad.get();
}

//------------------------------------------------------------------------------
std::string vtkBloomPassChainRunner::Variant(const PassSpec& spec, int xMode, int yMode)
{
  std::ostringstream os;
  os << "#define X_MODE " << xMode << "\n#define Y_MODE " << yMode << "\n";
  if (xMode == OP_PERIODIC)
  {
    os << this->InteriorOf(*spec.X).Defines("X");
  }
  if (yMode == OP_PERIODIC)
  {
    os << this->InteriorOf(*spec.Y).Defines("Y");
  }
  os << "#define STEP " << spec.Step << "\n#define THRESHOLD_MODE "
     << this->Resources.Chain.ThresholdMode << "\n#define MASK_BY_DEPTH "
     << (spec.ReadsSource && this->MaskSource ? 1 : 0) << "\n#define SANITIZE_SOURCE "
     << (spec.ReadsSource && this->SanitizeSource ? 1 : 0) << "\n#define SANITIZE_OUTPUT "
     << (this->SanitizeOutput ? 1 : 0) << "\n#define COMPOSITE_BLOOM "
     << (spec.CompositeBloom ? 1 : 0) << "\n#define DISCARD_ZERO " << (spec.DiscardZero ? 1 : 0)
     << "\n";
  return os.str();
}

//------------------------------------------------------------------------------
void vtkBloomPassChainRunner::Pass(
  vtkBloomPassTarget* target, const int origin[2], const PassSpec& spec)
{
  vtkOpenGLState* state = this->Resources.Context->GetState();
  if (this->Profiling)
  {
    this->BeginProfiledSpan();
  }
  if (target)
  {
    target->FBO->Bind();
    target->FBO->ActivateDrawBuffer(0);
  }
  if (spec.Blend)
  {
    state->vtkglEnable(GL_BLEND);
    state->vtkglBlendEquation(GL_FUNC_ADD);
    state->vtkglBlendFunc(GL_ONE, GL_ONE);
  }
  else
  {
    state->vtkglDisable(GL_BLEND);
  }
  const std::vector<Segment> xs = this->Segments(spec.X, spec.SourceSize[0]);
  const std::vector<Segment> ys = this->Segments(spec.Y, spec.SourceSize[1]);
  vtkTextureObject* textures[] = { spec.Source, spec.X ? this->OperatorTexture(*spec.X) : nullptr,
    spec.Y ? this->OperatorTexture(*spec.Y) : nullptr, spec.Addend,
    spec.Step == STEP_COMPOSITE ? this->Resources.Scene.Color.Get() : nullptr,
    spec.ReadsSource && this->MaskSource ? this->Resources.Emitter.Depth.Get() : nullptr,
    spec.ReadsSource && this->MaskSource ? this->Resources.Scene.Depth.Get() : nullptr };
  const char* samplers[] = { "source", "xRows", "yRows", "addend", "scene", "emitterDepth",
    "sceneDepth" };
  for (vtkTextureObject* texture : textures)
  {
    if (texture)
    {
      texture->Activate();
    }
  }
  for (const Segment& sy : ys)
  {
    for (const Segment& sx : xs)
    {
      vtkOpenGLQuadHelper* quad = this->Program(this->Variant(spec, sx.Mode, sy.Mode));
      if (!quad)
      {
        continue;
      }
      vtkShaderProgram* program = quad->Program;
      auto seti = [program](const char* name, int value)
      {
        if (program->IsUniformUsed(name))
        {
          program->SetUniformi(name, value);
        }
      };
      auto setf = [program](const char* name, double value)
      {
        if (program->IsUniformUsed(name))
        {
          program->SetUniformf(name, static_cast<float>(value));
        }
      };
      for (size_t t = 0; t < sizeof(textures) / sizeof(textures[0]); ++t)
      {
        if (textures[t])
        {
          seti(samplers[t], textures[t]->GetTextureUnit());
        }
      }
      const int offset[2] = { sx.Begin, sy.Begin };
      const float size[2] = { static_cast<float>(sx.End - sx.Begin),
        static_cast<float>(sy.End - sy.Begin) };
      program->SetUniform2i("regionOffset", offset);
      program->SetUniform2f("regionSize", size);
      setf("weight", spec.Weight);
      seti("xWidth", spec.X ? spec.X->Width : 0);
      seti("yWidth", spec.Y ? spec.Y->Width : 0);
      if (sx.Mode == OP_PERIODIC)
      {
        const Interior& in = this->InteriorOf(*spec.X);
        const int values[3] = { in.Begin, in.First[0], in.First[1] };
        program->SetUniform1iv("xInterior", 3, values);
        program->SetUniform1fv("xWeights", static_cast<int>(in.Weights.size()), in.Weights.data());
      }
      if (sy.Mode == OP_PERIODIC)
      {
        const Interior& in = this->InteriorOf(*spec.Y);
        const int values[3] = { in.Begin, in.First[0], in.First[1] };
        program->SetUniform1iv("yInterior", 3, values);
        program->SetUniform1fv("yWeights", static_cast<int>(in.Weights.size()), in.Weights.data());
      }
      this->SetStepUniforms(program, spec.Step);
      state->vtkglViewport(
        origin[0] + sx.Begin, origin[1] + sy.Begin, sx.End - sx.Begin, sy.End - sy.Begin);
      quad->Render();
    }
  }
  for (vtkTextureObject* texture : textures)
  {
    if (texture)
    {
      texture->Deactivate();
    }
  }
  if (this->Profiling)
  {
    this->EndProfiledPass(spec);
  }
  ++this->Passes;
}

//------------------------------------------------------------------------------
void vtkBloomPassChainRunner::SetStepUniforms(vtkShaderProgram* program, int step)
{
  const vtkBloomChain& c = this->Resources.Chain;
  auto setf = [program](const char* name, double value)
  {
    if (program->IsUniformUsed(name))
    {
      program->SetUniformf(name, static_cast<float>(value));
    }
  };
  auto set3f = [program](const char* name, const double values[3])
  {
    const float v[3] = { static_cast<float>(values[0]), static_cast<float>(values[1]),
      static_cast<float>(values[2]) };
    if (program->IsUniformUsed(name))
    {
      program->SetUniform3f(name, v);
    }
  };
  if (step == STEP_THRESHOLD || step == STEP_KARIS_TERM)
  {
    const double luma[3] = { vtkBloomKernels::LuminanceR, vtkBloomKernels::LuminanceG,
      vtkBloomKernels::LuminanceB };
    set3f("lumaWeights", luma);
  }
  if (step == STEP_THRESHOLD)
  {
    const double clampLum = std::min(c.ClampLuminance, static_cast<double>(VTK_FLOAT_MAX));
    setf("threshold", c.Threshold);
    setf("knee", c.Knee);
    setf("clampLuminance", clampLum);
    setf("ceiling", clampLum);
  }
  if (step == STEP_COMPOSITE)
  {
    setf("keep", c.Keep);
    const double strengthTint[3] = { c.Strength * c.Tint[0], c.Strength * c.Tint[1],
      c.Strength * c.Tint[2] };
    set3f("strengthTint", strengthTint);
    setf("largest",
      this->Resources.Format == GL_RGBA32F ? std::numeric_limits<float>::max() : 65504.0);
  }
}

//------------------------------------------------------------------------------
void vtkBloomPassChainRunner::Clear(vtkBloomPassTarget& target)
{
  vtkOpenGLState* state = this->Resources.Context->GetState();
  target.FBO->Bind();
  target.FBO->ActivateDrawBuffer(0);
  state->vtkglViewport(0, 0, target.Size[0], target.Size[1]);
  state->vtkglClearColor(0.0, 0.0, 0.0, 0.0);
  state->vtkglClear(GL_COLOR_BUFFER_BIT);
}

//------------------------------------------------------------------------------
bool vtkBloomPassChainRunner::Run(vtkImageBloom* parameters, vtkTextureObject* emission, bool mask)
{
  vtkBloomPassResources& res = this->Resources;
  const vtkBloomChain& c = res.Chain;
  this->MaskSource = mask;
  this->SanitizeSource = parameters->GetSanitizeNonFinite();
  this->SanitizeOutput = parameters->GetSanitizeNonFinite();
  const size_t n = c.Levels.size();
  if (n == 0)
  {
    return false;
  }
  if (parameters->GetSkipDisabledEffects())
  {
    // As vtkImageBloom::BloomIsDisabled: Strength 0, a black tint or every level weight 0.
    bool zeroTerm = true, zeroWeights = true;
    for (int i = 0; i < 3; ++i)
    {
      zeroTerm &= c.Strength * c.Tint[i] == 0.0;
    }
    for (const auto& level : c.Levels)
    {
      zeroWeights &= level.Weight == 0.0;
    }
    if (zeroTerm || zeroWeights)
    {
      return false;
    }
  }
  const int zero[2] = { 0, 0 };

  // 1. Bright pass: the source fetch and the threshold in one pass. With SkipEmptyBloom the
  // zero samples are not written (the level is cleared first) and an occlusion query counts
  // the others: a reduction over the whole bright pass that costs no extra pass, and whose
  // readback only waits for this pass.
  const bool skipEmpty = parameters->GetSkipEmptyBloom();
  PassSpec bright;
  bright.Source = emission;
  const int full[2] = { c.Width, c.Height };
  bright.SourceSize = full;
  bright.X = c.SourceIsIdentity ? nullptr : &c.Source.X;
  bright.Y = c.SourceIsIdentity ? nullptr : &c.Source.Y;
  bright.Step = STEP_THRESHOLD;
  bright.ReadsSource = true;
  bright.DiscardZero = skipEmpty;
  bright.Name = "bright";
  bright.Level = 0;
  if (skipEmpty)
  {
    this->Clear(res.Levels[0]);
    if (!this->Query)
    {
      glGenQueries(1, &this->Query);
    }
    glBeginQuery(GL_SAMPLES_PASSED, this->Query);
  }
  this->Pass(&res.Levels[0], zero, bright);
  if (skipEmpty)
  {
    glEndQuery(GL_SAMPLES_PASSED);
    GLuint samples = 0;
    glGetQueryObjectuiv(this->Query, GL_QUERY_RESULT, &samples);
    if (samples == 0)
    {
      return false; // nothing is bright: every level, and so the bloom, is zero
    }
  }

  // 2. The pyramid, each level from the unblurred level above it; each term is one
  // two-dimensional pass, added to the previous terms.
  for (size_t i = 1; i < n; ++i)
  {
    const vtkBloomChain::Level& level = c.Levels[i];
    vtkBloomPassTarget& dst = level.Karis ? res.Work[i] : res.Levels[i];
    for (size_t t = 0; t < level.Down.size(); ++t)
    {
      const vtkBloomChain::Term& term = level.Down[t];
      PassSpec down;
      down.Source = res.Levels[i - 1].Color;
      down.SourceSize = res.Levels[i - 1].Size;
      down.X = &term.X;
      down.Y = &term.Y;
      down.Step = level.Karis ? STEP_KARIS_TERM : STEP_SCALE;
      down.Weight = term.Weight;
      down.Blend = t > 0;
      down.Name = "down";
      down.Level = static_cast<int>(i);
      const int rows[2] = { level.Size[0], res.Levels[i - 1].Size[1] };
      if (!TwoDimensional(term))
      {
        // The x half into Temp, then the y half and the step.
        PassSpec x;
        x.Source = down.Source;
        x.SourceSize = down.SourceSize;
        x.X = &term.X;
        x.Name = "down-x";
        x.Level = static_cast<int>(i);
        this->Pass(&res.Temp, zero, x);
        down.Source = res.Temp.Color;
        down.SourceSize = rows;
        down.X = nullptr;
        down.Name = "down-y";
      }
      this->Pass(&dst, zero, down);
    }
    if (level.Karis)
    {
      PassSpec normalize;
      normalize.Source = res.Work[i].Color;
      normalize.SourceSize = level.Size;
      normalize.Step = STEP_KARIS_NORMALIZE;
      normalize.Name = "karis-normalize";
      normalize.Level = static_cast<int>(i);
      this->Pass(&res.Levels[i], zero, normalize);
    }
  }

  // 3. Blur the levels that contribute: x into Temp, y into Work (CASCADE: the last level
  // goes straight into its accumulation, scaled by its weight).
  const size_t last = n - 1;
  const bool cascade = c.AccumulateMode != vtkImageBloom::DIRECT;
  std::vector<vtkBloomPassTarget*> blurred(n);
  bool lastAccumulated = false;
  for (size_t i = 0; i < n; ++i)
  {
    const vtkBloomChain::Level& level = c.Levels[i];
    blurred[i] = &res.Levels[i];
    if (!level.Blur)
    {
      continue;
    }
    PassSpec x;
    x.Source = res.Levels[i].Color;
    x.SourceSize = level.Size;
    x.X = &level.BlurPass.X;
    x.Name = "blur-x";
    x.Level = static_cast<int>(i);
    this->Pass(&res.Temp, zero, x);
    PassSpec y;
    y.Source = res.Temp.Color;
    y.SourceSize = level.Size;
    y.Y = &level.BlurPass.Y;
    y.Name = "blur-y";
    y.Level = static_cast<int>(i);
    if (cascade && i == last)
    {
      y.Weight = level.Weight;
      this->Pass(&res.Accum[last], zero, y);
      lastAccumulated = true;
    }
    else
    {
      this->Pass(&res.Work[i], zero, y);
      blurred[i] = &res.Work[i];
    }
  }

  // 4. Accumulate.
  if (!cascade)
  {
    bool first = true;
    for (size_t i = 0; i < n; ++i)
    {
      const vtkBloomChain::Level& level = c.Levels[i];
      if (level.Weight != 0.0)
      {
        PassSpec up;
        up.Source = blurred[i]->Color;
        up.SourceSize = level.Size;
        up.X = &level.Full.X;
        up.Y = &level.Full.Y;
        up.Weight = level.Weight;
        up.Blend = !first;
        up.Name = "accumulate";
        up.Level = static_cast<int>(i);
        this->Pass(&res.Full, zero, up);
        first = false;
      }
    }
    if (first)
    {
      this->Clear(res.Full);
    }
    return true;
  }
  if (!lastAccumulated)
  {
    PassSpec scale;
    scale.Source = blurred[last]->Color;
    scale.SourceSize = c.Levels[last].Size;
    scale.Weight = c.Levels[last].Weight;
    scale.Name = "scale";
    scale.Level = static_cast<int>(last);
    this->Pass(&res.Accum[last], zero, scale);
  }
  for (size_t i = last; i-- > 0;)
  {
    const vtkBloomChain::Level& level = c.Levels[i];
    PassSpec x;
    x.Source = res.Accum[i + 1].Color;
    x.SourceSize = res.Accum[i + 1].Size;
    x.X = &level.Up.X;
    x.Name = "up-x";
    x.Level = static_cast<int>(i);
    this->Pass(&res.Temp, zero, x);
    PassSpec y;
    y.Source = res.Temp.Color;
    const int size[2] = { level.Size[0], res.Accum[i + 1].Size[1] };
    y.SourceSize = size;
    y.Y = &level.Up.Y;
    y.Name = "up-y";
    y.Level = static_cast<int>(i);
    if (level.Weight != 0.0)
    {
      y.Step = STEP_ADD;
      y.Weight = level.Weight;
      y.Addend = blurred[i]->Color;
    }
    this->Pass(&res.Accum[i], zero, y);
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkBloomPassChainRunner::Composite(vtkBloomPassTarget* target, const int origin[2], bool bloom)
{
  // out = keep * scene + Strength * Tint * bloom, the final resample of CASCADE included.
  vtkBloomPassResources& res = this->Resources;
  const vtkBloomChain& c = res.Chain;
  const int full[2] = { c.Width, c.Height };
  PassSpec composite;
  composite.Step = STEP_COMPOSITE;
  composite.Source = res.Scene.Color;
  composite.SourceSize = full;
  composite.CompositeBloom = bloom;
  composite.Name = "composite";
  if (bloom && c.AccumulateMode == vtkImageBloom::DIRECT)
  {
    composite.Source = res.Full.Color;
  }
  else if (bloom)
  {
    composite.Source = res.Accum[0].Color;
    if (!c.FinalIsIdentity)
    {
      composite.SourceSize = res.Accum[0].Size;
      composite.X = &c.Final.X;
      composite.Y = &c.Final.Y;
    }
  }
  this->Pass(target, origin, composite);
}

//------------------------------------------------------------------------------
void vtkBloomPassChainRunner::Copy(
  vtkBloomPassTarget* target, const int origin[2], vtkBloomPassTarget& source)
{
  PassSpec copy;
  copy.Source = source.Color;
  copy.SourceSize = source.Size;
  copy.Name = "copy";
  this->Pass(target, origin, copy);
}
