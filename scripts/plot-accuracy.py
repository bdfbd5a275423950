#!/usr/bin/env python3
"""Plot the accuracy-versus-time study with VTK's own charts (vtkChartXY), headless.

    /usr/bin/python3 scripts/plot-accuracy.py accuracy.csv out.png

Error (max abs over the peak) against time per megapixel, log-log, one curve per method (its
points are the sigmas, or the level counts for the pyramid chains). The GPU rows (family gpu:
vtkBloomPass, and family cpu: vtkImageBloom FAST, each against the filter's double chain) are
markers without lines, one per preset; the double chain itself (error 0) is not drawn. Needs an
X display (xvfb-run) with Debian's VTK.
"""
import csv
import sys
from collections import OrderedDict

from vtkmodules.vtkChartsCore import vtkAxis, vtkChart, vtkChartXY
from vtkmodules.vtkCommonCore import vtkFloatArray
from vtkmodules.vtkCommonDataModel import vtkTable
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingContext2D import vtkPen
from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter
from vtkmodules.vtkViewsContext2D import vtkContextView
import vtkmodules.vtkRenderingContextOpenGL2  # noqa: F401 (context device)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (render window)

COLOURS = [(31, 119, 180), (255, 127, 14), (44, 160, 44), (214, 39, 40), (148, 103, 189),
           (140, 86, 75), (227, 119, 194), (127, 127, 127), (188, 189, 34), (23, 190, 207),
           (0, 0, 0), (255, 187, 120), (0, 128, 128), (128, 0, 0)]


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
    view = vtkContextView()
    view.GetRenderWindow().SetSize(1100, 700)
    view.GetRenderWindow().SetOffScreenRendering(1)
    view.GetRenderer().SetBackground(1.0, 1.0, 1.0)
    chart = vtkChartXY()
    view.GetScene().AddItem(chart)
    chart.SetShowLegend(True)
    chart.SetTitle("Gaussian methods, bloom pyramids and the GPU pass: error against time "
                   "(1920x1080 RGBA)")
    for axis, title in ((vtkAxis.BOTTOM, "time per megapixel (ms)"),
                        (vtkAxis.LEFT, "max abs error / peak")):
        chart.GetAxis(axis).SetLogScale(True)
        chart.GetAxis(axis).SetTitle(title)
    for index, (name, points) in enumerate(curves.items()):
        # Points stay in sigma (or level) order, so a curve runs from narrow to wide.
        table = vtkTable()
        x = vtkFloatArray()
        x.SetName("time " + name)
        y = vtkFloatArray()
        y.SetName(name)
        table.AddColumn(x)
        table.AddColumn(y)
        table.SetNumberOfRows(len(points))
        for r, (t, e) in enumerate(points):
            table.SetValue(r, 0, t)
            table.SetValue(r, 1, e)
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
