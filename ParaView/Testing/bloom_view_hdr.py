# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
"""pvbatch script: an HDR scene in the bloom render view, saved as a screenshot.

    scripts/pvbatch.sh [-n N] ParaView/Testing/bloom_view_hdr.py OUT.png [FLOAT_COMPOSITE [BLOOM]]
    scripts/pvserver.sh [-n N] ParaView/Testing/bloom_view_hdr.py OUT.png [FLOAT_COMPOSITE [BLOOM]]

The scene: a sphere split into pieces over the ranks in a dim blue, and in front of it three
small spheres, all lit by a headlight of intensity 6 (ParaView clamps a property's Ambient to
1, not a light's intensity), so that the small ones reach 3 to 6, on a grey background. Only
what lies above 1 passes the threshold (1.0, knee 0), so a composite clamped to [0, 1], IceT's
8-bit one, blooms nothing: the image under MPI is the serial one only if IceT composited float
colour (FLOAT_COMPOSITE, default 1). OUT.png.txt receives whether the bloom read IceT's float
composite (the view's BloomLastSceneWasComposited).

Run by scripts/pvserver.sh, the script is a pvpython client (`--server PORT` comes first): it
connects to the pvserver on localhost and forces remote rendering (remote render threshold 0),
so the server renders, composites and blooms, and the screenshot is the image the client got.
"""
import os
import sys

from paraview.simple import *  # noqa: F403

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from spheres_scene import hdr_view  # noqa: E402
from screenshot import save  # noqa: E402  (SaveScreenshot that fails)

if sys.argv[1] == '--server':
    Connect('localhost', int(sys.argv[2]))
    GetSettingsProxy('RenderViewSettings').RemoteRenderThreshold = 0
    del sys.argv[1:3]
out = sys.argv[1]
float_composite = int(sys.argv[2]) if len(sys.argv) > 2 else 1
use_bloom = int(sys.argv[3]) if len(sys.argv) > 3 else 1

view = hdr_view([400, 300])
view.UseBloom = use_bloom
view.BloomCompositeFloatColor = float_composite
view.BloomFloatPrecision = 32
Render(view)
if os.environ.get('VTKBLOOM_RESIZE_ONCE'):
    # Rendered at another size, then resized: the screenshot is the one render at 400x300.
    view.ViewSize = [320, 240]
    Render(view)
    view.ViewSize = [400, 300]
# VTKBLOOM_SCREENSHOT_SCALE=k: the screenshot at k times the view's size (rendered in tiles).
scale = int(os.environ.get('VTKBLOOM_SCREENSHOT_SCALE', '1'))
save(out, view, ImageResolution=[400 * scale, 300 * scale])
view.UpdatePropertyInformation()
composited = view.GetProperty('BloomLastSceneWasComposited').GetData()
with open(out + '.txt', 'w') as f:
    f.write('%d\n' % composited)
print('bloom_view_hdr: wrote', out, 'composited', composited)
