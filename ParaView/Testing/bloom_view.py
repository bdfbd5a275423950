"""pvbatch script: render a distributed scene in the bloom render view and save a screenshot.

    scripts/pvbatch.sh [-n N] ParaView/Testing/bloom_view.py OUT.png [PRESET [USE_BLOOM]]

The scene: a sphere split into pieces over the ranks (each rank renders its own) in a dim blue,
and in front of it three small bright spheres, unlit (ambient 1), on a black background, in a
"Render View (Bloom)". Colours stay at or below 1, so the image that IceT composites in 8 bits
under MPI is the scene the serial float target holds; the bright spheres pass the threshold
(0.6) and bloom over the dim one and the background.
"""
import sys

from paraview.simple import *  # noqa: F403

out = sys.argv[1]
preset = sys.argv[2] if len(sys.argv) > 2 else 'custom'
use_bloom = int(sys.argv[3]) if len(sys.argv) > 3 else 1

view = CreateView('BloomRenderView')
view.ViewSize = [480, 360]
view.OrientationAxesVisibility = 0
view.UseFXAA = int(sys.argv[4]) if len(sys.argv) > 4 else 0
view.UseColorPaletteForBackground = 0
view.Background = [0.0, 0.0, 0.0]
view.UseBloom = use_bloom
view.BloomPreset = preset
view.BloomThreshold = 0.6
view.BloomKnee = 0.5
view.BloomStrength = 1.0


def sphere(center, radius, color, resolution):
    source = Sphere(Center=center, Radius=radius, ThetaResolution=resolution,
                    PhiResolution=resolution)
    display = Show(source, view)
    display.AmbientColor = color
    display.DiffuseColor = color
    display.Ambient = 1.0
    display.Diffuse = 0.0
    return display


sphere([0.0, 0.0, -2.0], 2.0, [0.10, 0.15, 0.45], 96)
sphere([-1.2, 0.6, 1.0], 0.35, [1.0, 0.85, 0.4], 48)
sphere([0.9, -0.5, 1.0], 0.25, [0.5, 1.0, 0.9], 48)
sphere([0.2, 1.1, 0.5], 0.15, [1.0, 0.5, 0.9], 48)
view.CameraPosition = [0.0, 0.0, 9.0]
view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraViewUp = [0.0, 1.0, 0.0]
Render(view)
SaveScreenshot(out, view, ImageResolution=[480, 360])
print('bloom_view: wrote', out)
