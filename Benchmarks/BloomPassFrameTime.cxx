// Frame time of an example scene rendered with the plain render steps and with vtkBloomPass,
// interleaved frame by frame in one run so that machine noise hits both alike.
//   BloomPassFrameTime [SCENE] [WIDTH HEIGHT] [FRAMES]
#include "vtkBloomExampleScenes.h"
#include "vtkBloomPass.h"
#include "vtkCamera.h"
#include "vtkNew.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

int main(int argc, char* argv[])
{
  const std::string scene = argc > 1 ? argv[1] : "lit-spheres";
  const int width = argc > 3 ? std::atoi(argv[2]) : 1920;
  const int height = argc > 3 ? std::atoi(argv[3]) : 1080;
  const int frames = argc > 4 ? std::atoi(argv[4]) : 15;

  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(width, height);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  vtkNew<vtkBloomPass> bloom;
  vtkNew<vtkRenderStepsPass> steps;
  bloom->SetDelegatePass(steps);
  if (!vtkBloomBuildExampleScene(scene, renderer, bloom))
  {
    std::fprintf(stderr, "unknown scene %s\n", scene.c_str());
    return 1;
  }
  // Selective scenes also render their emitters; measure the plain scene pass for all.
  std::vector<double> times[2];
  for (int f = -2; f < frames; ++f) // two warm-up frames of each
  {
    for (int withBloom = 0; withBloom < 2; ++withBloom)
    {
      renderer->SetPass(withBloom ? static_cast<vtkRenderPass*>(bloom) : steps);
      renderer->GetActiveCamera()->Azimuth(0.5); // a new frame, not a cached one
      const auto start = std::chrono::steady_clock::now();
      window->Render();
      window->WaitForCompletion();
      const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
      if (f >= 0)
      {
        times[withBloom].push_back(ms);
      }
    }
  }
  for (auto& t : times)
  {
    std::sort(t.begin(), t.end());
  }
  const double plain = times[0][times[0].size() / 2], bloomed = times[1][times[1].size() / 2];
  std::printf("| %s | %dx%d | %.1f ms | %.1f ms | %.2fx | %d |\n", scene.c_str(), width, height,
    plain, bloomed, bloomed / plain, bloom->GetNumberOfPasses());
  window->ReleaseGraphicsResources(window);
  return 0;
}
