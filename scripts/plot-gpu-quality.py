#!/usr/bin/env python3
# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
"""Plot vtkBloomPass's error against its time, per setting, on a GPU.

    /usr/bin/python3 scripts/plot-gpu-quality.py quality.csv out.png [CARD]

quality.csv is written by `BloomPassFrameTime --quality SCENE WIDTH HEIGHT FRAMES quality.csv`
(scripts/gpu-run.sh runs it at 3840x2160; docs/data/gpu-quality-h100.csv and
docs/data/gpu-quality-h200.csv are runs on an NVIDIA H100 and H200; CARD names the card in the
title, default "NVIDIA H100"). x: the bloom's GPU time over the float-target-plus-copy floor;
y: relative L2 of the colour against vtkImageBloom REFERENCE (double) on the same float render.
One point per setting: every preset, blurs tap by tap, PSF bloom exact and split. Files written
before the fast mode was retired have a `quality` column; only their exact rows are plotted.
Log-log, with VTK's vtkChartXY, headless (needs an X display: xvfb-run), like
scripts/plot-accuracy.py; where a bloom costs less than the floor (a negative time) vtkChartXY
keeps x linear.
"""
import csv
import os
import sys

from vtkmodules.vtkChartsCore import vtkChart

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), 'lib'))
from vtkbloom_charts import COLOURS, log_log_chart, save_png, xy_table  # noqa: E402


def main():
    source, target = sys.argv[1], sys.argv[2]
    card = sys.argv[3] if len(sys.argv) > 3 else "NVIDIA H100"
    points = []
    with open(source, newline="") as f:
        for row in csv.DictReader(f):
            if row.get("quality", "exact") == "exact":
                points.append((row["preset"], float(row["gpu_ms_over_floor"]),
                               float(row["rel_l2_vs_reference"])))
    view, chart = log_log_chart(
        "vtkBloomPass on an " + card + ", 3840x2160: error against time",
        "bloom over the floor, GPU time (ms)", "relative L2 against vtkImageBloom REFERENCE",
        (1000, 650))
    for index, (name, ms, error) in enumerate(points):
        colour = COLOURS[index % len(COLOURS)]
        plot = chart.AddPlot(vtkChart.POINTS)
        plot.SetInputData(xy_table(name, [(ms, error)]), 0, 1)
        plot.SetColor(colour[0], colour[1], colour[2], 255)
        plot.SetMarkerStyle(3)
        plot.SetMarkerSize(14.0)
    save_png(view, target)


if __name__ == "__main__":
    main()
