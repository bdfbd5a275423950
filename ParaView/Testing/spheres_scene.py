# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
"""The scene of bloom_view.py and bloom_view_hdr.py, shown in a view (imported, not run).

A large sphere split into pieces over the ranks (each rank renders its own) in a dim colour,
and in front of it three small bright spheres, the camera on +z. Unlit (ambient 1) the colours
are the ones given; lit (diffuse 1) they are scaled by the view's lights.
"""
from paraview.simple import AddLight, CreateView, Show, Sphere


def show_spheres(view, dim_colour, lit):
    spheres = ([0.0, 0.0, -2.0], 2.0, dim_colour, 96), \
              ([-1.2, 0.6, 1.0], 0.35, [1.0, 0.85, 0.4], 48), \
              ([0.9, -0.5, 1.0], 0.25, [0.5, 1.0, 0.9], 48), \
              ([0.2, 1.1, 0.5], 0.15, [1.0, 0.5, 0.9], 48)
    for center, radius, colour, resolution in spheres:
        source = Sphere(Center=center, Radius=radius, ThetaResolution=resolution,
                        PhiResolution=resolution)
        display = Show(source, view)
        display.AmbientColor = colour
        display.DiffuseColor = colour
        display.Ambient = 0.0 if lit else 1.0
        display.Diffuse = 1.0 if lit else 0.0
    view.CameraPosition = [0.0, 0.0, 9.0]
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraViewUp = [0.0, 1.0, 0.0]


def hdr_view(size):
    """The HDR view of bloom_view_hdr.py (and its interactive and timing variants): a grey
    background, a headlight of intensity 6 alone, bloom only above 1 (threshold 1, knee 0) at
    strength 0.5, no FXAA, the spheres lit, so that the small ones reach 3 to 6."""
    view = CreateView('BloomRenderView')
    view.ViewSize = size
    view.OrientationAxesVisibility = 0
    view.UseFXAA = 0
    view.UseColorPaletteForBackground = 0
    view.Background = [0.2, 0.2, 0.25]
    view.BloomThreshold = 1.0
    view.BloomKnee = 0.0
    view.BloomStrength = 0.5
    view.UseLight = 0  # no light kit: the headlight alone
    light = AddLight(view=view)
    light.Coords = 'Headlight'
    light.Intensity = 6.0
    show_spheres(view, [0.02, 0.025, 0.075], lit=True)
    return view
