// Frame time of an example scene rendered with the plain render steps, into a float target
// copied to the window (the least any HDR post-process does) and with vtkBloomPass,
// interleaved frame by frame in one run so that machine noise hits them alike.
//   BloomPassFrameTime [SCENE] [WIDTH HEIGHT] [FRAMES]
#include "vtkBloomFrameTimer.h"

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

  vtkBloomFrameTimer timer;
  if (!timer.Setup(scene, width, height))
  {
    std::fprintf(stderr, "unknown scene %s\n", scene.c_str());
    return 1;
  }
  // Selective scenes also render their emitters; measure the plain scene pass for all.
  const vtkBloomFrameTimer::Kind kinds[] = { vtkBloomFrameTimer::PLAIN,
    vtkBloomFrameTimer::FLOAT_COPY, vtkBloomFrameTimer::BLOOM };
  std::vector<double> times[3];
  for (int f = -2; f < frames; ++f) // two warm-up frames of each
  {
    for (int k = 0; k < 3; ++k)
    {
      const double ms = 1e3 * timer.Frame(kinds[k]);
      if (f >= 0)
      {
        times[k].push_back(ms);
      }
    }
  }
  const double plain = vtkBloomMedian(times[0]);
  const double floatCopy = vtkBloomMedian(times[1]);
  const double bloomed = vtkBloomMedian(times[2]);
  std::printf("| scene | size | without bloom | float target + copy | with bloom | float target "
              "+ copy / without | with / without | passes |\n|---|---|---|---|---|---|---|---|\n");
  std::printf("| %s | %dx%d | %.1f ms | %.1f ms | %.1f ms | %.2fx | %.2fx | %d |\n", scene.c_str(),
    width, height, plain, floatCopy, bloomed, floatCopy / plain, bloomed / plain,
    timer.Bloom->GetNumberOfPasses());
  return 0;
}
