// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// Tests of vtkBloomPass: GPU/CPU agreement per preset on the float render, shared parameters,
// selective bloom, chaining with tone mapping, GL errors and resource stability over many frames
// with resizes, the profile, regression images, non-finite input. What live scenes need
// (multisampling, alpha, resolution, the field lines) is in TestBloomPassLiveScenes.cxx.
#include "vtkBloomExampleScenes.h"
#include "vtkBloomPass.h"
#include "vtkBloomPassTestWindow.h"
#include "vtkBloomPassTesting.h"
#include "vtkBloomTestSupport.h"

#include "vtkActor.h"
#include "vtkBloomVTKCompat.h"
#include "vtkCamera.h"
#include "vtkCameraPass.h"
#include "vtkDoubleArray.h"
#include "vtkImageBloom.h"
#include "vtkImageBloomThreshold.h"
#include "vtkImageData.h"
#include "vtkLookupTable.h"
#include "vtkNew.h"
#include "vtkOpenEXRReader.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPointData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkTesting.h"
#include "vtkToneMappingPass.h"
#include "vtkUnsignedCharArray.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace
{
// The image of an OpenEXR file.
vtkSmartPointer<vtkImageData> ReadExr(const std::string& path)
{
  vtkNew<vtkOpenEXRReader> reader;
  reader->SetFileName(path.c_str());
  return vtkBloomTest::UpdateAndCopy(reader);
}

// Largest value of channel c.
double MaxChannel(vtkImageData* image, int c)
{
  double m = -VTK_DOUBLE_MAX;
  for (vtkIdType p = 0; p < image->GetNumberOfPoints(); ++p)
  {
    m = std::max(m, image->GetPointData()->GetScalars()->GetComponent(p, c));
  }
  return m;
}

// GPU result vs vtkImageBloom on the same float render, for one preset and precision.
double PresetAgreement(const std::string& preset, int precision, const std::string& scene,
  int width = 301, int height = 207)
{
  BloomWindow w(width, height);
  EXPECT_TRUE(vtkBloomBuildExampleScene(scene, w.Renderer, w.Bloom));
  w.Bloom->SetEmissionSourceToScene();
  EXPECT_TRUE(w.Bloom->SetPreset(preset.c_str()));
  w.Bloom->SetFloatPrecision(precision);
  w.Bloom->CaptureResultOn();
  w.Window->Render();
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  vtkNew<vtkImageData> sceneImage, gpu;
  EXPECT_TRUE(w.Bloom->ReadSceneImage(sceneImage));
  EXPECT_TRUE(w.Bloom->ReadResultImage(gpu));
  EXPECT_GT(w.Bloom->GetLastFrame()->GetNumberOfPasses(), 0);

  // The scene must actually be HDR, or the test would not exercise the float path.
  EXPECT_GT(MaxChannel(sceneImage, 0), 1.5) << "the scene has nothing above 1";

  // The filter evaluates the pass's own parameters: one set, shared.
  vtkNew<vtkImageBloom> cpu;
  cpu->SetParameters(w.Bloom->GetParameters());
  cpu->SetInputData(sceneImage);
  cpu->Update();
  const double error = vtkBloomTest::ColourRelativeL2(gpu, cpu->GetOutput());
  // The bloom must change the image, or agreement would be trivial.
  EXPECT_GT(vtkBloomTest::ColourRelativeL2(sceneImage, cpu->GetOutput()), 1e-3);
  return error;
}
}

//------------------------------------------------------------------------------
TEST(RenderingBloomPass, AgreesWithTheCPUFilterForEveryPresetInFloat32)
{
  for (const auto& preset : vtkImageBloom::GetPresetNames())
  {
    const double error = PresetAgreement(preset, vtkBloomPass::FLOAT32, "lit-spheres");
    EXPECT_LE(error, 1e-3) << preset;
    std::cout << "[ float32 ] " << preset << " relative L2 " << error << "\n";
  }
}

