#!/usr/bin/python3
# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
"""vtkbloom through PyVista's own plugin points (vtkbloom.pyvista_plugin), found by the
entry points of the distribution's metadata: plotter.bloom, image.bloom and
pyvista.read("x.exr"). Each is checked against the vtkbloom call it spells differently, bit for
bit; found with no import; listed by PyVista's own registries; and released when the plotter
closes. Built only where PyVista imports (CI's sid leg, PyVista 0.49)."""

import doctest
import gc
import glob
import os
import subprocess
import sys
import tempfile
import unittest
import weakref

import numpy as np
import pyvista as pv

import vtkbloom

pv.OFF_SCREEN = True
SHARED = os.path.join(os.environ.get("VTKBLOOM_SHARED_DATA_DIR", os.path.join(
    os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "shared", "data")), "exr")
CRAFTED = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Data", "EXR", "Crafted")


def lamp_plotter():
    p = pv.Plotter(window_size=(200, 150))
    lamp = p.add_mesh(pv.Sphere(radius=0.4), color="orange", name="lamp")
    p.add_mesh(pv.Cube(center=(1.2, 0, 0)), color="lightblue")
    p.camera_position = "xy"
    return p, lamp


def shot(p):
    p.render()
    return p.screenshot(return_img=True).astype(int)


class FoundWithNoImport(unittest.TestCase):
    def test_a_plotter_and_a_reader_with_no_import_of_vtkbloom(self):
        folder = tempfile.mkdtemp()
        path = os.path.join(folder, "x.exr")
        vtkbloom.write_exr(path, np.full((4, 6, 3), 3.0, np.float32), pixel_type="float")
        script = (
            "import sys, pyvista as pv\n"
            "assert 'vtkbloom' not in sys.modules, 'imported with pyvista'\n"
            "pl = pv.Plotter(off_screen=True)\n"
            "pl.bloom.enable()\n"
            "assert pl.bloom.passes[0].GetClassName() == 'vtkBloomPass'\n"
            "image = pv.read(sys.argv[1])\n"
            "assert isinstance(image, pv.ImageData) and image.dimensions == (6, 4, 1), image\n"
            "pl.close()\n"
        )
        run = subprocess.run([sys.executable, "-c", script, path], capture_output=True, text=True, timeout=120)
        self.assertEqual(run.returncode, 0, run.stderr)

    def test_listed_by_pyvista(self):
        components = {r.name: r for r in pv.registered_plotter_components()}
        self.assertIn("bloom", components)
        self.assertIs(components["bloom"].component, vtkbloom.pyvista_plugin.PlotterBloom)
        accessors = [(r.name, r.target) for r in pv.registered_accessors()]
        self.assertIn(("bloom", pv.ImageData), accessors)
        readers = {r.extension: r for r in pv.registered_readers()}
        self.assertIn(".exr", readers)
        self.assertIs(readers[".exr"].handler, vtkbloom.pyvista_plugin.read)


class PlotterComponent(unittest.TestCase):
    def test_the_same_frame_as_add_bloom_bit_for_bit(self):
        one, lamp = lamp_plotter()
        one.bloom.enable(strength=0.7)
        one.bloom.add_emitter(lamp)
        two, other = lamp_plotter()
        vtkbloom.add_bloom(two, strength=0.7)
        vtkbloom.add_emitter(two, other)
        plain, _ = lamp_plotter()
        a, b, c = shot(one), shot(two), shot(plain)
        np.testing.assert_array_equal(a, b)
        self.assertGreater((np.abs(a - c).max(axis=-1) > 8).mean(), 0.02)  # and it glows
        for p in (one, two, plain):
            p.close()

    def test_parameters_read_and_set_with_the_numpy_ranges(self):
        p, lamp = lamp_plotter()
        p.bloom.strength = 0.6  # before enable: applied by it
        self.assertFalse(p.bloom.enabled)
        self.assertEqual(p.bloom.strength, 0.6)
        p.bloom.enable()
        self.assertAlmostEqual(p.bloom.passes[0].GetParameters().GetStrength(), 0.6)
        p.bloom.threshold = 2.0
        self.assertEqual(p.bloom.passes[0].GetParameters().GetThreshold(), 2.0)
        self.assertEqual(p.bloom.threshold, 2.0)
        for bad, error in (({"knee": 2.0}, ValueError), ({"number_of_levels": 0}, ValueError),
                           ({"strength": "x"}, TypeError)):
            name, value = next(iter(bad.items()))
            with self.assertRaises(error) as raised:
                setattr(p.bloom, name, value)
            self.assertEqual(len(str(raised.exception).splitlines()), 1)
            self.assertIn(name, str(raised.exception))
            with self.assertRaises(error):
                vtkbloom.bloom(np.zeros((4, 4, 3), np.float32), **bad)  # the same ranges
        with self.assertRaises(AttributeError):
            p.bloom.no_such_parameter = 1
        with self.assertRaises(AttributeError):
            p.bloom.no_such_parameter
        self.assertIn("strength", dir(p.bloom))
        p.close()

    def test_enable_and_disable_in_any_order_with_pyvista_effects(self):
        # Each order, then bloom off: the frame the same effects give with no bloom at all
        # (PyVista's own FXAA falls back to SSAA on EGL, and its frame after switching it off
        # is not the first one: the reference runs the same steps).
        def run(p, step):
            {"bloom": p.bloom.enable, "-bloom": p.bloom.disable,
             "ssao": p.enable_ssao, "-ssao": p.disable_ssao,
             "fxaa": lambda: p.enable_anti_aliasing("fxaa"),
             "-fxaa": p.disable_anti_aliasing}[step]()
            shot(p)

        for steps in (("bloom", "ssao", "-bloom", "-ssao"), ("ssao", "bloom", "-ssao", "-bloom"),
                      ("fxaa", "bloom", "-bloom", "-fxaa"), ("bloom", "fxaa", "-fxaa", "-bloom"),
                      ("ssao", "bloom", "-bloom")):
            p, _ = lamp_plotter()
            reference, _ = lamp_plotter()
            for step in steps:
                run(p, step)
                if "bloom" not in step:
                    run(reference, step)
            self.assertFalse(p.bloom.enabled, steps)
            np.testing.assert_array_equal(shot(p), shot(reference), str(steps))
            p.close()
            reference.close()

    def test_close_and_deep_clean_leave_nothing_behind(self):
        for clean in ("close", "deep_clean"):
            p, lamp = lamp_plotter()
            p.bloom.enable()
            p.bloom.add_emitter(lamp)
            shot(p)
            passes = [weakref.ref(x) for x in p.bloom.passes]
            renderer = p.renderer
            if clean == "deep_clean":
                p.deep_clean()
            p.close()
            self.assertIsNone(vtkbloom.get_bloom(renderer), clean)  # no record left
            del renderer
            gc.collect()
            self.assertTrue(passes and all(ref() is None for ref in passes), clean)


