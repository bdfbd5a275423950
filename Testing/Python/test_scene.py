#!/usr/bin/python3
# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
"""Tests of vtkbloom.add_bloom and add_emitter on raw VTK renderers and windows: one pass per
renderer however often it is called, its place in a chain of passes (above the scene, below
what resolves the image) kept through a rebuild of the chain as PyVista and vedo do it, the
plain frame where nothing is light, a glow where an emitter is, and the frame as it was after
remove_bloom. vedo's own Plotter is tested where vedo is installed."""

import os
import sys
import unittest

import numpy as np
from vtkmodules.util import numpy_support
from vtkmodules.vtkFiltersSources import vtkCubeSource, vtkSphereSource
from vtkmodules.vtkRenderingCore import (
    vtkActor,
    vtkPolyDataMapper,
    vtkRenderer,
    vtkRenderWindow,
    vtkWindowToImageFilter,
)
from vtkmodules.vtkRenderingOpenGL2 import (
    vtkCameraPass,
    vtkOpenGLFXAAPass,
    vtkRenderStepsPass,
    vtkSSAAPass,
    vtkSequencePass,
    vtkRenderPassCollection,
)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the OpenGL factories)

import vtkbloom

try:
    from vtkmodules.vtkRenderingOpenGL2 import vtkSSAOPass
except ImportError:  # pragma: no cover
    vtkSSAOPass = None


def scene(colour=(0.9, 0.5, 0.2), size=(160, 120), renderers=1):
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(*size)
    actors = []
    for i in range(renderers):
        renderer = vtkRenderer()
        renderer.SetViewport(i / renderers, 0, (i + 1) / renderers, 1)
        renderer.SetBackground(0.1, 0.1, 0.12)
        source = vtkSphereSource()
        source.SetThetaResolution(32)
        source.SetPhiResolution(32)
        mapper = vtkPolyDataMapper()
        mapper.SetInputConnection(source.GetOutputPort())
        actor = vtkActor()
        actor.SetMapper(mapper)
        actor.GetProperty().SetColor(*colour)
        actor.SetScale(0.5)
        actor._keep = source
        renderer.AddActor(actor)
        window.AddRenderer(renderer)
        actors.append(actor)
    return window, actors


def grab(window):
    window.Render()
    capture = vtkWindowToImageFilter()
    capture.SetInput(window)
    capture.ReadFrontBufferOff()
    capture.Update()
    data = capture.GetOutput()
    w, h, _ = data.GetDimensions()
    scalars = data.GetPointData().GetScalars()
    return numpy_support.vtk_to_numpy(scalars).reshape(h, w, -1).astype(int)


def chain(renderer):
    names, current = [], renderer.GetPass()
    while current is not None:
        names.append(current.GetClassName())
        get = getattr(current, "GetDelegatePass", None)
        current = get() if get else None
    return names


def pyvista_like(renderer, *top):
    """A chain as PyVista's RenderPasses builds it: camera pass over a sequence of the steps,
    then the given passes, each delegating to the one before; returns the camera pass."""
    collection = vtkRenderPassCollection()
    collection.AddItem(vtkRenderStepsPass())
    sequence = vtkSequencePass()
    sequence.SetPasses(collection)
    camera = vtkCameraPass()
    camera.SetDelegatePass(sequence)
    current = camera
    for render_pass in top:
        render_pass.SetDelegatePass(current)
        current = render_pass
    renderer.SetPass(current)
    renderer._keep = (collection, sequence, camera) + top
    return camera


