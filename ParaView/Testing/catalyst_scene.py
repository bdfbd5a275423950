# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
"""The in situ scene of bloom_catalyst.py and its pvbatch reference (imported, not run).

The wavelet mini-app's field (paraview.demos.wavelet_miniapp: vtkRTAnalyticSource, RTData) in
a "Render View (Bloom)" of 320x240: the slice x = 0 coloured by RTData, unlit
(ambient 1), so nothing there exceeds display white; and the field's hot range, the isosurface
RTData = HOT, lit by a headlight of intensity 2, so that it reaches up to 2 and glows by its
excess above the threshold (1). The camera is fixed, so that every step and every rank
frame it the same. The hot range is present at every step (the field's maximum is 286 at the first
step): a representation that first gets data at a later step would make ParaView reset the
camera there.
"""
from paraview.simple import (AddLight, ColorBy, Contour, CreateView, GetColorTransferFunction,
                             Show, Slice)

VIEW_SIZE = [320, 240]
IMAGE_SIZE = [640, 480]  # the image extractor's, larger than the view: rendered in tiles
HOT = 270.0


def frame(view):
    """The fixed camera (Catalyst resets a new view's camera to the first step's data)."""
    view.CameraPosition = [190.0, 50.0, 60.0]
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    view.CameraViewAngle = 30.0


def bloom_view():
    view = CreateView('BloomRenderView')
    view.ViewSize = VIEW_SIZE
    view.OrientationAxesVisibility = 0
    view.UseFXAA = 0
    view.UseColorPaletteForBackground = 0
    view.Background = [0.04, 0.04, 0.06]
    view.UseLight = 0  # no light kit: the headlight alone
    light = AddLight(view=view)
    light.Coords = 'Headlight'
    light.Intensity = 2.0
    frame(view)
    return view


def show_field(source, view):
    cut = Slice(Input=source)  # the plane x = 0 through the middle
    slice_display = Show(cut, view)
    ColorBy(slice_display, ('POINTS', 'RTData'))
    lut = GetColorTransferFunction('RTData')
    # Viridis' ends and middle, given as points: the preset's name differs between ParaView
    # 5.11 and 6.1, and a failed ApplyPreset on ParaView 6.1 hangs a 3-rank Catalyst run.
    lut.RGBPoints = [30.0, 0.267, 0.005, 0.329, 155.0, 0.128, 0.567, 0.551,
                     280.0, 0.993, 0.906, 0.144]
    lut.AutomaticRescaleRangeMode = 'Never'
    slice_display.Ambient = 1.0
    slice_display.Diffuse = 0.0
    hot = Contour(Input=source)
    hot.ContourBy = ['POINTS', 'RTData']
    hot.Isosurfaces = [HOT]
    # Flat shading: point normals from the field's gradient differ where the ranks' pieces
    # meet (no ghost points), triangles do not.
    hot.ComputeNormals = 0
    hot.ComputeScalars = 0  # no RTData on the surface: it shows its solid colour
    hot_display = Show(hot, view)
    hot_display.DiffuseColor = [1.0, 0.55, 0.2]
    hot_display.Ambient = 0.0
    hot_display.Diffuse = 1.0