//------------------------------------------------------------------------------
TEST(RenderingBloomPass, AgreesWithTheCPUFilterForEveryPresetInFloat16)
{
  for (const auto& preset : vtkImageBloom::GetPresetNames())
  {
    const double error = PresetAgreement(preset, vtkBloomPass::FLOAT16, "lit-spheres");
    EXPECT_LE(error, 1e-3) << preset;
    std::cout << "[ float16 ] " << preset << " relative L2 " << error << "\n";
  }
}

//------------------------------------------------------------------------------
// At even sizes the 2:1 and 1:2 resamples are periodic, so their interiors run from uniform
// weights and First computed in the shader (odd sizes run them from the operator tables).
TEST(RenderingBloomPass, AgreesWithTheCPUFilterAtAnEvenSize)
{
  for (const auto& preset : vtkImageBloom::GetPresetNames())
  {
    const double error = PresetAgreement(preset, vtkBloomPass::FLOAT32, "lit-spheres", 320, 192);
    EXPECT_LE(error, 1e-3) << preset;
    std::cout << "[ 320x192 ] " << preset << " relative L2 " << error << "\n";
  }
}

//------------------------------------------------------------------------------
// Nothing above the threshold: the pass skips the chain after the bright pass (an occlusion
// query counts its non-zero samples) and writes the scene, bit for bit what the whole chain
// gives with SkipEmptyBloom off, as vtkImageBloom does.
TEST(RenderingBloomPass, SkipsAnEmptyBloomExactly)
{
  vtkNew<vtkImageData> scene, skipped, computed;
  for (const bool skip : { true, false })
  {
    BloomWindow w(160, 96);
    ASSERT_TRUE(vtkBloomBuildExampleScene("lit-spheres", w.Renderer, w.Bloom));
    w.Bloom->SetEmissionSourceToScene();
    w.Bloom->SetFloatPrecisionTo32Bit();
    w.Bloom->CaptureResultOn();
    vtkBloomParameters* p = w.Bloom->GetParameters();
    p->SetThreshold(1e30);
    p->SetSkipEmptyBloom(skip);
    // The occlusion query's path; the bright region's reduction (RestrictToBrightRegion) has
    // its own tests in TestBloomPassRegion.cxx.
    p->SetRestrictToBrightRegion(false);
    w.Window->Render();
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    EXPECT_EQ(w.Bloom->GetLastFrame()->GetBloomSkipped(), skip);
    if (skip)
    {
      // The bright pass, the composite and the copy of the captured result.
      EXPECT_EQ(w.Bloom->GetLastFrame()->GetNumberOfPasses(), 3);
      ASSERT_TRUE(w.Bloom->ReadSceneImage(scene));
      ASSERT_TRUE(w.Bloom->ReadResultImage(skipped));
      vtkNew<vtkImageBloom> cpu;
      cpu->SetParameters(p);
      cpu->SetInputData(scene);
      cpu->Update();
      EXPECT_TRUE(cpu->GetLastBloomSkipped());
      EXPECT_EQ(vtkBloomTest::ColourRelativeL2(skipped, cpu->GetOutput()), 0.0);
    }
    else
    {
      EXPECT_GT(w.Bloom->GetLastFrame()->GetNumberOfPasses(), 10);
      ASSERT_TRUE(w.Bloom->ReadResultImage(computed));
    }
  }
  ASSERT_EQ(skipped->GetNumberOfPoints(), computed->GetNumberOfPoints());
  EXPECT_EQ(std::memcmp(skipped->GetScalarPointer(), computed->GetScalarPointer(),
              sizeof(float) * 4 * skipped->GetNumberOfPoints()),
    0);
  EXPECT_GT(MaxChannel(scene, 0), 1.0) << "the scene is HDR, only below the threshold";
}

