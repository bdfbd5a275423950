# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
"""pvbatch script: the HDR view's interactive render with an image reduction factor.

    scripts/pvbatch.sh -n 3 ParaView/Testing/bloom_view_reduced.py OUT_PREFIX [FLOAT_COMPOSITE]

bloom_view_hdr.py's scene (HDR light, bloom only above 1) on 3 ranks: the still render saved as
OUT_PREFIX-still.png, then an interactive render with an image reduction factor of 2 (IceT
composites a quarter of the pixels, as ParaView does while the camera moves), read from the
window as it is (OUT_PREFIX-interactive.png), with bloom, and the same two without bloom
(OUT_PREFIX-{still,interactive}-plain.png). run_tests.py compares the bloom terms.
"""
import os
import sys

from paraview.simple import *  # noqa: F403
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from spheres_scene import hdr_view  # noqa: E402

prefix = sys.argv[1]
float_composite = int(sys.argv[2]) if len(sys.argv) > 2 else 1

view = hdr_view([400, 300])
view.BloomCompositeFloatColor = float_composite
view.BloomFloatPrecision = 32
view.LODThreshold = 1e9  # no level of detail: the interactive render shows the same geometry
view.ImageReductionFactor = 2  # IceT composites a quarter of the pixels while interacting

def grab(name):
    """The window's pixels as the last render left them (no render of its own)."""
    w2i = vtkWindowToImageFilter()
    w2i.SetInput(view.GetRenderWindow())
    w2i.ShouldRerenderOff()
    w2i.ReadFrontBufferOff()
    w2i.Update()
    writer = vtkPNGWriter()
    writer.SetFileName('%s-%s.png' % (prefix, name))
    writer.SetInputConnection(w2i.GetOutputPort())
    writer.Write()


for use_bloom in (1, 0):
    view.UseBloom = use_bloom
    suffix = '' if use_bloom else '-plain'
    Render(view)
    Render(view)
    grab('still' + suffix)
    view.InteractiveRender()
    grab('interactive' + suffix)
print('bloom_view_reduced: wrote', prefix)
