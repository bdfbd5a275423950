# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
"""pvbatch script: the bloom view's time per frame, the composite's cost, under MPI.

    scripts/pvbatch.sh [-n N] ParaView/Benchmarks/bloom_view_timing.py WIDTH HEIGHT FRAMES

The HDR scene of bloom_view_hdr.py (a sphere split over the ranks, three lamps lit above 1)
in a "Render View (Bloom)" of WIDTH x HEIGHT, rendered FRAMES times (after 3 warm-up frames)
in each of three modes: bloom off (ParaView's own 8-bit IceT composite), bloom over IceT's
8-bit composite (BloomCompositeFloatColor 0: the light clamped), and bloom over IceT's float
composite (the default). The camera turns by 0.1 degree a frame, so every frame renders.
Prints one line per mode: `timing RANKS WIDTH HEIGHT MODE median mean p99 max frames` in
milliseconds of wall time for a still render on the root (which waits for IceT's composite).
scripts/paraview-benchmark.sh runs it for 1, 2 and 4 ranks and two sizes.
"""
import os
import sys
import time

from paraview.simple import GetActiveCamera, Render  # noqa: F401

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'Testing'))
from spheres_scene import hdr_view  # noqa: E402

width, height, frames = int(sys.argv[1]), int(sys.argv[2]), int(sys.argv[3])
try:
    from mpi4py import MPI
    ranks = MPI.COMM_WORLD.Get_size()
except ImportError:
    ranks = int(os.environ.get('OMPI_COMM_WORLD_SIZE', '1'))

view = hdr_view([width, height])

def percentile(values, q):
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(round(q * (len(ordered) - 1))))]


for mode, use_bloom, float_composite in (('plain', 0, 1), ('bloom-8bit', 1, 0),
                                         ('bloom-float', 1, 1)):
    view.UseBloom = use_bloom
    view.BloomCompositeFloatColor = float_composite
    times = []
    for frame in range(3 + frames):
        view.GetActiveCamera().Azimuth(0.1)
        start = time.perf_counter()
        view.StillRender()
        elapsed = (time.perf_counter() - start) * 1000.0
        if frame >= 3:
            times.append(elapsed)
    times.sort()
    print('timing %d %d %d %s %.2f %.2f %.2f %.2f %d' % (
        ranks, width, height, mode, percentile(times, 0.5), sum(times) / len(times),
        percentile(times, 0.99), times[-1], len(times)), flush=True)
