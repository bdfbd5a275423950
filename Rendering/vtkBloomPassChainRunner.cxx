// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// Runs vtkBloomPass's chain as GLSL passes (see vtkBloomPassChainRunner.h): the shader variants
// and their programs, and one pass (Pass: its draws, textures and uniforms). The chain's steps,
// the composite and the copy are in vtkBloomPassChainSteps.cxx.
#include "vtkBloomPassChainRunner.h"

#include "vtkBloomChain.h"
#include "vtkBloomKernels.h"
#include "vtkBloomParameters.h"
#include "vtkBloomPassFS.h"
#include "vtkBloomPassReduceFS.h"
#include "vtkBloomPassResources.h"
#include "vtkBloomVTKCompat.h"
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

#include <algorithm>
#include <iomanip>
#include <limits>
#include <sstream>

//------------------------------------------------------------------------------
vtkBloomPassChainRunner::vtkBloomPassChainRunner(vtkObject* owner, vtkBloomPassResources& resources,
  vtkBloomPassFFTBlur& fftBlur, vtkBloomPassProfiler& profiler)
  : FFTBlur(&fftBlur)
  , Owner(owner)
  , Resources(resources)
  , Profiler(profiler)
{
}

//------------------------------------------------------------------------------
vtkBloomPassChainRunner::~vtkBloomPassChainRunner() = default;

//------------------------------------------------------------------------------
void vtkBloomPassChainRunner::ReleaseOperators(vtkWindow* w)
{
  this->Operators.Release(w);
  this->Variants.clear(); // keyed by the operators' addresses, pointing at compute programs
  this->EndProgramGeneration(w);
}

//------------------------------------------------------------------------------
void vtkBloomPassChainRunner::Release(FragmentProgram& program, vtkWindow* w)
{
  if (program.Quad)
  {
    if (program.Quad->Program)
    {
      program.Quad->Program->ReleaseGraphicsResources(w);
    }
    program.Quad->ReleaseGraphicsResources(w);
    program.Quad.reset();
  }
}

//------------------------------------------------------------------------------
void vtkBloomPassChainRunner::EndProgramGeneration(vtkWindow* w)
{
  this->Programs.EndGeneration([w](FragmentProgram& program) { Release(program, w); });
  this->ComputePrograms.EndGeneration(
    [this](ComputeProgram& program)
    {
      if (program.Id && this->Resources.Context)
      {
        glDeleteProgram(program.Id);
      }
    });
}

//------------------------------------------------------------------------------
void vtkBloomPassChainRunner::ReleaseGraphicsResources(vtkWindow* w)
{
  this->ReleaseOperators(w);
  this->Programs.Clear([w](FragmentProgram& program) { Release(program, w); });
  this->ReleaseCompute();
  this->ReleaseCostTiming();
  if (this->Query)
  {
    glDeleteQueries(1, &this->Query);
    this->Query = 0;
  }
}

//------------------------------------------------------------------------------
void vtkBloomPassChainRunner::BeginFrame(const Settings& settings)
{
  this->Frame = settings;
  this->Passes = 0;
  this->ComputePasses = 0;
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
     << "\n#define MODE_NONE " << vtkImageBloomThreshold::NONE << "\n#define MODE_EXCESS_KNEE "
     << vtkImageBloomThreshold::EXCESS_KNEE << "\n#define BACKGROUND_COLOR "
     << vtkBloomPassResources::BACKGROUND_COLOR << "\n#define BACKGROUND_TEXTURE "
     << vtkBloomPassResources::BACKGROUND_TEXTURE << "\n#define FLOAT_MAX " << std::scientific
     << std::setprecision(9) << std::numeric_limits<float>::max() << "\n";
  return os.str();
}

