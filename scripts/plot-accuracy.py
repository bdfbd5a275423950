#!/usr/bin/env python3
# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
"""Plot the accuracy-versus-time study with VTK's own charts (vtkChartXY), headless.

    /usr/bin/python3 scripts/plot-accuracy.py accuracy.csv out.png

Error (max abs over the peak) against time per megapixel, log-log, one curve per method (its
points are the sigmas, or the level counts for the pyramid chains). The GPU rows (family gpu:
vtkBloomPass, and family cpu: vtkImageBloom FAST, each against the filter's double chain) are
markers without lines, one per preset; the double chain itself (error 0) is not drawn. Needs an
X display (xvfb-run) with Debian's VTK.
"""
import csv
import os
import sys
from collections import OrderedDict

from vtkmodules.vtkChartsCore import vtkChart
from vtkmodules.vtkRenderingContext2D import vtkPen

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), 'lib'))
from vtkbloom_charts import COLOURS, log_log_chart, save_png, xy_table  # noqa: E402


def main():
    source, target = sys.argv[1], sys.argv[2]
    curves = OrderedDict()
    points_only = set()
    with open(source, newline="") as f:
        for row in csv.DictReader(f):
            if row["family"] in ("gpu", "cpu") or "ping-pong" in row["method"]:
                if float(row["max_abs"]) == 0.0:
                    continue  # the reference itself
                points_only.add(row["method"])
            curves.setdefault(row["method"], []).append(
                (float(row["ms_per_mp"]), max(float(row["max_abs"]), 1e-12)))
    view, chart = log_log_chart(
        "Gaussian methods, bloom pyramids and the GPU pass: error against time (1920x1080 RGBA)",
        "time per megapixel (ms)", "max abs error / peak", (1100, 700))
    for index, (name, points) in enumerate(curves.items()):
        # Points stay in sigma (or level) order, so a curve runs from narrow to wide.
        table = xy_table(name, points)
        colour = COLOURS[index % len(COLOURS)]
        if name in points_only:
            # One marker per preset: the presets are not a sequence.
            line = chart.AddPlot(vtkChart.POINTS)
            line.SetInputData(table, 0, 1)
            line.SetColor(colour[0], colour[1], colour[2], 255)
            line.SetMarkerStyle(5 if "GPU" in name else 3)
            line.SetMarkerSize(12.0)
            continue
        line = chart.AddPlot(vtkChart.LINE)
        line.SetInputData(table, 0, 1)
        line.SetColor(colour[0], colour[1], colour[2], 255)
        line.SetWidth(2.0)
        if name.startswith("pyramid"):
            line.GetPen().SetLineType(vtkPen.DASH_LINE)
        line.SetMarkerStyle(4 if name.startswith("pyramid") else 2)
    save_png(view, target)

if __name__ == "__main__":
    main()
