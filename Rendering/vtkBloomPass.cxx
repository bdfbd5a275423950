#include "vtkBloomPass.h"

#include "vtkActor.h"
#include "vtkBloomChain.h"
#include "vtkBloomKernels.h"
#include "vtkBloomPassFS.h"
#include "vtkCamera.h"
#include "vtkFloatArray.h"
#include "vtkImageBloom.h"
#include "vtkImageBloomThreshold.h"
#include "vtkImageData.h"
#include "vtkLookupTable.h"
#include "vtkMapper.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderUtilities.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkPointData.h"
#include "vtkProp.h"
#include "vtkPropCollection.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iomanip>
#include <limits>
#include <map>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkBloomPass);

namespace
{
// Values shared with vtkBloomPassFS.glsl, emitted into the shader as #defines.
enum
{
  OP_IDENTITY = 0,
  OP_TABLE = 1,
  OP_PERIODIC = 2
};
enum
{
  STEP_SCALE = 0,
  STEP_THRESHOLD,
  STEP_KARIS_TERM,
  STEP_KARIS_NORMALIZE,
  STEP_ADD,
  STEP_COMPOSITE
};

std::string ShaderConstants()
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

/**
 * The translation-invariant interior of a vtkBloomLinearOperator: output samples
 * [Begin, End) whose rows repeat with period Period, First advancing by Stride per period
 * (a convolution: period 1, stride 1; a 2:1 resample: 1, 2; a 1:2 resample: 2, 1). It is read
 * from the operator's own rows, in the float precision the GPU uses, so a pass that computes
 * the interior from these constants evaluates exactly the operator's weights.
 */
struct Interior
{
  int Begin = 0;
  int End = 0; ///< End == Begin: no interior
  int Period = 0;
  int Stride = 0;
  int Taps = 0;
  int First[2] = { 0, 0 };    ///< First of rows Begin and Begin + 1 (period 2)
  std::vector<float> Weights; ///< Period rows of Taps weights

  static Interior Find(const vtkBloomLinearOperator& op)
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

  /// The #defines of OP_PERIODIC along `axis` ("X" or "Y"); the weights are uniforms.
  std::string Defines(const char* axis) const
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
};

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

// A range of output samples along one axis and how the pass evaluates it.
struct Segment
{
  int Begin;
  int End;
  int Mode;
};

// The OpenGL state the pass changes, restored when it returns.
struct SavedState
{
  vtkOpenGLState::ScopedglEnableDisable Blend, Depth, Scissor;
  vtkOpenGLState::ScopedglBlendFuncSeparate BlendFunc;
  vtkOpenGLState::ScopedglViewport Viewport;
  vtkOpenGLState::ScopedglScissor ScissorBox;
  vtkOpenGLState::ScopedglClearColor ClearColor;

  explicit SavedState(vtkOpenGLState* state)
    : Blend(state, GL_BLEND)
    , Depth(state, GL_DEPTH_TEST)
    , Scissor(state, GL_SCISSOR_TEST)
    , BlendFunc(state)
    , Viewport(state)
    , ScissorBox(state)
    , ClearColor(state)
  {
  }
};

// A float texture and the framebuffer that renders into it.
struct Target
{
  vtkSmartPointer<vtkTextureObject> Color;
  vtkSmartPointer<vtkOpenGLFramebufferObject> FBO;
  int Size[2] = { 0, 0 };

  void Allocate(vtkOpenGLRenderWindow* context, int width, int height, unsigned int format)
  {
    if (this->Color && this->Size[0] == width && this->Size[1] == height)
    {
      return;
    }
    this->Release(context);
    this->Color = vtkSmartPointer<vtkTextureObject>::New();
    this->Color->SetContext(context);
    this->Color->SetInternalFormat(format);
    this->Color->SetMinificationFilter(vtkTextureObject::Nearest);
    this->Color->SetMagnificationFilter(vtkTextureObject::Nearest);
    this->Color->SetWrapS(vtkTextureObject::ClampToEdge);
    this->Color->SetWrapT(vtkTextureObject::ClampToEdge);
    this->Color->Allocate2D(width, height, 4, VTK_FLOAT);
    this->FBO = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    this->FBO->SetContext(context);
    context->GetState()->PushFramebufferBindings();
    this->FBO->Bind();
    this->FBO->AddColorAttachment(0, this->Color);
    this->FBO->ActivateDrawBuffer(0);
    context->GetState()->PopFramebufferBindings();
    this->Size[0] = width;
    this->Size[1] = height;
  }

