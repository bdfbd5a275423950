// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// What the bloom frame costs over the plain frame, counted rather than timed, so that a cost
// added around the chain fails here on llvmpipe before anyone measures it on a card: the
// GPU's own counts per frame, the samples that fragments wrote (an occlusion query,
// GL_SAMPLES_PASSED) and the compute shader invocations (ARB_pipeline_statistics_query), with
// bloom against the same scene without it, in full frames (over the frame's samples), and the
// full-size passes and bytes of the pass's profile. Counts, not times: they are the same on every
// run and every machine with the same driver. A full-screen draw (the depth's copy that the pass
// made before its scene rendered into the window's own depth buffer) adds one full frame of
// fragments; a copy or a target added later adds a full-size entry or bytes. The budgets below are
// the counts of the current design (the example scenes' own parameters, whose chains start at full
// resolution at this size: about 9.4 frames of compute invocations, work groups' padding included)
// with room for rounding, not for one more full-frame pass, which adds 1.0.
//
// The window's depth after a bloom frame is the plain frame's, shared or drawn.
#include "vtkBloomExampleScenes.h"
#include "vtkBloomPass.h"
#include "vtkBloomPassTesting.h"
#include "vtkBloomVTKCompat.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#ifndef GL_COMPUTE_SHADER_INVOCATIONS_ARB
#define GL_COMPUTE_SHADER_INVOCATIONS_ARB 0x82F5
#endif

namespace
{
const int Width = 320;
const int Height = 192;

// One frame's counts, in full frames of the window: the samples written by fragments over
// the window's samples, the compute invocations over its pixels.
struct FrameCounts
{
  double Fragments = 0.0;
  double Compute = 0.0;
};

// A window of one renderer (or two side by side) showing an example scene, with or without
// bloom on each renderer.
struct CostWindow
{
  vtkNew<vtkRenderWindow> Window;
  std::vector<vtkSmartPointer<vtkRenderer>> Renderers;
  std::vector<vtkSmartPointer<vtkBloomPass>> Passes;

  int Samples;
  bool Built = true; ///< every renderer's scene was built

  CostWindow(const std::string& scene, int viewports, int samples)
    : Samples(samples)
  {
    this->Window->SetOffScreenRendering(1);
    this->Window->SetMultiSamples(samples);
    this->Window->SetSize(Width, Height);
    for (int i = 0; i < viewports; ++i)
    {
      auto renderer = vtkSmartPointer<vtkRenderer>::New();
      auto pass = vtkSmartPointer<vtkBloomPass>::New();
      vtkNew<vtkRenderStepsPass> steps;
      pass->SetDelegatePass(steps);
      renderer->SetViewport(
        static_cast<double>(i) / viewports, 0.0, static_cast<double>(i + 1) / viewports, 1.0);
      this->Built = vtkBloomBuildExampleScene(scene, renderer, pass) && this->Built;
      this->Window->AddRenderer(renderer);
      this->Renderers.push_back(renderer);
      this->Passes.push_back(pass);
    }
  }
  ~CostWindow() { this->Window->ReleaseGraphicsResources(this->Window); }

  void Bloom(bool on)
  {
    for (size_t i = 0; i < this->Renderers.size(); ++i)
    {
      this->Renderers[i]->SetPass(on ? this->Passes[i].Get() : nullptr);
    }
  }

  FrameCounts Count()
  {
    this->Window->Render(); // the programs built, the targets made: a later frame's counts
    auto* gl = vtkOpenGLRenderWindow::SafeDownCast(this->Window);
    gl->MakeCurrent();
    GLuint queries[2] = { 0, 0 };
    glGenQueries(2, queries);
    glBeginQuery(GL_SAMPLES_PASSED, queries[0]);
    glBeginQuery(GL_COMPUTE_SHADER_INVOCATIONS_ARB, queries[1]);
    this->Window->Render();
    gl->MakeCurrent();
    glEndQuery(GL_SAMPLES_PASSED);
    glEndQuery(GL_COMPUTE_SHADER_INVOCATIONS_ARB);
    GLuint64 n[2] = { 0, 0 };
    glGetQueryObjectui64v(queries[0], GL_QUERY_RESULT, &n[0]);
    glGetQueryObjectui64v(queries[1], GL_QUERY_RESULT, &n[1]);
    glDeleteQueries(2, queries);
    const double pixels = static_cast<double>(Width) * Height;
    return FrameCounts{ static_cast<double>(n[0]) / (pixels * std::max(1, this->Samples)),
      static_cast<double>(n[1]) / pixels };
  }

