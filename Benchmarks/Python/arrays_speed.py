#!/usr/bin/python3
# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
"""vtkbloom.bloom on a numpy frame against vtkImageBloom on the same frame as a vtkImageData
(what a VTK user would otherwise run), and the cheapest float copy of it, interleaved:

    PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 Benchmarks/Python/arrays_speed.py [FRAMES]

Prints the median, mean and 99th percentile of each, in ms, and the ratio of the medians.
"""

import statistics
import sys
import time

import numpy as np
from vtkmodules.util import numpy_support
from vtkmodules.vtkCommonDataModel import vtkImageData

import vtkbloom


def frame(height=1080, width=1920):
    rng = np.random.default_rng(7)
    image = (0.4 * rng.random((height, width, 4))).astype(np.float32)
    for k in range(40):  # lights above 1
        y, x = rng.integers(0, height - 8), rng.integers(0, width - 8)
        image[y : y + 6, x : x + 6, :3] = 4.0 + 20.0 * rng.random()
    image[..., 3] = 1.0
    return image


def summary(times):
    ms = sorted(1e3 * t for t in times)
    p99 = ms[min(len(ms) - 1, int(round(0.99 * (len(ms) - 1))))]
    return statistics.median(ms), statistics.fmean(ms), p99


def main():
    frames = int(sys.argv[1]) if len(sys.argv) > 1 else 30
    image = frame()
    h, w, c = image.shape
    data = vtkImageData()
    data.SetDimensions(w, h, 1)
    data.GetPointData().SetScalars(numpy_support.numpy_to_vtk(image.reshape(h * w, c), deep=True))
    filter_ = vtkbloom.vtkImageBloom()
    filter_.SetPreset("webgpu-market")
    filter_.SetComputeStatistics(False)  # as vtkbloom.bloom without statistics=True
    filter_.SetInputData(data)

    def run_filter():
        filter_.Modified()
        filter_.Update()

    def run_arrays():
        vtkbloom.bloom(image, preset="webgpu-market")

    def run_copy():
        image.copy()

    runs = {"vtkImageBloom (vtkImageData)": run_filter, "vtkbloom.bloom (numpy)": run_arrays,
            "numpy copy of the frame": run_copy}
    times = {name: [] for name in runs}
    for name, run in runs.items():
        run()  # warm up
    for _ in range(frames):
        for name, run in runs.items():
            start = time.perf_counter()
            run()
            times[name].append(time.perf_counter() - start)
    print("1920x1080 RGBA float32, webgpu-market, %d frames each, interleaved" % frames)
    print("| run | median ms | mean ms | p99 ms |")
    print("|---|---:|---:|---:|")
    for name in runs:
        print("| %s | %.2f | %.2f | %.2f |" % ((name,) + summary(times[name])))
    ratio = summary(times["vtkbloom.bloom (numpy)"])[0] / summary(times["vtkImageBloom (vtkImageData)"])[0]
    print("vtkbloom.bloom / vtkImageBloom (medians): %.3f" % ratio)


if __name__ == "__main__":
    main()
