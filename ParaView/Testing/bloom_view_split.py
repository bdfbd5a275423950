# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
"""pvbatch script: two bloom render views side by side in one layout, each showing the wavelet
as a volume (composite blending, the one mode every ParaView's volume representation has; the
right view turned), saved as one screenshot of the layout with the bloom on and off.

    scripts/pvbatch.sh [-n N] ParaView/Testing/bloom_view_split.py OUT_PREFIX

Writes OUT_PREFIX-on.png and OUT_PREFIX-off.png. Nothing in the views is light (colours at or
below 1, the view's default threshold), so each view's half must be the same with the bloom as
without: ParaView renders the views of a layout into one shared window, each at its viewport,
where a volume in a view away from the window's origin was once lost (run_tests.py compares).
"""
import sys

from paraview.simple import *  # noqa: F403

prefix = sys.argv[1]
wavelet = Wavelet()
layout = CreateLayout('split')
layout.SplitHorizontal(0, 0.5)
views = []
for index in range(2):
    view = CreateView('BloomRenderView')
    layout.AssignView(1 + index, view)
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = [0.05, 0.05, 0.08]
    display = Show(wavelet, view)
    display.SetRepresentationType('Volume')
    ColorBy(display, ('POINTS', 'RTData'))
    display.VolumeRenderingMode = 'GPU Based'
    ResetCamera(view)
    view.GetActiveCamera().Azimuth(40.0 * index)
    views.append(view)
for use_bloom, name in ((1, 'on'), (0, 'off')):
    for view in views:
        view.UseBloom = use_bloom
        Render(view)
    SaveScreenshot('%s-%s.png' % (prefix, name), layout, ImageResolution=[800, 300])
print('bloom_view_split: wrote', prefix + '-on.png', prefix + '-off.png')
