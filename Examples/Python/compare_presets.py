#!/usr/bin/python3
# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
"""Compare the bloom presets side by side in one PNG.

    compare_presets.py [--input IN.exr] [--presets A,B,...] [--exposure E] [--gap G] OUTPUT.png

The first panel is the input, then one panel per preset (all of them by default, in the order
of vtkImageBloom.GetPresetNames()), left to right, each tone-mapped with the same exposure and
separated by G dark-grey columns. Without --input a generated emissive scene is used: a dim
gradient with bright discs, a thin line and single hot pixels. The panels are joined with
vtkImageAppend and written with vtkPNGWriter.
"""

import argparse
import sys

import numpy as np
import vtkbloom
from vtkmodules.vtkFiltersCore import vtkImageAppend
from vtkmodules.vtkIOImage import vtkPNGWriter

from example_support import array_from_image, image_from_array, statistics, tone_map

GAP_GREY = 40


def emissive_scene(width=192, height=128):
    """A float32 RGB scene whose bright parts (up to 50) sit on a background below 0.2."""
    y, x = np.mgrid[0:height, 0:width].astype(np.float64)
    rgb = np.empty((height, width, 3))
    rgb[:, :, 0] = 0.05 + 0.1 * x / width
    rgb[:, :, 1] = 0.05 + 0.1 * y / height
    rgb[:, :, 2] = 0.12
    for cx, cy, r, colour in ((48, 40, 10, (8.0, 3.0, 1.0)), (130, 80, 6, (1.0, 4.0, 12.0)),
                              (100, 30, 3, (20.0, 20.0, 20.0))):
        rgb[(x - cx) ** 2 + (y - cy) ** 2 <= r * r] = colour
    rgb[100, 20:170] = (2.0, 6.0, 2.0)
    for px, py in ((20, 110), (170, 15), (160, 115)):
        rgb[py, px] = (50.0, 50.0, 50.0)
    return rgb.astype(np.float32)


def panel(array, exposure):
    """A tone-mapped panel as vtkImageData, flipped so that row 0 ends up on top of the PNG."""
    return image_from_array(np.flipud(tone_map(array, exposure)))


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--input", help="an OpenEXR file (default: a generated scene)")
    parser.add_argument("--presets", help="comma-separated preset names (default: all)")
    parser.add_argument("--exposure", type=float, default=1.0)
    parser.add_argument("--gap", type=int, default=4)
    parser.add_argument("output")
    args = parser.parse_args(argv[1:])
    names = vtkbloom.vtkImageBloom.GetPresetNames()
    presets = args.presets.split(",") if args.presets else list(names)
    unknown = [p for p in presets if p not in names]
    if unknown:
        parser.error("unknown preset(s) %s; expected some of %s" % (unknown, ", ".join(names)))

    if args.input:
        reader = vtkbloom.vtkOpenEXRReader()
        reader.SetFileName(args.input)
        reader.Update()
        if reader.GetErrorCode() != 0:
            print("cannot read %s" % args.input, file=sys.stderr)
            return 1
        scene = reader.GetOutput()
    else:
        scene = image_from_array(emissive_scene(), name="radiance")
    height = scene.GetDimensions()[1]

    append = vtkImageAppend()
    append.SetAppendAxis(0)
    append.PreserveExtentsOff()
    append.AddInputData(panel(array_from_image(scene), args.exposure))
    print("panel 0: input")
    for index, name in enumerate(presets, start=1):
        bloom = vtkbloom.vtkImageBloom()
        bloom.SetPreset(name)
        bloom.SetInputData(scene)
        bloom.Update()
        if bloom.GetOutput().GetNumberOfPoints() == 0:
            print("the %s bloom failed" % name, file=sys.stderr)
            return 1
        if args.gap > 0:
            gap = np.full((height, args.gap, 3), GAP_GREY, dtype=np.uint8)
            append.AddInputData(image_from_array(gap))
        append.AddInputData(panel(array_from_image(bloom.GetOutput()), args.exposure))
        stats = statistics(bloom.GetOutput())
        print("panel %d: %s, energy x%.4f, peak %.6g -> %.6g" % (index, name,
            stats["BloomEnergyOut"] / stats["BloomEnergyIn"], stats["BloomPeakLuminanceIn"],
            stats["BloomPeakLuminanceOut"]))

    writer = vtkPNGWriter()
    writer.SetFileName(args.output)
    writer.SetInputConnection(append.GetOutputPort())
    writer.Write()
    if writer.GetErrorCode() != 0:
        print("cannot write %s" % args.output, file=sys.stderr)
        return 1
    print("wrote %s" % args.output)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
