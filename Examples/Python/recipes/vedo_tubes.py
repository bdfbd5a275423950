#!/usr/bin/python3
# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
"""Recipe: a vedo scene with bloom: glowing field lines around a dark body (vedo 2023 and
later).

    vedo_tubes.py OUTPUT.png
"""
import sys

import numpy as np
import vedo
import vtkbloom

body = vedo.Sphere(r=0.8).color("slategray")
lines = []
for k, phase in enumerate(np.linspace(0, np.pi, 6, endpoint=False)):
    t = np.linspace(0, 2 * np.pi, 200)
    points = np.c_[2 * np.sin(t) ** 2 * np.cos(phase), 2 * np.sin(t) ** 2 * np.sin(phase),
                   1.6 * np.sin(t) * np.cos(t) * 2]
    lines.append(vedo.Tube(points, r=0.03).color("cyan" if k % 2 else "magenta"))

plotter = vedo.Plotter(offscreen=True, size=(800, 500), bg="black")
plotter.show(body, *lines, interactive=False)
vtkbloom.add_bloom(plotter, strength=1.2)
for line in lines:
    vtkbloom.add_emitter(plotter, line)                    # vedo objects glow as they are
plotter.show(body, *lines, interactive=False, azimuth=20, elevation=15)
plotter.screenshot(sys.argv[1])
plotter.close()
