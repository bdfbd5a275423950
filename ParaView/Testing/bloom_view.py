# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
"""pvbatch script: render a distributed scene in the bloom render view and save a screenshot.

    scripts/pvbatch.sh [-n N] ParaView/Testing/bloom_view.py OUT.png [PRESET [USE_BLOOM]]

The scene: a sphere split into pieces over the ranks (each rank renders its own) in a dim blue,
and in front of it three small bright spheres, unlit (ambient 1), on a black background, in a
"Render View (Bloom)". Colours stay at or below 1, so the image that IceT composites in 8 bits
under MPI is the scene the serial float target holds; the bright spheres pass the threshold
(0.6, the smoothstep knee: the view's default, the excess knee at 1, would bloom nothing here)
and bloom over the dim one and the background.
"""
import os
import sys

from paraview.simple import *  # noqa: F403

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from spheres_scene import show_spheres  # noqa: E402
from screenshot import save  # noqa: E402  (SaveScreenshot that fails)

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
view.BloomThresholdMode = 0  # the smoothstep knee: these colours stay at or below 1
view.BloomThreshold = 0.6
view.BloomKnee = 0.5
view.BloomStrength = 1.0

show_spheres(view, [0.10, 0.15, 0.45], lit=False)
Render(view)
save(out, view, ImageResolution=[480, 360])
print('bloom_view: wrote', out)
