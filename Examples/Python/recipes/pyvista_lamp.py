#!/usr/bin/python3
# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
"""Recipe: a PyVista plotter with bloom, an emitting lamp and the glowing peaks of a field.

    pyvista_lamp.py OUTPUT.png
"""
import sys

import pyvista as pv
import vtkbloom

hills = pv.ParametricRandomHills(random_seed=2).elevation()

plotter = pv.Plotter(off_screen=True, window_size=(800, 500))
plotter.set_background("black", top="midnightblue")
field = plotter.add_mesh(hills, scalars="Elevation", cmap="inferno", show_scalar_bar=False)
lamp = plotter.add_mesh(pv.Sphere(radius=0.8, center=(4, 4, 12)), color="orange")
vtkbloom.add_bloom(plotter, strength=0.8)
vtkbloom.add_emitter(plotter, lamp)                        # this actor glows
top = hills["Elevation"].max()
vtkbloom.add_emitter(plotter, field, clim=(0.85 * top, top))  # and the field's peaks
plotter.camera.zoom(1.4)
plotter.show(screenshot=sys.argv[1])
