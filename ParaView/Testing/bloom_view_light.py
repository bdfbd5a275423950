# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
"""pvbatch script: a figure as users make it in the bloom render view, saved as screenshots.

    scripts/pvbatch.sh ParaView/Testing/bloom_view_light.py OUTDIR

A lit sphere coloured by its elevation, a text source, the colour legend and the orientation
axes, nothing in it above 1, in the bloom view at its defaults. Each screenshot is
OUTDIR/NAME-BLOOM.png, with the bloom off (0) and on (1):
- white: the white palette (figures for print), dark: a dark background;
- lamp-white, lamp-dark: the same with an HDR lamp beside the text (an unlit sphere whose
  ambient colour is 4, 2, 0.8: ParaView clamps the Ambient coefficient to 1, not the colour);
- nolabel-dark: the dark figure without its annotations (to find the text's pixels);
- fxaa, tonemap: the dark figure with the lamp and ParaView's FXAA or its tone mapping on.
Every shot renders the view with the bloom off, then turns it on, as a user toggles it: with
FXAA on, the renderer's own FXAA once ran inside the bloom's scene render, in 8 bits, which
clamped the lamp to 1 and darkened the edges over white.
run_tests.py checks them (part 6).
"""
import os
import sys

from paraview.simple import *  # noqa: F403

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from screenshot import save  # noqa: E402  (SaveScreenshot that fails)

out = sys.argv[1]
os.makedirs(out, exist_ok=True)

view = CreateView('BloomRenderView')
view.ViewSize = [400, 300]
view.UseFXAA = 0
view.CameraPosition = [0.0, 0.0, 6.0]
view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraViewUp = [0.0, 1.0, 0.0]

sphere = Sphere(Center=[-0.6, 0.0, 0.0], Radius=0.9, ThetaResolution=64, PhiResolution=64)
elevation = Elevation(Input=sphere, LowPoint=[0.0, -1.0, 0.0], HighPoint=[0.0, 1.0, 0.0])
surface = Show(elevation, view)
ColorBy(surface, ('POINTS', 'Elevation'))
surface.SetScalarBarVisibility(view, True)
text = Text(Text='T = 300 K')
label = Show(text, view)
label.WindowLocation = 'Any Location'
label.Position = [0.62, 0.55]
label.FontSize = 20
label.Color = [0.3, 0.6, 1.0]
lamp = Sphere(Center=[1.4, 0.62, 0.0], Radius=0.12, ThetaResolution=32, PhiResolution=32)
glow = Show(lamp, view)
glow.Ambient = 1.0
glow.Diffuse = 0.0
glow.AmbientColor = [4.0, 2.0, 0.8]


def shoot(name, background, lamp_on=False, annotations=True):
    LoadPalette('WhiteBackground' if background == 'white' else 'BlackBackground')
    view.OrientationAxesVisibility = 1 if annotations else 0
    label.Visibility = 1 if annotations else 0
    surface.SetScalarBarVisibility(view, annotations)
    glow.Visibility = 1 if lamp_on else 0
    for bloom in (0, 1):
        view.UseBloom = bloom
        Render(view)
        save(os.path.join(out, '%s-%d.png' % (name, bloom)), view,
                       ImageResolution=[400, 300])


shoot('white', 'white')
shoot('dark', 'dark')
shoot('lamp-white', 'white', lamp_on=True)
shoot('lamp-dark', 'dark', lamp_on=True)
shoot('nolabel-dark', 'dark', annotations=False)
view.UseFXAA = 1
shoot('fxaa', 'dark', lamp_on=True)
shoot('fxaa-nolamp', 'dark')
view.UseFXAA = 0
view.UseToneMapping = 1
shoot('tonemap', 'dark', lamp_on=True)
shoot('tonemap-nolamp', 'dark')
print('bloom_view_light: wrote', out)