class Reader(unittest.TestCase):
    def test_shared_images_bit_for_bit_against_read_exr(self):
        files = sorted(glob.glob(os.path.join(SHARED, "*.exr")))
        self.assertGreaterEqual(len(files), 8, SHARED)
        for path in files:
            try:
                expected = vtkbloom.read_exr(path)
            except OSError:
                with self.assertRaises(OSError):
                    pv.read(path)
                continue
            image = pv.read(path)
            self.assertIsInstance(image, pv.ImageData)
            width, height, _ = image.dimensions
            self.assertEqual(image.active_scalars_name, "OpenEXRImage")
            got = image.active_scalars.reshape(height, width, -1)
            np.testing.assert_array_equal(got.view(np.uint32) if got.dtype == np.float32 else got,
                                          expected.view(np.uint32) if expected.dtype == np.float32 else expected,
                                          os.path.basename(path))

    def test_read_texture_keeps_the_hdr_values(self):
        # PyVista's read_texture goes through pyvista.read: an EXR environment map keeps its
        # highlights above 1, in float32, and set_environment_texture takes it.
        path = os.path.join(tempfile.mkdtemp(), "studio.exr")
        frame = np.full((32, 64, 3), 0.2, np.float32)
        frame[10:14, 20:24] = 40.0
        vtkbloom.write_exr(path, frame, pixel_type="float")
        texture = pv.read_texture(path)
        scalars = texture.to_image().active_scalars
        self.assertEqual(scalars.dtype, np.float32)
        self.assertEqual(float(scalars.max()), 40.0)
        p = pv.Plotter(window_size=(160, 120))
        p.add_mesh(pv.Sphere(), pbr=True, metallic=1.0, roughness=0.1)
        p.set_environment_texture(texture)
        self.assertEqual(shot(p).shape, (120, 160, 3))
        p.close()

    def test_a_bad_file_is_one_python_exception(self):
        folder = tempfile.mkdtemp()
        not_exr = os.path.join(folder, "text.exr")
        with open(not_exr, "w") as out:
            out.write("not an OpenEXR file\n")
        truncated = os.path.join(folder, "truncated.exr")
        with open(os.path.join(SHARED, "TestImages_stripes.exr"), "rb") as source:
            data = source.read()
        with open(truncated, "wb") as out:
            out.write(data[: len(data) // 3])
        hostile = sorted(glob.glob(os.path.join(CRAFTED, "*.exr")))[0]
        for path in (not_exr, truncated, hostile):
            with self.assertRaises(OSError) as raised:
                pv.read(path)
            self.assertEqual(len(str(raised.exception).splitlines()), 1, path)
        with self.assertRaises(FileNotFoundError):
            pv.read(os.path.join(folder, "missing.exr"))


class Accessor(unittest.TestCase):
    def frame_image(self):
        rng = np.random.default_rng(3)
        frame = rng.random((48, 64, 3), dtype=np.float32)
        frame[20:23, 30:33] = 40.0
        image = pv.ImageData(dimensions=(64, 48, 1))
        image.point_data["frame"] = frame[::-1].reshape(-1, 3)  # VTK's row 0 at the bottom
        return image, frame

    def test_apply_blur_and_statistics_are_the_numpy_functions(self):
        image, frame = self.frame_image()
        glow = image.bloom.apply("webgpu-market", strength=0.5)
        self.assertIsInstance(glow, pv.ImageData)
        expected = vtkbloom.bloom(frame, preset="webgpu-market", strength=0.5)
        np.testing.assert_array_equal(glow.point_data["frame"].reshape(48, 64, 3)[::-1], expected)
        blurred = image.bloom.blur(1.5)
        np.testing.assert_array_equal(blurred.point_data["frame"].reshape(48, 64, 3)[::-1],
                                      vtkbloom.blur(frame, 1.5))
        _, stats = vtkbloom.bloom(frame, statistics=True)
        self.assertEqual(image.bloom.statistics(), stats)
        np.testing.assert_array_equal(image.point_data["frame"].reshape(48, 64, 3)[::-1], frame)  # unchanged

    def test_an_image_that_is_not_a_frame_is_refused(self):
        volume = pv.ImageData(dimensions=(4, 4, 4))
        volume.point_data["v"] = np.zeros((64, 3), np.float32)
        with self.assertRaises(ValueError):
            volume.bloom.apply()
        grey = pv.ImageData(dimensions=(4, 4, 1))
        grey.point_data["g"] = np.zeros(16, np.float32)
        with self.assertRaises(ValueError):
            grey.bloom.apply()


def docstring_frames(source, plain):
    """The frames a docstring's examples grab (plotter.screenshot), run as one script, as
    client_examples.py runs PyVista's own; `plain` runs them with plotter.bloom's enable and
    add_emitter doing nothing: the frame the same lines give without bloom. Each frame is kept
    with whether the plotter's passes ran their chain (the frame had light)."""
    from vtkbloom import pyvista_plugin as plugin

    frames, screenshot = [], pv.Plotter.screenshot
    kept = {name: getattr(plugin.PlotterBloom, name) for name in ("enable", "add_emitter")}

    def grab(plotter, *args, **kwargs):
        image = screenshot(plotter, *args, **kwargs)
        passes = vtkbloom.get_bloom(plotter)
        passes = passes if isinstance(passes, list) else [passes]
        light = any(p is not None and not p.GetLastFrame().GetBloomSkipped() for p in passes)
        frames.append((np.array(image, copy=True), light))
        return image

    pv.Plotter.screenshot = grab
    if plain:
        plugin.PlotterBloom.enable = lambda self, *a, **k: None
        plugin.PlotterBloom.add_emitter = lambda self, *a, **k: None
    try:
        exec(compile(source, "<docstring>", "exec"), {"__name__": "__docstring__"})
    finally:
        pv.Plotter.screenshot = screenshot
        for name, method in kept.items():
            setattr(plugin.PlotterBloom, name, method)
    return frames


class Examples(unittest.TestCase):
    def test_every_docstring_example_runs(self):
        import vtkbloom.pyvista_plugin as plugin

        result = doctest.testmod(plugin, optionflags=doctest.ELLIPSIS)
        self.assertGreaterEqual(result.attempted, 20)
        self.assertEqual(result.failed, 0)

    def test_docstring_frames_compared_as_client_examples_does(self):
        # client_examples.py's comparison: the plain frame renders the same twice, and so does
        # the bloomed one; a frame without light is the plain frame within a level; a frame with
        # light glows over areas, not at thin edges (client_examples' hint at a wrong
        # composite: lines and text). Not "only brighter": the default preset mixes the bloom
        # into the scene (energy-conserving), so a bright emitter's core darkens.
        import client_examples
        import vtkbloom.pyvista_plugin as plugin

        compared = 0
        for test in doctest.DocTestFinder(exclude_empty=True).find(plugin):
            source = "".join(e.source for e in test.examples)
            if "screenshot(" not in source:
                continue
            with self.subTest(test.name):
                plain = [docstring_frames(source, plain=True) for _ in range(2)]
                bloomed = [docstring_frames(source, plain=False) for _ in range(2)]
                self.assertGreater(len(plain[0]), 0)
                self.assertEqual(len({len(f) for f in plain + bloomed}), 1)
                for (a, _), (b, _), (c, light), (d, _) in zip(*plain, *bloomed):
                    np.testing.assert_array_equal(a, b)
                    np.testing.assert_array_equal(c, d)
                    result = client_examples.compare(a, c)
                    if "bloom.add_emitter(" in source:
                        self.assertTrue(light, "an emitter was added, and nothing glowed")
                    if light:
                        self.assertGreater(result["changed_fraction"], 0.01, result)
                        self.assertLess(result["thin_share"], 0.05, result)
                    else:
                        self.assertLessEqual(result["max_diff"], 1, result)
                    compared += 1
        self.assertGreaterEqual(compared, 1)


if __name__ == "__main__":
    from unittest_main import main

    sys.exit(main())
