// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// Tests of vtkBloomPass's content-aware chain (RestrictToBrightRegion: every pass after the
// bright pass covers only the box its output can be non-zero in) against the full chain, bit
// for bit, and of the compute passes against the fragment passes.
#include "vtkBloomExampleScenes.h"
#include "vtkBloomOpenGLEnvironment.h"
#include "vtkBloomParameters.h"
#include "vtkBloomPass.h"
#include "vtkBloomPassTesting.h"
#include "vtkBloomTestSupport.h"

#include "vtkBloomVTKCompat.h"
#include "vtkCommand.h"
#include "vtkFloatArray.h"
#include "vtkFramebufferPass.h"
#include "vtkImageBloom.h"
#include "vtkImageBloomThreshold.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPointData.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"
#include "vtkUnsignedCharArray.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace
{
// A dark image (0.2, below every preset's threshold) with bright rectangles of value 8.
struct Rect
{
  int X0, X1, Y0, Y1;
};

vtkSmartPointer<vtkImageData> SparseImage(int width, int height, const std::vector<Rect>& rects)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetExtent(0, width - 1, 0, height - 1, 0, 0);
  image->AllocateScalars(VTK_FLOAT, 4);
  float* p = static_cast<float*>(image->GetScalarPointer());
  for (int y = 0; y < height; ++y)
  {
    for (int x = 0; x < width; ++x)
    {
      float v = 0.2f + 0.001f * static_cast<float>((x * 7 + y * 13) % 17); // not flat
      for (const Rect& r : rects)
      {
        if (x >= r.X0 && x < r.X1 && y >= r.Y0 && y < r.Y1)
        {
          v = 8.0f;
        }
      }
      float* q = p + 4 * (static_cast<size_t>(y) * width + x);
      q[0] = v;
      q[1] = 0.75f * v;
      q[2] = 0.5f * v;
      q[3] = 1.0f;
    }
  }
  return image;
}

struct Gpu
{
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkBloomPass> Pass;

  Gpu()
  {
    this->Window->SetOffScreenRendering(1);
    this->Window->SetMultiSamples(0);
    this->Window->SetSize(16, 16);
  }
  ~Gpu() { this->Pass->ReleaseGraphicsResources(this->Window); }

  vtkSmartPointer<vtkImageData> Apply(vtkImageData* input)
  {
    auto output = vtkSmartPointer<vtkImageData>::New();
    EXPECT_TRUE(
      this->Pass->ApplyToImage(vtkOpenGLRenderWindow::SafeDownCast(this->Window), input, output));
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    return output;
  }
};

bool SameBits(vtkImageData* a, vtkImageData* b)
{
  return a->GetNumberOfPoints() == b->GetNumberOfPoints() &&
    std::memcmp(a->GetScalarPointer(), b->GetScalarPointer(),
      sizeof(float) * 4 * a->GetNumberOfPoints()) == 0;
}

std::vector<std::string> Presets()
{
  std::vector<std::string> presets = vtkImageBloom::GetPresetNames();
  presets.insert(presets.begin(), "default");
  return presets;
}

void UsePreset(vtkBloomPass* pass, const std::string& preset)
{
  vtkNew<vtkImageBloom> parameters;
  if (preset != "default")
  {
    ASSERT_TRUE(parameters->SetPreset(preset.c_str()));
  }
  pass->SetParameters(parameters);
}
}

