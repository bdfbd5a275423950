# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
# script-version: 2
"""Catalyst script: the wavelet mini-app's field in the bloom view, a PNG per time step.

    pvbatch --sym -m paraview.demos.wavelet_miniapp -t STEPS --size 101 \
        -s ParaView/Testing/bloom_catalyst.py

(run_tests.py runs it so, serial and on 3 ranks, with VTKBLOOM_CATALYST_OUT naming the output
folder). The plugin comes from PV_PLUGIN_PATH, as in pvbatch. The scene is catalyst_scene.py's;
the image extractor writes bloom_NN.png at 640x480, twice the view's size, which ParaView
renders in tiles (VTKBLOOM_CATALYST_SIZE=view: at the view's size).
"""
import os
import sys

from paraview import catalyst
from paraview.simple import CreateExtractor, Render, TrivialProducer

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from catalyst_scene import IMAGE_SIZE, VIEW_SIZE, bloom_view, frame, show_field  # noqa: E402

# The mini-app's channel ("input"): the simulation's data at each step.
producer = TrivialProducer(registrationName='input')
view = bloom_view()
show_field(producer, view)

extractor = CreateExtractor('PNG', view, registrationName='BloomPNG')
extractor.Trigger = 'TimeStep'
extractor.Writer.FileName = 'bloom_{timestep:02d}.png'
# VTKBLOOM_CATALYST_SIZE=view saves at the view's own size (no tiles).
extractor.Writer.ImageResolution = \
    VIEW_SIZE if os.environ.get('VTKBLOOM_CATALYST_SIZE') == 'view' else IMAGE_SIZE

options = catalyst.Options()
options.GlobalTrigger = 'TimeStep'
options.ExtractsOutputDirectory = os.environ.get('VTKBLOOM_CATALYST_OUT', 'catalyst')


def catalyst_execute(info):
    """Each step: the fixed camera, after a render (ParaView resets a view's camera to the data's
    bounds at its first render, and where a representation first gets data)."""
    view.ResetCamera(False)
    Render(view)
    frame(view)
