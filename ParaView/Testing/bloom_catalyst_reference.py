# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
"""pvbatch script: the time steps of bloom_catalyst.py, rendered from the mini-app's own data.

    scripts/pvbatch.sh ParaView/Testing/bloom_catalyst_reference.py OUT_DIR STEPS

The wavelet mini-app's dataset of each step, made by the mini-app's own function
(paraview.demos.wavelet_miniapp.create_dataset, --size 101, one piece), in catalyst_scene.py's
view, saved at the image extractor's resolution: OUT_DIR/bloom_NN.png, to compare with the
images Catalyst wrote.
"""
import argparse
import os
import sys

from paraview.simple import Render, TrivialProducer

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from catalyst_scene import IMAGE_SIZE, VIEW_SIZE, bloom_view, frame, show_field  # noqa: E402

out, steps = sys.argv[1], int(sys.argv[2])
os.makedirs(out, exist_ok=True)
producer = TrivialProducer()
view = bloom_view()
# After the view: ParaView 6.1's mini-app module initializes ParaView on import, and a session
# it starts does not load PV_PLUGIN_PATH's plugins.
from paraview.demos.wavelet_miniapp import create_dataset  # noqa: E402
from screenshot import save  # noqa: E402  (SaveScreenshot that fails)
for step in range(steps):
    dataset, _ = create_dataset(step, argparse.Namespace(size=101), 0, 1)
    producer.GetClientSideObject().SetOutput(dataset)
    producer.MarkModified(producer)
    if step == 0:
        show_field(producer, view)
    Render(view)  # ParaView may reset the camera where a representation first gets data
    frame(view)
    save(os.path.join(out, 'bloom_%02d.png' % step), view,
                   ImageResolution=VIEW_SIZE if os.environ.get('VTKBLOOM_CATALYST_SIZE') == 'view' else IMAGE_SIZE)
print('bloom_catalyst_reference: wrote', steps, 'steps to', out)
