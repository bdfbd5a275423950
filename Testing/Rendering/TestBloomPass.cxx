// Tests of vtkBloomPass: GPU/CPU agreement per preset on the float render, selective bloom,
// chaining with tone mapping, GL errors and resource stability over many frames with resizes.
#include "vtkBloomExampleScenes.h"
#include "vtkBloomPass.h"
#include "vtkBloomTestSupport.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCameraPass.h"
#include "vtkImageBloom.h"
#include "vtkImageBloomThreshold.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPointData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkToneMappingPass.h"
#include "vtk_glew.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>

namespace
{
// An offscreen window with one renderer whose pass is bloom(render steps).
struct BloomWindow
{
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkBloomPass> Bloom;
  vtkNew<vtkRenderStepsPass> Steps;

  BloomWindow(int width, int height)
  {
    this->Window->SetOffScreenRendering(1);
    this->Window->SetMultiSamples(0);
    this->Window->SetSize(width, height);
    this->Window->AddRenderer(this->Renderer);
    this->Bloom->SetDelegatePass(this->Steps);
    this->Renderer->SetPass(this->Bloom);
  }
  ~BloomWindow() { this->Window->ReleaseGraphicsResources(this->Window); }
  vtkOpenGLRenderWindow* GL() { return vtkOpenGLRenderWindow::SafeDownCast(this->Window); }
};

// Relative L2 over the colour channels of two RGBA float images of the same size.
double ColourRelativeL2(vtkImageData* a, vtkImageData* b)
{
  const vtkIdType n = a->GetNumberOfPoints();
  double num = 0.0, den = 0.0;
  for (vtkIdType p = 0; p < n; ++p)
  {
    for (int c = 0; c < 3; ++c)
    {
      const double x = a->GetPointData()->GetScalars()->GetComponent(p, c);
      const double y = b->GetPointData()->GetScalars()->GetComponent(p, c);
      num += (x - y) * (x - y);
      den += y * y;
    }
  }
  return std::sqrt(num / std::max(den, 1e-300));
}

// Largest value of channel c, and whether every value is finite.
double MaxChannel(vtkImageData* image, int c, bool* finite = nullptr)
{
  double m = -VTK_DOUBLE_MAX;
  bool ok = true;
  for (vtkIdType p = 0; p < image->GetNumberOfPoints(); ++p)
  {
    const double v = image->GetPointData()->GetScalars()->GetComponent(p, c);
    ok = ok && std::isfinite(v);
    m = std::max(m, v);
  }
  if (finite)
  {
    *finite = ok;
  }
  return m;
}

long ResidentKiB()
{
  std::ifstream status("/proc/self/status");
  std::string key;
  while (status >> key)
  {
    if (key == "VmRSS:")
    {
      long kib = 0;
      status >> kib;
      return kib;
    }
  }
  return 0;
}

// GPU result vs vtkImageBloom on the same float render, for one preset and precision.
double PresetAgreement(const std::string& preset, int precision, const std::string& scene)
{
  BloomWindow w(301, 207);
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
  EXPECT_GT(w.Bloom->GetNumberOfPasses(), 0);

  // The scene must actually be HDR, or the test would not exercise the float path.
  EXPECT_GT(MaxChannel(sceneImage, 0), 1.5) << "the scene has nothing above 1";

  vtkImageBloom* cpu = w.Bloom->GetParameters();
  cpu->SetInputData(sceneImage);
  cpu->Update();
  const double error = ColourRelativeL2(gpu, cpu->GetOutput());
  // The bloom must change the image, or agreement would be trivial.
  EXPECT_GT(ColourRelativeL2(sceneImage, cpu->GetOutput()), 1e-3);
  cpu->SetInputData(nullptr);
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
