// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkBloomGallery.h
 * @brief  The scenes of TestBloomPassGallery.cxx, built the way users build them, and the 8-bit
 *         frame metrics the gallery measures them with.
 *
 * A gallery scene is an ordinary VTK window: white, gradient or textured backgrounds, lit grey
 * and colour-mapped surfaces with VTK's default headlight (specular 0, so no colour exceeds 1),
 * text, scalar bars, corner annotations, legends and 2D widgets, several renderers, layers,
 * depth peeling, volumes, FXAA, vtkToneMappingPass and vtkSSAOPass chains. Every renderer that
 * blooms has a vtkBloomPass at its defaults, and a View says how to take the bloom out again
 * (the user's own pass chain without it), so that the gallery can compare the frame with the
 * pass against the frame without it: nothing in these scenes is light, so they must agree.
 */

#ifndef vtkBloomGallery_h
#define vtkBloomGallery_h

#include "vtkBloomPass.h"
#include "vtkImageData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"

#include <functional>
#include <string>
#include <vector>

class vtkActor;
class vtkProp;

namespace vtkBloomGallery
{
/// An 8-bit RGB frame read back from a window (row 0 at the bottom).
using Frame = vtkSmartPointer<vtkImageData>;

/// A renderer that blooms, and how the scene switches between its bloom and its plain pipeline.
struct View
{
  vtkSmartPointer<vtkRenderer> Renderer;
  vtkSmartPointer<vtkBloomPass> Bloom;
  /// Install the pipeline with the bloom (true) or the user's own without it (false). The
  /// default (AddBloomView) sets the bloom pass on the renderer, or no pass at all.
  std::function<void(bool)> Use;
};

/// One configuration of the gallery: a window, its blooming views and what to measure.
struct Scene
{
  std::string Name;
  vtkSmartPointer<vtkRenderWindow> Window;
  std::vector<View> Views;
  /// Annotation props, hidden to find the annotations' pixels (empty: no annotation check).
  std::vector<vtkSmartPointer<vtkProp>> Annotations;
  /// Objects the scene needs alive (widgets, interactors, passes, sources).
  std::vector<vtkSmartPointer<vtkObjectBase>> Keep;
  /// The view the emitter is added to, and where: normalized viewport coordinates of its
  /// centre, its radius in pixels, and how far it is moved from the focal plane towards the
  /// camera (a fraction of the distance, so that it is not buried in the geometry).
  int EmitterView = 0;
  double EmitterAt[2] = { 0.5, 0.5 };
  double EmitterPixels = 6.0;
  double EmitterTowardCamera = 0.3;
  /// The largest difference from the plain frame the pass may make, in 8-bit levels, and why
  /// it is more than 1 where it is.
  double MaxLevels = 1.0;
  std::string MaxLevelsWhy;
  /// Check that the scene's float render stays within [0, 1] (nothing is light).
  bool CheckSceneRange = true;
  /// Also compare with the plain pipeline rendered into a float framebuffer
  /// (vtkFramebufferPass, RGBA32F), within one level: where the window's own 8-bit
  /// framebuffer is the less exact of the two (blending many translucent layers).
  bool FloatReference = false;
  /// The annotations are composited in linear colour, so that an anti-aliased edge lets
  /// through (1 - coverage) of what lies below it. Off where a tone mapping follows.
  bool LinearOverlay = true;
  /// Run between building the scene and the first measured frame (picking, a resize).
  std::function<void(Scene&)> Prepare;
};

///@{
/// Scene pieces, as users make them.
vtkSmartPointer<vtkRenderWindow> MakeWindow(int width, int height, int samples = 0);
/// A renderer added to `scene`'s window with a vtkBloomPass(vtkRenderStepsPass) at its defaults.
View& AddBloomView(Scene& scene, vtkRenderer* renderer);
/// A lit, matte (specular 0) sphere of one colour.
vtkSmartPointer<vtkActor> LitSphere(const double centre[3], double radius, const double rgb[3]);
/// A sphere coloured by its elevation through VTK's default rainbow table (lit, matte).
vtkSmartPointer<vtkActor> ColourMappedSphere(const double centre[3], double radius);
/// A lit, matte floor (a square of half side `size` at height `y`) under the spheres.
vtkSmartPointer<vtkActor> GroundPlane(double size, double y, const double rgb[3]);
/// A text label at normalized viewport coordinates.
vtkSmartPointer<vtkProp> TextLabel(const char* text, double x, double y, const double rgb[3]);
/// A vertical scalar bar of the default rainbow table on the right, labels in `rgb`.
vtkSmartPointer<vtkProp> ScalarBar(const double rgb[3]);
/// A corner annotation (lower left and upper right) in `rgb`.
vtkSmartPointer<vtkProp> CornerText(const double rgb[3]);
/// A legend box with three entries at the upper left.
vtkSmartPointer<vtkProp> Legend(const double rgb[3]);
/// The small HDR emitter: an unlit sphere of colour (6, 2.4, 0.6) (ambient colour, diffuse 0).
vtkSmartPointer<vtkActor> Emitter(
  vtkRenderer* renderer, const double at[2], double pixels, double towardCamera);
///@}

///@{
/// The bloom's defaults, or the defaults before lights-only bloom (the "before" figures):
/// smoothstep knee at threshold 1, background and annotations bloomed, emitters thresholded.
void UseOldDefaults(vtkBloomPass* pass, bool old);
void UseBloom(Scene& scene, bool bloom);
void UseOldDefaults(Scene& scene, bool old);
/// The plain frame rendered through a float framebuffer (see Scene::FloatReference); single
/// renderer scenes whose plain pipeline is the renderer's own (no pass).
Frame GrabFloatPlain(Scene& scene);
///@}

///@{
/// Frames and their metrics. Grab renders the window explicitly, then reads the back buffer
/// as 8-bit RGB without rendering again; it adds the OpenGL errors the render raised to
/// `errors` where given (errors pending before the render are cleared first). With `presented`
/// it also reads the front buffer of the same render: the frame as the window presents it,
/// which VTK resolves from a multisampled window's samples through a gamma 2.2 average (the
/// back buffer's read resolves them by their plain mean). PyVista's and vedo's screenshots are
/// that frame.
Frame Grab(vtkRenderWindow* window, int* errors = nullptr, Frame* presented = nullptr);
/// The largest channel difference |a - b| of pixel `p`, in levels.
double Difference(vtkImageData* a, vtkImageData* b, vtkIdType p);
/// max over pixels and channels of |a - b|, in levels. Frames of different sizes differ
/// everywhere, by 256 levels (MaxOver and MeanOver too).
double MaxLevels(vtkImageData* a, vtkImageData* b);
/// The percentage of pixels whose largest channel difference exceeds `levels` (100 for frames
/// of different sizes).
double PercentOver(vtkImageData* a, vtkImageData* b, double levels);
/// Pixels (of `a`) whose largest channel difference exceeds `levels`: all of them where the
/// frames' sizes differ.
std::vector<char> DifferenceMask(vtkImageData* a, vtkImageData* b, double levels);
/// Pixels at a distance in (inner, outer] from the nearest pixel of `footprint`.
std::vector<char> Ring(
  const std::vector<char>& footprint, int width, int height, double inner, double outer);
/// Mean (or max) over the masked pixels of the largest channel difference; 0 for no pixels.
double MeanOver(vtkImageData* a, vtkImageData* b, const std::vector<char>& mask);
double MaxOver(vtkImageData* a, vtkImageData* b, const std::vector<char>& mask);
/// The pixels outside the viewport of `renderer` (in the window of `frame`).
std::vector<char> OutsideViewport(vtkImageData* frame, vtkRenderer* renderer);
/// The number of set pixels of a mask.
long Count(const std::vector<char>& mask);
/// The largest colour value of `pass`'s last float scene (its context must be current), or -1
/// where the pass gives none back.
double SceneMaximum(vtkBloomPass* pass);
/**
 * The annotations' coverage per pixel (0 to 1): the plain frame of the annotations alone
 * (every other prop hidden) over a black and over a white solid background, 1 - their largest
 * channel difference over the backdrop's own (the largest in the frame). Anti-aliased text edges
 * are partly transparent: what lies below them shows through, glow included.
 */
std::vector<double> AnnotationCoverage(Scene& scene);
///@}

///@{
/// Output for the docs: `a | b` written as a PNG, and one CSV line (with a header when the
/// file is new).
void WriteSideBySide(vtkImageData* a, vtkImageData* b, const std::string& path);
void AppendCSV(
  const std::string& path, const std::string& configuration, const std::vector<double>& values);
///@}
}

#endif
