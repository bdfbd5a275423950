#!/usr/bin/python3
# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
"""Bloom a slice of a simulation and save it as OpenEXR (linear) and PNG (tone-mapped).

    bloom_simulation_slice.py [--source wavelet|numpy] [--size N] [--preset NAME]
                              [--save-input] OUTPUT_PREFIX

--source wavelet (the default) takes the middle z slice of VTK's analytic wavelet
(vtkRTAnalyticSource), casts it to float with vtkImageCast, normalizes it to n in [0, 1] with
vtkImageShiftScale and makes the one-component radiance 3 n^4 with vtkImageMathematics, so that
only the crests of the field (n > 0.72) exceed the webgpu-market threshold (0.8). --source numpy computes a two-dimensional field in numpy
(a smooth temperature with a few hot spots), colours it as an RGB emission and hands it to VTK
through vtkmodules.util.numpy_support.

Writes OUTPUT_PREFIX.exr (float32, the bloomed radiance) and OUTPUT_PREFIX.png; with
--save-input also OUTPUT_PREFIX-input.exr, the slice before the bloom.
"""

import argparse
import sys

import numpy as np
import vtkbloom
from vtkmodules.vtkImagingCore import vtkExtractVOI, vtkImageCast, vtkImageShiftScale
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource
from vtkmodules.vtkImagingMath import vtkImageMathematics

from example_support import array_from_image, image_from_array, statistics, tone_map, write_png


def wavelet_slice(size):
    """A VTK pipeline: the z = 0 slice of the wavelet as a float radiance 3 n^4."""
    half = size // 2
    source = vtkRTAnalyticSource()
    source.SetWholeExtent(-half, size - half - 1, -half, size - half - 1, -8, 8)
    slice_ = vtkExtractVOI()
    slice_.SetInputConnection(source.GetOutputPort())
    slice_.SetVOI(-half, size - half - 1, -half, size - half - 1, 0, 0)
    cast = vtkImageCast()
    cast.SetInputConnection(slice_.GetOutputPort())
    cast.SetOutputScalarTypeToFloat()
    cast.Update()
    low, high = cast.GetOutput().GetScalarRange()
    normalized = vtkImageShiftScale()
    normalized.SetInputConnection(cast.GetOutputPort())
    normalized.SetShift(-low)
    normalized.SetScale(1.0 / (high - low))
    normalized.SetOutputScalarTypeToFloat()
    stages = [normalized]
    for operation in ("SetOperationToSquare", "SetOperationToSquare", "SetOperationToMultiplyByK"):
        stage = vtkImageMathematics()
        getattr(stage, operation)()
        stage.SetConstantK(3.0)
        stage.SetInputConnection(stages[-1].GetOutputPort())
        stages.append(stage)
    return stages[-1]


def numpy_slice(size):
    """A numpy field: a smooth temperature in [0, 0.6] with three hot spots up to 12."""
    y, x = np.mgrid[0:size, 0:size].astype(np.float64) / size
    temperature = 0.3 + 0.3 * np.sin(6.0 * x) * np.cos(4.0 * y)
    for cx, cy, peak in ((0.3, 0.35, 12.0), (0.7, 0.6, 6.0), (0.55, 0.2, 3.0)):
        temperature += peak * np.exp(-((x - cx) ** 2 + (y - cy) ** 2) / (2.0 * 0.01 ** 2))
    # A warm emission colour whose luminance is the temperature (0.2126 + 0.7152 * 0.6 +
    # 0.0722 * 0.25 = 0.6602, hence the 1 / 0.6602).
    colour = np.array([1.0, 0.6, 0.25]) / 0.6602
    rgb = (temperature[:, :, np.newaxis] * colour).astype(np.float32)
    return image_from_array(rgb, name="radiance")


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--source", choices=("wavelet", "numpy"), default="wavelet")
    parser.add_argument("--size", type=int, default=128)
    parser.add_argument("--preset", default="webgpu-market",
        choices=vtkbloom.vtkImageBloom.GetPresetNames())
    parser.add_argument("--save-input", action="store_true")
    parser.add_argument("output_prefix")
    args = parser.parse_args(argv[1:])
    if args.size < 2:
        parser.error("--size must be at least 2")

    bloom = vtkbloom.vtkImageBloom()
    bloom.SetPreset(args.preset)
    if args.source == "wavelet":
        source = wavelet_slice(args.size)
        bloom.SetInputConnection(source.GetOutputPort())
    else:
        bloom.SetInputData(numpy_slice(args.size))
    bloom.Update()
    if bloom.GetOutput().GetNumberOfPoints() == 0:
        print("the bloom failed", file=sys.stderr)
        return 1

    outputs = [(bloom, args.output_prefix + ".exr")]
    if args.save_input:
        outputs.append((bloom.GetInputAlgorithm(), args.output_prefix + "-input.exr"))
    for algorithm, path in outputs:
        writer = vtkbloom.vtkOpenEXRWriter()
        writer.SetFileName(path)
        writer.SetInputConnection(algorithm.GetOutputPort())
        if not writer.Write():
            print("cannot write %s" % path, file=sys.stderr)
            return 1
    write_png(tone_map(array_from_image(bloom.GetOutput())), args.output_prefix + ".png")

    stats = statistics(bloom.GetOutput())
    print("%s slice %dx%d, preset %s: energy %.6g -> %.6g (x%.3f), peak %.6g -> %.6g, "
        "%d bright pixels, %d levels" % (args.source, args.size, args.size, args.preset,
            stats["BloomEnergyIn"], stats["BloomEnergyOut"],
            stats["BloomEnergyOut"] / stats["BloomEnergyIn"], stats["BloomPeakLuminanceIn"],
            stats["BloomPeakLuminanceOut"], stats["BloomNumberOfBrightPixels"],
            stats["BloomNumberOfLevelsUsed"]))
    print("wrote %s.exr and %s.png" % (args.output_prefix, args.output_prefix))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
