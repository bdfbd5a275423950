# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
"""Long sessions through the Python API: add_bloom/remove_bloom, add_emitter/remove_emitter (a
whole actor and a clim range) and bloom() on numpy arrays, fifty times or more each in a loop of
frames, hold the process's memory flat after a warm-up, against the same loop without bloom.

Growth is the smallest resident size of the last samples minus the largest of the first ones,
so that the allocator's fluctuation does not count; the bound is less than one set of the
pass's targets, where a leak of one set per switch would grow fifty times as much. Run by ctest as Python.soak, under the X11
leg's Xvfb and in the sid leg (VTK 9.6, EGL)."""

import os
import sys
import unittest

import numpy as np

import vtkbloom
from vtkmodules.vtkFiltersCore import vtkElevationFilter
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkRenderWindow, vtkRenderer
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the OpenGL factory overrides)

WIDTH, HEIGHT = 480, 360
# The pass's scene target (RGBA16F colour and a 32-bit depth), in KiB, and the bound: eight of
# them, less than one set of the pass's targets at this size (the scene target and the chain's,
# 10.5 MiB at 400 x 300: docs/rendering.md), where a leak of the scene target alone at each of
# the fifty switches would grow by fifty.
SCENE_TARGET_KIB = 12 * WIDTH * HEIGHT / 1024.0
BOUND_KIB = 8 * SCENE_TARGET_KIB


def resident_kib():
    with open("/proc/self/status") as status:
        for line in status:
            if line.startswith("VmRSS:"):
                return float(line.split()[1])
    return 0.0


def growth(samples):
    """Smallest of the last sixth of `samples` minus the largest of the first sixth, in KiB."""
    k = max(3, len(samples) // 6)
    return min(samples[-k:]) - max(samples[:k])


class Scene:
    """One offscreen window: an HDR sphere, a grey one and one coloured by elevation."""

    def __init__(self):
        self.window = vtkRenderWindow()
        self.window.SetOffScreenRendering(1)
        self.window.SetSize(WIDTH, HEIGHT)
        self.renderer = vtkRenderer()
        self.window.AddRenderer(self.renderer)
        source = vtkSphereSource()
        source.SetThetaResolution(32)
        plain = vtkPolyDataMapper()
        plain.SetInputConnection(source.GetOutputPort())
        elevation = vtkElevationFilter()
        elevation.SetInputConnection(source.GetOutputPort())
        elevation.SetLowPoint(0, -0.5, 0)
        elevation.SetHighPoint(0, 0.5, 0)
        mapped = vtkPolyDataMapper()
        mapped.SetInputConnection(elevation.GetOutputPort())
        mapped.SetScalarRange(0, 1)
        self.hot, self.grey, self.coloured = vtkActor(), vtkActor(), vtkActor()
        for actor, mapper, x in ((self.hot, plain, 0), (self.grey, plain, 1.2), (self.coloured, mapped, -1.2)):
            actor.SetMapper(mapper)
            actor.SetPosition(x, 0, 0)
            self.renderer.AddActor(actor)
        self.hot.GetProperty().SetColor(4, 2, 0.8)
        self.renderer.ResetCamera()

    def close(self):
        vtkbloom.remove_bloom(self.window)
        self.window.Finalize()


def soak(frames, warm_up, step):
    """`frames` calls of step(i) (which renders), sampling memory every 10 frames after the
    warm-up; returns the growth in KiB."""
    samples = []
    for i in range(frames):
        step(i)
        if i >= warm_up and (i - warm_up) % 10 == 0:
            samples.append(resident_kib())
    return growth(samples)


class LongSessions(unittest.TestCase):
    def compare(self, what, run):
        plain, bloom = run(False), run(True)
        print("soak %-24s plain %+.2f MiB, bloom %+.2f MiB, bound %.2f MiB"
              % (what, plain / 1024, bloom / 1024, BOUND_KIB / 1024), flush=True)
        self.assertLess(bloom - max(plain, 0.0), BOUND_KIB,
                        "%s: memory grew by more than the bound" % what)

    def test_add_and_remove_bloom(self):
        def run(bloom):
            scene = Scene()

            def step(i):
                if bloom and i % 3 == 0:
                    vtkbloom.remove_bloom(scene.window)
                    scene.window.Render()
                    vtkbloom.add_bloom(scene.window)
                scene.window.Render()

            try:
                return soak(210, 60, step)
            finally:
                scene.close()

        self.compare("add_bloom/remove_bloom", run)

    def test_add_and_remove_emitters(self):
        def run(bloom):
            scene = Scene()
            if bloom:
                vtkbloom.add_bloom(scene.window)

            def step(i):
                if bloom and i % 2 == 0:
                    kind = i // 2 % 4
                    if kind == 0:
                        vtkbloom.add_emitter(scene.window, scene.grey)
                    elif kind == 1:
                        vtkbloom.remove_emitter(scene.window, scene.grey)
                    elif kind == 2:
                        vtkbloom.add_emitter(scene.window, scene.coloured, clim=(0.4, 0.7))
                    else:
                        vtkbloom.remove_emitter(scene.window, scene.coloured)
                scene.window.Render()

            try:
                return soak(200, 80, step)
            finally:
                scene.close()

        self.compare("add_emitter/remove_emitter", run)

    def test_numpy_bloom(self):
        rng = np.random.default_rng(7)
        frame = rng.random((256, 256, 3), dtype=np.float32)
        frame[100:110, 100:110] = 8.0

        def run(bloom):
            def step(i):
                out = vtkbloom.bloom(frame) if bloom else frame.copy()
                self.assertEqual(out.shape, frame.shape)

            return soak(200, 60, step)

        self.compare("bloom() on numpy arrays", run)


if __name__ == "__main__":
    if sys.platform.startswith("linux") and not os.path.exists("/proc/self/status"):
        sys.exit("test_soak.py reads /proc/self/status")
    from unittest_main import main

    sys.exit(main())
