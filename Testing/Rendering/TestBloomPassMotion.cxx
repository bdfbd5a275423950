// Temporal stability of the bloom on thin, moving geometry. The camera turns by sub-pixel steps
// across a thin-line scene (the field lines) and a points scene; for every frame the scene's
// energy (the sum of its luminance) and the bloom's added energy (the sum of the luminance of
// result minus scene) are measured. Their coefficients of variation over the sweep (standard
// deviation over mean) say how much each flickers.
//
// At 480x270 the defaults' bloom flickers less than the scene on the field lines (0.7 times
// its coefficient) and about 4 times more on the points; at the 320x180 of this test, 1.1 and
// 1.9 times. On the points: a point's anti-aliased edge samples straddle the threshold, so
// the energy that passes the bright pass depends on the point's sub-pixel position. Measured
// remedies (docs/gpu.md): a Karis average or a wider knee change nothing, a bright pass at half
// resolution (a 2x2 prefilter) makes it worse, a luminance clamp of 1.5 takes a third off, and
// only a threshold far below the points' luminance (0.25) makes the bloom as steady as the
// scene. The test bounds both ratios near where they stand (1.5 and 4), so that neither can
// grow unseen.
#include "vtkBloomExampleScenes.h"
#include "vtkBloomKernels.h"
#include "vtkBloomPass.h"
#include "vtkBloomTestSupport.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkImageData.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace
{
// A few hundred HDR points of two pixels, scattered in a ball.
void PointsScene(vtkRenderer* renderer, vtkBloomPass*)
{
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(11);
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> vertices;
  for (int i = 0; i < 400; ++i)
  {
    double x[3];
    for (double& v : x)
    {
      random->Next();
      v = 2.0 * random->GetValue() - 1.0;
    }
    const vtkIdType id = points->InsertNextPoint(x);
    vertices->InsertNextCell(1, &id);
  }
  vtkNew<vtkPolyData> cloud;
  cloud->SetPoints(points);
  cloud->SetVerts(vertices);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(cloud);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetAmbient(1.0);
  actor->GetProperty()->SetDiffuse(0.0);
  actor->GetProperty()->SetAmbientColor(3.0, 2.5, 1.5);
  actor->GetProperty()->SetPointSize(2.0);
  renderer->AddActor(actor);
  renderer->SetBackground(0.0, 0.0, 0.0);
  renderer->ResetCamera();
}

struct Energies
{
  double SceneCV = 0.0;
  double BloomCV = 0.0;
  double BloomMean = 0.0;
  /// The bloom's CV with the bright pass averaged over the last 2 and 4 frames (Averaged).
  double AveragedCV[2] = { 0.0, 0.0 };
};

// The bloom's energy had the bright pass been averaged over the last `k` frames (a temporal
// average of the bright pass, one of the engines' remedies for flicker): everything after the
// bright pass is linear and, with an additive composite (the defaults'), so is the energy it
// adds, which is then the mean of the last k frames' (from frame k - 1 on), up to rounding. It
// says nothing of the trails such an average leaves behind moving geometry.
std::vector<double> Averaged(const std::vector<double>& energy, int k)
{
  std::vector<double> out;
  for (size_t f = static_cast<size_t>(k - 1); f < energy.size(); ++f)
  {
    double sum = 0.0;
    for (int j = 0; j < k; ++j)
    {
      sum += energy[f - j];
    }
    out.push_back(sum / k);
  }
  return out;
}

double CoefficientOfVariation(const std::vector<double>& values)
{
  double mean = 0.0;
  for (double v : values)
  {
    mean += v / values.size();
  }
  double variance = 0.0;
  for (double v : values)
  {
    variance += (v - mean) * (v - mean) / values.size();
  }
  return mean != 0.0 ? std::sqrt(variance) / std::abs(mean) : 0.0;
}

/**
 * Sweep `frames` camera steps of `degrees` (azimuth) over a scene, `configure` applied to the
 * pass after the scene's own set-up; a window of width x height with `samples` samples.
 */
Energies Sweep(const std::function<void(vtkRenderer*, vtkBloomPass*)>& scene,
  const std::function<void(vtkBloomPass*)>& configure, int frames, double degrees)
{
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(4);
  window->SetSize(320, 180);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  vtkNew<vtkBloomPass> bloom;
  vtkNew<vtkRenderStepsPass> steps;
  bloom->SetDelegatePass(steps);
  renderer->SetPass(bloom);
  scene(renderer, bloom);
  configure(bloom);
  bloom->SetFloatPrecisionTo32Bit();
  bloom->CaptureResultOn();
  std::vector<double> sceneEnergy, bloomEnergy;
  vtkNew<vtkImageData> before, after;
  for (int f = 0; f < frames; ++f)
  {
    renderer->GetActiveCamera()->Azimuth(degrees);
    window->Render();
    EXPECT_TRUE(bloom->ReadSceneImage(before));
    EXPECT_TRUE(bloom->ReadResultImage(after));
    const float* s = static_cast<const float*>(before->GetScalarPointer());
    const float* r = static_cast<const float*>(after->GetScalarPointer());
    double es = 0.0, eb = 0.0;
    for (vtkIdType p = 0; p < before->GetNumberOfPoints(); ++p)
    {
      const double w[3] = { vtkBloomKernels::LuminanceR, vtkBloomKernels::LuminanceG,
        vtkBloomKernels::LuminanceB };
      for (int c = 0; c < 3; ++c)
      {
        es += w[c] * s[4 * p + c];
        eb += w[c] * (r[4 * p + c] - s[4 * p + c]);
      }
    }
    sceneEnergy.push_back(es);
    bloomEnergy.push_back(eb);
  }
  Energies e;
  e.SceneCV = CoefficientOfVariation(sceneEnergy);
  e.BloomCV = CoefficientOfVariation(bloomEnergy);
  e.AveragedCV[0] = CoefficientOfVariation(Averaged(bloomEnergy, 2));
  e.AveragedCV[1] = CoefficientOfVariation(Averaged(bloomEnergy, 4));
  for (double v : bloomEnergy)
  {
    e.BloomMean += v / bloomEnergy.size();
  }
  return e;
}

struct Configuration
{
  std::string Name;
  std::function<void(vtkBloomPass*)> Configure;
};

std::vector<Configuration> Configurations()
{
  std::vector<Configuration> all = { { "scene", [](vtkBloomPass*) {} },
    { "defaults", [](vtkBloomPass* p) { p->SetParameters(vtkNew<vtkBloomParameters>()); } } };
  for (const std::string& preset : vtkBloomParameters::GetPresetNames())
  {
    all.push_back({ preset, [preset](vtkBloomPass* p) { p->SetPreset(preset.c_str()); } });
  }
  return all;
}
}

