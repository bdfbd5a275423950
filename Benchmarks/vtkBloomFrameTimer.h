// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// Frame time of an example scene with the plain render steps, with vtkBloomPass, or with the
// least any HDR post-process does: the scene into a float target, then one full-screen copy to
// the window, either VTK's own vtkFramebufferPass (a glBlitFramebuffer, at the precision of the
// bloom pass's scene target) or the cheapest copy (COMPUTE_COPY: vtkBloomPass with strength 0,
// which skips its chain and copies the scene with a compute pass where the context has one),
// for the benchmark executables (BloomPassFrameTime and the GPU rows of BloomChainSpeed). The
// caller interleaves the kinds of frame, so machine noise hits them alike.
//
// Each frame is timed twice: by the wall clock from the start of Render() to the end of
// glFinish (Frame's return value), and by a GL_TIME_ELAPSED query around Render()
// (LastGPUSeconds), the GPU's own time for the frame's commands, which excludes the CPU work
// of submitting them and the wait for the driver. The query needs a context, so the first
// frame of a timer has no GPU time (NaN).
#ifndef vtkBloomFrameTimer_h
#define vtkBloomFrameTimer_h

#include "vtkActor.h"
#include "vtkBloomExampleScenes.h"
#include "vtkBloomFrameStatistics.h"
#include "vtkBloomParameters.h"
#include "vtkBloomPass.h"
#include "vtkBloomVTKCompat.h"
#include "vtkCamera.h"
#include "vtkFramebufferPass.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkTextureObject.h"

#include <chrono>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

/**
 * One window's frames timed twice: the wall clock from the start of Render() to the end of
 * glFinish (Render's return value; LastSubmitSeconds stops before the wait), and a
 * GL_TIME_ELAPSED query around Render() (LastGPUSeconds; NaN for the first frame, before the
 * context exists). Release() before the window goes.
 */
class vtkBloomRenderTiming
{
public:
  double Render(vtkRenderWindow* window)
  {
    const bool timed = this->Query != 0;
    if (timed)
    {
      window->MakeCurrent();
    }
    const auto start = std::chrono::steady_clock::now();
    if (timed)
    {
      glBeginQuery(GL_TIME_ELAPSED, this->Query);
    }
    window->Render();
    if (timed)
    {
      glEndQuery(GL_TIME_ELAPSED);
    }
    this->LastSubmitSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    window->WaitForCompletion();
    const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    this->LastGPUSeconds = std::numeric_limits<double>::quiet_NaN();
    if (timed)
    {
      GLuint64 ns = 0;
      glGetQueryObjectui64v(this->Query, GL_QUERY_RESULT, &ns);
      this->LastGPUSeconds = 1e-9 * static_cast<double>(ns);
    }
    else
    {
      glGenQueries(1, &this->Query); // the context exists now
    }
    return wall;
  }

  void Release(vtkRenderWindow* window)
  {
    if (this->Query)
    {
      window->MakeCurrent();
      glDeleteQueries(1, &this->Query);
      this->Query = 0;
    }
  }

  double LastGPUSeconds = std::numeric_limits<double>::quiet_NaN();
  /// Wall-clock seconds of the last frame's Render() alone (before glFinish): the CPU's time
  /// to submit it, and any wait for the GPU within it.
  double LastSubmitSeconds = std::numeric_limits<double>::quiet_NaN();

private:
  GLuint Query = 0;
};

class vtkBloomFrameTimer
{
public:
  enum Kind
  {
    PLAIN,        ///< the render steps into the window
    FLOAT_COPY,   ///< the render steps into a float target, blitted to the window (VTK's pass)
    BLOOM,        ///< vtkBloomPass around the render steps
    ALTERNATIVE,  ///< a second vtkBloomPass (Alternative), to compare two settings frame by frame
    COMPUTE_COPY, ///< a float target copied by a compute pass (vtkBloomPass, strength 0)
  };

  /// The window's samples (multisampling; 0: none), set before Setup.
  int Samples = 0;

  /// The offscreen window of width x height, its renderer, and the three passes' delegates.
  void AttachWindow(int width, int height)
  {
    this->Window->SetOffScreenRendering(1);
    this->Window->SetMultiSamples(this->Samples);
    this->Window->SetSize(width, height);
    this->Window->AddRenderer(this->Renderer);
    this->Bloom->SetDelegatePass(this->Steps);
    this->Alternative->SetDelegatePass(this->Steps);
    this->FloatCopy->SetDelegatePass(this->Steps);
    this->ComputeCopy->SetDelegatePass(this->Steps);
    // Strength 0 skips the chain (SkipDisabledEffects): the scene's float target is copied to
    // the window by the composite alone, a compute pass where it can be.
    vtkBloomParameters* copy = this->ComputeCopy->GetParameters();
    copy->SetStrength(0.0);
    copy->SetRestrictToBrightRegion(false);
  }

  /// An offscreen window of width x height showing `scene`; false for an unknown scene.
  bool Setup(const std::string& scene, int width, int height)
  {
    this->AttachWindow(width, height);
    if (!vtkBloomBuildExampleScene(scene, this->Renderer, this->Bloom))
    {
      return false;
    }
    this->Alternative->SetParameters(this->Bloom->GetParameters());
    this->ComputeCopy->SetFloatPrecision(this->Bloom->GetFloatPrecision());
    this->FloatCopy->SetColorFormat(this->Bloom->GetFloatPrecision() == vtkBloomPass::FLOAT32
        ? vtkTextureObject::Float32
        : vtkTextureObject::Float16);
    return true;
  }

