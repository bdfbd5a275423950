// Frame time of an example scene with the plain render steps or with vtkBloomPass, for the
// benchmark executables (BloomPassFrameTime and the GPU rows of BloomChainSpeed). Frames with
// and without bloom are meant to be interleaved by the caller, so machine noise hits both alike.
#ifndef vtkBloomFrameTimer_h
#define vtkBloomFrameTimer_h

#include "vtkBloomExampleScenes.h"
#include "vtkBloomPass.h"
#include "vtkCamera.h"
#include "vtkNew.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <algorithm>
#include <chrono>
#include <string>
#include <vector>

class vtkBloomFrameTimer
{
public:
  /// An offscreen window of width x height showing `scene`; false for an unknown scene.
  bool Setup(const std::string& scene, int width, int height)
  {
    this->Window->SetOffScreenRendering(1);
    this->Window->SetMultiSamples(0);
    this->Window->SetSize(width, height);
    this->Window->AddRenderer(this->Renderer);
    this->Bloom->SetDelegatePass(this->Steps);
    return vtkBloomBuildExampleScene(scene, this->Renderer, this->Bloom);
  }

  /// Render one new frame (the camera moves a little, so nothing is cached) and wait for it;
  /// seconds.
  double Frame(bool withBloom)
  {
    this->Renderer->SetPass(
      withBloom ? static_cast<vtkRenderPass*>(this->Bloom) : this->Steps.Get());
    this->Renderer->GetActiveCamera()->Azimuth(0.5);
    const auto start = std::chrono::steady_clock::now();
    this->Window->Render();
    this->Window->WaitForCompletion();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

  static double Median(std::vector<double> v)
  {
    if (v.empty())
    {
      return 0.0;
    }
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
  }

  ~vtkBloomFrameTimer() { this->Window->ReleaseGraphicsResources(this->Window); }

  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkBloomPass> Bloom;
  vtkNew<vtkRenderStepsPass> Steps;
};

#endif