  void Release(vtkWindow* window)
  {
    if (this->FBO)
    {
      this->FBO->ReleaseGraphicsResources(window);
    }
    if (this->Color)
    {
      this->Color->ReleaseGraphicsResources(window);
    }
    this->FBO = nullptr;
    this->Color = nullptr;
    this->Size[0] = this->Size[1] = 0;
  }
};

// A float colour target with a depth texture, for the delegate's render.
struct SceneTarget : Target
{
  vtkSmartPointer<vtkTextureObject> Depth;

  void AllocateWithDepth(vtkOpenGLRenderWindow* context, int width, int height, unsigned int format)
  {
    if (this->Color && this->Size[0] == width && this->Size[1] == height)
    {
      return;
    }
    this->Allocate(context, width, height, format);
    this->Depth = vtkSmartPointer<vtkTextureObject>::New();
    this->Depth->SetContext(context);
    this->Depth->AllocateDepth(width, height, vtkTextureObject::Float32);
    context->GetState()->PushFramebufferBindings();
    this->FBO->Bind();
    this->FBO->AddDepthAttachment(this->Depth);
    context->GetState()->PopFramebufferBindings();
  }

  void ReleaseAll(vtkWindow* window)
  {
    this->Release(window);
    if (this->Depth)
    {
      this->Depth->ReleaseGraphicsResources(window);
    }
    this->Depth = nullptr;
  }
};
}

//------------------------------------------------------------------------------
class vtkBloomPass::vtkInternals
{
public:
  vtkBloomPass* Owner = nullptr;
  vtkOpenGLRenderWindow* Context = nullptr;
  unsigned int Format = 0;

  SceneTarget Scene;
  SceneTarget Emitter;
  Target Result;

  // The chain and its resources, rebuilt when the size or the parameters change.
  vtkBloomChain Chain;
  vtkMTimeType ChainTime = 0;
  std::vector<Target> Levels; // L_i
  std::vector<Target> Work;   // blurred levels and Karis sums
  std::vector<Target> Accum;  // CASCADE accumulation A_i
  Target Temp;                // the output of every x pass, at most the size of level 0
  Target Full;                // DIRECT: the full-size bloom
  std::map<const vtkBloomLinearOperator*, vtkSmartPointer<vtkTextureObject>> Operators;
  std::map<const vtkBloomLinearOperator*, Interior> Interiors;

  // One program per variant (operator modes, interior weights, step, flags), made on first use.
  std::map<std::string, std::unique_ptr<vtkOpenGLQuadHelper>> Programs;

  // Occlusion query that counts the non-zero samples of the bright pass (SkipEmptyBloom).
  unsigned int Query = 0;

  int Passes = 0;

  // Values of the current evaluation that the programs read as uniforms.
  bool MaskSource = false;
  bool SanitizeSource = false;
  bool SanitizeOutput = false;

  void ReleaseChain(vtkWindow* w)
  {
    for (auto* list : { &this->Levels, &this->Work, &this->Accum })
    {
      for (auto& t : *list)
      {
        t.Release(w);
      }
      list->clear();
    }
    this->Temp.Release(w);
    this->Full.Release(w);
    for (auto& op : this->Operators)
    {
      op.second->ReleaseGraphicsResources(w);
    }
    this->Operators.clear();
    this->Interiors.clear();
    this->ChainTime = 0;
  }

  void ReleaseAll(vtkWindow* w)
  {
    this->ReleaseChain(w);
    this->Scene.ReleaseAll(w);
    this->Emitter.ReleaseAll(w);
    this->Result.Release(w);
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
    this->Context = nullptr;
  }