//------------------------------------------------------------------------------
// The GPU chain on an image (ApplyToImage) matches the shared presets' float64 expectations as
// closely as the CPU filter does: the same operators, evaluated in float32.
TEST(RenderingBloomPass, ApplyToImageMatchesThePresetExamples)
{
  VTKBLOOM_REQUIRE_DATA(input, "presets/example_161x91.exr");
  vtkSmartPointer<vtkImageData> image = ReadExr(input);
  BloomWindow w(16, 16);
  w.Bloom->SetFloatPrecisionTo32Bit(); // the image is stored at the pass's precision
  for (const auto& preset : vtkImageBloom::GetPresetNames())
  {
    vtkNew<vtkOpenEXRReader> expectedReader;
    expectedReader->SetFileName(
      vtkBloomTest::SharedDataPath("presets/example_161x91__" + preset + ".exr").c_str());
    expectedReader->Update();
    ASSERT_TRUE(w.Bloom->SetPreset(preset.c_str()));
    vtkNew<vtkImageData> gpu;
    ASSERT_TRUE(w.Bloom->ApplyToImage(w.GL(), image, gpu));
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    const double error = vtkBloomTest::ColourRelativeL2(gpu, expectedReader->GetOutput());
    EXPECT_LE(error, 1e-5) << preset;
    std::cout << "[ presets ] " << preset << " relative L2 vs float64 " << error << "\n";
  }
}

//------------------------------------------------------------------------------
// One parameter set: a pass given parameters made before its chain was built (an older
// modification time) still rebuilds its chain for them, and a filter sharing them computes the
// same bloom; an edit through the filter reaches the pass.
TEST(RenderingBloomPass, SharedParametersDriveThePassAndTheFilter)
{
  VTKBLOOM_REQUIRE_DATA(input, "presets/example_161x91.exr");
  vtkSmartPointer<vtkImageData> image = ReadExr(input);
  vtkNew<vtkImageBloom> cpu;
  cpu->SetPreset("crt-halfres"); // older than the chain the pass is about to build
  cpu->SetExecutionModeToReference();
  cpu->SetInputData(image);
  BloomWindow w(16, 16);
  w.Bloom->SetFloatPrecisionTo32Bit();
  vtkNew<vtkImageData> defaults, shared;
  ASSERT_TRUE(w.Bloom->ApplyToImage(w.GL(), image, defaults));
  w.Bloom->SetParameters(cpu->GetParameters());
  EXPECT_EQ(w.Bloom->GetParameters(), cpu->GetParameters());
  for (const double strength : { 1.5 /* the preset's own: no edit */, 0.25 })
  {
    cpu->GetParameters()->SetStrength(strength);
    ASSERT_TRUE(w.Bloom->ApplyToImage(w.GL(), image, shared));
    cpu->Update();
    EXPECT_LE(vtkBloomTest::ColourRelativeL2(shared, cpu->GetOutput()), 1e-5) << strength;
    EXPECT_GT(vtkBloomTest::ColourRelativeL2(shared, defaults), 1e-3) << strength;
  }
}

//------------------------------------------------------------------------------
// Selective bloom: an emitter hidden behind an opaque wall adds nothing; in front it glows.
TEST(RenderingBloomPass, OccludedEmittersDoNotGlow)
{
  for (const bool inFront : { false, true })
  {
    BloomWindow w(160, 120);
    vtkNew<vtkSphereSource> wallSource;
    wallSource->SetRadius(3.0);
    wallSource->SetCenter(0.0, 0.0, inFront ? -6.0 : 0.0);
    vtkNew<vtkPolyDataMapper> wallMapper;
    wallMapper->SetInputConnection(wallSource->GetOutputPort());
    vtkNew<vtkActor> wall;
    wall->SetMapper(wallMapper);
    wall->GetProperty()->SetColor(0.2, 0.2, 0.2);
    vtkNew<vtkSphereSource> lampSource;
    lampSource->SetRadius(0.5);
    lampSource->SetCenter(0.0, 0.0, -1.0);
    vtkNew<vtkPolyDataMapper> lampMapper;
    lampMapper->SetInputConnection(lampSource->GetOutputPort());
    vtkNew<vtkActor> lamp;
    lamp->SetMapper(lampMapper);
    lamp->GetProperty()->SetAmbient(1.0);
    lamp->GetProperty()->SetDiffuse(0.0);
    lamp->GetProperty()->SetAmbientColor(20.0, 10.0, 5.0);
    w.Renderer->AddActor(wall);
    w.Renderer->AddActor(lamp);
    w.Renderer->GetActiveCamera()->SetPosition(0.0, 0.0, 20.0);
    w.Renderer->GetActiveCamera()->SetFocalPoint(0.0, 0.0, 0.0);
    w.Bloom->SetPreset("webgpu-market");
    w.Bloom->AddEmitter(lamp);
    w.Bloom->SetEmissionSourceToEmitters();
    w.Bloom->SetFloatPrecisionTo32Bit();
    w.Bloom->CaptureResultOn();
    w.Window->Render();
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    vtkNew<vtkImageData> sceneImage, result;
    ASSERT_TRUE(w.Bloom->ReadSceneImage(sceneImage));
    ASSERT_TRUE(w.Bloom->ReadResultImage(result));
    const double change = vtkBloomTest::ColourRelativeL2(result, sceneImage);
    if (inFront)
    {
      EXPECT_GT(change, 0.05) << "a visible emitter must glow";
    }
    else
    {
      EXPECT_EQ(change, 0.0) << "an emitter behind the wall must add nothing";
    }
  }
}

