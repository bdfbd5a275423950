# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
# script-version: 2
"""Catalyst script: a long in situ run of the bloom view, each rank's resident memory sampled.

    pvbatch --sym -m paraview.demos.wavelet_miniapp -t STEPS --size 31 \
        -s ParaView/Testing/bloom_catalyst_soak.py

bloom_catalyst.py's scene rendered at every time step, no image written. With
VTKBLOOM_SOAK_BLOOM=1 the view's bloom is switched off and on every 5 steps (else it stays
off); every rank appends its resident memory in KiB to VTKBLOOM_SOAK_OUT-RANK.txt every 10th
step from the 50th on. run_tests.py compares the growth of the two runs, rank by rank.
"""
import os
import sys

from paraview import catalyst, servermanager
from paraview.simple import Render, TrivialProducer

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from catalyst_scene import bloom_view, frame, show_field  # noqa: E402
from resident_memory import resident_kib  # noqa: E402

producer = TrivialProducer(registrationName='input')
view = bloom_view()
show_field(producer, view)
options = catalyst.Options()
options.GlobalTrigger = 'TimeStep'
switching = os.environ.get('VTKBLOOM_SOAK_BLOOM') == '1'
rank = servermanager.vtkProcessModule.GetProcessModule().GetPartitionId()
path = '%s-%d.txt' % (os.environ.get('VTKBLOOM_SOAK_OUT', 'catalyst-soak'), rank)
steps = [0]


def catalyst_execute(info):
    step = steps[0]
    steps[0] += 1
    view.UseBloom = 1 if switching and step // 5 % 2 == 0 else 0
    view.ResetCamera(False)
    Render(view)
    frame(view)
    if step >= 50 and step % 10 == 0:
        with open(path, 'a') as out:
            out.write('%d\n' % resident_kib())
