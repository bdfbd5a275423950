// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// Selective bloom: what each prop emits and where the emission is written (see
// vtkBloomPassEmission.h).
#include "vtkBloomPassEmission.h"

#include "vtkActor.h"
#include "vtkInformation.h"
#include "vtkInformationDoubleVectorKey.h"
#include "vtkInformationObjectBaseKey.h"
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkProp.h"
#include "vtkPropCollection.h"
#include "vtkRenderPass.h"
#include "vtkScalarsToColors.h"
#include "vtkShaderProgram.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_set>

namespace
{
// Whether `prop`'s fragments all come from a polydata mapper's shader, which writes the
// emission: an opaque actor, not a level-of-detail actor (its mappers are its own), nor a
// follower (vtkFollower draws through an actor of its own, which the mapper sees instead: vedo
// 2023's meshes are followers).
bool WritesEmission(vtkProp* prop)
{
  auto* actor = vtkActor::SafeDownCast(prop);
  return actor && !actor->IsA("vtkLODActor") && !actor->IsA("vtkQuadricLODActor") &&
    !actor->IsA("vtkFollower") && vtkOpenGLPolyDataMapper::SafeDownCast(actor->GetMapper()) &&
    !actor->HasTranslucentPolygonalGeometry();
}
}

//------------------------------------------------------------------------------
vtkProp* vtkBloomPassEmission::RangeSource(vtkProp* emitter, double range[2]) const
{
  vtkInformation* keys = emitter->GetPropertyKeys();
  if (!keys || !keys->Has(this->SourceKey) || !keys->Has(this->RangeKey))
  {
    return nullptr;
  }
  keys->Get(this->RangeKey, range);
  return vtkProp::SafeDownCast(keys->Get(this->SourceKey));
}

//------------------------------------------------------------------------------
bool vtkBloomPassEmission::Plan(
  vtkPropCollection* emitters, vtkProp** props, int count, vtkRenderPass* delegate, bool inScene)
{
  const std::unordered_set<vtkProp*> scene(props, props + count);
  bool one = inScene && delegate &&
    (delegate->IsA("vtkRenderStepsPass") || delegate->IsA("vtkCameraPass")) &&
    std::all_of(props, props + count, WritesEmission);

  // What the emitters emit rendered alone, and what the scene's props emit in one render.
  std::unordered_map<vtkProp*, Emission> alone, together;
  std::vector<vtkProp*> visible;
  vtkCollectionSimpleIterator it;
  emitters->InitTraversal(it);
  while (vtkProp* emitter = emitters->GetNextProp(it))
  {
    if (!emitter->GetVisibility())
    {
      continue;
    }
    visible.push_back(emitter);
    Emission e;
    vtkProp* source = RangeSource(emitter, e.Range);
    e.What = source ? RANGE : WHOLE;
    alone[emitter] = e;
    vtkProp* drawn =
      scene.count(emitter) ? emitter : (source && scene.count(source) ? source : nullptr);
    if (!drawn)
    {
      one = false;
      continue;
    }
    if (drawn == emitter)
    {
      e.What = WHOLE; // the prop itself emits, whatever else it is made from
    }
    Emission& planned = together[drawn];
    if (planned.What != WHOLE)
    {
      planned = e;
    }
  }
  this->InSceneRender = one;
  this->Props = one ? together : alone;
  this->SecondRender = one ? std::vector<vtkProp*>() : visible;
  return one;
}

//------------------------------------------------------------------------------
void vtkBloomPassEmission::PreReplace(std::string& fragmentShader, vtkAbstractMapper* mapper)
{
  if (!vtkOpenGLPolyDataMapper::SafeDownCast(mapper))
  {
    return;
  }
  // After the lighting and the textures: the fragment's final colour.
  vtkShaderProgram::Substitute(fragmentShader, "//VTK::TCoord::Impl",
    "//VTK::TCoord::Impl\n  //VTK::BloomEmission::Impl", false);
  vtkShaderProgram::Substitute(
    fragmentShader, "//VTK::Output::Dec", "//VTK::Output::Dec\n//VTK::BloomEmission::Dec", false);
}