  std::vector<float> Depth()
  {
    std::vector<float> depth(static_cast<size_t>(Width) * Height);
    this->Window->GetZbufferData(0, 0, Width - 1, Height - 1, depth.data());
    return depth;
  }
};

bool HasPipelineStatistics(vtkRenderWindow* window)
{
  auto* gl = vtkOpenGLRenderWindow::SafeDownCast(window);
  gl->MakeCurrent();
  GLint count = 0;
  glGetIntegerv(GL_NUM_EXTENSIONS, &count);
  for (GLint i = 0; i < count; ++i)
  {
    const char* name = reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, i));
    if (name && std::string(name) == "GL_ARB_pipeline_statistics_query")
    {
      return true;
    }
  }
  GLint major = 0, minor = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  return major > 4 || (major == 4 && minor >= 6);
}

double LargestDifference(const std::vector<float>& a, const std::vector<float>& b)
{
  if (a.size() != b.size() || a.empty())
  {
    return INFINITY;
  }
  double largest = 0.0;
  for (size_t i = 0; i < a.size(); ++i)
  {
    largest = std::max(largest, static_cast<double>(std::fabs(a[i] - b[i])));
  }
  return largest;
}

// The bloom frame's counts over the plain frame's, and the window's depth against the plain
// frame's. `fragments` is the budget of extra fragments, in full frames; `compute` the compute
// invocations' (the chain and the composite).
struct Budget
{
  double Fragments;
  double Compute;
  double BytesPerPixel; ///< the profile's compulsory traffic over the window's pixels
};

void ExpectWithin(const std::string& scene, int viewports, int samples, const Budget& budget)
{
  CostWindow w(scene, viewports, samples);
  ASSERT_TRUE(w.Built) << scene;
  w.Bloom(false);
  w.Window->Render();
  ASSERT_TRUE(HasPipelineStatistics(w.Window))
    << "this leg's context has no ARB_pipeline_statistics_query: the frame's cost cannot be "
       "counted (every leg's Mesa has it)";
  const FrameCounts plain = w.Count();
  const std::vector<float> plainDepth = w.Depth();
  w.Bloom(true);
  const FrameCounts bloom = w.Count();
  const std::vector<float> bloomDepth = w.Depth();
  const double fragments = bloom.Fragments - plain.Fragments;
  const double compute = bloom.Compute - plain.Compute;
  std::printf(
    "%s, %d viewport(s), %d samples: samples written %.3f -> %.3f frames (%+.3f), compute "
    "%.3f -> %.3f frames (%+.3f)\n",
    scene.c_str(), viewports, samples, plain.Fragments, bloom.Fragments, fragments, plain.Compute,
    bloom.Compute, compute);
  EXPECT_GT(plain.Fragments, 0.01) << "the counter counts nothing: this check could not fail";
  EXPECT_LE(fragments, budget.Fragments) << scene << ": a full-frame draw was added";
  EXPECT_GE(compute, 0.9) << scene << ": no compute composite (the chain ran as fragments?)";
  EXPECT_LE(compute, budget.Compute) << scene << ": a compute pass over the frame was added";
  EXPECT_LE(LargestDifference(bloomDepth, plainDepth), 1e-6)
    << scene << ": the window's depth after the bloom is not the scene's";

  // The passes' own record: the full-size entries and their traffic.
  double bytes = 0.0;
  std::vector<std::string> full;
  for (const auto& pass : w.Passes)
  {
    vtkBloomPassTesting::SetProfilePasses(pass, true);
    w.Window->Render();
    const double part = static_cast<double>(Width) / viewports * Height;
    for (const auto& entry : vtkBloomPassTesting::GetProfile(pass))
    {
      bytes += entry.Bytes;
      if (static_cast<double>(entry.Size[0]) * entry.Size[1] >= 0.99 * part)
      {
        full.push_back(entry.Name);
      }
    }
    vtkBloomPassTesting::SetProfilePasses(pass, false);
  }
  std::string names;
  for (const std::string& name : full)
  {
    names += " " + name;
  }
  const double perPixel = bytes / (static_cast<double>(Width) * Height);
  std::printf("  full-size passes:%s; %.1f bytes a pixel\n", names.c_str(), perPixel);
  EXPECT_LE(perPixel, budget.BytesPerPixel) << scene << ":" << names;
  const bool drawsDepth = std::find(full.begin(), full.end(), "depth") != full.end();
  EXPECT_EQ(drawsDepth, viewports > 1) << scene << ":" << names;
}
}