//------------------------------------------------------------------------------
// For every preset, both precisions and both qualities, at an odd and an even size, with one
// bright spot, two far apart (one on the border), and nothing bright with SkipEmptyBloom off
// (the whole chain then runs on empty boxes): the restricted chain's output has the same bits
// as the full chain's.
TEST(RenderingBloomPassRegion, RestrictedChainIsBitIdenticalToTheFullChain)
{
  struct Case
  {
    int Width, Height;
    std::vector<Rect> Rects;
    const char* Name;
  };
  const Case cases[] = { { 301, 207, { { 200, 205, 60, 64 } }, "one spot" },
    { 320, 192, { { 4, 9, 150, 153 }, { 300, 320, 0, 2 } }, "two spots, one on the border" },
    { 161, 91, {}, "nothing bright" } };
  for (const Case& c : cases)
  {
    vtkSmartPointer<vtkImageData> input = SparseImage(c.Width, c.Height, c.Rects);
    for (const std::string& preset : Presets())
    {
      for (const int precision : { vtkBloomPass::FLOAT32, vtkBloomPass::FLOAT16 })
      {
        for (const bool compute : { true, false })
        {
          const std::string what = std::string(c.Name) + ", " + preset + ", float" +
            std::to_string(precision) + (compute ? ", compute" : ", fragment");
          Gpu gpu;
          UsePreset(gpu.Pass, preset);
          gpu.Pass->SetUseComputeShaders(compute);
          gpu.Pass->SetFloatPrecision(precision);
          vtkBloomParameters* p = gpu.Pass->GetParameters();
          p->SetSkipEmptyBloom(false);
          p->SetRestrictToBrightRegion(false);
          vtkSmartPointer<vtkImageData> full = gpu.Apply(input);
          EXPECT_EQ(gpu.Pass->GetLastFrame()->GetChainCoverage(), 1.0) << what;
          p->SetRestrictToBrightRegion(true);
          vtkSmartPointer<vtkImageData> restricted = gpu.Apply(input);
          EXPECT_TRUE(SameBits(full, restricted)) << what;
          const double coverage = gpu.Pass->GetLastFrame()->GetChainCoverage();
          EXPECT_LE(coverage, 1.0) << what;
          int region[4];
          gpu.Pass->GetLastFrame()->GetBrightRegion(region);
          if (p->GetThresholdMode() == vtkImageBloomThreshold::NONE)
          {
            // mip-atlas: every sample is bright.
            EXPECT_EQ(coverage, 1.0) << what;
          }
          else if (c.Rects.empty())
          {
            EXPECT_EQ(coverage, 0.0) << what;
            EXPECT_EQ(region[1] - region[0], 0) << what;
          }
          else
          {
            // The bloom must reach past the spots, or the comparison would be trivial.
            EXPECT_GT(vtkBloomTest::ColourRelativeL2(full, input), 1e-3) << what;
            EXPECT_GT(coverage, 0.0) << what;
          }
          if (c.Rects.size() == 1 && preset == "default")
          {
            // Five levels from 150 x 103 down: a small spot leaves most of the chain out.
            EXPECT_LT(coverage, 0.5) << what;
          }
        }
      }
    }
  }
}

//------------------------------------------------------------------------------
// The bright region is the box of the bright pass's non-zero samples: at level 0 of a preset
// that starts at full resolution with a threshold (ping-pong), the box of the spots themselves.
TEST(RenderingBloomPassRegion, BrightRegionIsTheBoxOfTheBrightSamples)
{
  vtkSmartPointer<vtkImageData> input =
    SparseImage(301, 207, { { 200, 205, 60, 64 }, { 17, 20, 150, 151 } });
  for (const char* preset : { "ping-pong" })
  {
    Gpu gpu;
    UsePreset(gpu.Pass, preset);
    ASSERT_EQ(gpu.Pass->GetParameters()->GetStartLevel(), 0) << preset;
    gpu.Apply(input);
    int region[4];
    gpu.Pass->GetLastFrame()->GetBrightRegion(region);
    EXPECT_EQ(region[0], 17) << preset;
    EXPECT_EQ(region[1], 205) << preset;
    EXPECT_EQ(region[2], 60) << preset;
    EXPECT_EQ(region[3], 151) << preset;
  }
}

//------------------------------------------------------------------------------
// A rendered frame into the window (the composite at the renderer's viewport, with its zero-
// bloom rectangles), restricted and full: the same bits.
TEST(RenderingBloomPassRegion, RenderedFrameIsBitIdentical)
{
  std::vector<vtkSmartPointer<vtkImageData>> results;
  for (const bool restrict : { false, true })
  {
    vtkNew<vtkRenderWindow> window;
    vtkNew<vtkRenderer> renderer;
    vtkNew<vtkBloomPass> bloom;
    vtkNew<vtkRenderStepsPass> steps;
    window->SetOffScreenRendering(1);
    window->SetMultiSamples(0);
    window->SetSize(240, 160);
    window->AddRenderer(renderer);
    bloom->SetDelegatePass(steps);
    renderer->SetPass(bloom);
    ASSERT_TRUE(vtkBloomBuildExampleScene("field-lines", renderer, bloom));
    bloom->GetParameters()->SetRestrictToBrightRegion(restrict);
    bloom->CaptureResultOn();
    window->Render();
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    results.push_back(vtkSmartPointer<vtkImageData>::New());
    ASSERT_TRUE(bloom->ReadResultImage(results.back()));
    bloom->ReleaseGraphicsResources(window);
  }
  EXPECT_TRUE(SameBits(results[0], results[1]));
}

