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
#include <map>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkBloomPass);

namespace
{
// Values shared with vtkBloomPassFS.glsl, emitted into the shader as #defines.
enum
{
  AXIS_NONE = -1,
  AXIS_X = 0,
  AXIS_Y = 1
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
  os << "#define AXIS_NONE " << AXIS_NONE << "\n#define AXIS_X " << AXIS_X << "\n#define AXIS_Y "
     << AXIS_Y << "\n#define STEP_SCALE " << STEP_SCALE << "\n#define STEP_THRESHOLD "
     << STEP_THRESHOLD << "\n#define STEP_KARIS_TERM " << STEP_KARIS_TERM
     << "\n#define STEP_KARIS_NORMALIZE " << STEP_KARIS_NORMALIZE << "\n#define STEP_ADD "
     << STEP_ADD << "\n#define STEP_COMPOSITE " << STEP_COMPOSITE
     << "\n#define MODE_SMOOTHSTEP_KNEE " << vtkImageBloomThreshold::SMOOTHSTEP_KNEE
     << "\n#define MODE_QUADRATIC_KNEE " << vtkImageBloomThreshold::QUADRATIC_KNEE
     << "\n#define MODE_HARD_LUMINANCE " << vtkImageBloomThreshold::HARD_LUMINANCE
     << "\n#define MODE_PER_CHANNEL " << vtkImageBloomThreshold::PER_CHANNEL
     << "\n#define MODE_NONE " << vtkImageBloomThreshold::NONE << "\n#define FLOAT_MAX "
     << std::scientific << std::setprecision(9) << VTK_FLOAT_MAX << "\n";
  return os.str();
}

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
  vtkOpenGLRenderWindow* Context = nullptr;
  std::unique_ptr<vtkOpenGLQuadHelper> Quad;
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
  Target Temp;                // the output of every x pass
  Target Full;                // DIRECT: the full-size bloom
  std::map<const vtkBloomLinearOperator*, vtkSmartPointer<vtkTextureObject>> Operators;