class AddBloom(unittest.TestCase):
    def test_nothing_is_light_so_the_frame_is_plain_and_an_emitter_glows(self):
        window, (actor,) = scene()
        renderer = window.GetRenderers().GetFirstRenderer()
        plain = grab(window)
        bloom = vtkbloom.add_bloom(window, strength=1.0)
        self.assertEqual(bloom.GetClassName(), "vtkBloomPass")
        self.assertLessEqual(np.abs(grab(window) - plain).max(), 1)
        emitter = vtkbloom.add_emitter(window, actor)
        self.assertIs(emitter, actor)
        glowing = grab(window)
        self.assertGreater(np.abs(glowing - plain).max(), 20)
        # The glow lies around the sphere: the corners stay the background.
        self.assertLessEqual(np.abs(glowing[:8, :8] - plain[:8, :8]).max(), 1)
        vtkbloom.remove_emitter(window, actor)
        self.assertLessEqual(np.abs(grab(window) - plain).max(), 1)
        vtkbloom.remove_bloom(window)
        self.assertIsNone(renderer.GetPass())
        np.testing.assert_array_equal(grab(window), plain)

    def test_what_a_frame_did_is_one_read_only_record(self):
        window, (actor,) = scene()
        bloom = vtkbloom.add_bloom(window, strength=1.0)
        grab(window)
        frame = bloom.GetLastFrame()
        self.assertEqual(frame.GetClassName(), "vtkBloomFrameReport")
        # Nothing is light: the chain is skipped; the bright pass, the bright region's
        # reduction and the composite (its multisampled edges) ran.
        self.assertTrue(frame.GetBloomSkipped())
        self.assertGreaterEqual(frame.GetNumberOfPasses(), 2)
        self.assertLessEqual(frame.GetNumberOfPasses(), 4)
        self.assertEqual(frame.GetBrightRegion(), (0, 0, 0, 0))
        vtkbloom.add_emitter(window, actor)
        grab(window)
        # The same record, rewritten by the frame.
        self.assertIs(bloom.GetLastFrame(), frame)
        self.assertFalse(frame.GetBloomSkipped())
        self.assertGreater(frame.GetNumberOfPasses(), 10)
        self.assertLessEqual(frame.GetComputePasses(), frame.GetNumberOfPasses())
        self.assertIn(frame.GetFloatPrecision(), (16, 32))
        self.assertTrue(frame.GetEmissionInSceneRender())
        self.assertEqual(frame.GetTileGuardBand(), (0, 0))
        self.assertEqual(frame.GetPSFGrid(), (0, 0))
        # Read-only: Python has no setter for what a frame did.
        for name in ("BloomSkipped", "NumberOfPasses", "ComputePasses", "BrightRegion",
                     "ChainCoverage", "PSFGrid", "FloatPrecision", "ChainMilliseconds"):
            self.assertFalse(hasattr(frame, "Set" + name), name)
        # The pass no longer has the getters the record replaced.
        self.assertFalse(hasattr(bloom, "GetLastBloomSkipped"))
        self.assertFalse(hasattr(bloom, "GetNumberOfPasses"))

    def test_a_renderer_only_its_window_holds(self):
        # No Python reference to the renderer: each fetch makes a new wrapper of it.
        window, (actor,) = scene()
        plain = grab(window)
        vtkbloom.add_emitter(window, actor)
        self.assertGreater(np.abs(grab(window) - plain).max(), 20)
        vtkbloom.add_bloom(window, strength=0.5)
        self.assertEqual(chain(window.GetRenderers().GetFirstRenderer()).count("vtkBloomPass"), 1)
        vtkbloom.remove_bloom(window)
        np.testing.assert_array_equal(grab(window), plain)

    def test_called_again_it_changes_parameters_and_never_stacks(self):
        window, _ = scene()
        renderer = window.GetRenderers().GetFirstRenderer()
        first = vtkbloom.add_bloom(renderer, preset="webgpu-market")
        second = vtkbloom.add_bloom(renderer, strength=0.25)
        self.assertIs(first, second)
        self.assertEqual(second.GetParameters().GetStrength(), 0.25)
        grab(window)
        self.assertEqual(chain(renderer).count("vtkBloomPass"), 1)
        vtkbloom.remove_bloom(renderer)

    def test_below_anti_aliasing_and_kept_through_a_rebuild(self):
        window, (actor,) = scene()
        renderer = window.GetRenderers().GetFirstRenderer()
        fxaa, ssaa = vtkOpenGLFXAAPass(), vtkSSAAPass()
        camera = pyvista_like(renderer, fxaa, ssaa)
        plain = grab(window)
        vtkbloom.add_bloom(renderer)
        vtkbloom.add_emitter(renderer, actor)
        # FXAA's pass is replaced by the renderer's FXAA; bloom goes below SSAA.
        self.assertEqual(chain(renderer)[:3], ["vtkSSAAPass", "vtkBloomPass", "vtkCameraPass"])
        self.assertTrue(renderer.GetUseFXAA())
        self.assertGreater(np.abs(grab(window) - plain).max(), 20)
        # PyVista switches SSAA off: it rebuilds its chain from its own passes only.
        fxaa.SetDelegatePass(camera)
        renderer.SetPass(fxaa)
        self.assertNotIn("vtkBloomPass", chain(renderer))
        after = grab(window)  # the pass is put back before the render
        self.assertEqual(chain(renderer)[:2], ["vtkBloomPass", "vtkCameraPass"])
        self.assertGreater(np.abs(after - plain).max(), 20)
        # Every effect off: PyVista sets no pass at all.
        renderer.SetPass(None)
        self.assertGreater(np.abs(grab(window) - plain).max(), 20)
        self.assertEqual(chain(renderer), ["vtkBloomPass", "vtkRenderStepsPass"])
        vtkbloom.remove_bloom(renderer)
        self.assertIsNone(renderer.GetPass())
        self.assertFalse(renderer.GetUseFXAA())

    def test_inside_ssaa_it_fills_ssaa_framebuffer(self):
        # vtkSSAAPass renders its delegate into a framebuffer sqrt(5) times the window's size:
        # the pass renders and composites all of it (not the window's size in its corner), so
        # the frame is the plain SSAA frame where nothing is light.
        window, (actor,) = scene(size=(160, 120))
        renderer = window.GetRenderers().GetFirstRenderer()
        pyvista_like(renderer, vtkSSAAPass())
        plain = grab(window)
        vtkbloom.add_bloom(renderer)
        self.assertEqual(chain(renderer)[:2], ["vtkSSAAPass", "vtkBloomPass"])
        bloomed = grab(window)
        self.assertLessEqual((np.abs(bloomed - plain).max(axis=-1) > 8).mean(), 0.01)
        self.assertLessEqual(abs(bloomed.mean() - plain.mean()), 1.0)
        vtkbloom.remove_bloom(renderer)

    def test_hidden_lines_stay_hidden(self):
        # vtkOpenGLRenderer removes the hidden lines of wireframe actors itself, not through a
        # pass: a wireframe sphere in front of nothing shows its front half only, with bloom too.
        window, (actor,) = scene(size=(160, 120))
        # Lines one pixel wide: with wider ones VTK 9.6's own hidden-line removal changes almost
        # nothing in this scene (0.005 % of its pixels), and the check below could not fail.
        actor.GetProperty().SetRepresentationToWireframe()
        renderer = window.GetRenderers().GetFirstRenderer()
        visible = grab(window)
        renderer.UseHiddenLineRemovalOn()
        plain = grab(window)
        # The check can fail: the hidden lines are a visible part of the frame.
        self.assertGreater((np.abs(visible - plain).max(axis=-1) > 8).mean(), 0.02)
        vtkbloom.add_bloom(renderer)
        bloomed = grab(window)
        self.assertLessEqual(np.abs(bloomed - plain).max(), 1)
        renderer.UseHiddenLineRemovalOff()
        self.assertLessEqual(np.abs(grab(window) - visible).max(), 1)
        vtkbloom.remove_bloom(renderer)

    def test_labels_of_visible_points_stay(self):
        # A label mapper that hides the labels of occluded points reads the depth buffer while
        # the annotations draw (PyVista's add_point_labels and add_point_scalar_labels): the
        # pass writes the scene's depth under the composited frame, or every label is hidden.
        from vtkmodules.vtkCommonCore import vtkStringArray
        from vtkmodules.vtkRenderingCore import vtkActor2D
        from vtkmodules.vtkRenderingLabel import vtkLabelPlacementMapper, vtkPointSetToLabelHierarchy
        import vtkmodules.vtkRenderingFreeType  # noqa: F401  (the text renderer)

        window, (actor,) = scene(size=(200, 160))
        renderer = window.GetRenderers().GetFirstRenderer()
        source = actor.GetMapper().GetInputConnection(0, 0).GetProducer()
        source.Update()
        points = source.GetOutput()
        names = vtkStringArray()
        names.SetName("names")
        for i in range(points.GetNumberOfPoints()):
            names.InsertNextValue("P%d" % i)
        points.GetPointData().AddArray(names)
        hierarchy = vtkPointSetToLabelHierarchy()
        hierarchy.SetInputData(points)
        hierarchy.SetLabelArrayName("names")
        labels = vtkLabelPlacementMapper()
        labels.SetInputConnection(hierarchy.GetOutputPort())
        labels.UseDepthBufferOn()
        labels.SetShapeToRect()
        labelled = vtkActor2D()
        labelled.SetMapper(labels)
        without = grab(window)
        renderer.AddActor(labelled)
        plain = grab(window)
        # The check can fail: the labels are a visible part of the frame.
        self.assertGreater((np.abs(plain - without).max(axis=-1) > 8).mean(), 0.02)
        vtkbloom.add_bloom(renderer)
        self.assertLessEqual(np.abs(grab(window) - plain).max(), 1)
        vtkbloom.remove_bloom(renderer)

    def test_translucency_inside_ssaa_as_without_bloom(self):
        # Inside other passes (PyVista's SSAA here) the frame without bloom draws translucency
        # with the plain translucent step, not the renderer's order-independent transparency:
        # the pass leaves that step as it is (PyVista's plot_cell examples were 12 to 17 levels
        # off where it wrapped it).
        window, (actor,) = scene(colour=(0.7, 0.85, 0.9), size=(160, 120))
        actor.GetProperty().SetOpacity(0.5)
        renderer = window.GetRenderers().GetFirstRenderer()
        renderer.SetBackground(1, 1, 1)
        cube = vtkCubeSource()
        mapper = vtkPolyDataMapper()
        mapper.SetInputConnection(cube.GetOutputPort())
        box = vtkActor()
        box.SetMapper(mapper)
        box.GetProperty().SetColor(0.8, 0.7, 0.5)
        box.SetPosition(0.3, 0, -1)
        renderer.AddActor(box)
        renderer.ResetCamera()
        pyvista_like(renderer, vtkSSAAPass())
        plain = grab(window)
        vtkbloom.add_bloom(renderer)
        self.assertLessEqual(np.abs(grab(window) - plain).max(), 1)
        vtkbloom.remove_bloom(renderer)

    def test_remove_bloom_puts_fxaa_back(self):
        window, _ = scene()
        renderer = window.GetRenderers().GetFirstRenderer()
        fxaa = vtkOpenGLFXAAPass()
        pyvista_like(renderer, fxaa)
        plain = grab(window)
        vtkbloom.add_bloom(renderer)
        grab(window)
        vtkbloom.remove_bloom(renderer)
        self.assertEqual(chain(renderer)[:2], ["vtkOpenGLFXAAPass", "vtkCameraPass"])
        np.testing.assert_array_equal(grab(window), plain)

    @unittest.skipIf(vtkSSAOPass is None, "no vtkSSAOPass in this VTK")
    def test_above_ssao(self):
        window, _ = scene()
        renderer = window.GetRenderers().GetFirstRenderer()
        pyvista_like(renderer, vtkSSAOPass(), vtkSSAAPass())
        vtkbloom.add_bloom(renderer)
        grab(window)
        self.assertEqual(chain(renderer)[:4], ["vtkSSAAPass", "vtkBloomPass", "vtkSSAOPass", "vtkCameraPass"])
        vtkbloom.remove_bloom(renderer)
        self.assertEqual(chain(renderer)[:3], ["vtkSSAAPass", "vtkSSAOPass", "vtkCameraPass"])

    def test_every_renderer_of_a_window(self):
        window, actors = scene(renderers=2)
        passes = vtkbloom.add_bloom(window)
        self.assertEqual(len(passes), 2)
        self.assertIsNot(passes[0], passes[1])
        vtkbloom.add_emitter(window, actors[0])
        grab(window)
        vtkbloom.remove_bloom(window)

    def test_no_display_is_an_exception_not_an_abort(self):
        import subprocess
        import sys

        script = (
            "import vtkbloom\n"
            "from vtkmodules.vtkRenderingCore import vtkRenderer, vtkRenderWindow\n"
            "import vtkmodules.vtkRenderingOpenGL2\n"
            "window = vtkRenderWindow(); window.SetOffScreenRendering(1)\n"
            "renderer = vtkRenderer(); window.AddRenderer(renderer)\n"
            "try:\n"
            "    vtkbloom.add_bloom(window)\n"
            "except RuntimeError as e:\n"
            "    print('refused:', e); raise SystemExit(3)\n"
            "window.Render(); print('rendered')\n"
        )
        env = dict(os.environ)
        env.pop("DISPLAY", None)
        run = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, env=env)
        from vtkmodules.vtkCommonCore import vtkVersion

        old_x = vtkRenderWindow().GetClassName() == "vtkXOpenGLRenderWindow" and (
            vtkVersion.GetVTKMajorVersion(), vtkVersion.GetVTKMinorVersion()) < (9, 4)
        if old_x:
            # VTK 9.1 built for X: one line, not SIGABRT.
            self.assertEqual(run.returncode, 3, run.stderr)
            self.assertIn("xvfb-run", run.stdout)
        else:
            # A VTK that renders headless (9.4 and later choose EGL or OSMesa) just renders.
            self.assertEqual(run.returncode, 0, run.stdout + run.stderr)
            self.assertIn("rendered", run.stdout)

    def test_a_target_it_does_not_know(self):
        with self.assertRaises(TypeError) as raised:
            vtkbloom.add_bloom("plotter")
        self.assertIn("pyvista.Plotter", str(raised.exception))
        window, _ = scene()
        with self.assertRaises(ValueError):
            vtkbloom.add_bloom(window, preset="glowy")
        with self.assertRaises(TypeError):
            vtkbloom.add_bloom(window, strenght=1.0)
        vtkbloom.remove_bloom(window)


