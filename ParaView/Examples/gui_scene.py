# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
"""Run in ParaView's GUI (paraview --script=...): the README's screenshot scene.

Left, "Render View (Bloom)": a dim sphere and three small bright ones, unlit, bloomed by the
render pass after compositing. Right, a render view showing the Bloom filter's output: an HDR
image (an RGB field computed from the Wavelet, peaks near 3) bloomed with the webgpu-market
preset, as true colours. The Bloom filter is the active source, so its panel is shown.
"""
from paraview.simple import *  # noqa: F403

layout = GetLayout()
bloom_view = GetActiveViewOrCreate('RenderView')
Delete(bloom_view)
bloom_view = CreateView('BloomRenderView')
AssignViewToLayout(view=bloom_view, layout=layout, hint=0)
bloom_view.OrientationAxesVisibility = 0
bloom_view.UseColorPaletteForBackground = 0
bloom_view.Background = [0.0, 0.0, 0.0]
bloom_view.BloomThreshold = 0.6
for center, radius, color in (([0.0, 0.0, -2.0], 2.0, [0.10, 0.15, 0.45]),
                              ([-1.2, 0.6, 1.0], 0.35, [1.0, 0.85, 0.4]),
                              ([0.9, -0.5, 1.0], 0.25, [0.5, 1.0, 0.9]),
                              ([0.2, 1.1, 0.5], 0.15, [1.0, 0.5, 0.9])):
    sphere = Sphere(Center=center, Radius=radius, ThetaResolution=64, PhiResolution=64)
    shown = Show(sphere, bloom_view)
    shown.AmbientColor = color
    shown.DiffuseColor = color
    shown.Ambient = 1.0
    shown.Diffuse = 0.0
bloom_view.CameraPosition = [0.0, 0.0, 13.0]
bloom_view.CameraFocalPoint = [0.0, 0.0, 0.0]
bloom_view.CameraViewUp = [0.0, 1.0, 0.0]

image_view = CreateView('RenderView')
AssignViewToLayout(view=image_view, layout=layout, hint=0)
image_view.OrientationAxesVisibility = 0
image_view.UseColorPaletteForBackground = 0
image_view.Background = [0.0, 0.0, 0.0]
image_view.InteractionMode = '2D'
wavelet = Wavelet(WholeExtent=[-128, 127, -96, 95, 0, 0], Maximum=300.0)
hdr = Calculator(Input=wavelet, ResultArrayName='rgb', ResultArrayType='Float',
                 Function='3*(RTData/300)^12*iHat + 2*(RTData/300)^16*jHat'
                          ' + (0.03 + 0.2*(RTData/300)^4)*kHat')
bloom = Bloom(Input=hdr, Preset='webgpu-market')
bloom.Scalars = ['POINTS', 'rgb']
display = Show(bloom, image_view)
display.SetRepresentationType('Slice')
display.MapScalars = 0
image_view.CameraPosition = [0.0, 0.0, 500.0]
image_view.CameraFocalPoint = [0.0, 0.0, 0.0]
image_view.CameraViewUp = [0.0, 1.0, 0.0]
image_view.CameraParallelProjection = 1
image_view.CameraParallelScale = 130.0
SetActiveView(image_view)
SetActiveSource(bloom)
Render(bloom_view)
Render(image_view)
