# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
"""pvbatch script, symmetric: which GPU each rank renders on, and the image they make together.

    pvbatch --sym [--displays=0,1,...] ParaView/Testing/bloom_gpu_devices.py OUTDIR [W H [HOLD]]
    (under mpiexec for several ranks; scripts/paraview-gpu-run.sh runs it)

Every rank runs this script (--sym). Each builds the HDR view of bloom_view_hdr.py (the sphere
split over the ranks, lights above 1, IceT's float composite, 32-bit targets) at W x H (default
400 x 300, bloom_view_hdr.py's size), renders it, and asks its own context what it runs on
(gpu_context.describe: the EGL device and its index, NVIDIA's CUDA device number, the GPU's
UUID as nvidia-smi prints it). Each rank writes OUTDIR/device-RANK.json and prints it as one
line `device {...}`; then all ranks keep their contexts for HOLD seconds (default 4) so that
nvidia-smi, asked from outside, lists every rank's process on its GPU; then rank 0 saves the
screenshot OUTDIR/hdr-W-H.png (every rank takes part in the composite).
"""
import json
import os
import sys
import time

from paraview.simple import *  # noqa: F403
from paraview.modules.vtkRemotingCore import vtkProcessModule

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from spheres_scene import hdr_view  # noqa: E402
from gpu_context import describe  # noqa: E402

out = sys.argv[1]
width = int(sys.argv[2]) if len(sys.argv) > 2 else 400
height = int(sys.argv[3]) if len(sys.argv) > 3 else 300
hold = float(sys.argv[4]) if len(sys.argv) > 4 else 4.0
os.makedirs(out, exist_ok=True)
module = vtkProcessModule.GetProcessModule()
rank, ranks = module.GetPartitionId(), module.GetNumberOfLocalPartitions()

view = hdr_view([width, height])
view.BloomCompositeFloatColor = 1
view.BloomFloatPrecision = 32
Render(view)
info = describe(view.GetRenderWindow())
info.update(rank=rank, ranks=ranks, pid=os.getpid(), host=os.uname().nodename,
            env_device=os.environ.get('VTK_DEFAULT_EGL_DEVICE_INDEX'))
with open(os.path.join(out, 'device-%d.json' % rank), 'w') as f:
    json.dump(info, f, indent=1)
print('device ' + json.dumps(info, sort_keys=True), flush=True)
time.sleep(hold)
Render(view)
# Rank 0 writes the file; the others take part in the composite and write nothing.
png = os.path.join(out, 'hdr-%d-%d.png' % (width, height))
SaveScreenshot(png if rank == 0 else os.path.join(out, '.rank-%d.png' % rank), view,
               ImageResolution=[width, height])
if rank == 0:
    view.UpdatePropertyInformation()
    composited = view.GetProperty('BloomLastSceneWasComposited').GetData()
    print('bloom_gpu_devices: %d rank(s) wrote %s, composited %d' % (ranks, png, composited),
          flush=True)
