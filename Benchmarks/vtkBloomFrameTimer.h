// Frame time of an example scene with the plain render steps, with vtkBloomPass, or with the
// least any HDR post-process does (the scene into a float target, then one full-screen copy to
// the window: VTK's own vtkFramebufferPass, at the precision of the bloom pass's scene target),
// for the benchmark executables (BloomPassFrameTime and the GPU rows of BloomChainSpeed). The
// caller interleaves the kinds of frame, so machine noise hits them alike.
#ifndef vtkBloomFrameTimer_h
#define vtkBloomFrameTimer_h

#include "vtkBloomExampleScenes.h"
#include "vtkBloomMedian.h"
#include "vtkBloomPass.h"
#include "vtkCamera.h"
#include "vtkFramebufferPass.h"
#include "vtkNew.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTextureObject.h"

#include <chrono>
#include <string>
#include <vector>

class vtkBloomFrameTimer
{
public:
  enum Kind
  {
    PLAIN,      ///< the render steps into the window
    FLOAT_COPY, ///< the render steps into a float target, copied to the window
    BLOOM       ///< vtkBloomPass around the render steps
  };

  /// An offscreen window of width x height showing `scene`; false for an unknown scene.
  bool Setup(const std::string& scene, int width, int height)
  {
    this->Window->SetOffScreenRendering(1);
    this->Window->SetMultiSamples(0);
    this->Window->SetSize(width, height);
    this->Window->AddRenderer(this->Renderer);
    this->Bloom->SetDelegatePass(this->Steps);
    this->FloatCopy->SetDelegatePass(this->Steps);
    if (!vtkBloomBuildExampleScene(scene, this->Renderer, this->Bloom))
    {
      return false;
    }
    this->FloatCopy->SetColorFormat(this->Bloom->GetFloatPrecision() == vtkBloomPass::FLOAT32
        ? vtkTextureObject::Float32
        : vtkTextureObject::Float16);
    return true;
  }

  /// Render one new frame (the camera moves a little, so nothing is cached) and wait for it;
  /// seconds.
  double Frame(Kind kind)
  {
    vtkRenderPass* passes[] = { this->Steps, this->FloatCopy, this->Bloom };
    this->Renderer->SetPass(passes[kind]);
    this->Renderer->GetActiveCamera()->Azimuth(0.5);
    const auto start = std::chrono::steady_clock::now();
    this->Window->Render();
    this->Window->WaitForCompletion();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

  ~vtkBloomFrameTimer()
  {
    // The passes not set on the renderer last are not reached through the window.
    this->FloatCopy->ReleaseGraphicsResources(this->Window);
    this->Bloom->ReleaseGraphicsResources(this->Window);
    this->Window->ReleaseGraphicsResources(this->Window);
  }

  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkBloomPass> Bloom;
  vtkNew<vtkRenderStepsPass> Steps;
  vtkNew<vtkFramebufferPass> FloatCopy;
};

#endif