  int Passes = 0;

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
    this->ChainTime = 0;
  }

  void ReleaseAll(vtkWindow* w)
  {
    this->ReleaseChain(w);
    this->Scene.ReleaseAll(w);
    this->Emitter.ReleaseAll(w);
    this->Result.Release(w);
    this->Quad.reset();
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

  // The bound program (the delegate binds its own between our passes).
  vtkShaderProgram* Program()
  {
    this->Context->GetShaderCache()->ReadyShaderProgram(this->Quad->Program);
    return this->Quad->Program;
  }

  /**
   * One full-screen pass into `target` (or the bound framebuffer when null, at `origin`):
   * the operator `op` along `axis` (null for a point-wise pass) on `source`, then `step`.
   */
  void Draw(Target* target, const int origin[2], int width, int height, vtkTextureObject* source,
    const vtkBloomLinearOperator* op, int axis, int step, double weight, bool blend)
  {
    vtkOpenGLState* state = this->Context->GetState();
    if (target)
    {
      target->FBO->Bind();
      target->FBO->ActivateDrawBuffer(0);
    }
    vtkShaderProgram* program = this->Program();
    source->Activate();
    program->SetUniformi("source", source->GetTextureUnit());
    vtkTextureObject* rows = nullptr;
    if (op)
    {
      rows = this->OperatorTexture(*op);
      rows->Activate();
      program->SetUniformi("operatorRows", rows->GetTextureUnit());
      program->SetUniformi("bandWidth", op->Width);
      program->SetUniformi("axis", axis);
    }
    else
    {
      program->SetUniformi("axis", AXIS_NONE);
    }
    const float outputSize[2] = { static_cast<float>(width), static_cast<float>(height) };
    program->SetUniform2f("outputSize", outputSize);
    program->SetUniformi("step", step);
    program->SetUniformf("weight", static_cast<float>(weight));
    if (blend)
    {
      state->vtkglEnable(GL_BLEND);
      state->vtkglBlendEquation(GL_FUNC_ADD);
      state->vtkglBlendFunc(GL_ONE, GL_ONE);
    }
    else
    {
      state->vtkglDisable(GL_BLEND);
    }
    state->vtkglViewport(origin[0], origin[1], width, height);
    this->Quad->Render();
    if (rows)
    {
      rows->Deactivate();
    }
    source->Deactivate();
    ++this->Passes;
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

  // How the first pass reads the chain's source: masked by depth (selective bloom) and with
  // non-finite samples replaced (SanitizeNonFinite), as vtkImageBloom reads its input.
  bool MaskSource = false;
  bool SanitizeSource = false;

  /// Whether the next passes read the chain's source (the scene or the emitters).
  void ReadingSource(bool source)
  {
    vtkShaderProgram* program = this->Program();
    program->SetUniformi("maskByDepth", source && this->MaskSource ? 1 : 0);
    program->SetUniformi("sanitizeSource", source && this->SanitizeSource ? 1 : 0);
  }

  /**
   * dst = step(term.Y term.X src): the x pass into Temp, then the y pass into dst (blended
   * additively when `blend`). `source`: src is the chain's source (first pass only).
   */
  void Separable(vtkTextureObject* src, int srcHeight, const vtkBloomChain::Term& term, Target& dst,
    int step, double weight, bool blend, bool source)
  {
    const int zero[2] = { 0, 0 };
    this->ReadingSource(source);
    this->Draw(&this->Temp, zero, term.X.OutputSize, srcHeight, src, &term.X, AXIS_X, STEP_SCALE,
      1.0, false);
    this->ReadingSource(false);
    this->Draw(&dst, zero, term.X.OutputSize, term.Y.OutputSize, this->Temp.Color, &term.Y, AXIS_Y,
      step, weight, blend);
  }

  bool Prepare(vtkBloomPass* self, vtkOpenGLRenderWindow* window, int w, int h);
  void RenderDelegate(vtkBloomPass* self, const vtkRenderState* s, SceneTarget& target,
    vtkProp** props, int count, bool emitters);
  void RunChain(vtkTextureObject* emission, bool mask, bool sanitize);
  void Composite(vtkBloomPass* self, Target* target, const int origin[2], int width, int height);
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
  if (!this->Quad)
  {
    std::string fs = vtkBloomPassFS;
    vtkShaderProgram::Substitute(fs, "//BLOOM::Constants", ShaderConstants());
    this->Quad.reset(new vtkOpenGLQuadHelper(
      window, vtkOpenGLRenderUtilities::GetFullScreenQuadVertexShader().c_str(), fs.c_str(), ""));
  }
  else
  {
    window->GetShaderCache()->ReadyShaderProgram(this->Quad->Program);
  }
  if (!this->Quad->Program || !this->Quad->Program->GetCompiled())
  {
    vtkErrorWithObjectMacro(self, << "Could not build the bloom shader program.");
    return false;
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
      this->Temp.Allocate(window, w, h, chainFormat);
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
void vtkBloomPass::vtkInternals::RunChain(vtkTextureObject* emission, bool mask, bool sanitize)
{
  this->MaskSource = mask;
  this->SanitizeSource = sanitize;
  const vtkBloomChain& c = this->Chain;
  const size_t n = c.Levels.size();
  if (n == 0)
  {
    return;
  }
  vtkShaderProgram* program = this->Program();
  const int zero[2] = { 0, 0 };
  this->ReadingSource(false);
  program->SetUniformi("thresholdMode", c.ThresholdMode);
  program->SetUniformf("threshold", static_cast<float>(c.Threshold));
  program->SetUniformf("knee", static_cast<float>(c.Knee));
  const double clampLum = std::min(c.ClampLuminance, static_cast<double>(VTK_FLOAT_MAX));
  program->SetUniformf("clampLuminance", static_cast<float>(clampLum));
  program->SetUniformf("ceiling", static_cast<float>(clampLum));
  const float luma[3] = { static_cast<float>(vtkBloomKernels::LuminanceR),
    static_cast<float>(vtkBloomKernels::LuminanceG),
    static_cast<float>(vtkBloomKernels::LuminanceB) };
  program->SetUniform3f("lumaWeights", luma);

  // 1. Bright pass: fetch first (the source operator), threshold second.
  if (mask)
  {
    this->Emitter.Depth->Activate();
    this->Scene.Depth->Activate();
    program->SetUniformi("emitterDepth", this->Emitter.Depth->GetTextureUnit());
    program->SetUniformi("sceneDepth", this->Scene.Depth->GetTextureUnit());
  }
  if (c.SourceIsIdentity)
  {
    this->ReadingSource(true);
    this->Draw(&this->Levels[0], zero, c.Width, c.Height, emission, nullptr, AXIS_NONE,
      STEP_THRESHOLD, 1.0, false);
    this->ReadingSource(false);
  }
  else
  {
    this->Separable(
      emission, c.Height, c.Source, this->Levels[0], STEP_THRESHOLD, 1.0, false, true);
  }
  if (mask)
  {
    this->Scene.Depth->Deactivate();
    this->Emitter.Depth->Deactivate();
  }

  // 2. The pyramid, each level from the unblurred level above it.
  for (size_t i = 1; i < n; ++i)
  {
    const vtkBloomChain::Level& level = c.Levels[i];
    Target& dst = level.Karis ? this->Work[i] : this->Levels[i];
    const bool single = level.Down.size() == 1 && !level.Karis;
    if (!single)
    {
      this->Clear(dst);
    }
    for (const auto& term : level.Down)
    {
      this->Separable(this->Levels[i - 1].Color, this->Levels[i - 1].Size[1], term, dst,
        level.Karis ? STEP_KARIS_TERM : STEP_SCALE, term.Weight, !single, false);
    }
    if (level.Karis)
    {
      this->Draw(&this->Levels[i], zero, level.Size[0], level.Size[1], this->Work[i].Color, nullptr,
        AXIS_NONE, STEP_KARIS_NORMALIZE, 1.0, false);
    }
  }

  // 3. Blur the levels that contribute.
  std::vector<Target*> blurred(n);
  for (size_t i = 0; i < n; ++i)
  {
    const vtkBloomChain::Level& level = c.Levels[i];
    blurred[i] = &this->Levels[i];
    if (level.Blur)
    {
      this->Separable(this->Levels[i].Color, level.Size[1], level.BlurPass, this->Work[i],
        STEP_SCALE, 1.0, false, false);
      blurred[i] = &this->Work[i];
    }
  }

  // 4. Accumulate.
  if (c.AccumulateMode == vtkImageBloom::DIRECT)
  {
    this->Clear(this->Full);
    for (size_t i = 0; i < n; ++i)
    {
      const vtkBloomChain::Level& level = c.Levels[i];
      if (level.Weight != 0.0)
      {
        this->Separable(blurred[i]->Color, level.Size[1], level.Full, this->Full, STEP_SCALE,
          level.Weight, true, false);
      }
    }
    return;
  }
  const size_t last = n - 1;
  this->Draw(&this->Accum[last], zero, c.Levels[last].Size[0], c.Levels[last].Size[1],
    blurred[last]->Color, nullptr, AXIS_NONE, STEP_SCALE, c.Levels[last].Weight, false);
  for (size_t i = last; i-- > 0;)
  {
    const vtkBloomChain::Level& level = c.Levels[i];
    const vtkTextureObject* previous = this->Accum[i + 1].Color;
    const int previousHeight = this->Accum[i + 1].Size[1];
    if (level.Weight != 0.0)
    {
      vtkTextureObject* addend = blurred[i]->Color;
      addend->Activate();
      program->SetUniformi("addend", addend->GetTextureUnit());
      this->Separable(const_cast<vtkTextureObject*>(previous), previousHeight, level.Up,
        this->Accum[i], STEP_ADD, level.Weight, false, false);
      addend->Deactivate();
    }
    else
    {
      this->Separable(const_cast<vtkTextureObject*>(previous), previousHeight, level.Up,
        this->Accum[i], STEP_SCALE, 1.0, false, false);
    }
  }
  if (!c.FinalIsIdentity)
  {
    // The x half of the final upsample; its y half runs in the composite.
    this->Draw(&this->Temp, zero, c.Width, c.Levels[0].Size[1], this->Accum[0].Color, &c.Final.X,
      AXIS_X, STEP_SCALE, 1.0, false);
  }
}

//------------------------------------------------------------------------------
void vtkBloomPass::vtkInternals::Composite(
  vtkBloomPass* self, Target* target, const int origin[2], int width, int height)
{
  const vtkBloomChain& c = this->Chain;
  this->ReadingSource(false);
  vtkShaderProgram* program = this->Program();
  program->SetUniformf("keep", static_cast<float>(c.Keep));
  float strengthTint[3];
  for (int i = 0; i < 3; ++i)
  {
    strengthTint[i] = c.Levels.empty() ? 0.0f : static_cast<float>(c.Strength * c.Tint[i]);
  }
  program->SetUniform3f("strengthTint", strengthTint);
  program->SetUniformi("sanitize", self->Parameters->GetSanitizeNonFinite() ? 1 : 0);
  program->SetUniformf("largest", this->Format == GL_RGBA32F ? VTK_FLOAT_MAX : 65504.0f);
  this->Scene.Color->Activate();
  program->SetUniformi("scene", this->Scene.Color->GetTextureUnit());
  if (c.Levels.empty())
  {
    this->Draw(target, origin, width, height, this->Scene.Color, nullptr, AXIS_NONE, STEP_COMPOSITE,
      1.0, false);
  }
  else if (c.AccumulateMode == vtkImageBloom::DIRECT)
  {
    this->Draw(target, origin, width, height, this->Full.Color, nullptr, AXIS_NONE, STEP_COMPOSITE,
      1.0, false);
  }
  else if (c.FinalIsIdentity)
  {
    this->Draw(target, origin, width, height, this->Accum[0].Color, nullptr, AXIS_NONE,
      STEP_COMPOSITE, 1.0, false);
  }
  else
  {
    this->Draw(target, origin, width, height, this->Temp.Color, &c.Final.Y, AXIS_Y, STEP_COMPOSITE,
      1.0, false);
  }
  this->Scene.Color->Deactivate();
}

//------------------------------------------------------------------------------
vtkBloomPass::vtkBloomPass()
  : Parameters(vtkSmartPointer<vtkImageBloom>::New())
  , Emitters(vtkPropCollection::New())
  , FloatPrecision(FLOAT16)
  , EmissionSource(EMISSION_SCENE)
  , CaptureResult(false)
  , NumberOfPasses(0)
  , Internals(new vtkInternals)
{
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
  in.RunChain(selective ? in.Emitter.Color : in.Scene.Color, selective,
    this->Parameters->GetSanitizeNonFinite());
  const int zero[2] = { 0, 0 };
  const int origin[2] = { x, y };
  if (this->CaptureResult)
  {
    in.Composite(this, &in.Result, zero, w, h);
    state->PopFramebufferBindings();
    in.Draw(nullptr, origin, w, h, in.Result.Color, nullptr, AXIS_NONE, STEP_SCALE, 1.0, false);
  }
  else
  {
    state->PopFramebufferBindings();
    in.Composite(this, nullptr, origin, w, h);
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
  in.RunChain(in.Scene.Color, false, this->Parameters->GetSanitizeNonFinite());
  const int zero[2] = { 0, 0 };
  in.Composite(this, &in.Result, zero, w, h);
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
  os << indent << "Parameters:\n";
  this->Parameters->PrintSelf(os, indent.GetNextIndent());
}