//------------------------------------------------------------------------------
// Bloom in linear HDR, then tone mapping: vtkToneMappingPass's delegate is the bloom pass.
TEST(RenderingBloomPass, ChainsWithToneMapping)
{
  double mean[2] = { 0.0, 0.0 };
  for (const bool bloom : { false, true })
  {
    BloomWindow w(240, 160);
    ASSERT_TRUE(vtkBloomBuildExampleScene("lit-spheres", w.Renderer, w.Bloom));
    vtkNew<vtkToneMappingPass> toneMapping;
    toneMapping->SetToneMappingType(vtkToneMappingPass::GenericFilmic);
    toneMapping->SetGenericFilmicDefaultPresets();
    toneMapping->SetDelegatePass(w.Bloom);
    w.Renderer->SetPass(toneMapping);
    w.Bloom->GetParameters()->SetStrength(bloom ? 1.0 : 0.0);
    w.Window->Render();
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    vtkNew<vtkUnsignedCharArray> pixels;
    w.Window->GetPixelData(0, 0, 239, 159, 0, pixels, 0);
    const vtkIdType n = pixels->GetNumberOfValues();
    for (vtkIdType i = 0; i < n; ++i)
    {
      mean[bloom] += pixels->GetValue(i) / static_cast<double>(n);
    }
    if (bloom)
    {
      EXPECT_GT(w.Bloom->GetLastFrame()->GetNumberOfPasses(), 10);
    }
    else
    {
      // Strength 0 switches the effect off: no chain, only the composite (SkipDisabledEffects).
      EXPECT_TRUE(w.Bloom->GetLastFrame()->GetBloomSkipped());
      EXPECT_EQ(w.Bloom->GetLastFrame()->GetNumberOfPasses(), 1);
    }
  }
  // Tone mapping compresses highlights, so the glow must still show as added light.
  EXPECT_GT(mean[1], mean[0] + 1.0);
  EXPECT_LT(mean[1], 250.0);
}

