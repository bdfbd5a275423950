// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkBloomTestSupport.h"

#include <vtkDataArray.h>
#include <vtkImageAlgorithm.h>
#include <vtkPointData.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>

namespace vtkBloomTest
{
//------------------------------------------------------------------------------
vtkSmartPointer<vtkImageData> UpdateAndCopy(vtkImageAlgorithm* algorithm)
{
  algorithm->Update();
  auto out = vtkSmartPointer<vtkImageData>::New();
  out->DeepCopy(algorithm->GetOutput());
  return out;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkImageData> RunAndCopy(vtkImageAlgorithm* filter, vtkImageData* input)
{
  filter->SetInputData(input);
  return UpdateAndCopy(filter);
}

//------------------------------------------------------------------------------
bool RunningInCI()
{
  const char* ci = std::getenv("CI");
  return ci && (std::strcmp(ci, "true") == 0 || std::strcmp(ci, "1") == 0);
}

//------------------------------------------------------------------------------
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

std::string SharedDataPath(const std::string& relative)
{
  const std::string path = std::string(VTKBLOOM_SHARED_DATA_DIR) + "/" + relative;
  std::ifstream probe(path);
  return probe.good() ? path : std::string();
}

std::string OutputDirectory()
{
  // One directory per test, so tests that CTest runs in parallel never share files.
  std::string dir = VTKBLOOM_TEST_OUTPUT_DIR;
  if (const auto* info = ::testing::UnitTest::GetInstance()->current_test_info())
  {
    std::string name = std::string(info->test_suite_name()) + "." + info->name();
    for (char& c : name)
    {
      if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '_' && c != '-')
      {
        c = '_';
      }
    }
    dir += "/" + name;
  }
  std::filesystem::create_directories(dir);
  return dir;
}

std::string OutputPath(const std::string& name)
{
  return OutputDirectory() + "/" + name;
}

vtkSmartPointer<vtkImageData> MakeImage(const int extent[6], int components, int scalarType,
  const std::function<double(int, int, int, int)>& f)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetExtent(const_cast<int*>(extent));
  image->AllocateScalars(scalarType, components);
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  vtkIdType t = 0;
  for (int k = extent[4]; k <= extent[5]; ++k)
  {
    for (int j = extent[2]; j <= extent[3]; ++j)
    {
      for (int i = extent[0]; i <= extent[1]; ++i, ++t)
      {
        for (int c = 0; c < components; ++c)
        {
          scalars->SetComponent(t, c, f(i, j, k, c));
        }
      }
    }
  }
  return image;
}

double Value(vtkImageData* image, int i, int j, int k, int c)
{
  return image->GetScalarComponentAsDouble(i, j, k, c);
}

namespace
{
bool SameShape(vtkImageData* a, vtkImageData* b)
{
  if (!a || !b || !a->GetPointData()->GetScalars() || !b->GetPointData()->GetScalars())
  {
    return false;
  }
  int ea[6], eb[6];
  a->GetExtent(ea);
  b->GetExtent(eb);
  int da[3] = { ea[1] - ea[0], ea[3] - ea[2], ea[5] - ea[4] };
  int db[3] = { eb[1] - eb[0], eb[3] - eb[2], eb[5] - eb[4] };
  return da[0] == db[0] && da[1] == db[1] && da[2] == db[2] &&
    a->GetNumberOfScalarComponents() == b->GetNumberOfScalarComponents();
}

// Two images whose colours can be compared: the same shape, not empty, with at least three
// components. An empty pair would give 0, which passes any bound.
bool ComparableColours(vtkImageData* a, vtkImageData* b)
{
  return SameShape(a, b) && a->GetNumberOfPoints() > 0 && a->GetNumberOfScalarComponents() >= 3;
}
}

double RelativeL2(vtkImageData* a, vtkImageData* b)
{
  if (!SameShape(a, b))
  {
    return std::numeric_limits<double>::quiet_NaN();
  }
  vtkDataArray* sa = a->GetPointData()->GetScalars();
  vtkDataArray* sb = b->GetPointData()->GetScalars();
  double num = 0.0, den = 0.0;
  const vtkIdType n = sa->GetNumberOfValues();
  for (vtkIdType t = 0; t < n; ++t)
  {
    const double d = sa->GetVariantValue(t).ToDouble() - sb->GetVariantValue(t).ToDouble();
    const double r = sb->GetVariantValue(t).ToDouble();
    num += d * d;
    den += r * r;
  }
  return den > 0.0 ? std::sqrt(num / den) : std::sqrt(num);
}

double ColourRelativeL2(vtkImageData* a, vtkImageData* b)
{
  if (!ComparableColours(a, b))
  {
    return std::numeric_limits<double>::quiet_NaN();
  }
  double num = 0.0, den = 0.0;
  vtkDataArray* sa = a->GetPointData()->GetScalars();
  vtkDataArray* sb = b->GetPointData()->GetScalars();
  for (vtkIdType p = 0; p < a->GetNumberOfPoints(); ++p)
  {
    for (int c = 0; c < 3; ++c)
    {
      const double x = sa->GetComponent(p, c), y = sb->GetComponent(p, c);
      num += (x - y) * (x - y);
      den += y * y;
    }
  }
  return std::sqrt(num / std::max(den, 1e-300));
}

double BloomRelativeL2(vtkImageData* base, vtkImageData* a, vtkImageData* b)
{
  if (!ComparableColours(base, a) || !ComparableColours(base, b))
  {
    return std::numeric_limits<double>::quiet_NaN();
  }
  double num = 0.0, den = 0.0;
  vtkDataArray* s0 = base->GetPointData()->GetScalars();
  vtkDataArray* sa = a->GetPointData()->GetScalars();
  vtkDataArray* sb = b->GetPointData()->GetScalars();
  for (vtkIdType p = 0; p < base->GetNumberOfPoints(); ++p)
  {
    for (int c = 0; c < 3; ++c)
    {
      const double s = s0->GetComponent(p, c);
      const double x = sa->GetComponent(p, c) - s, y = sb->GetComponent(p, c) - s;
      num += (x - y) * (x - y);
      den += y * y;
    }
  }
  return std::sqrt(num / std::max(den, 1e-300));
}

double MaxAbsDifference(vtkImageData* a, vtkImageData* b)
{
  if (!SameShape(a, b))
  {
    return std::numeric_limits<double>::quiet_NaN();
  }
  vtkDataArray* sa = a->GetPointData()->GetScalars();
  vtkDataArray* sb = b->GetPointData()->GetScalars();
  double m = 0.0;
  const vtkIdType n = sa->GetNumberOfValues();
  for (vtkIdType t = 0; t < n; ++t)
  {
    const double d =
      std::abs(sa->GetVariantValue(t).ToDouble() - sb->GetVariantValue(t).ToDouble());
    if (!(d <= m))
    {
      m = d;
    }
  }
  return m;
}

bool BitIdentical(vtkImageData* a, vtkImageData* b)
{
  if (!SameShape(a, b) || a->GetScalarType() != b->GetScalarType())
  {
    return false;
  }
  vtkDataArray* sa = a->GetPointData()->GetScalars();
  vtkDataArray* sb = b->GetPointData()->GetScalars();
  const size_t bytes = static_cast<size_t>(sa->GetNumberOfValues()) * sa->GetDataTypeSize();
  return std::memcmp(sa->GetVoidPointer(0), sb->GetVoidPointer(0), bytes) == 0;
}
}