  vtkTextureObject* OperatorTexture(const vtkBloomLinearOperator& op)
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
    texture->SetContext(this->Context);
    texture->SetInternalFormat(GL_R32F);
    texture->SetMinificationFilter(vtkTextureObject::Nearest);
    texture->SetMagnificationFilter(vtkTextureObject::Nearest);
    texture->Create2DFromRaw(columns, op.OutputSize, 1, VTK_FLOAT, rows.data());
    this->Operators[&op] = texture.Get();
    return texture;
  }

  const Interior& InteriorOf(const vtkBloomLinearOperator& op)
  {
    auto found = this->Interiors.find(&op);
    if (found == this->Interiors.end())
    {
      found = this->Interiors.emplace(&op, Interior::Find(op)).first;
    }
    return found->second;
  }

  /// The output samples along one axis: the periodic interior, and the borders by table.
  std::vector<Segment> Segments(const vtkBloomLinearOperator* op, int size)
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

  /// What one pass computes: step(Y X source), see vtkBloomPassFS.glsl.
  struct PassSpec
  {
    vtkTextureObject* Source = nullptr;
    const int* SourceSize = nullptr;
    const vtkBloomLinearOperator* X = nullptr; ///< null: identity along x
    const vtkBloomLinearOperator* Y = nullptr; ///< null: identity along y
    int Step = STEP_SCALE;
    double Weight = 1.0;
    bool Blend = false;       ///< add to the target instead of replacing it
    bool ReadsSource = false; ///< the chain's source: depth mask and sanitizing apply
    bool DiscardZero = false; ///< leave zero results unwritten (counted by the query)
    bool CompositeBloom = true;
    vtkTextureObject* Addend = nullptr; ///< STEP_ADD
  };

  /// The program of one variant, made on first use; null (with an error) if it fails.
  vtkOpenGLQuadHelper* Program(const std::string& variant)
  {
    std::unique_ptr<vtkOpenGLQuadHelper>& quad = this->Programs[variant];
    if (!quad)
    {
      std::string fs = vtkBloomPassFS;
      vtkShaderProgram::Substitute(fs, "//BLOOM::Constants", ShaderConstants());
      vtkShaderProgram::Substitute(fs, "//BLOOM::Variant", variant);
      quad.reset(new vtkOpenGLQuadHelper(this->Context,
        vtkOpenGLRenderUtilities::GetFullScreenQuadVertexShader().c_str(), fs.c_str(), ""));
    }
    else
    {
      this->Context->GetShaderCache()->ReadyShaderProgram(quad->Program);
    }
    if (!quad->Program || !quad->Program->GetCompiled())
    {
      vtkErrorWithObjectMacro(this->Owner, << "Could not build the bloom shader program:\n"
                                           << variant);
      return nullptr;
    }
    return quad.get();
  }

  std::string Variant(const PassSpec& spec, int xMode, int yMode)
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
    os << "#define STEP " << spec.Step << "\n#define THRESHOLD_MODE " << this->Chain.ThresholdMode
       << "\n#define MASK_BY_DEPTH " << (spec.ReadsSource && this->MaskSource ? 1 : 0)
       << "\n#define SANITIZE_SOURCE " << (spec.ReadsSource && this->SanitizeSource ? 1 : 0)
       << "\n#define SANITIZE_OUTPUT " << (this->SanitizeOutput ? 1 : 0)
       << "\n#define COMPOSITE_BLOOM " << (spec.CompositeBloom ? 1 : 0) << "\n#define DISCARD_ZERO "
       << (spec.DiscardZero ? 1 : 0) << "\n";
    return os.str();
  }

  /**
   * One pass into `target` (or the bound framebuffer when null, at `origin`): one draw per
   * combination of x and y segments, each with the program of its evaluation modes.
   */
  void Pass(Target* target, const int origin[2], const PassSpec& spec)
  {
    vtkOpenGLState* state = this->Context->GetState();
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
      spec.Step == STEP_COMPOSITE ? this->Scene.Color.Get() : nullptr,
      spec.ReadsSource && this->MaskSource ? this->Emitter.Depth.Get() : nullptr,
      spec.ReadsSource && this->MaskSource ? this->Scene.Depth.Get() : nullptr };
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
          program->SetUniform1fv(
            "xWeights", static_cast<int>(in.Weights.size()), in.Weights.data());
        }
        if (sy.Mode == OP_PERIODIC)
        {
          const Interior& in = this->InteriorOf(*spec.Y);
          const int values[3] = { in.Begin, in.First[0], in.First[1] };
          program->SetUniform1iv("yInterior", 3, values);
          program->SetUniform1fv(
            "yWeights", static_cast<int>(in.Weights.size()), in.Weights.data());
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
    ++this->Passes;
  }

  void SetStepUniforms(vtkShaderProgram* program, int step)
  {
    const vtkBloomChain& c = this->Chain;
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
      setf("largest", this->Format == GL_RGBA32F ? std::numeric_limits<float>::max() : 65504.0);
    }
  }

  void Clear(Target& target)
  {
    vtkOpenGLState* state = this->Context->GetState();
    target.FBO->Bind();
    target.FBO->ActivateDrawBuffer(0);
    state->vtkglViewport(0, 0, target.Size[0], target.Size[1]);
    state->vtkglClearColor(0.0, 0.0, 0.0, 0.0);
    state->vtkglClear(GL_COLOR_BUFFER_BIT);
  }

  bool Prepare(vtkBloomPass* self, vtkOpenGLRenderWindow* window, int w, int h);
  void RenderDelegate(vtkBloomPass* self, const vtkRenderState* s, SceneTarget& target,
    vtkProp** props, int count, bool emitters);
  bool RunChain(vtkBloomPass* self, vtkTextureObject* emission, bool mask);
  void Composite(Target* target, const int origin[2], bool bloom);
  void Copy(Target* target, const int origin[2], Target& source);
};

