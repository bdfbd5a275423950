# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
"""pvbatch script: apply the plugin's filters to a distributed HDR image and save the results.

    scripts/pvbatch.sh [-n N] ParaView/Testing/bloom_pieces.py OUTDIR

The image is an RGB float field computed from ParaView's Wavelet (101 x 71, uneven pieces for
every N > 1), with values from 0.1 to about 8. Each result is saved with SaveData as OUTDIR/
NAME.exr (float channels): under MPI the plugin's parallel OpenEXR writer gathers the pieces to
rank 0. One result is also saved as .vti (the plugin's gathering .vti writer under MPI). The input itself is saved as OUTDIR/input.exr. run_tests.py compares the results across
rank counts (bit for bit) and with `vtk-bloom image` (to 1e-5).
"""
import os
import sys

from paraview.simple import *  # noqa: F403 (pvbatch scripts use the simple module's names)

out = sys.argv[1]
os.makedirs(out, exist_ok=True)

wavelet = Wavelet(WholeExtent=[0, 100, 0, 70, 0, 0])
hdr = Calculator(Input=wavelet, ResultArrayName='rgb', ResultArrayType='Float',
                 Function='(RTData/120)^6*iHat + (RTData/160)^6*jHat + 0.1*kHat')
SaveData(os.path.join(out, 'input.exr'), proxy=hdr, Scalars=['POINTS', 'rgb'])


def save(name, proxy):
    proxy.UpdatePipeline()
    SaveData(os.path.join(out, name + '.exr'), proxy=proxy)


for preset in ['webgpu-market', 'mip-atlas', 'ping-pong', 'crt-halfres']:
    bloom = Bloom(Input=hdr, Preset=preset)
    bloom.Scalars = ['POINTS', 'rgb']
    save('bloom-' + preset, bloom)
    if preset == 'crt-halfres':
        # Also as .vti: under MPI the plugin's gathering .vti writer, serially ParaView's own.
        SaveData(os.path.join(out, 'bloom-crt-halfres.vti'), proxy=bloom)

custom = Bloom(Input=hdr)
custom.Scalars = ['POINTS', 'rgb']
custom.Threshold = 0.8
custom.Knee = 0.2
custom.NumberOfLevels = 4
custom.BlurStandardDeviation = 2.0
custom.LevelWeights = [1.0, 0.5, 0.25]
custom.Strength = 0.7
custom.Tint = [1.0, 0.8, 0.6]
save('bloom-custom', custom)

# The image filters work on the active scalars: the bloom's output has the RGB ones.
gaussian = SeparableGaussian(Input=custom, StandardDeviations=[3.0, 2.0, 0.0])
save('gaussian', gaussian)
wide = SeparableGaussian(Input=custom, StandardDeviations=[12.0, 12.0, 0.0], ConvolutionMode='FFT')
save('gaussian-fft', wide)
bright = BrightPass(Input=custom, Threshold=1.0, Knee=0.5)
save('bright', bright)
down = PyramidDown(Input=bright)
save('down', down)
up = PyramidUp(Input=down, Fine=bright, FineWeight=1.0)
save('up', up)
print('bloom_pieces: wrote', out)
