// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkBloomPassTypes.h
 * @brief  (private to vtkBloomPass) the small types the pass's parts share: the values the
 *         shader and the passes agree on, a box of samples, a segment of an axis, what one pass
 *         computes, a float target and one entry of the profile.
 *
 * They own and call nothing, and this header includes none of the pass's own: the lowest floor
 * of the design in docs/architecture.md, so that every other part may include it.
 */

#ifndef vtkBloomPassTypes_h
#define vtkBloomPassTypes_h

#include "vtkSmartPointer.h" // For the target's texture and framebuffer

#include <string> // For the profile's pass names

class vtkBloomLinearOperator;
class vtkImageData;
class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkTextureObject;
class vtkWindow;

/// Values shared with vtkBloomPassFS.glsl, emitted into the shader as #defines.
struct vtkBloomPassShaderValues
{
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
};

/// A box of samples [X0, X1) x [Y0, Y1); empty when X0 >= X1 or Y0 >= Y1.
struct vtkBloomPassBox
{
  int X0 = 0;
  int X1 = 0;
  int Y0 = 0;
  int Y1 = 0;
  bool Empty() const { return this->X0 >= this->X1 || this->Y0 >= this->Y1; }
  static vtkBloomPassBox Whole(int width, int height) { return { 0, width, 0, height }; }
  /// x0 x1 y0 y1 as a box; all 0: the whole width x height.
  static vtkBloomPassBox Window(const int window[4], int width, int height);
  vtkBloomPassBox Union(const vtkBloomPassBox& o) const;
  vtkBloomPassBox Intersection(const vtkBloomPassBox& o) const;
};

/// A range of output samples along one axis and how the pass evaluates it (an OP_ value).
struct vtkBloomPassSegment
{
  int Begin;
  int End;
  int Mode;
};

/// What one pass computes: step(Y X source), see vtkBloomPassFS.glsl.
struct vtkBloomPassSpec
{
  vtkTextureObject* Source = nullptr;
  const int* SourceSize = nullptr;
  const vtkBloomLinearOperator* X = nullptr; ///< null: identity along x
  const vtkBloomLinearOperator* Y = nullptr; ///< null: identity along y
  int Step = vtkBloomPassShaderValues::STEP_SCALE;
  double Weight = 1.0;
  bool Blend = false;       ///< add to the target instead of replacing it
  bool ReadsSource = false; ///< the chain's source: depth mask and sanitizing apply
  bool DiscardZero = false; ///< leave zero results unwritten (counted by the query)
  bool CompositeBloom = true;
  vtkTextureObject* Addend = nullptr;      ///< STEP_ADD
  const char* Name = "pass";               ///< for the profile
  int Level = -1;                          ///< the pyramid level it writes, for the profile
  const vtkBloomPassBox* Region = nullptr; ///< restricted: the samples to compute, else all
  bool ZeroBloom = false; ///< composite where the bloom is known zero (no operator taps)
  bool Tiled = false;     ///< X and Y both set: the x sums shared by a work group (Fuses)
  /**
   * Tiled only: a second separable term of the same output (its Source, SourceSize, X, Y
   * and Weight), its x sums shared too (TILE2 in vtkBloomPassFS.glsl): the ADD step's addend
   * (SecondIsAddend), or added to the result times its Weight. What a pass of its own would
   * have written into a target for this one to read, the same bits (FusesTwo).
   */
  const vtkBloomPassSpec* Second = nullptr;
  bool SecondIsAddend = false;
  /// The bright pass: the multisampled source, thresholded sample by sample (Light::Samples).
  vtkTextureObject* Samples = nullptr;
  int SampleCount = 0;
  /// The composite: the multisampled scene, composited sample by sample (Output::SceneSamples).
  vtkTextureObject* SceneSamples = nullptr;
  int SceneSampleCount = 0;
};

//------------------------------------------------------------------------------
// A float texture and the framebuffer that renders into it (its methods:
// vtkBloomPassResources.cxx).
struct vtkBloomPassTarget
{
  vtkSmartPointer<vtkTextureObject> Color;
  vtkSmartPointer<vtkOpenGLFramebufferObject> FBO;
  int Size[2] = { 0, 0 };

  /**
   * Content-aware passes (vtkBloomPassRegion.cxx): the texture is zero outside the box
   * [Dirty[0], Dirty[1]) x [Dirty[2], Dirty[3]). A new texture is dirty everywhere.
   */
  int Dirty[4] = { 0, 0, 0, 0 };

  /**
   * Make the target at width x height in `format`, unless it already has that size and
   * format.
   */
  void Allocate(vtkOpenGLRenderWindow* context, int width, int height, unsigned int format);
  void Release(vtkWindow* window);

  /**
   * Read the colour back into `image` as float RGBA (origin 0, spacing 1, row 0 at the
   * bottom) and return true. The framebuffer bindings are restored afterwards.
   */
  bool Read(vtkOpenGLRenderWindow* context, vtkImageData* image);
};

//------------------------------------------------------------------------------
/// One entry of the pass's GPU profile (vtkBloomPassTesting::GetProfile).
struct vtkBloomPassProfiledPass
{
  std::string Name;       ///< "scene", "bright L0", "blur-x L3", "composite", ...
  int Size[2] = { 0, 0 }; ///< the pixels it wrote
  double Milliseconds = 0.0;
  /// Its compulsory memory traffic: every texture it reads read once, its target written
  /// once and read again when it blends; for "scene" and "emitters", the float colour and
  /// the 32-bit depth written once.
  double Bytes = 0.0;
};

#endif
// VTK-HeaderTest-Exclude: vtkBloomPassTypes.h
