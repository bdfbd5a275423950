# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
"""pvbatch script: the bloom view saved at its size, resized, and in tiles.

    scripts/pvbatch.sh ParaView/Testing/bloom_view_scale.py OUT_PREFIX REFERENCE_HEIGHT [TILED]

The scene of bloom_view.py in a "Render View (Bloom)" of 480x360, then of 960x720 (the view
resized before SaveScreenshot, so that ParaView renders the larger frame at once rather than in
tiles), with and without bloom: OUT_PREFIX-{bloom,plain}-{1,2}.png. With a reference height
(BloomReferenceHeight) the bloom keeps its size relative to the picture; with 0 (sizes in
pixels) the glow shrinks. run_tests.py compares the two bloom terms.

With TILED (1), also the screenshots that ParaView renders in tiles: the 480x360 view saved at
2x and 4x its size (OUT_PREFIX-{bloom,plain}-tiled{2,4}.png), and the view resized to 4x
(OUT_PREFIX-{bloom,plain}-4.png), which the tiled ones must equal.
"""
import os
import sys

from paraview.simple import *  # noqa: F403

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from spheres_scene import show_spheres  # noqa: E402
from screenshot import save  # noqa: E402  (SaveScreenshot that fails)

prefix = sys.argv[1]
reference_height = int(sys.argv[2])
tiled = len(sys.argv) > 3 and sys.argv[3] == '1'

view = CreateView('BloomRenderView')
view.OrientationAxesVisibility = 0
view.UseColorPaletteForBackground = 0
view.Background = [0.0, 0.0, 0.0]
view.BloomThresholdMode = 0  # the smoothstep knee: these colours stay at or below 1
view.BloomThreshold = 0.6
view.BloomKnee = 0.5
view.BloomStrength = 1.0
view.BloomReferenceHeight = reference_height
show_spheres(view, [0.10, 0.15, 0.45], lit=False)
for use_bloom in (1, 0):
    view.UseBloom = use_bloom
    for scale in (1, 2):
        size = [480 * scale, 360 * scale]
        view.ViewSize = size
        Render(view)
        out = '%s-%s-%d.png' % (prefix, 'bloom' if use_bloom else 'plain', scale)
        save(out, view, ImageResolution=size)
        print('bloom_view_scale: wrote', out)
    if not tiled:
        continue
    view.ViewSize = [1920, 1440]
    Render(view)
    save('%s-%s-4.png' % (prefix, 'bloom' if use_bloom else 'plain'), view,
                   ImageResolution=[1920, 1440])
    view.ViewSize = [480, 360]
    Render(view)
    for scale in (2, 4):
        out = '%s-%s-tiled%d.png' % (prefix, 'bloom' if use_bloom else 'plain', scale)
        save(out, view, ImageResolution=[480 * scale, 360 * scale])
        print('bloom_view_scale: wrote', out)
