# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
"""pvbatch script: bad parameters and bad input give clear errors, and nothing crashes.

    scripts/pvbatch.sh ParaView/Testing/bloom_errors.py OUTDIR

Each case prints its vtkErrorMacro message (run_tests.py checks the messages on stderr) and
this script checks what it can see itself, then prints "bloom_errors: ok".
"""
import os
import sys

from paraview.simple import *  # noqa: F403

out = sys.argv[1]
os.makedirs(out, exist_ok=True)
wavelet = Wavelet(WholeExtent=[0, 31, 0, 23, 0, 0])
hdr = Calculator(Input=wavelet, ResultArrayName='rgb', ResultArrayType='Float',
                 Function='(RTData/120)^6*iHat + 0.5*jHat + 0.1*kHat')

# An unknown preset is refused: the filter keeps the preset it had.
bloom = Bloom(Input=hdr, Preset='crt-halfres')
bloom.Scalars = ['POINTS', 'rgb']
bloom.Preset = 'no-such-preset'
bloom.UpdatePipeline()
bloom.UpdatePropertyInformation()
assert bloom.GetProperty('PresetInfo').GetData() == 'crt-halfres', 'unknown preset was taken'

# Same for the view's preset.
view = CreateView('BloomRenderView')
view.BloomPreset = 'no-such-preset'
Render(view)
view.UpdatePropertyInformation()
assert view.GetProperty('BloomPresetInfo').GetData() == 'custom', 'unknown view preset was taken'

# Integer scalars: the bloom needs float or double.
ints = Calculator(Input=wavelet, ResultArrayName='n', ResultArrayType='Int',
                  Function='floor(RTData)')
bad = Bloom(Input=ints)
bad.Scalars = ['POINTS', 'n']
bad.UpdatePipeline()

# Pyramid Up without its finer level cannot define its output.
up = PyramidUp(Input=hdr)
up.UpdatePipeline()

# A missing OpenEXR file.
reader = OpenEXRReader(FileName=os.path.join(out, 'missing.exr'))
reader.UpdatePipeline()

# Writing where no directory exists fails with an error and writes nothing.
target = os.path.join(out, 'no-such-dir', 'x.exr')
try:
    SaveData(target, proxy=bloom)
except Exception as error:  # paraview.simple raises when the writer reports failure
    print('SaveData raised:', error)
assert not os.path.exists(target), 'a file was written where it could not be'
print('bloom_errors: ok')