TEST(RenderingBloomPassMotion, BloomFlickerIsMeasuredAndBounded)
{
  const std::pair<const char*, std::function<void(vtkRenderer*, vtkBloomPass*)>> scenes[] = {
    { "field-lines",
      [](vtkRenderer* r, vtkBloomPass* p) { vtkBloomBuildExampleScene("field-lines", r, p); } },
    { "points", PointsScene }
  };
  for (const auto& scene : scenes)
  {
    for (const Configuration& c : Configurations())
    {
      const Energies e = Sweep(scene.second, c.Configure, 32, 0.02);
      std::cout << "[ flicker ] " << scene.first << ", " << c.Name << ": scene CV " << e.SceneCV
                << ", bloom CV " << e.BloomCV << " (bloom mean " << e.BloomMean
                << "; bright pass averaged over 2 / 4 frames: " << e.AveragedCV[0] << " / "
                << e.AveragedCV[1] << ")\n";
      EXPECT_GT(e.SceneCV, 0.0) << "the camera must move";
      if (c.Name == "defaults" || c.Name == "scene")
      {
        const bool lines = std::string(scene.first) == "field-lines";
        EXPECT_LE(e.BloomCV, (lines ? 1.5 : 4.0) * e.SceneCV) << scene.first << ", " << c.Name;
      }
    }
  }
}
