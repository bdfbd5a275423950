# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
"""pvbatch script: a long session of the bloom render view, each rank's resident memory sampled.

    scripts/pvbatch.sh [-n N] ParaView/Testing/bloom_view_soak.py OUT_PREFIX FRAMES USE_BLOOM

bloom_view.py's spheres rendered FRAMES times. With USE_BLOOM 1, the view's bloom is switched
off and on every 5 frames and its preset changed every 20; every 30 frames the view is resized
(both runs alike). The rank that runs the script (pvbatch's first) writes OUT_PREFIX-RANK.txt:
its resident memory in KiB after every 10th frame from the first quarter on. run_tests.py
compares the growth of the bloom's session with the plain one's.
"""
import os
import sys

from paraview import servermanager
from paraview.simple import *  # noqa: F403

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from resident_memory import resident_kib  # noqa: E402
from spheres_scene import show_spheres  # noqa: E402


prefix, frames, use_bloom = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
view = CreateView('BloomRenderView')
view.OrientationAxesVisibility = 0
view.UseColorPaletteForBackground = 0
view.Background = [0.0, 0.0, 0.0]
view.BloomThresholdMode = 0
view.BloomThreshold = 0.6
show_spheres(view, [0.10, 0.15, 0.45], lit=False)
presets = view.GetProperty('BloomPreset').Available
sizes = ([320, 240], [400, 260], [280, 300])
rank = servermanager.vtkProcessModule.GetProcessModule().GetPartitionId()
samples = []
for i in range(frames):
    if i % 30 == 0:
        view.ViewSize = sizes[i // 30 % len(sizes)]
    if use_bloom:
        view.UseBloom = 1 if i // 5 % 2 == 0 else 0
        if i % 20 == 0:
            view.BloomPreset = presets[i // 20 % len(presets)]
    else:
        view.UseBloom = 0
    Render(view)
    if i >= frames // 4 and i % 10 == 0:
        samples.append(resident_kib())
with open('%s-%d.txt' % (prefix, rank), 'w') as out:
    out.write(' '.join(str(s) for s in samples) + '\n')
print('bloom_view_soak: rank %d, %d samples, %d -> %d KiB' % (rank, len(samples), samples[0],
                                                              samples[-1]))
