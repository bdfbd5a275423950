# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
"""Shared by the plot scripts: log-log charts drawn with VTK's own vtkChartXY, saved as PNG.

Needs an X display (xvfb-run) with Debian's VTK. Not a script: imported by
scripts/plot-accuracy.py and scripts/plot-gpu-quality.py, from this folder (scripts/lib).
"""
from vtkmodules.vtkChartsCore import vtkAxis, vtkChartXY
from vtkmodules.vtkCommonCore import vtkFloatArray
from vtkmodules.vtkCommonDataModel import vtkTable
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter
from vtkmodules.vtkViewsContext2D import vtkContextView
import vtkmodules.vtkRenderingContextOpenGL2  # noqa: F401 (context device)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (render window)

COLOURS = [(31, 119, 180), (255, 127, 14), (44, 160, 44), (214, 39, 40), (148, 103, 189),
           (140, 86, 75), (227, 119, 194), (127, 127, 127), (188, 189, 34), (23, 190, 207),
           (0, 0, 0), (255, 187, 120), (0, 128, 128), (128, 0, 0)]


def xy_table(name, points):
    """A two-column vtkTable ("time NAME", NAME) of (x, y) points, in the order given."""
    table = vtkTable()
    x = vtkFloatArray()
    x.SetName("time " + name)
    y = vtkFloatArray()
    y.SetName(name)
    table.AddColumn(x)
    table.AddColumn(y)
    table.SetNumberOfRows(len(points))
    for r, (a, b) in enumerate(points):
        table.SetValue(r, 0, a)
        table.SetValue(r, 1, b)
    return table


def log_log_chart(title, x_title, y_title, size):
    """An off-screen context view holding a vtkChartXY with a legend and log-scaled axes."""
    view = vtkContextView()
    view.GetRenderWindow().SetSize(*size)
    view.GetRenderWindow().SetOffScreenRendering(1)
    view.GetRenderer().SetBackground(1.0, 1.0, 1.0)
    chart = vtkChartXY()
    view.GetScene().AddItem(chart)
    chart.SetShowLegend(True)
    chart.SetTitle(title)
    for axis, axis_title in ((vtkAxis.BOTTOM, x_title), (vtkAxis.LEFT, y_title)):
        chart.GetAxis(axis).SetLogScale(True)
        chart.GetAxis(axis).SetTitle(axis_title)
    return view, chart


def save_png(view, path):
    """Render the view and write its image to path."""
    view.GetRenderWindow().Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(view.GetRenderWindow())
    grab.ReadFrontBufferOff()
    grab.Update()
    writer = vtkPNGWriter()
    writer.SetFileName(path)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()
