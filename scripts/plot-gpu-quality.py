#!/usr/bin/env python3
# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
"""Plot vtkBloomPass's exact pass and fast mode, per preset, on a GPU: error against time.

    /usr/bin/python3 scripts/plot-gpu-quality.py quality.csv out.png [CARD]

quality.csv is written by `BloomPassFrameTime --quality SCENE WIDTH HEIGHT FRAMES quality.csv`
(scripts/gpu-run.sh runs it on the H100 at 3840x2160; docs/data/gpu-quality-h100.csv is that
run, docs/data/gpu-quality-h200.csv the latest, on an NVIDIA H200; CARD names the card in the
title, default "NVIDIA H100"). x: the bloom's GPU time over the float-target-plus-copy floor; y: relative L2 of the
colour against vtkImageBloom REFERENCE (double) on the same float render. One colour per
preset; a square for the exact pass, a cross for the fast mode, a line joining the two. Log-log,
with VTK's vtkChartXY, headless (needs an X display: xvfb-run), like scripts/plot-accuracy.py;
where a bloom costs less than the floor (a negative time) vtkChartXY keeps x linear.
"""
import csv
import os
import sys
from collections import OrderedDict

from vtkmodules.vtkChartsCore import vtkChart

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), 'lib'))
from vtkbloom_charts import COLOURS, log_log_chart, save_png, xy_table  # noqa: E402


def main():
    source, target = sys.argv[1], sys.argv[2]
    card = sys.argv[3] if len(sys.argv) > 3 else "NVIDIA H100"
    presets = OrderedDict()
    with open(source, newline="") as f:
        for row in csv.DictReader(f):
            presets.setdefault(row["preset"], {})[row["quality"]] = (
                float(row["gpu_ms_over_floor"]), float(row["rel_l2_vs_reference"]))
    view, chart = log_log_chart(
        "vtkBloomPass on an " + card + ", 3840x2160: exact pass (square) and fast mode (cross)",
        "bloom over the floor, GPU time (ms)", "relative L2 against vtkImageBloom REFERENCE",
        (1000, 650))
    for index, (preset, rows) in enumerate(presets.items()):
        colour = COLOURS[index % len(COLOURS)]
        both = [rows[q] for q in ("exact", "fast") if q in rows]
        if len(both) > 1:
            # A setting with one row (the compute FFT's: PSF bloom, blurs tap by tap) has no line.
            line = chart.AddPlot(vtkChart.LINE)
            line.SetInputData(xy_table(preset, both), 0, 1)
            line.SetColor(colour[0], colour[1], colour[2], 255)
            line.SetWidth(1.5)
            line.SetMarkerStyle(0)
        for quality, marker in (("exact", 3), ("fast", 1)):
            if quality in rows:
                points = chart.AddPlot(vtkChart.POINTS)
                alone = len(both) < 2  # no line names it in the legend: the square does
                points.SetInputData(
                    xy_table(preset if alone else preset + " " + quality, [rows[quality]]), 0, 1)
                points.SetColor(colour[0], colour[1], colour[2], 255)
                points.SetMarkerStyle(marker)
                points.SetMarkerSize(14.0)
                points.SetLegendVisibility(alone)
    save_png(view, target)

if __name__ == "__main__":
    main()
