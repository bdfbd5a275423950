#!/usr/bin/env python3
"""Plot vtkBloomPass's exact pass and fast mode, per preset, on a GPU: error against time.

    /usr/bin/python3 scripts/plot-gpu-quality.py quality.csv out.png

quality.csv is written by `BloomPassFrameTime --quality SCENE WIDTH HEIGHT FRAMES quality.csv`
(scripts/gpu-run.sh runs it on the H100 at 3840x2160; docs/data/gpu-quality-h100.csv is that
run). x: the bloom's GPU time over the float-target-plus-copy floor; y: relative L2 of the
colour against vtkImageBloom REFERENCE (double) on the same float render. One colour per
preset; a square for the exact pass, a cross for the fast mode, a line joining the two. Log-log,
with VTK's vtkChartXY, headless (needs an X display: xvfb-run), like scripts/plot-accuracy.py.
"""
import csv
import sys
from collections import OrderedDict

from vtkmodules.vtkChartsCore import vtkAxis, vtkChart, vtkChartXY
from vtkmodules.vtkCommonCore import vtkFloatArray
from vtkmodules.vtkCommonDataModel import vtkTable
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter
from vtkmodules.vtkViewsContext2D import vtkContextView
import vtkmodules.vtkRenderingContextOpenGL2  # noqa: F401 (context device)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (render window)

COLOURS = [(31, 119, 180), (255, 127, 14), (44, 160, 44), (214, 39, 40), (148, 103, 189)]


def table(name, points):
    t = vtkTable()
    x = vtkFloatArray()
    x.SetName("time " + name)
    y = vtkFloatArray()
    y.SetName(name)
    t.AddColumn(x)
    t.AddColumn(y)
    t.SetNumberOfRows(len(points))
    for r, (a, b) in enumerate(points):
        t.SetValue(r, 0, a)
        t.SetValue(r, 1, b)
    return t


def main():
    source, target = sys.argv[1], sys.argv[2]
    presets = OrderedDict()
    with open(source, newline="") as f:
        for row in csv.DictReader(f):
            presets.setdefault(row["preset"], {})[row["quality"]] = (
                float(row["gpu_ms_over_floor"]), float(row["rel_l2_vs_reference"]))
    view = vtkContextView()
    view.GetRenderWindow().SetSize(1000, 650)
    view.GetRenderWindow().SetOffScreenRendering(1)
    view.GetRenderer().SetBackground(1.0, 1.0, 1.0)
    chart = vtkChartXY()
    view.GetScene().AddItem(chart)
    chart.SetShowLegend(True)
    chart.SetTitle("vtkBloomPass on an NVIDIA H100, 3840x2160: exact pass (square) and fast "
                   "mode (cross)")
    for axis, title in ((vtkAxis.BOTTOM, "bloom over the floor, GPU time (ms)"),
                        (vtkAxis.LEFT, "relative L2 against vtkImageBloom REFERENCE")):
        chart.GetAxis(axis).SetLogScale(True)
        chart.GetAxis(axis).SetTitle(title)
    for index, (preset, rows) in enumerate(presets.items()):
        colour = COLOURS[index % len(COLOURS)]
        both = [rows[q] for q in ("exact", "fast") if q in rows]
        line = chart.AddPlot(vtkChart.LINE)
        line.SetInputData(table(preset, both), 0, 1)
        line.SetColor(colour[0], colour[1], colour[2], 255)
        line.SetWidth(1.5)
        line.SetMarkerStyle(0)
        for quality, marker in (("exact", 3), ("fast", 1)):
            if quality in rows:
                points = chart.AddPlot(vtkChart.POINTS)
                points.SetInputData(table(preset + " " + quality, [rows[quality]]), 0, 1)
                points.SetColor(colour[0], colour[1], colour[2], 255)
                points.SetMarkerStyle(marker)
                points.SetMarkerSize(14.0)
                points.SetLegendVisibility(False)
    view.GetRenderWindow().Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(view.GetRenderWindow())
    grab.ReadFrontBufferOff()
    grab.Update()
    writer = vtkPNGWriter()
    writer.SetFileName(target)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()


if __name__ == "__main__":
    main()
