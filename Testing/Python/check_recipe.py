#!/usr/bin/python3
# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
"""Runs one of docs/python.md's recipes as written and checks what it shows: that it glows.

    check_recipe.py RECIPE OUTPUT.png [ARGS...]
    check_recipe.py --side-by-side RECIPE OUTPUT.png [ARGS...]

The recipe runs once as written (OUTPUT.png) and once with vtkbloom's add_bloom and
add_emitter made to do nothing (OUTPUT-plain.png). With --side-by-side the recipe writes its
frame before and after bloom side by side in one image, and the two halves are compared
instead. The glow must be there: at least MIN_GLOW of the pixels brighter by more than LEVELS
levels; and bloom adds light, so at most MAX_DARKER of them darker by more than LEVELS (the
edges of a second emitter render, a documented limit). An
output that is missing, empty or of another size fails."""

import os
import subprocess
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader

LEVELS = 8
MIN_GLOW = 0.002
# The pass's resolve of anti-aliased edges where emitters render a second time is not the
# window's own (docs/python.md, "Not yet"): PyVista's lamp recipe has 0.7 % such pixels.
MAX_DARKER = 0.01

# The recipe with vtkbloom's scene calls made to do nothing: the frame it would show unbloomed.
PLAIN = """
import runpy, sys, vtkbloom
vtkbloom.add_bloom = lambda *args, **kwargs: None
vtkbloom.add_emitter = lambda *args, **kwargs: None
sys.argv = sys.argv[1:]
runpy.run_path(sys.argv[0], run_name="__main__")
"""


def read_png(path):
    if not os.path.isfile(path) or os.path.getsize(path) == 0:
        sys.exit("check_recipe: %s was not written" % path)
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    width, height, _ = image.GetDimensions()
    pixels = vtk_to_numpy(image.GetPointData().GetScalars()).reshape(height, width, -1)
    if pixels.size == 0:
        sys.exit("check_recipe: %s holds no pixels" % path)
    return pixels[..., :3].astype(np.int16)


def main():
    arguments = sys.argv[1:]
    side_by_side = arguments[:1] == ["--side-by-side"]
    arguments = arguments[1:] if side_by_side else arguments
    if len(arguments) < 2:
        sys.exit(__doc__.split("\n\n")[1])
    recipe, output, rest = arguments[0], arguments[1], arguments[2:]
    subprocess.run([sys.executable, recipe, output] + rest, check=True, timeout=300)
    bloomed = read_png(output)
    if side_by_side:
        half = bloomed.shape[1] // 2
        plain, bloomed = bloomed[:, :half], bloomed[:, half:2 * half]
    else:
        plain_output = os.path.splitext(output)[0] + "-plain.png"
        subprocess.run([sys.executable, "-c", PLAIN, recipe, plain_output] + rest, check=True, timeout=300)
        plain = read_png(plain_output)
    if plain.shape != bloomed.shape:
        sys.exit("check_recipe: the bloomed frame is %s, the plain frame %s" % (bloomed.shape, plain.shape))
    difference = bloomed - plain
    pixels = difference.shape[0] * difference.shape[1]
    brighter = np.count_nonzero((difference > LEVELS).any(axis=2)) / pixels
    darker = np.count_nonzero((difference < -LEVELS).any(axis=2)) / pixels
    print("check_recipe: %s: %.2f %% of the pixels glow (brighter by more than %d levels; at least %.1f %%), "
          "%.3f %% darker (at most %.1f %%)" % (os.path.basename(recipe), 100 * brighter, LEVELS,
                                                100 * MIN_GLOW, 100 * darker, 100 * MAX_DARKER))
    if brighter < MIN_GLOW or darker > MAX_DARKER:
        print("check_recipe: %s does not show what it says" % recipe, file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