//------------------------------------------------------------------------------
bool vtkBloomPass::vtkInternals::Prepare(
  vtkBloomPass* self, vtkOpenGLRenderWindow* window, int w, int h)
{
  if (this->Context && this->Context != window)
  {
    self->ReleaseGraphicsResources(this->Context);
  }
  this->Context = window;
  const unsigned int format = self->FloatPrecision == FLOAT32 ? GL_RGBA32F : GL_RGBA16F;
  if (format != this->Format)
  {
    this->ReleaseAll(window);
    this->Context = window;
    this->Format = format;
  }
  this->Passes = 0;
  this->Scene.AllocateWithDepth(window, w, h, format);
  if (self->EmissionSource == EMISSION_EMITTERS)
  {
    this->Emitter.AllocateWithDepth(window, w, h, format);
  }
  else
  {
    this->Emitter.ReleaseAll(window);
  }

  // The chain depends on the size and the parameters only.
  const vtkMTimeType parametersTime = self->Parameters->GetMTime();
  if (this->ChainTime == 0 || this->ChainTime < parametersTime || this->Chain.Width != w ||
    this->Chain.Height != h)
  {
    this->ReleaseChain(window);
    this->Chain.Build(self->Parameters, w, h);
    this->ChainTime = parametersTime;
    const size_t n = this->Chain.Levels.size();
    // The scene is stored at the requested precision; the chain always runs on 32-bit floats,
    // so that half-float rounding does not compound over its dozen passes.
    const unsigned int chainFormat = GL_RGBA32F;
    this->Levels.resize(n);
    this->Work.resize(n);
    this->Accum.resize(this->Chain.AccumulateMode == vtkImageBloom::CASCADE ? n : 0);
    for (size_t i = 0; i < n; ++i)
    {
      const int* size = this->Chain.Levels[i].Size;
      this->Levels[i].Allocate(window, size[0], size[1], chainFormat);
      this->Work[i].Allocate(window, size[0], size[1], chainFormat);
      if (!this->Accum.empty())
      {
        this->Accum[i].Allocate(window, size[0], size[1], chainFormat);
      }
    }
    if (n > 0)
    {
      // The x passes run on the levels only (the source fetch and the final resample are
      // two-dimensional passes), so level 0 is the largest intermediate.
      this->Temp.Allocate(
        window, this->Chain.Levels[0].Size[0], this->Chain.Levels[0].Size[1], chainFormat);
      if (this->Chain.AccumulateMode == vtkImageBloom::DIRECT)
      {
        this->Full.Allocate(window, w, h, chainFormat);
      }
    }
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkBloomPass::vtkInternals::RenderDelegate(vtkBloomPass* self, const vtkRenderState* s,
  SceneTarget& target, vtkProp** props, int count, bool emitters)
{
  vtkRenderer* r = s->GetRenderer();
  vtkOpenGLState* state = this->Context->GetState();
  vtkRenderState s2(r);
  s2.SetPropArrayAndCount(props, count);
  s2.SetFrameBuffer(target.FBO);
  target.FBO->Bind();
  target.FBO->ActivateDrawBuffer(0);
  state->vtkglViewport(0, 0, target.Size[0], target.Size[1]);
  state->vtkglScissor(0, 0, target.Size[0], target.Size[1]);

  // Emitters shine on black: the renderer's background must not bloom with them.
  double background[3], background2[3];
  r->GetBackground(background);
  r->GetBackground2(background2);
  const double backgroundAlpha = r->GetBackgroundAlpha();
  const bool gradient = r->GetGradientBackground();
  const bool textured = r->GetTexturedBackground();
  if (emitters)
  {
    r->SetBackground(0.0, 0.0, 0.0);
    r->SetBackgroundAlpha(0.0);
    r->SetGradientBackground(false);
    r->SetTexturedBackground(false);
  }
  if (r->Transparent() || emitters)
  {
    // The camera pass does not clear layered renderers; an offscreen target must start empty.
    state->vtkglClearColor(0.0, 0.0, 0.0, 0.0);
    state->vtkglClearDepth(1.0);
    state->vtkglDepthMask(GL_TRUE);
    state->vtkglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  }
  state->vtkglEnable(GL_DEPTH_TEST);
  self->DelegatePass->Render(&s2);
  if (!emitters)
  {
    self->NumberOfRenderedProps += self->DelegatePass->GetNumberOfRenderedProps();
  }
  else
  {
    r->SetBackground(background);
    r->SetBackground2(background2);
    r->SetBackgroundAlpha(backgroundAlpha);
    r->SetGradientBackground(gradient);
    r->SetTexturedBackground(textured);
  }
}

//------------------------------------------------------------------------------
bool vtkBloomPass::vtkInternals::RunChain(vtkBloomPass* self, vtkTextureObject* emission, bool mask)
{
  const vtkBloomChain& c = this->Chain;
  vtkImageBloom* p = self->Parameters;
  this->MaskSource = mask;
  this->SanitizeSource = p->GetSanitizeNonFinite();
  this->SanitizeOutput = p->GetSanitizeNonFinite();
  const size_t n = c.Levels.size();
  if (n == 0)
  {
    return false;
  }
  if (p->GetSkipDisabledEffects())
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
  const bool skipEmpty = p->GetSkipEmptyBloom();
  PassSpec bright;
  bright.Source = emission;
  const int full[2] = { c.Width, c.Height };
  bright.SourceSize = full;
  bright.X = c.SourceIsIdentity ? nullptr : &c.Source.X;
  bright.Y = c.SourceIsIdentity ? nullptr : &c.Source.Y;
  bright.Step = STEP_THRESHOLD;
  bright.ReadsSource = true;
  bright.DiscardZero = skipEmpty;
  if (skipEmpty)
  {
    this->Clear(this->Levels[0]);
    if (!this->Query)
    {
      glGenQueries(1, &this->Query);
    }
    glBeginQuery(GL_SAMPLES_PASSED, this->Query);
  }
  this->Pass(&this->Levels[0], zero, bright);
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
    Target& dst = level.Karis ? this->Work[i] : this->Levels[i];
    for (size_t t = 0; t < level.Down.size(); ++t)
    {
      const vtkBloomChain::Term& term = level.Down[t];
      PassSpec down;
      down.Source = this->Levels[i - 1].Color;
      down.SourceSize = this->Levels[i - 1].Size;
      down.X = &term.X;
      down.Y = &term.Y;
      down.Step = level.Karis ? STEP_KARIS_TERM : STEP_SCALE;
      down.Weight = term.Weight;
      down.Blend = t > 0;
      const int rows[2] = { level.Size[0], this->Levels[i - 1].Size[1] };
      if (!TwoDimensional(term))
      {
        // The x half into Temp, then the y half and the step.
        PassSpec x;
        x.Source = down.Source;
        x.SourceSize = down.SourceSize;
        x.X = &term.X;
        this->Pass(&this->Temp, zero, x);
        down.Source = this->Temp.Color;
        down.SourceSize = rows;
        down.X = nullptr;
      }
      this->Pass(&dst, zero, down);
    }
    if (level.Karis)
    {
      PassSpec normalize;
      normalize.Source = this->Work[i].Color;
      normalize.SourceSize = level.Size;
      normalize.Step = STEP_KARIS_NORMALIZE;
      this->Pass(&this->Levels[i], zero, normalize);
    }
  }

  // 3. Blur the levels that contribute: x into Temp, y into Work (CASCADE: the last level
  // goes straight into its accumulation, scaled by its weight).
  const size_t last = n - 1;
  const bool cascade = c.AccumulateMode != vtkImageBloom::DIRECT;
  std::vector<Target*> blurred(n);
  bool lastAccumulated = false;
  for (size_t i = 0; i < n; ++i)
  {
    const vtkBloomChain::Level& level = c.Levels[i];
    blurred[i] = &this->Levels[i];
    if (!level.Blur)
    {
      continue;
    }
    PassSpec x;
    x.Source = this->Levels[i].Color;
    x.SourceSize = level.Size;
    x.X = &level.BlurPass.X;
    this->Pass(&this->Temp, zero, x);
    PassSpec y;
    y.Source = this->Temp.Color;
    y.SourceSize = level.Size;
    y.Y = &level.BlurPass.Y;
    if (cascade && i == last)
    {
      y.Weight = level.Weight;
      this->Pass(&this->Accum[last], zero, y);
      lastAccumulated = true;
    }
    else
    {
      this->Pass(&this->Work[i], zero, y);
      blurred[i] = &this->Work[i];
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
        this->Pass(&this->Full, zero, up);
        first = false;
      }
    }
    if (first)
    {
      this->Clear(this->Full);
    }
    return true;
  }
  if (!lastAccumulated)
  {
    PassSpec scale;
    scale.Source = blurred[last]->Color;
    scale.SourceSize = c.Levels[last].Size;
    scale.Weight = c.Levels[last].Weight;
    this->Pass(&this->Accum[last], zero, scale);
  }
  for (size_t i = last; i-- > 0;)
  {
    const vtkBloomChain::Level& level = c.Levels[i];
    PassSpec x;
    x.Source = this->Accum[i + 1].Color;
    x.SourceSize = this->Accum[i + 1].Size;
    x.X = &level.Up.X;
    this->Pass(&this->Temp, zero, x);
    PassSpec y;
    y.Source = this->Temp.Color;
    const int size[2] = { level.Size[0], this->Accum[i + 1].Size[1] };
    y.SourceSize = size;
    y.Y = &level.Up.Y;
    if (level.Weight != 0.0)
    {
      y.Step = STEP_ADD;
      y.Weight = level.Weight;
      y.Addend = blurred[i]->Color;
    }
    this->Pass(&this->Accum[i], zero, y);
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkBloomPass::vtkInternals::Composite(Target* target, const int origin[2], bool bloom)
{
  // out = keep * scene + Strength * Tint * bloom, the final resample of CASCADE included.
  const vtkBloomChain& c = this->Chain;
  const int full[2] = { c.Width, c.Height };
  PassSpec composite;
  composite.Step = STEP_COMPOSITE;
  composite.Source = this->Scene.Color;
  composite.SourceSize = full;
  composite.CompositeBloom = bloom;
  if (bloom && c.AccumulateMode == vtkImageBloom::DIRECT)
  {
    composite.Source = this->Full.Color;
  }
  else if (bloom)
  {
    composite.Source = this->Accum[0].Color;
    if (!c.FinalIsIdentity)
    {
      composite.SourceSize = this->Accum[0].Size;
      composite.X = &c.Final.X;
      composite.Y = &c.Final.Y;
    }
  }
  this->Pass(target, origin, composite);
}

//------------------------------------------------------------------------------
void vtkBloomPass::vtkInternals::Copy(Target* target, const int origin[2], Target& source)
{
  PassSpec copy;
  copy.Source = source.Color;
  copy.SourceSize = source.Size;
  this->Pass(target, origin, copy);
}

//------------------------------------------------------------------------------
vtkBloomPass::vtkBloomPass()
  : Parameters(vtkSmartPointer<vtkImageBloom>::New())
  , Emitters(vtkPropCollection::New())
  , FloatPrecision(FLOAT16)
  , EmissionSource(EMISSION_SCENE)
  , CaptureResult(false)
  , NumberOfPasses(0)
  , LastBloomSkipped(false)
  , Internals(new vtkInternals)
{
  this->Internals->Owner = this;
}

//------------------------------------------------------------------------------
vtkBloomPass::~vtkBloomPass()
{
  this->Emitters->Delete();
}

//------------------------------------------------------------------------------
void vtkBloomPass::SetParameters(vtkImageBloom* parameters)
{
  if (!parameters)
  {
    vtkErrorMacro(<< "The bloom parameters cannot be null.");
    return;
  }
  if (this->Parameters != parameters)
  {
    this->Parameters = parameters;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
bool vtkBloomPass::SetPreset(const char* name)
{
  return this->Parameters->SetPreset(name);
}

//------------------------------------------------------------------------------
void vtkBloomPass::AddEmitter(vtkProp* prop)
{
  if (prop && !this->Emitters->IsItemPresent(prop))
  {
    this->Emitters->AddItem(prop);
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkBloomPass::RemoveEmitter(vtkProp* prop)
{
  if (prop && this->Emitters->IsItemPresent(prop))
  {
    this->Emitters->RemoveItem(prop);
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkBloomPass::RemoveAllEmitters()
{
  if (this->Emitters->GetNumberOfItems() > 0)
  {
    this->Emitters->RemoveAllItems();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkActor> vtkBloomPass::CreateScalarRangeEmitter(
  vtkActor* actor, const double range[2])
{
  vtkMapper* mapper = actor ? actor->GetMapper() : nullptr;
  vtkScalarsToColors* colours = mapper ? mapper->GetLookupTable() : nullptr;
  if (!mapper || !colours || !range || !(range[0] <= range[1]))
  {
    return nullptr;
  }
  // Sample the actor's colours over the range; everything outside maps to black.
  const int n = 256;
  vtkNew<vtkLookupTable> table;
  table->SetNumberOfTableValues(n);
  table->SetTableRange(range[0], range[1]);
  for (int i = 0; i < n; ++i)
  {
    const double value = range[0] + (range[1] - range[0]) * (i + 0.5) / n;
    double rgb[3];
    colours->GetColor(value, rgb);
    table->SetTableValue(i, rgb[0], rgb[1], rgb[2], 1.0);
  }
  table->SetUseBelowRangeColor(true);
  table->SetBelowRangeColor(0.0, 0.0, 0.0, 1.0);
  table->SetUseAboveRangeColor(true);
  table->SetAboveRangeColor(0.0, 0.0, 0.0, 1.0);

  vtkSmartPointer<vtkMapper> copy;
  copy.TakeReference(mapper->NewInstance());
  // Not ShallowCopy: the OpenGL mapper's copies its deprecated shader-code members too.
  if (mapper->GetNumberOfInputConnections(0) > 0)
  {
    copy->SetInputConnection(mapper->GetInputConnection(0, 0));
  }
  else
  {
    copy->SetInputDataObject(mapper->GetInputDataObject(0, 0));
  }
  copy->SetScalarVisibility(true);
  copy->SetScalarMode(mapper->GetScalarMode());
  copy->SetArrayAccessMode(mapper->GetArrayAccessMode());
  copy->SetArrayId(mapper->GetArrayId());
  copy->SetArrayName(mapper->GetArrayName());
  copy->SetArrayComponent(mapper->GetArrayComponent());
  copy->SetColorMode(mapper->GetColorMode());
  copy->SetInterpolateScalarsBeforeMapping(mapper->GetInterpolateScalarsBeforeMapping());
  copy->SetLookupTable(table);
  copy->SetScalarRange(range[0], range[1]);

  auto emitter = vtkSmartPointer<vtkActor>::New();
  emitter->ShallowCopy(actor);
  emitter->SetMapper(copy);
  return emitter;
}

//------------------------------------------------------------------------------
void vtkBloomPass::Render(const vtkRenderState* s)
{
  vtkOpenGLClearErrorMacro();
  this->NumberOfRenderedProps = 0;
  this->NumberOfPasses = 0;
  if (!this->DelegatePass)
  {
    vtkWarningMacro(<< "No delegate in vtkBloomPass.");
    return;
  }
  vtkRenderer* r = s->GetRenderer();
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(r->GetRenderWindow());
  if (!window)
  {
    vtkErrorMacro(<< "vtkBloomPass needs a vtkOpenGLRenderWindow.");
    return;
  }
  int x, y, w, h;
  r->GetTiledSizeAndOrigin(&w, &h, &x, &y);
  if (w <= 0 || h <= 0)
  {
    return;
  }
  vtkOpenGLState* state = window->GetState();
  const SavedState saved(state);
  vtkInternals& in = *this->Internals;
  if (!in.Prepare(this, window, w, h))
  {
    return;
  }
  if (this->CaptureResult)
  {
    in.Result.Allocate(window, w, h, GL_RGBA32F);
  }

  // 1. The scene, and the emitters on their own, in float.
  state->PushFramebufferBindings();
  in.RenderDelegate(this, s, in.Scene, s->GetPropArray(), s->GetPropArrayCount(), false);
  const bool selective = this->EmissionSource == EMISSION_EMITTERS;
  if (selective)
  {
    std::vector<vtkProp*> emitters;
    vtkCollectionSimpleIterator it;
    this->Emitters->InitTraversal(it);
    while (vtkProp* prop = this->Emitters->GetNextProp(it))
    {
      if (prop->GetVisibility())
      {
        emitters.push_back(prop);
      }
    }
    in.RenderDelegate(
      this, s, in.Emitter, emitters.data(), static_cast<int>(emitters.size()), true);
  }

  // 2. The chain, then 3. the composite into the framebuffer the pass was called with.
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDisable(GL_SCISSOR_TEST);
  const bool bloom = in.RunChain(this, selective ? in.Emitter.Color : in.Scene.Color, selective);
  this->LastBloomSkipped = !bloom;
  const int zero[2] = { 0, 0 };
  const int origin[2] = { x, y };
  if (this->CaptureResult)
  {
    in.Composite(&in.Result, zero, bloom);
    state->PopFramebufferBindings();
    in.Copy(nullptr, origin, in.Result);
  }
  else
  {
    state->PopFramebufferBindings();
    in.Composite(nullptr, origin, bloom);
  }
  this->NumberOfPasses = in.Passes;
  vtkOpenGLCheckErrorMacro("failed after vtkBloomPass::Render");
}

//------------------------------------------------------------------------------
bool vtkBloomPass::ApplyToImage(
  vtkOpenGLRenderWindow* window, vtkImageData* input, vtkImageData* output)
{
  if (!window || !input || !output)
  {
    vtkErrorMacro(<< "ApplyToImage needs a window, an input and an output.");
    return false;
  }
  vtkDataArray* scalars = input->GetPointData()->GetScalars();
  int dims[3];
  input->GetDimensions(dims);
  const int nc = scalars ? scalars->GetNumberOfComponents() : 0;
  if (!scalars || (input->GetScalarType() != VTK_FLOAT && input->GetScalarType() != VTK_DOUBLE) ||
    nc < 3 || nc > 4)
  {
    vtkErrorMacro(<< "ApplyToImage needs float or double scalars with 3 or 4 components.");
    return false;
  }
  if (dims[0] < 1 || dims[1] < 1 || dims[2] != 1)
  {
    vtkErrorMacro(<< "ApplyToImage needs a non-empty two-dimensional image.");
    return false;
  }
  window->Initialize();
  window->MakeCurrent();
  const int w = dims[0], h = dims[1];
  vtkOpenGLState* state = window->GetState();
  const SavedState saved(state);
  vtkInternals& in = *this->Internals;
  if (!in.Prepare(this, window, w, h))
  {
    return false;
  }
  in.Result.Allocate(window, w, h, GL_RGBA32F);

  // Upload the image as the scene, in float RGBA (alpha 1 when there is none).
  std::vector<float> pixels(static_cast<size_t>(w) * h * 4);
  for (vtkIdType p = 0; p < static_cast<vtkIdType>(w) * h; ++p)
  {
    for (int c = 0; c < 4; ++c)
    {
      pixels[p * 4 + c] = c < nc ? static_cast<float>(scalars->GetComponent(p, c)) : 1.0f;
    }
  }
  in.Scene.Color->Bind();
  state->vtkglPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, w, h, GL_RGBA, GL_FLOAT, pixels.data());
  in.Scene.Color->Deactivate();

  state->PushFramebufferBindings();
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDisable(GL_SCISSOR_TEST);
  const bool bloom = in.RunChain(this, in.Scene.Color, false);
  this->LastBloomSkipped = !bloom;
  const int zero[2] = { 0, 0 };
  in.Composite(&in.Result, zero, bloom);
  state->PopFramebufferBindings();
  this->NumberOfPasses = in.Passes;

  const bool ok = this->ReadResultImage(output);
  if (ok)
  {
    int extent[6];
    input->GetExtent(extent);
    output->SetExtent(extent);
    output->SetOrigin(input->GetOrigin());
    output->SetSpacing(input->GetSpacing());
  }
  vtkOpenGLCheckErrorMacro("failed after vtkBloomPass::ApplyToImage");
  return ok;
}

namespace
{
bool ReadTarget(vtkOpenGLRenderWindow* context, Target& target, vtkImageData* image)
{
  context->MakeCurrent();
  vtkOpenGLState* state = context->GetState();
  state->PushFramebufferBindings();
  target.FBO->Bind(GL_READ_FRAMEBUFFER);
  target.FBO->ActivateReadBuffer(0);
  image->Initialize();
  image->SetExtent(0, target.Size[0] - 1, 0, target.Size[1] - 1, 0, 0);
  image->SetOrigin(0.0, 0.0, 0.0);
  image->SetSpacing(1.0, 1.0, 1.0);
  image->AllocateScalars(VTK_FLOAT, 4);
  image->GetPointData()->GetScalars()->SetName("RGBA");
  state->vtkglPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, target.Size[0], target.Size[1], GL_RGBA, GL_FLOAT, image->GetScalarPointer());
  state->PopFramebufferBindings();
  return true;
}
}

//------------------------------------------------------------------------------
bool vtkBloomPass::ReadSceneImage(vtkImageData* image)
{
  vtkInternals& in = *this->Internals;
  if (!image || !in.Context || !in.Scene.FBO)
  {
    vtkErrorMacro(<< "There is no rendered scene to read; render first.");
    return false;
  }
  return ReadTarget(in.Context, in.Scene, image);
}

//------------------------------------------------------------------------------
bool vtkBloomPass::ReadResultImage(vtkImageData* image)
{
  vtkInternals& in = *this->Internals;
  if (!image || !in.Context || !in.Result.FBO)
  {
    vtkErrorMacro(<< "There is no bloomed result to read; turn CaptureResult on and render.");
    return false;
  }
  return ReadTarget(in.Context, in.Result, image);
}

//------------------------------------------------------------------------------
void vtkBloomPass::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Superclass::ReleaseGraphicsResources(w);
  this->Internals->ReleaseAll(w);
}

//------------------------------------------------------------------------------
void vtkBloomPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FloatPrecision: " << this->FloatPrecision << "\n";
  os << indent
     << "EmissionSource: " << (this->EmissionSource == EMISSION_EMITTERS ? "Emitters" : "Scene")
     << "\n";
  os << indent << "Emitters: " << this->Emitters->GetNumberOfItems() << "\n";
  os << indent << "CaptureResult: " << (this->CaptureResult ? "On" : "Off") << "\n";
  os << indent << "NumberOfPasses: " << this->NumberOfPasses << "\n";
  os << indent << "LastBloomSkipped: " << (this->LastBloomSkipped ? "On" : "Off") << "\n";
  os << indent << "Parameters:\n";
  this->Parameters->PrintSelf(os, indent.GetNextIndent());
}
