# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
"""Helpers shared by the vtk-bloom Python examples: numpy <-> vtkImageData, display encoding and
PNG output.

Image arrays are numpy arrays of shape (height, width, components) whose row 0 is the top of
the picture, the order OpenEXR files and vtkOpenEXRReader use (structured index (x, y, 0) is
array[y, x]).
"""

import numpy as np
from vtkmodules.util import numpy_support
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkIOImage import vtkPNGWriter


def image_from_array(array, name="scalars"):
    """A single-slice vtkImageData holding a (height, width[, components]) array (deep copy)."""
    array = np.asarray(array)
    if array.ndim == 2:
        array = array[:, :, np.newaxis]
    if array.ndim != 3:
        raise ValueError("expected an array of shape (height, width[, components])")
    height, width, components = array.shape
    image = vtkImageData()
    image.SetDimensions(width, height, 1)
    # x varies fastest in VTK's point order, which is C order for (height, width, components).
    scalars = numpy_support.numpy_to_vtk(
        np.ascontiguousarray(array).reshape(-1, components), deep=True)
    scalars.SetName(name)
    image.GetPointData().SetScalars(scalars)
    return image


def array_from_image(image):
    """The point scalars of a single-slice vtkImageData as a (height, width, components) copy."""
    width, height, depth = image.GetDimensions()
    if depth != 1:
        raise ValueError("expected a single-slice image, got %d slices" % depth)
    scalars = image.GetPointData().GetScalars()
    values = numpy_support.vtk_to_numpy(scalars)
    return values.reshape(height, width, scalars.GetNumberOfComponents()).copy()


def tone_map(array, exposure=1.0):
    """Display encoding as the vtk-bloom tool does it: exposure, the ACES filmic fit of
    Narkowicz (2015), the sRGB transfer function, 8 bits. Returns (height, width, 3) uint8;
    1-2 component images (value, alpha) are shown in grey and alpha is dropped."""
    array = np.asarray(array, dtype=np.float64)
    if array.ndim == 2:
        array = array[:, :, np.newaxis]
    colour = array[:, :, :3] if array.shape[2] >= 3 else np.repeat(array[:, :, :1], 3, axis=2)
    x = np.nan_to_num(colour * exposure, nan=0.0, posinf=1e6, neginf=0.0)
    x = np.clip(x, 0.0, 1e6)
    y = np.clip((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0)
    s = np.where(y <= 0.0031308, 12.92 * y, 1.055 * np.power(y, 1.0 / 2.4) - 0.055)
    return np.rint(255.0 * np.clip(s, 0.0, 1.0)).astype(np.uint8)


def write_png(rgb, path):
    """Write a (height, width, 3) uint8 array, row 0 on top, as a PNG file."""
    # vtkPNGWriter puts the last row of the image on top, so flip to keep row 0 on top.
    image = image_from_array(np.flipud(np.asarray(rgb, dtype=np.uint8)))
    writer = vtkPNGWriter()
    writer.SetFileName(str(path))
    writer.SetInputData(image)
    writer.Write()
    if writer.GetErrorCode() != 0:
        raise OSError("cannot write %s" % path)


def statistics(image):
    """The bloom statistics vtkImageBloom attached to its output, as a dict name -> value."""
    fields = image.GetFieldData()
    result = {}
    for i in range(fields.GetNumberOfArrays()):
        array = fields.GetAbstractArray(i)
        if array.GetName() and array.GetName().startswith("Bloom"):
            result[array.GetName()] = numpy_support.vtk_to_numpy(array)[0].item()
    return result