//------------------------------------------------------------------------------
void vtkBloomPassEmission::PostReplace(std::string& fragmentShader, vtkAbstractMapper* mapper)
{
  if (!vtkOpenGLPolyDataMapper::SafeDownCast(mapper))
  {
    return;
  }
  // The colour texture coordinate, where the mapper colours through a texture (its name
  // differs between VTK versions).
  const std::string lookup = "texture(colortexture, ";
  std::string tcoord;
  const size_t at = fragmentShader.find(lookup);
  if (at != std::string::npos)
  {
    const size_t begin = at + lookup.size();
    tcoord = fragmentShader.substr(begin, fragmentShader.find_first_of(".)", begin) - begin);
  }
  const std::string range = tcoord.empty() ? "    if (bloomEmission == 2)\n"
                                             "    {\n"
                                             "      bloomWeight = 0.0;\n"
                                             "    }\n"
                                           : "    if (bloomEmission == 2)\n"
                                             "    {\n"
                                             "      vec2 t = " +
      tcoord +
      ".st;\n"
      "      bool inRange = t.s >= bloomTextureRange.x && t.s <= bloomTextureRange.y;\n"
      "      bloomWeight = inRange && t.t < 0.5 ? 1.0 : 0.0;\n"
      "    }\n";
  vtkShaderProgram::Substitute(fragmentShader, "//VTK::BloomEmission::Dec",
    "uniform int bloomEmission;\n"
    "uniform int bloomEmittersAlone;\n"
    "uniform vec2 bloomTextureRange;\n",
    false);
  vtkShaderProgram::Substitute(fragmentShader, "//VTK::BloomEmission::Impl",
    "{\n"
    "    // vtkBloomPass: this fragment's emission (0 none, 1 its colour, 2 its colour where\n"
    "    // the scalar lies in the range), as a weight of its colour.\n"
    "    float bloomWeight = bloomEmission == 0 ? 0.0 : 1.0;\n" +
      range +
      "    if (bloomEmittersAlone != 0)\n"
      "    {\n"
      "      gl_FragData[0].rgb *= bloomWeight;\n"
      "    }\n"
      "    else\n"
      "    {\n"
      "      // In the scene's render, the weight rides on the alpha of an opaque fragment.\n"
      "      gl_FragData[0].a += bloomWeight;\n"
      "    }\n"
      "  }\n",
    false);
}

//------------------------------------------------------------------------------
void vtkBloomPassEmission::SetUniforms(
  vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkProp* prop) const
{
  if (!program->IsUniformUsed("bloomEmission"))
  {
    return;
  }
  const auto found = this->Props.find(prop);
  Emission e = found == this->Props.end() ? Emission() : found->second;
  if (found == this->Props.end() && this->EmittersAlone)
  {
    // Only emitters render alone: a prop the plan does not know draws one of them (a
    // vtkFollower's own actor), and emits its whole colour.
    e.What = WHOLE;
  }
  program->SetUniformi("bloomEmission", e.What);
  if (program->IsUniformUsed("bloomEmittersAlone"))
  {
    program->SetUniformi("bloomEmittersAlone", this->EmittersAlone ? 1 : 0);
  }
  if (program->IsUniformUsed("bloomTextureRange"))
  {
    float bounds[2] = { 1.0f, 0.0f };
    if (e.What == RANGE)
    {
      vtkBloomPassEmission::TextureRange(mapper, e.Range, bounds);
    }
    program->SetUniform2f("bloomTextureRange", bounds);
  }
}

//------------------------------------------------------------------------------
void vtkBloomPassEmission::TextureRange(
  vtkAbstractMapper* mapper, const double range[2], float bounds[2])
{
  // vtkMapper::MapScalarsToTexture's coordinates: the table's range widened by one colour on
  // each side (the below- and above-range texels), s = (v - low) / (high - low).
  auto* polyMapper = vtkOpenGLPolyDataMapper::SafeDownCast(mapper);
  vtkScalarsToColors* table = polyMapper ? polyMapper->GetLookupTable() : nullptr;
  bounds[0] = 1.0f;
  bounds[1] = 0.0f; // empty unless the table is linear with a range
  if (!table || table->UsingLogScale())
  {
    return;
  }
  const double* r = table->GetRange();
  const double colours =
    std::max<double>(1.0, static_cast<double>(table->GetNumberOfAvailableColors()));
  const double texel = (r[1] - r[0]) / colours;
  const double low = r[0] - texel, high = r[1] + texel;
  if (!(high > low))
  {
    // A table of one value: everything or nothing is in the range.
    const bool in = range[0] <= r[0] && r[0] <= range[1];
    bounds[0] = in ? -std::numeric_limits<float>::max() : 1.0f;
    bounds[1] = in ? std::numeric_limits<float>::max() : 0.0f;
    return;
  }
  // A hair wider, so that a vertex exactly at an end of the range is inside in float.
  const double hair = 1e-6;
  bounds[0] = static_cast<float>((range[0] - low) / (high - low) - hair);
  bounds[1] = static_cast<float>((range[1] - low) / (high - low) + hair);
}