try:
    import vedo
except ImportError:  # vedo is optional; CI installs python3-vedo on Debian 12 and in sid
    vedo = None
    if os.environ.get("CI") == "true":
        raise SystemExit("vedo is not installed, and CI has it (python3-vedo)")


@unittest.skipIf(vedo is None, "vedo is not installed")
class Vedo(unittest.TestCase):
    def test_a_vedo_plotter_blooms_through_show_and_its_effects(self):
        plotter = vedo.Plotter(offscreen=True, size=(160, 120))
        _, (actor,) = scene()
        plotter.show(actor, interactive=False)
        plain = grab(plotter.window)
        vtkbloom.add_emitter(plotter, actor)
        plotter.show(actor, interactive=False)
        self.assertGreater(np.abs(grab(plotter.window) - plain).max(), 20)
        screenshot = plotter.screenshot(asarray=True)
        self.assertGreater(np.abs(screenshot.astype(int) - plain[::-1, :, :3]).max(), 20)
        # vedo's own effects set the renderer's pass; the bloom is put back over them.
        for effect, arguments in (("add_depth_of_field", ()), ("add_ambient_occlusion", (0.1,))):
            getattr(plotter, effect)(*arguments)
            plotter.show(actor, interactive=False)
            passes = chain(plotter.renderer)
            self.assertEqual(passes.count("vtkBloomPass"), 1, effect)
            self.assertEqual(passes[0], "vtkBloomPass", effect)  # above vedo's effect
        vtkbloom.remove_bloom(plotter)
        self.assertNotIn("vtkBloomPass", chain(plotter.renderer))
        plotter.close()

    def test_a_vedo_mesh_glows(self):
        # vedo's own objects: followers in vedo 2023, objects holding an actor from 2024.
        plotter = vedo.Plotter(offscreen=True, size=(160, 120))
        lamp = vedo.Sphere(r=0.5).color("orange")
        wall = vedo.Cube(pos=(1.5, 0, 0)).color("lightblue")
        plotter.show(lamp, wall, interactive=False)
        plain = plotter.screenshot(asarray=True).astype(int)
        vtkbloom.add_bloom(plotter)
        plotter.show(lamp, wall, interactive=False)
        self.assertLessEqual(np.abs(plotter.screenshot(asarray=True).astype(int) - plain).max(), 8)
        vtkbloom.add_emitter(plotter, lamp)
        plotter.show(lamp, wall, interactive=False)
        glowing = plotter.screenshot(asarray=True).astype(int)
        self.assertGreater((np.abs(glowing - plain).max(axis=-1) > 8).mean(), 0.02)
        self.assertEqual(np.abs(glowing[:4, :4] - plain[:4, :4]).max(), 0)
        plotter.close()


if __name__ == "__main__":
    from unittest_main import main

    sys.exit(main())