//------------------------------------------------------------------------------
// A small pass in one draw, its operators from their tables
// (vtkBloomPassTesting::SetSingleDrawSamples, the default at this size on a GPU), and every pass in
// pieces (periodic interiors from uniform weights, borders from the tables): the same weights, taps
// and order, so the same bits, for every preset, as compute and as fragment passes.
TEST(RenderingBloomPassRegion, SingleDrawsGiveTheSameBits)
{
  vtkSmartPointer<vtkImageData> input =
    SparseImage(301, 207, { { 100, 160, 60, 90 }, { 20, 24, 150, 170 }, { 250, 251, 10, 11 } });
  for (const std::string& preset : Presets())
  {
    for (const bool compute : { true, false })
    {
      Gpu gpu;
      UsePreset(gpu.Pass, preset);
      gpu.Pass->SetFloatPrecisionTo32Bit();
      gpu.Pass->SetUseComputeShaders(compute);
      vtkBloomPassTesting::SetSingleDrawSamples(
        gpu.Pass, 512 * 512); // the automatic value is 0 on llvmpipe
      vtkSmartPointer<vtkImageData> single = gpu.Apply(input);
      vtkBloomPassTesting::SetSingleDrawSamples(gpu.Pass, 0);
      vtkSmartPointer<vtkImageData> pieces = gpu.Apply(input);
      EXPECT_TRUE(SameBits(single, pieces)) << preset << (compute ? ", compute" : ", fragment");
    }
  }
}

//------------------------------------------------------------------------------
// A separable pair of passes as one tiled compute dispatch
// (vtkBloomPassTesting::SetFuseSeparablePasses: the x sums in shared memory) and as two passes
// through a target: the same bits, for every preset, with either precision of the scene (the exact
// chain's own targets are 32-bit floats), full and restricted to the bright region (whose tiles
// start at the region, not at 0); and the default chain runs in fewer passes.
TEST(RenderingBloomPassRegion, FusedSeparablePassesGiveTheSameBits)
{
  vtkSmartPointer<vtkImageData> input =
    SparseImage(301, 207, { { 100, 160, 60, 90 }, { 20, 24, 150, 170 }, { 250, 251, 10, 11 } });
  for (const std::string& preset : Presets())
  {
    for (const int precision : { vtkBloomPass::FLOAT32, vtkBloomPass::FLOAT16 })
    {
      for (const bool restrict : { false, true })
      {
        const std::string what =
          preset + ", float" + std::to_string(precision) + (restrict ? ", restricted" : ", full");
        Gpu gpu;
        UsePreset(gpu.Pass, preset);
        gpu.Pass->SetFloatPrecision(precision);
        gpu.Pass->GetParameters()->SetRestrictToBrightRegion(restrict);
        vtkBloomPassTesting::SetSingleDrawSamples(
          gpu.Pass, 512 * 512); // the automatic value is 0 on llvmpipe
        vtkBloomPassTesting::SetFuseSeparablePasses(gpu.Pass, true);
        vtkSmartPointer<vtkImageData> fused = gpu.Apply(input);
        const int fusedPasses = gpu.Pass->GetLastFrame()->GetNumberOfPasses();
        vtkBloomPassTesting::SetFuseSeparablePasses(gpu.Pass, false);
        vtkSmartPointer<vtkImageData> pairs = gpu.Apply(input);
        const int pairPasses = gpu.Pass->GetLastFrame()->GetNumberOfPasses();
        EXPECT_TRUE(SameBits(fused, pairs)) << what;
        std::cout << "[ fused ] " << what << ": " << fusedPasses << " passes (" << pairPasses
                  << " as pairs)\n";
        if (!restrict) // a restricted chain's passes depend on its probes
        {
          EXPECT_LE(fusedPasses, pairPasses) << what;
        }
        if (preset == "default" && !restrict && vtkBloomTestComputePassesRun())
        {
          // Each level's blur, downsample tent and upsample is one pass fewer.
          EXPECT_LE(fusedPasses + 10, pairPasses) << what;
        }
      }
    }
  }
}