//------------------------------------------------------------------------------
// 500 frames with a resize every 25: no GL error, no growth of memory, and the same chain at
// every frame of a size. Every resize remakes about 10 MB of targets, so a leak of any of them
// over the 16 resizes after the warm-up would exceed the bound many times over.
TEST(RenderingBloomPass, NoErrorsOrGrowthOverManyFramesWithResizes)
{
  BloomWindow w(240, 160);
  ASSERT_TRUE(vtkBloomBuildExampleScene("field-lines", w.Renderer, w.Bloom));
  w.Bloom->CaptureResultOn();
  long rssAfterWarmUp = 0;
  // Whether a frame measures the bright region (its reduction adds passes) follows the GPU's
  // timings of the two chains (vtkBloomFrameReport::GetRegionCost), which another process's
  // load changes. So the passes are compared between frames of one size and one choice: the
  // first such frame's count, against which every later one must agree.
  std::map<std::pair<int, bool>, int> passesOf;
  int compared = 0;
  for (int frame = 0; frame < 500; ++frame)
  {
    const int k = (frame / 25) % 4;
    if (frame % 25 == 0)
    {
      w.Window->SetSize(240 + 37 * k, 160 + 23 * k);
    }
    w.Window->Render();
    ASSERT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR)) << "frame " << frame;
    vtkBloomFrameReport* report = w.Bloom->GetLastFrame();
    ASSERT_FALSE(report->GetBloomSkipped()) << "frame " << frame;
    const int* region = report->GetBrightRegion();
    const auto key = std::make_pair(k, region[1] > region[0]);
    const auto known = passesOf.emplace(key, report->GetNumberOfPasses());
    if (!known.second)
    {
      ASSERT_EQ(report->GetNumberOfPasses(), known.first->second)
        << "frame " << frame << ", size " << k << ", region measured " << key.second;
      ++compared;
    }
    if (frame == 99)
    {
      rssAfterWarmUp = vtkBloomTest::ResidentKiB();
    }
  }
  // Four sizes, each with at most two choices: every other frame was compared.
  EXPECT_GE(compared, 500 - 8);
  // AddressSanitizer keeps freed blocks in its quarantine (capped at 32 MB for these tests by
  // Testing/CMakeLists.txt), which shows as resident memory; a leak would be ~160 MB.
#ifdef __SANITIZE_ADDRESS__
  const long boundKiB = (16 + 32) * 1024;
#else
  const long boundKiB = 16 * 1024;
#endif
  EXPECT_LT(vtkBloomTest::ResidentKiB() - rssAfterWarmUp, boundKiB) << "resident memory grew";
}

//------------------------------------------------------------------------------
// The profile (vtkBloomPassTesting::SetProfilePasses) lists every GPU pass of the render (the
// delegate's scene and emitters, the chain, the composite and the captured copy) with its
// size, traffic and GPU time, and changes nothing in the image; off, the profile is empty.
TEST(RenderingBloomPass, ProfilesEveryPassWithoutChangingTheImage)
{
  for (const char* scene : { "lit-spheres", "scalar-field", "scalar-field two renders" })
  {
    BloomWindow w(200, 120);
    const std::string name = scene;
    ASSERT_TRUE(vtkBloomBuildExampleScene(name.substr(0, name.find(' ')), w.Renderer, w.Bloom));
    w.Bloom->SetEmitInSceneRender(name.find(' ') == std::string::npos);
    w.Bloom->SetFloatPrecisionTo32Bit();
    w.Bloom->CaptureResultOn();
    vtkNew<vtkImageData> plain, profiled;
    w.Window->Render();
    // A second render of the emitters is profiled as "emitters" (scalar-field's emission is
    // written in the scene's render, unless that is off).
    const bool selective = w.Bloom->GetEmissionSource() == vtkBloomPass::EMISSION_EMITTERS &&
      !w.Bloom->GetLastFrame()->GetEmissionInSceneRender();
    ASSERT_TRUE(w.Bloom->ReadResultImage(plain));
    EXPECT_TRUE(vtkBloomPassTesting::GetProfile(w.Bloom).empty());

    vtkBloomPassTesting::SetProfilePasses(w.Bloom, true);
    w.Window->Render();
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR)) << scene;
    ASSERT_TRUE(w.Bloom->ReadResultImage(profiled));
    ASSERT_EQ(plain->GetNumberOfPoints(), profiled->GetNumberOfPoints());
    EXPECT_EQ(std::memcmp(plain->GetScalarPointer(), profiled->GetScalarPointer(),
                sizeof(float) * 4 * plain->GetNumberOfPoints()),
      0)
      << scene;

    // The chain's passes, then the frame's own spans: the scene (and the emitters) before,
    // the depth's write after it where the scene did not render into the window's depth.
    std::vector<vtkBloomPassTesting::ProfiledPass> profile =
      vtkBloomPassTesting::GetProfile(w.Bloom);
    if (!profile.empty() && profile.back().Name == "depth")
    {
      profile.pop_back();
    }
    const int n = static_cast<int>(profile.size());
    ASSERT_EQ(n, w.Bloom->GetLastFrame()->GetNumberOfPasses() + (selective ? 2 : 1)) << scene;
    EXPECT_GT(w.Bloom->GetLastFrame()->GetNumberOfPasses(), 10) << scene;
    EXPECT_EQ(profile[0].Name, "scene");
    EXPECT_EQ(profile[1].Name, selective ? "emitters" : "bright L0");
    EXPECT_EQ(profile[n - 2].Name, "composite");
    EXPECT_EQ(profile[n - 1].Name, "copy");
    double total = 0.0;
    for (int i = 0; i < n; ++i)
    {
      const vtkBloomPassTesting::ProfiledPass& pass = profile[i];
      EXPECT_FALSE(pass.Name.empty()) << i;
      EXPECT_GT(pass.Size[0], 0) << i;
      EXPECT_GT(pass.Size[1], 0) << i;
      EXPECT_LE(pass.Size[0], 200) << i;
      EXPECT_LE(pass.Size[1], 120) << i;
      // At least the target written once, in RGBA32F.
      EXPECT_GE(pass.Bytes, 16.0 * pass.Size[0] * pass.Size[1]) << i;
      EXPECT_TRUE(
        std::isfinite(pass.Milliseconds) && pass.Milliseconds >= 0.0 && pass.Milliseconds < 1e4)
        << i << " " << pass.Milliseconds;
      total += pass.Milliseconds;
    }
    EXPECT_GT(total, 0.0) << scene;

    vtkBloomPassTesting::SetProfilePasses(w.Bloom, false);
    w.Window->Render();
    EXPECT_TRUE(vtkBloomPassTesting::GetProfile(w.Bloom).empty());
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR)) << scene;
  }
}

