// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// Scenes shared by the Performance suites: random HDR images, sparse bright blobs, empty frames.
#ifndef vtkBloomPerformanceScenes_h
#define vtkBloomPerformanceScenes_h

#include "vtkBloomTestSupport.h"
#include "vtkDataArray.h"
#include "vtkImageBloom.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"

#include <cmath>
#include <cstdint>
#include <string>

namespace vtkBloomPerformanceTest
{
enum Scene
{
  EMPTY = 0,  // everything below every preset's threshold (0.05), but not black
  SINGLE = 1, // one bright pixel near a corner
  BLOB = 2,   // a bright disc in one quadrant on a dim background
  RANDOM = 3, // random HDR values everywhere
  SPECIAL = 4 // RANDOM with -0, NaN, +Inf and -Inf samples
};

inline const char* SceneName(int scene)
{
  static const char* names[] = { "empty", "single", "blob", "random", "special" };
  return names[scene];
}

// A deterministic hash in [0, 1).
inline double Hash(int i, int j, int c, int seed)
{
  uint32_t h = static_cast<uint32_t>(i) * 73856093u ^ static_cast<uint32_t>(j) * 19349663u ^
    static_cast<uint32_t>(c + 7 * seed) * 83492791u;
  h ^= h >> 13;
  h *= 0x5bd1e995u;
  h ^= h >> 15;
  return (h & 0xffffff) / 16777216.0;
}

inline vtkSmartPointer<vtkImageData> MakeScene(
  int scene, int w, int h, int nc, int scalarType = VTK_FLOAT)
{
  const int ext[6] = { 0, w - 1, 0, h - 1, 0, 0 };
  return vtkBloomTest::MakeImage(ext, nc, scalarType,
    [=](int i, int j, int, int c) -> double
    {
      const bool alpha = (nc == 2 && c == 1) || (nc == 4 && c == 3);
      if (alpha)
      {
        return 0.25 + 0.5 * Hash(i, j, c, 1);
      }
      const double dim = 0.05 * Hash(i, j, c, 2);
      switch (scene)
      {
        case EMPTY:
          return dim;
        case SINGLE:
          return (i == w - 2 && j == 1) || (w < 2 && i == 0 && j == 0) ? 40.0 : dim;
        case BLOB:
        {
          const double dx = i - 0.7 * w, dy = j - 0.3 * h;
          const double r = 0.12 * std::max(w, h) + 0.5;
          return dx * dx + dy * dy <= r * r ? 2.0 + 6.0 * Hash(i, j, c, 3) : dim;
        }
        case SPECIAL:
        {
          const double u = Hash(i, j, c, 5);
          if (u < 0.01)
          {
            return -0.0;
          }
          if (u < 0.015)
          {
            return std::nan("");
          }
          if (u < 0.018)
          {
            return HUGE_VAL;
          }
          if (u < 0.02)
          {
            return -HUGE_VAL;
          }
          return 3.0 * std::pow(Hash(i, j, c, 4), 4.0);
        }
        case RANDOM:
        default:
          return 3.0 * std::pow(Hash(i, j, c, 4), 4.0);
      }
    });
}

inline vtkSmartPointer<vtkImageData> RunBloom(vtkImageData* input, const std::string& preset,
  int mode, bool adaptive, vtkImageBloom* keep = nullptr)
{
  vtkNew<vtkImageBloom> local;
  vtkImageBloom* bloom = keep ? keep : local.Get();
  bloom->SetPreset(preset.c_str());
  bloom->SetExecutionMode(mode);
  bloom->SetSkipEmptyBloom(adaptive);
  bloom->SetSkipDisabledEffects(adaptive);
  bloom->SetTrimPyramid(adaptive);
  bloom->SetRestrictToBrightRegion(adaptive);
  bloom->ComputeStatisticsOff();
  return vtkBloomTest::RunAndCopy(bloom, input);
}

// Relative L2 over the colour components only (alpha is compared bit for bit elsewhere).
inline double ColourRelativeL2(vtkImageData* a, vtkImageData* b)
{
  vtkDataArray* sa = a->GetPointData()->GetScalars();
  vtkDataArray* sb = b->GetPointData()->GetScalars();
  const int nc = sa->GetNumberOfComponents();
  const int colours = nc >= 3 ? 3 : 1;
  double num = 0.0, den = 0.0;
  for (vtkIdType t = 0; t < sa->GetNumberOfTuples(); ++t)
  {
    for (int c = 0; c < colours; ++c)
    {
      const double d = sa->GetComponent(t, c) - sb->GetComponent(t, c);
      num += d * d;
      den += sb->GetComponent(t, c) * sb->GetComponent(t, c);
    }
  }
  return den > 0.0 ? std::sqrt(num / den) : std::sqrt(num);
}
}

#endif
// VTK-HeaderTest-Exclude: vtkBloomPerformanceScenes.h
