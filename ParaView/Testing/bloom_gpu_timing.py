# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
"""pvbatch script: the bloom view's frame time and where it goes, for GPU nodes.

    pvbatch [--displays=0,1,...] ParaView/Testing/bloom_gpu_timing.py WIDTH HEIGHT FRAMES
    (under mpiexec for several ranks; scripts/paraview-gpu-run.sh runs it, one rank per GPU)

The HDR scene of bloom_view_hdr.py (ParaView/Benchmarks/bloom_view_timing.py's, as measured on
llvmpipe in docs/paraview.md) in a "Render View (Bloom)" of WIDTH x HEIGHT, rendered in three
modes: bloom off (ParaView's 8-bit IceT composite), bloom over IceT's 8-bit composite
(BloomCompositeFloatColor 0) and bloom over IceT's float composite (the default). Each mode
renders 3 warm-up frames, then FRAMES frames, the camera turning by 0.1 degree a frame so that
every frame renders. A frame is the wall time of a still render on rank 0 up to glFinish
(vtkRenderWindow::WaitForCompletion), so the GPU's work is in it. For each frame also:

- IceT's own timers on rank 0 (more than one rank), read with icetGetDoublev from the IceT
  library ParaView loaded: ICET_RENDER_TIME (the rank's render and its read-back into IceT's
  image, in IceT's draw callback), ICET_COMPOSITE_TIME (compression, exchange and blending),
  ICET_COLLECT_TIME (gathering the tiles to rank 0), ICET_TOTAL_DRAW_TIME and ICET_BYTES_SENT
  (what rank 0 sent that frame);
- the bloom's GPU time (vtkBloomFrameReport::GetChainMilliseconds of the pass's GetLastFrame(),
  with vtkBloomPassTesting::SetTimeChains on: GPU timestamps from the bright pass to the end of
  the composite, the scene's render excluded), through ctypes on the plugin's
  libvtkRenderingBloom.so, the pass found on the renderer's pass chain.

Prints one line per mode, `timing-json {...}`: mean, median, p99 (the 99th of 100 sorted) and
max of each series in milliseconds (bytes: mean), IceT's strategy, and with bloom how many of
the chain's passes the last frame ran, and how many of those as compute shaders.
"""
import ctypes
import glob
import json
import os
import sys
import time

from paraview.simple import Render  # noqa: F401
from paraview.modules.vtkRemotingCore import vtkProcessModule

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from spheres_scene import hdr_view  # noqa: E402

ICET_RENDER_TIME, ICET_BUFFER_READ_TIME, ICET_COMPOSITE_TIME = 0xC1, 0xC2, 0xC7
ICET_COLLECT_TIME, ICET_TOTAL_DRAW_TIME, ICET_BYTES_SENT = 0xC8, 0xC9, 0xCA
NOLOAD = getattr(os, 'RTLD_NOLOAD', 4) | getattr(os, 'RTLD_LAZY', 1)

width, height, frames = int(sys.argv[1]), int(sys.argv[2]), int(sys.argv[3])
ranks = vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()
view = hdr_view([width, height])
window = view.GetRenderWindow()


def loaded(pattern):
    """The already loaded library whose file matches pattern (searched where ParaView and the
    plugin load from)."""
    for directory in os.environ.get('PV_PLUGIN_PATH', '').split(':') + \
            ['/usr/lib/x86_64-linux-gnu', '/usr/lib64', '/usr/lib']:
        for path in sorted(glob.glob(os.path.join(directory, pattern))):
            try:
                return ctypes.CDLL(path, mode=NOLOAD)
            except OSError:
                continue
    return None


def bloom_pass():
    """The vtkPVBloomPass on the renderer's pass chain (a vtkImageProcessingPass to Python)."""
    render_pass = view.GetClientSideObject().GetRenderer().GetPass()
    while render_pass is not None:
        if render_pass.GetClassName() == 'vtkPVBloomPass':
            return int(render_pass.__this__[1:].split('_')[0], 16)
        render_pass = getattr(render_pass, 'GetDelegatePass', lambda: None)()
    return None