//------------------------------------------------------------------------------
// The chain as compute shaders and as fragment passes (UseComputeShaders): the same sums, so
// the pass agrees to float rounding, for every preset; and where the pass runs compute passes
// in this context (every CI leg: VTKBLOOM_EXPECT_COMPUTE) they do run here.
TEST(RenderingBloomPassCompute, ComputeAndFragmentPassesAgree)
{
  vtkSmartPointer<vtkImageData> input =
    SparseImage(301, 207, { { 100, 160, 60, 90 }, { 20, 24, 150, 170 }, { 250, 251, 10, 11 } });
  for (const std::string& preset : Presets())
  {
    const std::string& what = preset;
    Gpu gpu;
    UsePreset(gpu.Pass, preset);
    gpu.Pass->SetFloatPrecisionTo32Bit();
    gpu.Pass->UseComputeShadersOff();
    vtkSmartPointer<vtkImageData> fragment = gpu.Apply(input);
    EXPECT_EQ(gpu.Pass->GetLastFrame()->GetComputePasses(), 0) << what;
    gpu.Pass->UseComputeShadersOn();
    vtkSmartPointer<vtkImageData> compute = gpu.Apply(input);
    if (vtkBloomTestComputePassesRun())
    {
      // Every pass but the bright pass (under the occlusion query with the content-aware
      // chain off; here it is on) and the composite.
      EXPECT_GE(gpu.Pass->GetLastFrame()->GetComputePasses(),
        gpu.Pass->GetLastFrame()->GetNumberOfPasses() - 1)
        << what;
    }
    EXPECT_LE(vtkBloomTest::ColourRelativeL2(compute, fragment), 1e-6) << what;
    EXPECT_GT(vtkBloomTest::ColourRelativeL2(fragment, input), 1e-3) << what;
  }
}

//------------------------------------------------------------------------------
// Whether the context can write a framebuffer's colour texture from a compute pass (OpenGL
// 4.5, vtkBloomPassChainRunner::FramebufferImage).
bool ComposesByCompute()
{
  GLint major = 0, minor = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  return major * 10 + minor >= 45;
}

//------------------------------------------------------------------------------
// The composite writes the framebuffer the pass was called with. Into VTK's render
// framebuffer without multisampling (a texture) it is a compute pass that writes at the
// renderer's origin; with multisampling a fragment pass, then the edges' samples composited
// one by one (their mean is the captured result). Either way the window holds the captured
// float result converted to 8 bits (GL leaves the rounding of a half to the implementation:
// within 1 level of round-to-nearest), and the renderer beside it keeps its
// pixels. The window's multisampling reaches the scene (KeepsMultisampling), so the two
// results differ at the spheres' edges.
TEST(RenderingBloomPassCompute, CompositeWritesTheWindowAsFragmentsWould)
{
  const int width = 160, height = 90, left = 40; // the bloom's renderer: x >= left
  std::vector<float> results[2];
  for (const int samples : { 0, 4 })
  {
    vtkNew<vtkRenderWindow> window;
    window->SetOffScreenRendering(1);
    window->SetMultiSamples(samples);
    window->SetSize(width, height);
    vtkNew<vtkRenderer> beside;
    beside->SetViewport(0.0, 0.0, 0.25, 1.0);
    beside->SetBackground(0.2, 0.4, 0.6);
    vtkNew<vtkRenderer> renderer;
    renderer->SetViewport(0.25, 0.0, 1.0, 1.0);
    vtkNew<vtkBloomPass> bloom;
    vtkNew<vtkRenderStepsPass> steps;
    bloom->SetDelegatePass(steps);
    ASSERT_TRUE(vtkBloomBuildExampleScene("lit-spheres", renderer, bloom));
    bloom->CaptureResultOn();
    renderer->SetPass(bloom);
    window->AddRenderer(beside);
    window->AddRenderer(renderer);
    window->Render();
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    vtkNew<vtkImageData> result;
    ASSERT_TRUE(bloom->ReadResultImage(result));
    int dims[3];
    result->GetDimensions(dims);
    ASSERT_EQ(dims[0], width - left);
    ASSERT_EQ(dims[1], height);
    vtkNew<vtkUnsignedCharArray> pixels;
    window->GetPixelData(0, 0, width - 1, height - 1, 0, pixels, 0);
    const unsigned char* rgb = pixels->GetPointer(0);
    const float* bloomed = static_cast<const float*>(result->GetScalarPointer());
    int largest = 0, lit = 0;
    const int way = samples ? 1 : 0;
    results[way].assign(bloomed, bloomed + 4 * dims[0] * dims[1]);
    for (int y = 0; y < height; ++y)
    {
      for (int x = 0; x < width; ++x)
      {
        for (int c = 0; c < 3; ++c)
        {
          const int got = rgb[3 * (y * width + x) + c];
          if (x < left)
          {
            const int background[3] = { 51, 102, 153 };
            ASSERT_EQ(got, background[c]) << x << " " << y << " " << samples;
            continue;
          }
          const float v = bloomed[4 * (y * (width - left) + x - left) + c];
          const int expected =
            static_cast<int>(std::lround(std::min(std::max(v, 0.0f), 1.0f) * 255.0f));
          largest = std::max(largest, std::abs(got - expected));
          lit += expected > 0;
        }
      }
    }
    EXPECT_LE(largest, 1) << samples;
    EXPECT_GT(lit, (width - left) * height) << samples;
    if (ComposesByCompute())
    {
      // The chain, the composite into the captured result, and the copy into the window: all
      // compute but the copy into the multisampled framebuffer and the composite of its edges'
      // samples that follows it (COMPOSITE_SAMPLES), fragment passes.
      EXPECT_EQ(bloom->GetLastFrame()->GetComputePasses(),
        bloom->GetLastFrame()->GetNumberOfPasses() - (samples ? 2 : 0))
        << samples;
    }
    bloom->ReleaseGraphicsResources(window);
  }
  EXPECT_FALSE(results[0] == results[1]) << "the window's multisampling must reach the scene";
}

