#!/usr/bin/python3
# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
"""Fails unless two bloomed images of one scene agree: their bloom terms within a bound.

    compare-bloom.py SCENE.exr A.exr B.exr BOUND

The bloom term of an image is what it adds to SCENE (the unbloomed float render). Prints
||(A - SCENE) - (B - SCENE)|| / ||B - SCENE|| over the colour channels, in double precision,
and exits 1 when it is over BOUND, when the images differ in shape or when B adds nothing."""

import sys

import numpy as np
import vtkbloom


def main(argv):
    if len(argv) != 5:
        sys.exit(__doc__.split("\n\n")[1])
    scene, a, b = (vtkbloom.read_exr(path)[..., :3].astype(np.float64) for path in argv[1:4])
    bound = float(argv[4])
    if not scene.shape == a.shape == b.shape:
        sys.exit("compare-bloom: shapes differ: %s, %s, %s" % (scene.shape, a.shape, b.shape))
    term_a, term_b = a - scene, b - scene
    norm = np.sqrt(np.sum(term_b * term_b))
    if not norm > 0:
        sys.exit("compare-bloom: %s adds nothing to %s" % (argv[3], argv[1]))
    error = np.sqrt(np.sum((term_a - term_b) ** 2)) / norm
    print("compare-bloom: bloom terms of %s and %s: %.3g relative L2 (bound %g)" % (argv[2], argv[3], error, bound))
    return 0 if error <= bound else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
