#!/usr/bin/python3
# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
"""Recipe: bloom a float32 frame held as a numpy array, and save it before and after.

    numpy_frame.py OUTPUT.png [OUTPUT.exr]
"""
import sys

import numpy as np
import vtkbloom

# An HDR frame: a dim gradient with a bright filament and a few stars above 1.
h, w = 360, 640
y, x = np.mgrid[0:h, 0:w].astype(np.float32)
frame = np.zeros((h, w, 3), np.float32)
frame[...] = 0.01 + 0.03 * (x / w)[..., None]
filament = np.exp(-((y - h / 2 - 60 * np.sin(x / 70)) / 2.0) ** 2)
frame += filament[..., None] * np.array([4.0, 1.2, 0.3], np.float32)
for cx, cy in [(120, 80), (500, 90), (560, 300), (90, 290)]:
    frame[cy - 1:cy + 2, cx - 1:cx + 2] += np.array([20.0, 24.0, 30.0], np.float32)

glow, stats = vtkbloom.bloom(frame, preset="webgpu-market", statistics=True)
print("energy in %.1f, out %.1f, bright pixels %d" % (
    stats["energy_in"], stats["energy_out"], stats["number_of_bright_pixels"]))
if len(sys.argv) > 2:
    vtkbloom.write_exr(sys.argv[2], glow)

# Before (left) and after (right), tone-mapped x / (1 + x) for the PNG.
side_by_side = np.concatenate([frame, glow], axis=1)
png = (255 * (side_by_side / (1 + side_by_side)) ** (1 / 2.2) + 0.5).astype(np.uint8)
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkIOImage import vtkPNGWriter

image = vtkImageData()
image.SetDimensions(png.shape[1], png.shape[0], 1)
image.GetPointData().SetScalars(numpy_to_vtk(png[::-1].reshape(-1, 3)))  # VTK's row 0 is the bottom
writer = vtkPNGWriter()
writer.SetFileName(sys.argv[1])
writer.SetInputData(image)
writer.Write()