//------------------------------------------------------------------------------
// Regression images of the three example scenes (8-bit, through vtkTesting's comparison).
TEST(RenderingBloomPass, RegressionImages)
{
  for (const auto& scene : vtkBloomExampleSceneNames())
  {
    BloomWindow w(320, 180);
    ASSERT_TRUE(vtkBloomBuildExampleScene(scene, w.Renderer, w.Bloom));
    vtkNew<vtkToneMappingPass> toneMapping;
    toneMapping->SetToneMappingType(vtkToneMappingPass::GenericFilmic);
    toneMapping->SetGenericFilmicDefaultPresets();
    toneMapping->SetDelegatePass(w.Bloom);
    w.Renderer->SetPass(toneMapping);
    w.Window->Render();
    const std::string baseline =
      std::string(VTKBLOOM_BASELINE_DIR) + "/TestBloomPass_" + scene + ".png";
    vtkNew<vtkTesting> testing;
    testing->AddArgument("-V");
    testing->AddArgument(baseline.c_str());
    testing->AddArgument("-T");
    testing->AddArgument(vtkBloomTest::OutputDirectory().c_str());
    testing->SetRenderWindow(w.Window);
    EXPECT_EQ(testing->RegressionTest(10.0), vtkTesting::PASSED) << scene << " vs " << baseline;
  }
}

