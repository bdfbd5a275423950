#!/usr/bin/python3
# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
"""Join PNG images left to right into one PNG, optionally scaled:

    side-by-side.py [--scale F] OUT.png IN1.png IN2.png ...
"""
import sys

from vtkmodules.vtkIOImage import vtkPNGReader, vtkPNGWriter
from vtkmodules.vtkFiltersCore import vtkImageAppend
from vtkmodules.vtkImagingCore import vtkImageResize


def main(argv):
    scale = 1.0
    if len(argv) > 2 and argv[1] == "--scale":
        scale = float(argv[2])
        argv = argv[:1] + argv[3:]
    if len(argv) < 3:
        print(__doc__, file=sys.stderr)
        return 2
    append = vtkImageAppend()
    append.SetAppendAxis(0)
    append.PreserveExtentsOff()
    for path in argv[2:]:
        reader = vtkPNGReader()
        reader.SetFileName(path)
        reader.Update()
        append.AddInputData(reader.GetOutput())
    last = append
    if scale != 1.0:
        last = vtkImageResize()
        last.SetResizeMethodToMagnificationFactors()
        last.SetMagnificationFactors(scale, scale, 1.0)
        last.SetInputConnection(append.GetOutputPort())
    writer = vtkPNGWriter()
    writer.SetFileName(argv[1])
    writer.SetInputConnection(last.GetOutputPort())
    writer.Write()
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