// One renderer over the whole window: the scene renders into the window's depth buffer, and
// the frame adds no fragment of its own: the chain and the composite are compute passes.
TEST(RenderingBloomPassFrameCost, OneRendererDrawsNoFullFrameOfItsOwn)
{
  ExpectWithin("lit-spheres", 1, 0, Budget{ 0.05, 9.7, 175.0 });
  ExpectWithin("field-lines", 1, 0, Budget{ 0.05, 9.7, 175.0 });
}

// Selective bloom with the emission in the scene's own render costs what whole-scene bloom
// costs.
TEST(RenderingBloomPassFrameCost, SelectiveBloomInTheSceneRenderCostsTheSame)
{
  ExpectWithin("scalar-field", 1, 0, Budget{ 0.05, 9.7, 175.0 });
}

// Multisampled: the scene's samples go into the window's multisampled depth. The composite
// of a multisampled framebuffer is a fragment pass (compute shaders cannot write one): one
// full frame of samples, which the budget counts.
TEST(RenderingBloomPassFrameCost, MultisampledRendersIntoTheWindowsDepth)
{
  ExpectWithin("lit-spheres", 1, 4, Budget{ 1.1, 8.7, 200.0 });
}

// Two renderers side by side: the window's depth buffer is not the size of either's target,
// so each draws its depth after its composite: one full frame of fragments in all, which the
// count sees (so the budget of the cases above can fail).
TEST(RenderingBloomPassFrameCost, TwoViewportsDrawTheirDepth)
{
  ExpectWithin("lit-spheres", 2, 0, Budget{ 1.1, 10.4, 185.0 });
  CostWindow w("lit-spheres", 2, 0);
  w.Bloom(false);
  w.Window->Render();
  const FrameCounts plain = w.Count();
  w.Bloom(true);
  const FrameCounts bloom = w.Count();
  EXPECT_GE(bloom.Fragments - plain.Fragments, 0.9) << "the depth's draws were not counted";
}

// The frame as it was before the scene rendered into the window's depth: the depth drawn after
// the composite. The count sees that draw (one full frame), and the depth is the same.
TEST(RenderingBloomPassFrameCost, TheDepthsDrawIsCounted)
{
  CostWindow w("lit-spheres", 1, 0);
  ASSERT_TRUE(w.Built);
  w.Bloom(false);
  w.Window->Render();
  const FrameCounts plain = w.Count();
  const std::vector<float> plainDepth = w.Depth();
  w.Bloom(true);
  const FrameCounts shared = w.Count();
  ASSERT_TRUE(vtkBloomPassTesting::GetShareWindowDepth(w.Passes[0]));
  vtkBloomPassTesting::SetShareWindowDepth(w.Passes[0], false);
  const FrameCounts drawn = w.Count();
  EXPECT_LE(shared.Fragments - plain.Fragments, 0.05);
  EXPECT_GE(drawn.Fragments - plain.Fragments, 0.99);
  EXPECT_LE(drawn.Fragments - plain.Fragments, 1.01);
  EXPECT_LE(LargestDifference(w.Depth(), plainDepth), 1e-6);
}