//------------------------------------------------------------------------------
// Into another pass's float framebuffer (vtkFramebufferPass, RGBA32F), the composite writes
// what it writes into the captured result, bit for bit where both are compute passes.
TEST(RenderingBloomPassCompute, CompositeIntoAFloatFramebufferIsTheResult)
{
  const int width = 120, height = 80;
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(width, height);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  vtkNew<vtkBloomPass> bloom;
  vtkNew<vtkRenderStepsPass> steps;
  bloom->SetDelegatePass(steps);
  ASSERT_TRUE(vtkBloomBuildExampleScene("field-lines", renderer, bloom));
  vtkNew<vtkFramebufferPass> framebuffer;
  framebuffer->SetColorFormat(vtkTextureObject::Float32);
  framebuffer->SetDelegatePass(bloom);
  renderer->SetPass(framebuffer);

  // The composite straight into vtkFramebufferPass's texture, then into the captured result.
  window->Render();
  const int passes = bloom->GetLastFrame()->GetNumberOfPasses(),
            computed = bloom->GetLastFrame()->GetComputePasses();
  std::vector<float> direct(static_cast<size_t>(width) * height * 4);
  vtkTextureObject* texture = framebuffer->GetColorTexture();
  ASSERT_EQ(texture->GetWidth(), static_cast<unsigned int>(width));
  texture->Bind();
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, direct.data());
  texture->Deactivate();
  bloom->CaptureResultOn();
  window->Render();
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  vtkNew<vtkImageData> result;
  ASSERT_TRUE(bloom->ReadResultImage(result));
  const float* captured = static_cast<const float*>(result->GetScalarPointer());
  double num = 0.0, den = 0.0;
  int above = 0;
  for (size_t i = 0; i < direct.size(); ++i)
  {
    num += (static_cast<double>(direct[i]) - captured[i]) * (direct[i] - captured[i]);
    den += static_cast<double>(captured[i]) * captured[i];
    above += (i % 4 != 3 && captured[i] > 1.0f) ? 1 : 0;
  }
  EXPECT_GT(above, 0) << "the result must be HDR, or the float framebuffer is not exercised";
  EXPECT_LE(std::sqrt(num / den), 1e-6);
  if (ComposesByCompute())
  {
    EXPECT_EQ(computed, passes);
    EXPECT_EQ(std::memcmp(direct.data(), captured, direct.size() * sizeof(float)), 0);
  }
  bloom->ReleaseGraphicsResources(window);
  framebuffer->ReleaseGraphicsResources(window);
}