  /**
   * A sparse scene: a dark background (0.25, below vtkImageBloom's default threshold) and one
   * flat HDR disk, (4, 3, 2) (an ambient-only sphere at the centre of a parallel projection,
   * so that turning the camera keeps its size), covering `fraction` of the window (none for
   * 0). Both bloom passes get vtkBloomParameters' defaults.
   */
  void SetupSparse(double fraction, int width, int height)
  {
    this->AttachWindow(width, height);
    this->Renderer->SetBackground(0.25, 0.25, 0.25);
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    camera->ParallelProjectionOn();
    camera->SetParallelScale(1.0);
    camera->SetPosition(0.0, 0.0, 10.0);
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    camera->SetViewUp(0.0, 1.0, 0.0);
    if (fraction > 0.0)
    {
      // Disk area pi r^2 over the view's 2 x 2 aspect world units.
      const double aspect = static_cast<double>(width) / height;
      vtkNew<vtkSphereSource> sphere;
      sphere->SetRadius(std::sqrt(4.0 * fraction * aspect / 3.14159265358979));
      sphere->SetThetaResolution(96);
      sphere->SetPhiResolution(48);
      vtkNew<vtkPolyDataMapper> mapper;
      mapper->SetInputConnection(sphere->GetOutputPort());
      vtkNew<vtkActor> actor;
      actor->SetMapper(mapper);
      actor->GetProperty()->SetAmbient(1.0);
      actor->GetProperty()->SetDiffuse(0.0);
      actor->GetProperty()->SetSpecular(0.0);
      actor->GetProperty()->SetAmbientColor(4.0, 3.0, 2.0);
      this->Renderer->AddActor(actor);
    }
    camera->SetClippingRange(1.0, 20.0);
    vtkNew<vtkBloomParameters> defaults;
    this->Alternative->SetParameters(defaults);
    this->FloatCopy->SetColorFormat(vtkTextureObject::Float16);
  }

  /**
   * Replace the scene's bloom parameters by a preset's ("default": vtkBloomParameters' defaults),
   * keeping the scene's bright pass (threshold mode, threshold, knee) so that the same pixels
   * bloom. "scene" keeps the scene's own parameters. False for an unknown preset.
   */
  bool UsePreset(const std::string& preset)
  {
    if (preset == "scene")
    {
      return true;
    }
    vtkNew<vtkBloomParameters> parameters;
    if (preset != "default" && !parameters->SetPreset(preset.c_str()))
    {
      return false;
    }
    vtkBloomParameters* scene = this->Bloom->GetParameters();
    parameters->SetThresholdMode(scene->GetThresholdMode());
    parameters->SetThreshold(scene->GetThreshold());
    parameters->SetKnee(scene->GetKnee());
    this->Bloom->SetParameters(parameters);
    // The alternative pass gets a copy of its own, so that it may differ.
    vtkNew<vtkBloomParameters> copy;
    if (preset != "default")
    {
      copy->SetPreset(preset.c_str());
    }
    copy->SetThresholdMode(parameters->GetThresholdMode());
    copy->SetThreshold(parameters->GetThreshold());
    copy->SetKnee(parameters->GetKnee());
    this->Alternative->SetParameters(copy);
    return true;
  }

  /// Render one new frame (the camera moves a little, so nothing is cached) and wait for it;
  /// wall-clock seconds. LastGPUSeconds is the frame's GPU time.
  double Frame(Kind kind)
  {
    vtkRenderPass* passes[] = { this->Steps, this->FloatCopy, this->Bloom, this->Alternative,
      this->ComputeCopy };
    return this->FrameWith(passes[kind]);
  }

  /// Frame() with any pass around the renderer (its delegate is the caller's to set).
  double FrameWith(vtkRenderPass* pass)
  {
    this->Renderer->SetPass(pass);
    this->Renderer->GetActiveCamera()->Azimuth(0.5);
    const double wall = this->Timing.Render(this->Window);
    this->LastGPUSeconds = this->Timing.LastGPUSeconds;
    this->LastSubmitSeconds = this->Timing.LastSubmitSeconds;
    return wall;
  }

  ~vtkBloomFrameTimer()
  {
    this->Timing.Release(this->Window);
    // The passes not set on the renderer last are not reached through the window.
    this->FloatCopy->ReleaseGraphicsResources(this->Window);
    this->Bloom->ReleaseGraphicsResources(this->Window);
    this->Alternative->ReleaseGraphicsResources(this->Window);
    this->ComputeCopy->ReleaseGraphicsResources(this->Window);
    this->Window->ReleaseGraphicsResources(this->Window);
  }

  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkBloomPass> Bloom;
  vtkNew<vtkBloomPass> Alternative;
  vtkNew<vtkRenderStepsPass> Steps;
  vtkNew<vtkFramebufferPass> FloatCopy;
  vtkNew<vtkBloomPass> ComputeCopy;
  double LastGPUSeconds = std::numeric_limits<double>::quiet_NaN();
  /// Wall-clock seconds of the last frame's Render() alone (before glFinish): the CPU's time
  /// to submit it, and any wait for the GPU within it.
  double LastSubmitSeconds = std::numeric_limits<double>::quiet_NaN();

private:
  vtkBloomRenderTiming Timing;
};

#endif