//------------------------------------------------------------------------------
vtkOpenGLQuadHelper* vtkBloomPassChainRunner::Program(const std::string& variant)
{
  FragmentProgram& entry = this->Programs[variant];
  std::unique_ptr<vtkOpenGLQuadHelper>& quad = entry.Quad;
  if (quad)
  {
    this->Resources.Context->GetShaderCache()->ReadyShaderProgram(quad->Program);
    // Another pass of the window freed the program it shares (EndProgramGeneration) and the
    // cache compiled it again: its attributes may have moved, so the quad is made again.
    if (!quad->Program || quad->Program->GetHandle() != entry.Handle)
    {
      quad->ReleaseGraphicsResources(this->Resources.Context);
      quad.reset();
    }
  }
  if (!quad)
  {
    // The bright region's reduction has a shader of its own (vtkBloomPassRegion.cxx).
    std::string fs =
      variant.rfind("#define REDUCE", 0) == 0 ? vtkBloomPassReduceFS : vtkBloomPassFS;
    vtkShaderProgram::Substitute(fs, "//BLOOM::Constants", ShaderConstants());
    // gl_SampleID, which VTK's GLSL 1.50 has from the extension (core in GLSL 4.00).
    vtkShaderProgram::Substitute(fs, "//BLOOM::Extensions",
      variant.find("#define COMPOSITE_SAMPLES") != std::string::npos
        ? "#extension GL_ARB_sample_shading : require\n"
        : "");
    vtkShaderProgram::Substitute(fs, "//BLOOM::Variant", variant);
    this->CompiledProgram = true;
    quad.reset(new vtkOpenGLQuadHelper(this->Resources.Context,
      vtkOpenGLRenderUtilities::GetFullScreenQuadVertexShader().c_str(), fs.c_str(), ""));
    entry.Handle = quad->Program ? quad->Program->GetHandle() : 0;
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
  // VariantOf's key holds everything read here: a new #define needs its value there too.
  std::ostringstream os;
  os << "#define X_MODE " << xMode << "\n#define Y_MODE " << yMode << "\n";
  // A table's width as a constant, so that the loop over its taps unrolls: on an NVIDIA H100
  // each small pass waited on its taps' fetches one by one.
  if (xMode == OP_TABLE)
  {
    os << "#define X_TABLE_WIDTH " << spec.X->Width << "\n";
  }
  if (yMode == OP_TABLE)
  {
    os << "#define Y_TABLE_WIDTH " << spec.Y->Width << "\n";
  }
  if (xMode == OP_PERIODIC)
  {
    os << this->Operators.InteriorOf(*spec.X).Defines("X");
  }
  if (yMode == OP_PERIODIC)
  {
    os << this->Operators.InteriorOf(*spec.Y).Defines("Y");
  }
  // Emitters are light whatever their colour: their emission is not thresholded.
  const int mode = this->In.Threshold ? this->Frame.Parameters->GetThresholdMode()
                                      : static_cast<int>(vtkImageBloomThreshold::NONE);
  os << "#define STEP " << spec.Step << "\n#define THRESHOLD_MODE " << mode
     << "\n#define SCENE_BACKGROUND "
     << (spec.Step == STEP_COMPOSITE ? this->Resources.BackgroundMode : 0)
     << "\n#define MASK_BY_DEPTH " << (spec.ReadsSource && this->In.Mask ? 1 : 0)
     << "\n#define SANITIZE_SOURCE " << (spec.ReadsSource && this->SanitizeSource ? 1 : 0)
     << "\n#define EMISSION_IN_ALPHA " << (spec.ReadsSource && this->In.InAlpha ? 1 : 0)
     << "\n#define SCENE_ALPHA_CLAMPED "
     << (spec.Step == STEP_COMPOSITE && this->Out.EmissionInAlpha ? 1 : 0)
     << "\n#define SANITIZE_OUTPUT " << (this->SanitizeOutput ? 1 : 0)
     << "\n#define COMPOSITE_BLOOM " << (spec.CompositeBloom ? 1 : 0) << "\n#define DISCARD_ZERO "
     << (spec.DiscardZero ? 1 : 0) << "\n#define ZERO_BLOOM " << (spec.ZeroBloom ? 1 : 0) << "\n";
  if (spec.Tiled)
  {
    os << "#define TILE 1\n#define TILE_ROWS " << this->Operators.TileRows(*spec.Y) << "\n";
  }
  if (spec.Samples)
  {
    os << "#define SAMPLE_THRESHOLD " << spec.SampleCount << "\n";
  }
  if (spec.SceneSamples)
  {
    os << "#define COMPOSITE_SAMPLES " << spec.SceneSampleCount << "\n";
  }
  if (spec.Tiled && spec.Second)
  {
    os << "#define TILE2 1\n#define TILE2_ROWS " << this->Operators.TileRows(*spec.Second->Y)
       << "\n#define TILE2_ADDEND " << (spec.SecondIsAddend ? 1 : 0) << "\n#define X2_WIDTH "
       << spec.Second->X->Width << "\n#define Y2_WIDTH " << spec.Second->Y->Width << "\n";
  }
  return os.str();
}

//------------------------------------------------------------------------------
void vtkBloomPassChainRunner::Pass(
  vtkBloomPassTarget* target, const int origin[2], const PassSpec& spec)
{
  this->Profiler.Begin();
  const int width = spec.X ? spec.X->OutputSize : spec.SourceSize[0];
  const int height = spec.Y ? spec.Y->OutputSize : spec.SourceSize[1];
  ImageTarget image = this->BeginPass(target, origin, spec, width, height);
  const std::vector<Draw> draws = this->Draws(spec, width, height);
  // Each draw's program variant, found once.
  std::vector<VariantEntry*> variants;
  for (const Draw& draw : draws)
  {
    variants.push_back(&this->VariantOf(spec, draw, image.Format));
  }
  std::vector<ComputeProgram*> programs;
  if (image.Texture != 0 && !this->ComputeProgramsOf(variants, spec.Blend, image.Format, programs))
  {
    // A compute variant did not build (Compute warned once): this pass, and every later
    // one of that variant, runs as fragments instead.
    image = ImageTarget();
    if (target)
    {
      target->FBO->Bind();
      target->FBO->ActivateDrawBuffer(0);
    }
  }
  const bool compute = image.Texture != 0;
  const PassTextures textures = this->PassTexturesOf(spec);
  const TextureNames names = NamesOf(textures);
  // Into one of the chain's own targets, a compute pass's barrier waits for the pass that
  // needs it (BeforeComputePass); anything else first makes every pending write visible.
  const bool deferred = compute && target && this->Deferring;
  if (deferred)
  {
    this->BeforeComputePass(names, image.Texture);
  }
  else
  {
    this->FlushComputeWrites();
  }
  for (vtkTextureObject* texture : textures.Textures)
  {
    if (texture)
    {
      texture->Activate();
    }
  }
  for (size_t d = 0; d < draws.size(); ++d)
  {
    const Draw& draw = draws[d];
    Uniforms u;
    vtkOpenGLQuadHelper* quad = nullptr;
    if (compute)
    {
      glUseProgram(programs[d]->Id);
      u.Raw = programs[d]->Id;
      u.Locations = &programs[d]->Locations;
    }
    else
    {
      quad = this->Program(variants[d]->Variant);
      if (!quad)
      {
        continue;
      }
      u.Program = quad->Program;
    }
    this->SetDrawUniforms(u, spec, draw, textures);
    if (compute)
    {
      u.Int2("targetOffset", image.Offset);
      this->Dispatch(image, spec.Blend, draw.Rect);
    }
    else
    {
      this->Resources.Context->GetState()->vtkglViewport(origin[0] + draw.Rect.X0,
        origin[1] + draw.Rect.Y0, draw.Rect.X1 - draw.Rect.X0, draw.Rect.Y1 - draw.Rect.Y0);
      quad->Render();
    }
  }
  if (deferred)
  {
    this->AfterComputePass(names, image.Texture);
    ++this->ComputePasses;
  }
  else if (compute)
  {
    this->EndCompute();
    ++this->ComputePasses;
  }
  for (vtkTextureObject* texture : textures.Textures)
  {
    if (texture)
    {
      texture->Deactivate();
    }
  }
  if (this->Profiler.IsOn())
  {
    this->EndProfiledPass(spec);
  }
  ++this->Passes;
}

//------------------------------------------------------------------------------
bool vtkBloomPassChainRunner::ComputeProgramsOf(const std::vector<VariantEntry*>& variants,
  bool blend, unsigned int format, std::vector<ComputeProgram*>& programs)
{
  programs.clear();
  for (VariantEntry* variant : variants)
  {
    if (!variant->Asked)
    {
      variant->Program = this->Compute(variant->Variant, blend, format);
      variant->Asked = true;
    }
    if (!variant->Program)
    {
      return false;
    }
    programs.push_back(variant->Program);
  }
  return true;
}

//------------------------------------------------------------------------------
vtkBloomPassChainRunner::VariantEntry& vtkBloomPassChainRunner::VariantOf(
  const PassSpec& spec, const Draw& draw, unsigned int format)
{
  // Everything Variant() reads, in the order it writes it.
  const bool composite = spec.Step == STEP_COMPOSITE;
  const int mode = this->In.Threshold ? this->Frame.Parameters->GetThresholdMode()
                                      : static_cast<int>(vtkImageBloomThreshold::NONE);
  const bool flags[] = { spec.ReadsSource && this->In.Mask,
    spec.ReadsSource && this->SanitizeSource, spec.ReadsSource && this->In.InAlpha,
    composite && this->Out.EmissionInAlpha, this->SanitizeOutput, spec.CompositeBloom,
    spec.DiscardZero, draw.Zero, spec.Blend, spec.Tiled, spec.SecondIsAddend };
  std::uintptr_t bits = 0;
  for (bool flag : flags)
  {
    bits = (bits << 1) | (flag ? 1u : 0u);
  }
  const VariantKey key = { reinterpret_cast<std::uintptr_t>(spec.X),
    reinterpret_cast<std::uintptr_t>(spec.Y), static_cast<std::uintptr_t>(draw.XMode),
    static_cast<std::uintptr_t>(draw.YMode), static_cast<std::uintptr_t>(spec.Step),
    static_cast<std::uintptr_t>(mode),
    static_cast<std::uintptr_t>(composite ? this->Resources.BackgroundMode : 0),
    static_cast<std::uintptr_t>(format), bits,
    reinterpret_cast<std::uintptr_t>(spec.Second ? spec.Second->X : nullptr),
    reinterpret_cast<std::uintptr_t>(spec.Second ? spec.Second->Y : nullptr),
    static_cast<std::uintptr_t>(spec.Samples ? spec.SampleCount : 0),
    static_cast<std::uintptr_t>(spec.SceneSamples ? spec.SceneSampleCount : 0) };
  VariantEntry& entry = this->Variants[key];
  if (entry.Variant.empty())
  {
    PassSpec variant = spec;
    variant.ZeroBloom = draw.Zero;
    entry.Variant = this->Variant(variant, draw.XMode, draw.YMode);
  }
  return entry;
}

//------------------------------------------------------------------------------
vtkBloomPassChainRunner::ImageTarget vtkBloomPassChainRunner::BeginPass(
  vtkBloomPassTarget* target, const int origin[2], const PassSpec& spec, int width, int height)
{
  if (target && !spec.Blend && spec.Step != STEP_COMPOSITE)
  {
    this->PrepareTarget(*target, spec.Region, width, height);
  }
  const ImageTarget image = this->ComputeTarget(target, origin, spec, width, height);
  if (target && image.Texture == 0)
  {
    target->FBO->Bind();
    target->FBO->ActivateDrawBuffer(0);
  }
  vtkOpenGLState* state = this->Resources.Context->GetState();
  if (spec.Blend)
  {
    state->vtkglEnable(GL_BLEND);
    state->vtkglBlendEquation(GL_FUNC_ADD);
    state->vtkglBlendFunc(GL_ONE, GL_ONE);
  }
  else if (!target && this->Out.Over)
  {
    // Over the layers below, premultiplied (the scene was rendered over transparent black).
    state->vtkglEnable(GL_BLEND);
    state->vtkglBlendEquation(GL_FUNC_ADD);
    state->vtkglBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  }
  else
  {
    state->vtkglDisable(GL_BLEND);
  }
  return image;
}

//------------------------------------------------------------------------------
std::vector<vtkBloomPassChainRunner::Draw> vtkBloomPassChainRunner::Draws(
  const PassSpec& spec, int width, int height)
{
  const Box whole = spec.Step == STEP_COMPOSITE
    ? Box::Window(this->Out.Window, width, height).Intersection(Box::Whole(width, height))
    : Box::Whole(width, height);
  const Box region = spec.Region ? spec.Region->Intersection(whole) : whole;
  if (spec.Step != STEP_COMPOSITE && !spec.ReadsSource)
  {
    this->FullSamples += static_cast<double>(width) * height;
    this->ComputedSamples += static_cast<double>(region.Empty() ? 0 : region.X1 - region.X0) *
      (region.Empty() ? 0 : region.Y1 - region.Y0);
  }
  // One draw per combination of x and y segments, cut to the region (a small pass: one draw,
  // every axis by its table)...
  const bool single = spec.Tiled || static_cast<double>(width) * height <= this->SingleDrawLimit();
  std::vector<Draw> draws;
  for (const Segment& sy : this->Operators.Segments(spec.Y, spec.SourceSize[1], single))
  {
    for (const Segment& sx : this->Operators.Segments(spec.X, spec.SourceSize[0], single))
    {
      const Box cut = Box{ sx.Begin, sx.End, sy.Begin, sy.End }.Intersection(region);
      if (!cut.Empty())
      {
        draws.push_back({ cut, sx.Mode, sy.Mode, false });
      }
    }
  }
  // ... then, for a restricted composite, the rectangles outside the region, where the bloom is
  // zero (ZERO_BLOOM).
  if (spec.Step == STEP_COMPOSITE && spec.Region)
  {
    if (region.Empty())
    {
      draws.push_back({ whole, OP_IDENTITY, OP_IDENTITY, true });
      return draws;
    }
    const Box parts[] = { { whole.X0, whole.X1, whole.Y0, region.Y0 },
      { whole.X0, whole.X1, region.Y1, whole.Y1 }, { whole.X0, region.X0, region.Y0, region.Y1 },
      { region.X1, whole.X1, region.Y0, region.Y1 } };
    for (const Box& part : parts)
    {
      if (!part.Empty())
      {
        draws.push_back({ part, OP_IDENTITY, OP_IDENTITY, true });
      }
    }
  }
  return draws;
}

//------------------------------------------------------------------------------
int vtkBloomPassChainRunner::SingleDrawLimit()
{
  // Automatic: none on a CPU rasterizer; else every pass up to 2^21 samples.
  return this->Frame.SingleDrawSamples >= 0 ? this->Frame.SingleDrawSamples
    : this->SoftwareRasterizer()            ? 0
                                            : 1 << 21;
}

//------------------------------------------------------------------------------
bool vtkBloomPassChainRunner::Fuses(
  const vtkBloomLinearOperator& x, const vtkBloomLinearOperator& y)
{
  // The tiled pass evaluates both axes by their tables, as one draw does. A compute program that
  // does not build runs as a fragment 2D pass: the same sums, each row summed again per output.
  return this->Frame.FuseSeparablePasses && this->Frame.UseCompute &&
    !this->Frame.SimulateComputeFailure && this->ComputeSupported() &&
    static_cast<double>(x.OutputSize) * y.OutputSize <= this->SingleDrawLimit() &&
    this->Operators.TileRows(y) <= MaximumTileRows;
}

//------------------------------------------------------------------------------
bool vtkBloomPassChainRunner::FusesTwo(const vtkBloomLinearOperator& x,
  const vtkBloomLinearOperator& y, const vtkBloomLinearOperator& x2,
  const vtkBloomLinearOperator& y2)
{
  return x.OutputSize == x2.OutputSize && y.OutputSize == y2.OutputSize && this->Fuses(x, y) &&
    this->Fuses(x2, y2) &&
    this->Operators.TileRows(y) + this->Operators.TileRows(y2) <= MaximumTileRows;
}

//------------------------------------------------------------------------------
vtkBloomPassChainRunner::PassTextures vtkBloomPassChainRunner::PassTexturesOf(const PassSpec& spec)
{
  const bool mask = spec.ReadsSource && this->In.Mask;
  PassTextures t;
  t.Textures = { spec.Source,
    spec.X ? this->Operators.Texture(this->Resources.Context, *spec.X) : nullptr,
    spec.Y ? this->Operators.Texture(this->Resources.Context, *spec.Y) : nullptr, spec.Addend,
    spec.Step == STEP_COMPOSITE ? this->Resources.Scene.Color.Get() : nullptr,
    mask ? this->Resources.Emitter.Depth.Get() : nullptr,
    mask ? this->Resources.Scene.Depth.Get() : nullptr,
    spec.Step == STEP_COMPOSITE &&
        this->Resources.BackgroundMode == vtkBloomPassResources::BACKGROUND_TEXTURE
      ? this->Resources.Background.Color.Get()
      : nullptr,
    spec.Second ? spec.Second->Source : nullptr,
    spec.Second ? this->Operators.Texture(this->Resources.Context, *spec.Second->X) : nullptr,
    spec.Second ? this->Operators.Texture(this->Resources.Context, *spec.Second->Y) : nullptr,
    spec.Samples, spec.SceneSamples };
  return t;
}

//------------------------------------------------------------------------------
void vtkBloomPassChainRunner::SetDrawUniforms(
  Uniforms& u, const PassSpec& spec, const Draw& draw, const PassTextures& textures)
{
  for (size_t t = 0; t < textures.Textures.size(); ++t)
  {
    if (textures.Textures[t])
    {
      u.Int(PassTextures::Samplers[t], textures.Textures[t]->GetTextureUnit());
    }
  }
  const int offset[2] = { draw.Rect.X0, draw.Rect.Y0 };
  const float size[2] = { static_cast<float>(draw.Rect.X1 - draw.Rect.X0),
    static_cast<float>(draw.Rect.Y1 - draw.Rect.Y0) };
  u.Int2("regionOffset", offset);
  u.Float2("regionSize", size);
  u.Float("weight", spec.Weight);
  u.Float("zeroBloom", 0.0);
  if (spec.Second)
  {
    u.Float("weight2", spec.Second->Weight);
  }
  // The interior's weights of each axis evaluated as a periodic convolution.
  const vtkBloomLinearOperator* ops[2] = { spec.X, spec.Y };
  const int modes[2] = { draw.XMode, draw.YMode };
  const char* names[2][2] = { { "xInterior", "xWeights" }, { "yInterior", "yWeights" } };
  for (int axis = 0; axis < 2; ++axis)
  {
    if (modes[axis] != OP_PERIODIC)
    {
      continue;
    }
    const Interior& in = this->Operators.InteriorOf(*ops[axis]);
    const int values[3] = { in.Begin, in.First[0], in.First[1] };
    u.Ints(names[axis][0], 3, values);
    u.Floats(names[axis][1], static_cast<int>(in.Weights.size()), in.Weights.data());
  }
  this->SetStepUniforms(u, spec.Step);
}

//------------------------------------------------------------------------------
void vtkBloomPassChainRunner::SetStepUniforms(Uniforms& u, int step)
{
  vtkBloomParameters* p = this->Frame.Parameters;
  auto setf = [&u](const char* name, double value) { u.Float(name, value); };
  auto set3f = [&u](const char* name, const double values[3]) { u.Float3(name, values); };
  if (step == STEP_THRESHOLD || step == STEP_KARIS_TERM)
  {
    const double luma[3] = { vtkBloomKernels::LuminanceR, vtkBloomKernels::LuminanceG,
      vtkBloomKernels::LuminanceB };
    set3f("lumaWeights", luma);
  }
  if (step == STEP_THRESHOLD)
  {
    const double clampLum = std::min(p->GetClampLuminance(), static_cast<double>(VTK_FLOAT_MAX));
    setf("threshold", p->GetThreshold());
    setf("knee", p->GetKnee());
    setf("clampLuminance", clampLum);
    setf("ceiling", clampLum);
  }
  if (step == STEP_COMPOSITE)
  {
    const double strength = p->GetStrength();
    const double* tint = p->GetTint();
    setf("keep", p->GetCompositeMode() == vtkBloomParameters::LERP ? 1.0 - strength : 1.0);
    setf("glowAlpha", this->Out.GlowAlpha ? 1.0 : 0.0);
    if (this->Resources.BackgroundMode == vtkBloomPassResources::BACKGROUND_COLOR)
    {
      u.Float4("backgroundColor", this->Resources.BackgroundColor);
    }
    else if (this->Resources.BackgroundMode == vtkBloomPassResources::BACKGROUND_TEXTURE)
    {
      // The background holds the renderer's pixels; the window's first sample is its first.
      const int* origin = this->Resources.BackgroundOrigin;
      const int* window = this->Out.Window;
      const int shifted[2] = { origin[0] - window[0], origin[1] - window[2] };
      u.Int2("backgroundOrigin", shifted);
    }
    const double strengthTint[3] = { strength * tint[0], strength * tint[1], strength * tint[2] };
    set3f("strengthTint", strengthTint);
    setf("largest",
      this->Resources.Format == GL_RGBA32F ? std::numeric_limits<float>::max() : 65504.0);
  }
}

//------------------------------------------------------------------------------
void vtkBloomPassChainRunner::Clear(vtkBloomPassTarget& target)
{
  this->FlushComputeWrites();
  vtkOpenGLState* state = this->Resources.Context->GetState();
  target.FBO->Bind();
  target.FBO->ActivateDrawBuffer(0);
  state->vtkglViewport(0, 0, target.Size[0], target.Size[1]);
  state->vtkglClearColor(0.0, 0.0, 0.0, 0.0);
  state->vtkglClear(GL_COLOR_BUFFER_BIT);
  std::fill(target.Dirty, target.Dirty + 4, 0);
}

//------------------------------------------------------------------------------
void vtkBloomPassChainRunner::EndProfiledPass(const PassSpec& spec)
{
  // Bytes per texel of the chain's targets; the window's framebuffer (the composite's target
  // when it is null) is counted at the same rate.
  const double texel = this->Resources.Format == GL_RGBA32F ? 16.0 : 8.0;
  const double w = spec.X ? spec.X->OutputSize : spec.SourceSize[0];
  const double h = spec.Y ? spec.Y->OutputSize : spec.SourceSize[1];
  double bytes = texel * spec.SourceSize[0] * spec.SourceSize[1] + texel * w * h;
  if (spec.Blend)
  {
    bytes += texel * w * h;
  }
  if (spec.Addend)
  {
    bytes += texel * w * h;
  }
  if (spec.Step == STEP_COMPOSITE)
  {
    bytes += texel * this->Resources.Chain.Width * this->Resources.Chain.Height;
  }
  if (spec.ReadsSource && this->In.Mask)
  {
    bytes += 2.0 * 4.0 * spec.SourceSize[0] * spec.SourceSize[1]; // the two depth textures
  }
  std::string name = spec.Name;
  if (spec.Level >= 0)
  {
    name += " L" + std::to_string(spec.Level);
  }
  this->Profiler.End(name, static_cast<int>(w), static_cast<int>(h), bytes);
}