//------------------------------------------------------------------------------
// A dense region is measured on the first render, then once in 8 renders while it pays. Once
// the GPU's timestamps say it costs more than the full chain, it is never measured again, so
// that no frame waits for the GPU while the others do not. Every render gives the same bits.
TEST(RenderingBloomPassRegion, DenseRegionIsMeasuredEveryEighthRenderWhileItPays)
{
  // A bright half: the default preset's region then covers well over a quarter of the chain.
  vtkSmartPointer<vtkImageData> input = SparseImage(160, 96, { { 0, 80, 0, 96 } });
  Gpu gpu;
  vtkSmartPointer<vtkImageData> first;
  bool declined = false;
  for (int render = 0; render < 20; ++render)
  {
    const double regionCost = gpu.Pass->GetLastFrame()->GetRegionCost(),
                 fullCost = gpu.Pass->GetLastFrame()->GetFullCost();
    declined = declined || (regionCost >= 0.0 && fullCost >= 0.0 && regionCost > fullCost);
    vtkSmartPointer<vtkImageData> output = gpu.Apply(input);
    int region[4];
    gpu.Pass->GetLastFrame()->GetBrightRegion(region);
    const bool measured = region[1] > region[0];
    if (render % 8 != 0 || render == 0)
    {
      EXPECT_EQ(measured, render == 0) << "render " << render;
    }
    if (declined)
    {
      EXPECT_FALSE(measured) << "render " << render << ": the region no longer pays";
    }
    if (measured)
    {
      EXPECT_GE(gpu.Pass->GetLastFrame()->GetChainCoverage(), 0.25) << "render " << render;
    }
    else
    {
      EXPECT_EQ(gpu.Pass->GetLastFrame()->GetChainCoverage(), 1.0) << "render " << render;
    }
    if (!first)
    {
      first = output;
    }
    EXPECT_TRUE(SameBits(first, output)) << "render " << render;
  }
}

//------------------------------------------------------------------------------
// A small region is measured on the first render, whose cost is not known yet. Later renders
// follow what the GPU's timestamps say the region costs against the full chain: measured
// every render while it pays, never again once it does not; either way the 4th render runs the
// full chain (the timing's own probe, then one render in 32). Every render gives the same bits.
TEST(RenderingBloomPassRegion, SmallRegionFollowsItsMeasuredCost)
{
  vtkSmartPointer<vtkImageData> input = SparseImage(960, 540, { { 470, 476, 260, 264 } });
  Gpu gpu;
  vtkSmartPointer<vtkImageData> first;
  int full = 0;
  for (int render = 0; render < 40; ++render)
  {
    vtkSmartPointer<vtkImageData> output = gpu.Apply(input);
    int region[4];
    gpu.Pass->GetLastFrame()->GetBrightRegion(region);
    const bool measured = region[1] > region[0];
    if (render == 0)
    {
      EXPECT_TRUE(measured);
    }
    if (render == 3)
    {
      EXPECT_FALSE(measured);
    }
    if (measured)
    {
      EXPECT_LT(gpu.Pass->GetLastFrame()->GetChainCoverage(), 0.25) << "render " << render;
    }
    else
    {
      EXPECT_EQ(gpu.Pass->GetLastFrame()->GetChainCoverage(), 1.0) << "render " << render;
      ++full;
    }
    if (!first)
    {
      first = output;
    }
    EXPECT_TRUE(SameBits(first, output)) << "render " << render;
  }
  EXPECT_GE(full, 1);
}

namespace
{
// Counts the warnings and errors an object sends.
class WarningLog : public vtkCommand
{
public:
  static WarningLog* New() { return new WarningLog; }
  void Execute(vtkObject*, unsigned long, void*) override { ++this->Count; }
  int Count = 0;
};
}

//------------------------------------------------------------------------------
/// lit-spheres in a 160 x 90 window without samples, the pass the renderer's own and its result
/// captured; Result() reads it and frees the pass's resources.
struct LitSpheres
{
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkBloomPass> Bloom;
  vtkNew<vtkRenderStepsPass> Steps;

  bool Build()
  {
    this->Window->SetOffScreenRendering(1);
    this->Window->SetMultiSamples(0);
    this->Window->SetSize(160, 90);
    this->Bloom->SetDelegatePass(this->Steps);
    if (!vtkBloomBuildExampleScene("lit-spheres", this->Renderer, this->Bloom))
    {
      return false;
    }
    this->Bloom->CaptureResultOn();
    this->Renderer->SetPass(this->Bloom);
    this->Window->AddRenderer(this->Renderer);
    return true;
  }

