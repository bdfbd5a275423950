// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// Write a small simulation-like dataset for `vtk-bloom render FILE`: a heated plate (a 200x200
// grid warped by its temperature) with a few hot spots on a cooler rippled field, as a VTK XML
// PolyData file with the point arrays Temperature (about 20 to 100) and Gradient (a vector).
//
//   WriteHeatedPlate OUT.vtp
#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkPlaneSource.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataNormals.h>
#include <vtkWarpScalar.h>
#include <vtkXMLPolyDataWriter.h>

#include <cmath>
#include <iostream>

int main(int argc, char* argv[])
{
  if (argc != 2)
  {
    std::cerr << "usage: WriteHeatedPlate OUT.vtp\n";
    return 2;
  }
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-1.0, -1.0, 0.0);
  plane->SetPoint1(1.0, -1.0, 0.0);
  plane->SetPoint2(-1.0, 1.0, 0.0);
  plane->SetResolution(200, 200);
  plane->Update();
  vtkNew<vtkPolyData> surface;
  surface->ShallowCopy(plane->GetOutput());

  // Hot spots (x, y, width, peak) over a 20-degree field with a ripple.
  const double spots[][4] = { { 0.45, 0.35, 0.10, 80.0 }, { -0.50, 0.30, 0.16, 55.0 },
    { -0.20, -0.55, 0.07, 75.0 }, { 0.55, -0.45, 0.12, 45.0 } };
  vtkNew<vtkDoubleArray> temperature;
  temperature->SetName("Temperature");
  vtkNew<vtkDoubleArray> gradient;
  gradient->SetName("Gradient");
  gradient->SetNumberOfComponents(3);
  for (vtkIdType p = 0; p < surface->GetNumberOfPoints(); ++p)
  {
    double x[3];
    surface->GetPoint(p, x);
    double t = 20.0 + 3.0 * std::sin(9.0 * x[0]) * std::cos(7.0 * x[1]);
    double g[3] = { 27.0 * std::cos(9.0 * x[0]) * std::cos(7.0 * x[1]),
      -21.0 * std::sin(9.0 * x[0]) * std::sin(7.0 * x[1]), 0.0 };
    for (const auto& s : spots)
    {
      const double dx = x[0] - s[0], dy = x[1] - s[1];
      const double e = s[3] * std::exp(-(dx * dx + dy * dy) / (2.0 * s[2] * s[2]));
      t += e;
      g[0] -= e * dx / (s[2] * s[2]);
      g[1] -= e * dy / (s[2] * s[2]);
    }
    temperature->InsertNextValue(t);
    gradient->InsertNextTuple(g);
  }
  surface->GetPointData()->SetScalars(temperature);
  surface->GetPointData()->AddArray(gradient);

  // The relief: height proportional to temperature, with smooth normals for shading.
  vtkNew<vtkWarpScalar> warp;
  warp->SetInputData(surface);
  warp->SetScaleFactor(0.004);
  warp->SetNormal(0.0, 0.0, 1.0);
  warp->UseNormalOn();
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputConnection(warp->GetOutputPort());
  normals->SplittingOff();
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputConnection(normals->GetOutputPort());
  writer->SetFileName(argv[1]);
  if (!writer->Write())
  {
    std::cerr << "WriteHeatedPlate: cannot write " << argv[1] << "\n";
    return 1;
  }
  return 0;
}
