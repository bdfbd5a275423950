// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkBloomPassEmission.h
 * @brief  (private to vtkBloomPass) selective bloom: what each prop emits, and where the
 *         emission is written.
 *
 * With vtkBloomPass::EMISSION_EMITTERS only the emitter props bloom. Where it can, the pass
 * writes their emission in the scene's own render: the pass joins the render passes of every
 * prop (vtkOpenGLRenderPass::PreRender), and its shader replacement makes each polydata
 * mapper's fragment shader add the fragment's emission weight to its alpha: 1 for an emitter,
 * 0 for any other prop (every prop of that render is opaque, alpha 1, and blending is off). An
 * emitting fragment so has alpha 2, and the emission is the scene's colour where its alpha is
 * above 1 (the chain's bright pass reads it so, the composite takes min(alpha, 1)). The depth
 * test that decides the scene's visible surface decides the emission's, so an occluded emitter
 * stays dark, with no second render, no second colour attachment and no clear of one. (A
 * second colour attachment was measured first: on an NVIDIA H100 at 3840x2160 writing and
 * clearing it cost about 3 ms, as much as the emitters' second render.) Multisampled, the
 * resolve averages colour and weight separately, so along an emitter's silhouette the emission
 * is the average colour times the average weight rather than the average of their products.
 *
 * An emitter made by vtkBloomPass::CreateScalarRangeEmitter from a texture-coloured actor
 * (InterpolateScalarsBeforeMapping on, a linear lookup table) names its source actor and its
 * range (the keys EMITTER_SOURCE and EMITTER_SCALAR_RANGE): its emission is the source's own
 * fragment colour where the interpolated scalar lies in the range, tested on the colour
 * texture coordinate, and zero elsewhere.
 *
 * Where the emission cannot be written in the scene's render, the emitters are rendered a
 * second time, alone, as before (docs/rendering.md, "Selective bloom"): when a visible prop is not
 * an opaque vtkActor drawn by a vtkOpenGLPolyDataMapper (its shader would not write the second
 * output: 2D actors, volumes, translucent geometry, glyph mappers), when an emitter is neither
 * in the scene nor made from an actor that is, when the delegate is not a vtkRenderStepsPass or
 * vtkCameraPass, or when vtkBloomPass::EmitInSceneRender is off. The emitters' own render uses
 * the same shader code, with the masked colour as their colour, so both paths give the same
 * image to float rounding (tested).
 */

#ifndef vtkBloomPassEmission_h
#define vtkBloomPassEmission_h

#include <string>
#include <unordered_map>
#include <vector>

class vtkAbstractMapper;
class vtkInformationDoubleVectorKey;
class vtkInformationObjectBaseKey;
class vtkProp;
class vtkPropCollection;
class vtkRenderPass;
class vtkShaderProgram;

class vtkBloomPassEmission
{
public:
  /**
   * `sourceKey` and `rangeKey` are the property keys under which a scalar-range emitter records
   * the actor it was made from and its range (vtkBloomPass::EMITTER_SOURCE and
   * EMITTER_SCALAR_RANGE).
   */
  vtkBloomPassEmission(
    vtkInformationObjectBaseKey* sourceKey, vtkInformationDoubleVectorKey* rangeKey)
    : SourceKey(sourceKey)
    , RangeKey(rangeKey)
  {
  }

  /// What a prop emits; the values are the shader's `bloomEmission`.
  enum Kind
  {
    NONE = 0,  ///< nothing: a prop of the scene that is not an emitter
    WHOLE = 1, ///< its whole colour: an emitter prop
    RANGE = 2  ///< its colour where the scalar lies in a range: a scalar-range emitter's source
  };

  /**
   * Plan a frame: which of `props` (the scene's) emit and how, and which emitters must be
   * rendered again. Returns true when the emission can be written in the scene's own render
   * (`inScene`, vtkBloomPass::EmitInSceneRender, allows it).
   */
  bool Plan(
    vtkPropCollection* emitters, vtkProp** props, int count, vtkRenderPass* delegate, bool inScene);

  /// The last plan: emission in the scene's render, else SecondRender holds the emitters.
  bool InSceneRender = false;
  std::vector<vtkProp*> SecondRender;

  /**
   * Whether the shaders now render the emitters alone (their masked colour replaces their
   * colour) rather than the scene (the weight rides on the alpha).
   */
  bool EmittersAlone = false;

  ///@{
  /// The shader replacement, the same for every prop (what differs is a uniform).
  static void PreReplace(std::string& fragmentShader, vtkAbstractMapper* mapper);
  static void PostReplace(std::string& fragmentShader, vtkAbstractMapper* mapper);
  ///@}

  /// Set the uniforms of `prop`'s draw.
  void SetUniforms(vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkProp* prop) const;

private:
  vtkInformationObjectBaseKey* SourceKey;
  vtkInformationDoubleVectorKey* RangeKey;
  /// The source actor and scalar range recorded on `emitter`, if any.
  vtkProp* RangeSource(vtkProp* emitter, double range[2]) const;

  struct Emission
  {
    Kind What = NONE;
    double Range[2] = { 0.0, 0.0 }; // the scalar range, RANGE only
  };
  std::unordered_map<vtkProp*, Emission> Props;

  // The colour texture coordinates' [lower, upper] bounds of a RANGE emission drawn by
  // `mapper`.
  static void TextureRange(vtkAbstractMapper* mapper, const double range[2], float bounds[2]);
};

#endif
// VTK-HeaderTest-Exclude: vtkBloomPassEmission.h