//------------------------------------------------------------------------------
// NaN/Inf input on the GPU follows vtkImageBloom's policy: with SanitizeNonFinite every output
// is finite; without it a non-finite sample reaches only its own pixel, exactly where the CPU
// filter has one, and everything else agrees with the CPU filter.
TEST(RenderingBloomPass, NonFiniteInputFollowsTheCPUPolicy)
{
  VTKBLOOM_REQUIRE_DATA(path, "exr/TestImages_BrightRingsNanInf.exr");
  vtkSmartPointer<vtkImageData> image = ReadExr(path);
  BloomWindow w(16, 16);
  w.Bloom->SetFloatPrecisionTo32Bit();
  w.Bloom->SetPreset("webgpu-market");
  vtkNew<vtkImageBloom> cpu;
  cpu->SetParameters(w.Bloom->GetParameters());
  cpu->SetExecutionModeToReference();
  cpu->SetInputData(image);
  for (const bool sanitize : { true, false })
  {
    cpu->SetSanitizeNonFinite(sanitize);
    vtkNew<vtkImageData> gpu;
    ASSERT_TRUE(w.Bloom->ApplyToImage(w.GL(), image, gpu));
    cpu->Update();
    vtkDataArray* g = gpu->GetPointData()->GetScalars();
    vtkDataArray* c = cpu->GetOutput()->GetPointData()->GetScalars();
    double num = 0.0, den = 0.0;
    vtkIdType nonFinite = 0;
    for (vtkIdType p = 0; p < gpu->GetNumberOfPoints(); ++p)
    {
      for (int k = 0; k < 3; ++k)
      {
        const double x = g->GetComponent(p, k), y = c->GetComponent(p, k);
        ASSERT_EQ(std::isfinite(x), std::isfinite(y)) << "pixel " << p << " sanitize " << sanitize;
        if (sanitize)
        {
          ASSERT_TRUE(std::isfinite(x)) << p;
        }
        if (std::isfinite(x))
        {
          num += (x - y) * (x - y);
          den += y * y;
        }
        else
        {
          ++nonFinite;
        }
      }
    }
    std::cout << "sanitize " << sanitize << " relative L2 " << std::sqrt(num / den) << "\n";
    // Sanitizing, +-Inf become the largest floats before the chain on both sides.
    EXPECT_LE(std::sqrt(num / den), 1e-3);
    EXPECT_EQ(nonFinite > 0, !sanitize);
  }
  cpu->SetInputData(nullptr);
}

//------------------------------------------------------------------------------
// The scalar-range emitter keeps both ends of its range, and maps vectors as the actor does.
TEST(RenderingBloomPass, ScalarRangeEmitterIncludesItsEndsAndFollowsTheVectorMode)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->Update();
  vtkNew<vtkDoubleArray> velocity;
  velocity->SetName("Velocity");
  velocity->SetNumberOfComponents(3);
  for (vtkIdType p = 0; p < sphere->GetOutput()->GetNumberOfPoints(); ++p)
  {
    velocity->InsertNextTuple3(3.0, 4.0, 0.0); // magnitude 5, component 0 is 3
  }
  sphere->GetOutput()->GetPointData()->AddArray(velocity);
  vtkNew<vtkLookupTable> colours;
  colours->SetTableRange(0.0, 10.0);
  colours->SetVectorModeToMagnitude();
  colours->Build();
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(sphere->GetOutput());
  mapper->SetLookupTable(colours);
  mapper->SetScalarModeToUsePointFieldData();
  mapper->SelectColorArray("Velocity");
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);

  const double range[2] = { 4.0, 5.0 };
  auto emitter = vtkBloomPass::CreateScalarRangeEmitter(actor, range);
  ASSERT_NE(emitter, nullptr);
  auto* table = vtkScalarsToColors::SafeDownCast(emitter->GetMapper()->GetLookupTable());
  ASSERT_NE(table, nullptr);
  EXPECT_EQ(table->GetVectorMode(), vtkScalarsToColors::MAGNITUDE);
  // The ends glow (not black), values just outside do not.
  auto brightness = [&](double v)
  {
    double rgb[3];
    table->GetColor(v, rgb);
    return rgb[0] + rgb[1] + rgb[2];
  };
  EXPECT_GT(brightness(4.0), 0.0);
  EXPECT_GT(brightness(5.0), 0.0);
  EXPECT_EQ(brightness(3.99), 0.0);
  EXPECT_EQ(brightness(5.01), 0.0);
  // The mapped colour of the data (magnitude 5, the top end) is the actor's colour there.
  vtkSmartPointer<vtkUnsignedCharArray> mapped;
  mapped.TakeReference(table->MapScalars(velocity, VTK_COLOR_MODE_MAP_SCALARS, -1));
  unsigned char expected[3];
  std::memcpy(expected, colours->MapValue(5.0), 3);
  for (int c = 0; c < 3; ++c)
  {
    EXPECT_NEAR(mapped->GetValue(c), expected[c], 2) << c;
  }
}