bloom_library = loaded('libvtkRenderingBloom.so')
chain_ms = None
if bloom_library is not None:
    # The library's own symbols (vtkBloomPassTesting.h and vtkBloomFrameReport.h): no wrapping
    # of vtk-bloom is built against ParaView's VTK.
    time_chains = bloom_library._ZN19vtkBloomPassTesting13SetTimeChainsEP12vtkBloomPassb
    time_chains.restype, time_chains.argtypes = None, [ctypes.c_void_p, ctypes.c_bool]
    last_frame = bloom_library._ZN12vtkBloomPass12GetLastFrameEv
    last_frame.restype, last_frame.argtypes = ctypes.c_void_p, [ctypes.c_void_p]
    report_ms = bloom_library._ZNK19vtkBloomFrameReport20GetChainMillisecondsEv
    report_ms.restype, report_ms.argtypes = ctypes.c_double, [ctypes.c_void_p]
    # How many of the chain's passes ran as compute shaders, of how many (the last frame's).
    report_compute = bloom_library._ZNK19vtkBloomFrameReport16GetComputePassesEv
    report_all = bloom_library._ZNK19vtkBloomFrameReport17GetNumberOfPassesEv
    for getter in (report_compute, report_all):
        getter.restype, getter.argtypes = ctypes.c_int, [ctypes.c_void_p]
    chain_ms = lambda address: report_ms(last_frame(address))  # noqa: E731
    compute_passes = lambda address: report_compute(last_frame(address))  # noqa: E731
    all_passes = lambda address: report_all(last_frame(address))  # noqa: E731
icet = loaded('libvtkIceTCore-pv*.so*') if ranks > 1 else None
if icet is not None:
    icet.icetGetDoublev.argtypes = [ctypes.c_uint, ctypes.POINTER(ctypes.c_double)]
    icet.icetGetStrategyName.restype = ctypes.c_char_p
    icet.icetGetSingleImageStrategyName.restype = ctypes.c_char_p


def icet_value(name):
    value = ctypes.c_double(0.0)
    icet.icetGetDoublev(name, ctypes.byref(value))
    return value.value


def stats(values):
    if not values:
        return None
    ordered = sorted(values)
    pick = lambda q: ordered[min(len(ordered) - 1, int(round(q * (len(ordered) - 1))))]  # noqa: E731
    return {'mean': sum(ordered) / len(ordered), 'median': pick(0.5), 'p99': pick(0.99),
            'max': ordered[-1], 'n': len(ordered)}


for mode, use_bloom, float_composite in (('plain', 0, 1), ('bloom-8bit', 1, 0),
                                         ('bloom-float', 1, 1)):
    view.UseBloom = use_bloom
    view.BloomCompositeFloatColor = float_composite
    series = {k: [] for k in ('frame', 'icet_render', 'icet_read', 'icet_composite',
                              'icet_collect', 'icet_total', 'icet_bytes', 'bloom_gpu')}
    address = None
    for frame in range(3 + frames):
        view.GetActiveCamera().Azimuth(0.1)
        start = time.perf_counter()
        view.StillRender()
        window.WaitForCompletion()
        elapsed = (time.perf_counter() - start) * 1000.0
        if use_bloom and chain_ms is not None:
            if not address:
                address = bloom_pass()
                if address:
                    time_chains(address, True)  # from the next frame on
            bloom = chain_ms(address) if address else -1.0
        if frame < 3:
            continue
        series['frame'].append(elapsed)
        if use_bloom and address and bloom >= 0:
            series['bloom_gpu'].append(bloom)
        if icet is not None:
            series['icet_render'].append(icet_value(ICET_RENDER_TIME) * 1000.0)
            series['icet_read'].append(icet_value(ICET_BUFFER_READ_TIME) * 1000.0)
            series['icet_composite'].append(icet_value(ICET_COMPOSITE_TIME) * 1000.0)
            series['icet_collect'].append(icet_value(ICET_COLLECT_TIME) * 1000.0)
            series['icet_total'].append(icet_value(ICET_TOTAL_DRAW_TIME) * 1000.0)
            series['icet_bytes'].append(icet_value(ICET_BYTES_SENT))
    view.UpdatePropertyInformation()
    record = {'ranks': ranks, 'width': width, 'height': height, 'mode': mode,
              'composited_float': view.GetProperty('BloomLastSceneWasComposited').GetData(),
              'strategy': icet.icetGetStrategyName().decode() if icet else None,
              'single_image_strategy':
                  icet.icetGetSingleImageStrategyName().decode() if icet else None}
    record.update({k: stats(v) for k, v in series.items()})
    if use_bloom and chain_ms is not None and address:
        record['passes'] = all_passes(address)
        record['compute_passes'] = compute_passes(address)
    print('timing-json ' + json.dumps(record, sort_keys=True), flush=True)
