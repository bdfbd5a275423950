// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// Helpers shared by the vtk-bloom GoogleTest suites.
#ifndef vtkBloomTestSupport_h
#define vtkBloomTestSupport_h

#include <vtkCommand.h>
#include <vtkImageData.h>
#include <vtkSmartPointer.h>

#include <gtest/gtest.h>

#include <functional>
#include <string>

class vtkImageAlgorithm;

namespace vtkBloomTest
{
/// Counts the events it observes: `vtkNew<EventCounter> errors;
/// filter->AddObserver(vtkCommand::ErrorEvent, errors);` then errors->Count.
class EventCounter : public vtkCommand
{
public:
  static EventCounter* New() { return new EventCounter; }
  void Execute(vtkObject*, unsigned long, void*) override { ++this->Count; }
  int Count = 0;
};

/// Update `algorithm` (a filter, or a reader with its file name set) and return a copy of its
/// output, which outlives it.
vtkSmartPointer<vtkImageData> UpdateAndCopy(vtkImageAlgorithm* algorithm);

/// Run `filter` on `input` and return a copy of its output (UpdateAndCopy).
vtkSmartPointer<vtkImageData> RunAndCopy(vtkImageAlgorithm* filter, vtkImageData* input);

/// True when the CI environment variable says we run under CI.
bool RunningInCI();

/// This process's resident memory (VmRSS of /proc/self/status), in KiB; 0 where unknown.
long ResidentKiB();

/// Absolute path of a file under ../shared/data, or "" when it is absent.
std::string SharedDataPath(const std::string& relative);

/// A directory of the running test's own for the files it writes (created on demand).
std::string OutputDirectory();

/// A file in OutputDirectory().
std::string OutputPath(const std::string& name);

/// An image with the given extent and components, filled by f(i, j, k, c).
vtkSmartPointer<vtkImageData> MakeImage(const int extent[6], int components, int scalarType,
  const std::function<double(int, int, int, int)>& f);

/// Scalar value at structured index (i, j, k), component c, as double.
double Value(vtkImageData* image, int i, int j, int k, int c);

/// ||a - b||_2 / ||b||_2 over all scalars; NaN if the shapes differ.
double RelativeL2(vtkImageData* a, vtkImageData* b);

/**
 * ||a - b||_2 / ||b||_2 over the colour channels (the first three components) of two
 * images of the same size: a rendered or bloomed frame against its reference. NaN (which fails
 * every bound) unless both have the same shape, at least one pixel and three components.
 */
double ColourRelativeL2(vtkImageData* a, vtkImageData* b);

/**
 * The relative L2 of two bloom terms over the colour channels: ||(a - base) - (b - base)|| /
 * ||b - base||, for a result `a` against a reference result `b` of the same input `base`. NaN
 * unless all three have the same shape, at least one pixel and three components.
 */
double BloomRelativeL2(vtkImageData* base, vtkImageData* a, vtkImageData* b);

/// max |a - b| over all scalars; NaN if the shapes differ.
double MaxAbsDifference(vtkImageData* a, vtkImageData* b);

/// True when both images have identical shape and bit-identical scalars.
bool BitIdentical(vtkImageData* a, vtkImageData* b);
}

/// Resolve a shared data file into `var`; skip the test when it is missing, or fail under CI.
#define VTKBLOOM_REQUIRE_DATA(var, relative)                                                       \
  const std::string var = vtkBloomTest::SharedDataPath(relative);                                  \
  if (var.empty())                                                                                 \
  {                                                                                                \
    if (vtkBloomTest::RunningInCI())                                                               \
    {                                                                                              \
      FAIL() << "shared test data missing under CI: " << (relative);                               \
    }                                                                                              \
    GTEST_SKIP() << "shared test data missing: " << (relative);                                    \
  }

#endif