  std::vector<float> Result()
  {
    vtkNew<vtkImageData> result;
    std::vector<float> values;
    if (this->Bloom->ReadResultImage(result))
    {
      const float* first = static_cast<const float*>(result->GetScalarPointer());
      values.assign(first, first + 4 * result->GetNumberOfPoints());
    }
    this->Bloom->ReleaseGraphicsResources(this->Window);
    return values;
  }
};

//------------------------------------------------------------------------------
// A compute variant that does not build falls back to the fragment pass: one warning over
// several frames, no OpenGL error, no more compute passes than with compute shaders off (the
// bright region's reduction has its own program and fallback), and the same result, bit for bit
// (both are fragment passes then).
TEST(RenderingBloomPassCompute, FailedComputeProgramFallsBackToFragments)
{
  std::vector<float> results[2];
  int computePasses[2] = { 0, 0 };
  for (const bool simulate : { false, true })
  {
    LitSpheres run;
    ASSERT_TRUE(run.Build());
    run.Bloom->SetUseComputeShaders(simulate); // off: the reference fragment passes
    vtkBloomPassTesting::SetSimulateComputeShaderFailure(run.Bloom, simulate);
    vtkNew<WarningLog> warnings;
    run.Bloom->AddObserver(vtkCommand::WarningEvent, warnings);
    run.Bloom->AddObserver(vtkCommand::ErrorEvent, warnings);
    for (int frame = 0; frame < 3; ++frame)
    {
      run.Window->Render();
      EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
      computePasses[simulate ? 1 : 0] = run.Bloom->GetLastFrame()->GetComputePasses();
    }
    EXPECT_EQ(warnings->Count, simulate && ComposesByCompute() ? 1 : 0);
    results[simulate ? 1 : 0] = run.Result();
  }
  ASSERT_FALSE(results[0].empty());
  EXPECT_TRUE(results[0] == results[1]);
  EXPECT_EQ(computePasses[1], computePasses[0]);
}

//------------------------------------------------------------------------------
// VTK 9.6's EGL window asks for OpenGL 3.2, and NVIDIA's driver gives exactly 3.2, with every
// extension of the card: the compute passes run there through GL_ARB_compute_shader and its
// companions. Rendering.cmake registers this test with Mesa told to report OpenGL 3.3
// (MESA_GL_VERSION_OVERRIDE) and VTKBLOOM_EXPECT_OLDER_CONTEXT set; in a 4.3 context it has
// nothing to show and skips (on Mesa, where the override applies, it fails instead).
TEST(RenderingBloomPassCompute, OlderContextWithTheExtensions)
{
  std::vector<float> results[2];
  int computePasses[2] = { 0, 0 };
  int version = 0;
  bool mesa = false;
  for (const bool compute : { false, true })
  {
    LitSpheres run;
    ASSERT_TRUE(run.Build());
    run.Bloom->SetUseComputeShaders(compute);
    run.Window->Render();
    GLint major = 0, minor = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    version = major * 10 + minor;
    const auto* text = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    mesa = text && std::strstr(text, "Mesa");
    computePasses[compute ? 1 : 0] = run.Bloom->GetLastFrame()->GetComputePasses();
    results[compute ? 1 : 0] = run.Result();
  }
  if (version >= 43)
  {
    // MESA_GL_VERSION_OVERRIDE is Mesa's: another driver (NVIDIA's, on the GPU machine) keeps
    // its own version, and the test has nothing older to show there.
    ASSERT_TRUE(!mesa || !std::getenv("VTKBLOOM_EXPECT_OLDER_CONTEXT"))
      << "Mesa's context has OpenGL " << version / 10 << "." << version % 10
      << ", not the older one MESA_GL_VERSION_OVERRIDE asked for";
    GTEST_SKIP() << "an OpenGL " << version / 10 << "." << version % 10
                 << " context: nothing older to show";
  }
  EXPECT_EQ(computePasses[0], 0);
  EXPECT_GT(computePasses[1], 0) << "OpenGL " << version / 10 << "." << version % 10
                                 << " with the compute extensions ran no compute pass";
  double difference = 0.0, norm = 0.0;
  for (size_t i = 0; i < results[0].size() && i < results[1].size(); ++i)
  {
    difference += (results[1][i] - results[0][i]) * (results[1][i] - results[0][i]);
    norm += results[0][i] * results[0][i];
  }
  ASSERT_FALSE(results[0].empty());
  ASSERT_EQ(results[0].size(), results[1].size());
  EXPECT_LE(std::sqrt(difference / std::max(norm, 1e-30)), 1e-6);
}
