#!/usr/bin/python3
# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
"""Tests of vtkbloom's numpy functions (bloom, blur, read_exr, write_exr): the same pixels as
the filters they wrap, no copies of contiguous arrays, and a Python exception with one line
for every mistake a user makes, with nothing printed by VTK."""

import os
import subprocess
import sys
import tempfile
import unittest

import numpy as np
from vtkmodules.util import numpy_support
from vtkmodules.vtkCommonDataModel import vtkImageData

import vtkbloom
from vtkbloom import arrays

HERE = os.path.dirname(os.path.abspath(__file__))
CRAFTED = os.path.join(HERE, "..", "Data", "EXR", "Crafted")


def frame(height=90, width=120, channels=4, dtype=np.float32, seed=0):
    """A dark frame with a few lights above 1."""
    rng = np.random.default_rng(seed)
    image = (0.3 * rng.random((height, width, channels))).astype(dtype)
    image[20:24, 30:34, :3] = 6.0
    image[60, 90, :3] = 40.0
    if channels == 4:
        image[..., 3] = 1.0
    return image


def through_filter(algorithm, image):
    """What `algorithm` makes of `image` through a vtkImageData of its own (deep copied)."""
    h, w, c = image.shape
    data = vtkImageData()
    data.SetDimensions(w, h, 1)
    scalars = numpy_support.numpy_to_vtk(image.reshape(h * w, c).copy(), deep=True)
    data.GetPointData().SetScalars(scalars)
    algorithm.SetInputData(data)
    algorithm.Update()
    out = algorithm.GetOutput().GetPointData().GetScalars()
    return numpy_support.vtk_to_numpy(out).reshape(h, w, c)


class Bloom(unittest.TestCase):
    def test_same_pixels_as_the_filter_for_each_shape_and_dtype(self):
        for channels in (3, 4):
            for dtype in (np.float32, np.float64):
                image = frame(channels=channels, dtype=dtype)
                result = vtkbloom.bloom(image, preset="webgpu-market", strength=0.7)
                self.assertEqual(result.shape, image.shape)
                self.assertEqual(result.dtype, image.dtype)
                reference = vtkbloom.vtkImageBloom()
                reference.SetPreset("webgpu-market")
                reference.SetStrength(0.7)
                expected = through_filter(reference, image)
                np.testing.assert_array_equal(result, expected)
                self.assertGreater(np.abs(result - image).max(), 0.01)  # it bloomed

    def test_keywords_reach_their_parameter(self):
        image = frame()
        base = vtkbloom.bloom(image)
        for keyword, value, setter in (
            ("strength", 2.0, "SetStrength"),
            ("threshold", 3.0, "SetThreshold"),
            ("number_of_levels", 2, "SetNumberOfLevels"),
            ("tint", (1.0, 0.5, 0.25), "SetTint"),
            ("karis_average", True, "SetKarisAverage"),
            ("execution_mode", "reference", "SetExecutionModeToReference"),
        ):
            result = vtkbloom.bloom(image, **{keyword: value})
            reference = vtkbloom.vtkImageBloom()
            method = getattr(reference, setter)
            method() if isinstance(value, str) else method(*value) if isinstance(
                value, tuple
            ) else method(value)
            np.testing.assert_array_equal(result, through_filter(reference, image), keyword)
            if keyword not in ("karis_average", "execution_mode"):
                self.assertFalse(np.array_equal(result, base), keyword)

    def test_a_contiguous_array_is_not_copied_in_or_out(self):
        image = frame()
        data = arrays._image_from_array(image)
        inside = numpy_support.vtk_to_numpy(data.GetPointData().GetScalars())
        self.assertTrue(np.shares_memory(inside, image))
        result = vtkbloom.bloom(image)
        self.assertFalse(result.flags.owndata)  # a view of VTK's output
        self.assertTrue(result.flags.c_contiguous)
        # A strided view is accepted (copied once) and gives the same pixels.
        wide = np.zeros((90, 240, 4), np.float32)
        wide[:, ::2] = image
        np.testing.assert_array_equal(vtkbloom.bloom(wide[:, ::2]), result)

    def test_statistics_on_request(self):
        image = frame(dtype=np.float64)
        result, stats = vtkbloom.bloom(image, statistics=True)
        self.assertEqual(
            set(stats),
            {"energy_in", "energy_out", "number_of_bright_pixels", "peak_luminance_in",
             "peak_luminance_out", "number_of_levels_used"},
        )
        luminance = image[..., :3] @ np.array([0.2126, 0.7152, 0.0722])
        self.assertAlmostEqual(stats["energy_in"], luminance.sum(), delta=1e-9 * luminance.sum())
        self.assertAlmostEqual(stats["peak_luminance_in"], luminance.max(), places=12)
        self.assertIsInstance(stats["number_of_bright_pixels"], int)

    def test_mistakes_raise_one_line_naming_what_is_accepted(self):
        image = frame()
        cases = [
            (dict(image=image.astype(np.uint8)), TypeError, "float32 or float64"),
            (dict(image=image[..., 0]), ValueError, "H x W x 3 or H x W x 4"),
            (dict(image=np.zeros((4, 4, 2), np.float32)), ValueError, "H x W x 3"),
            (dict(image=image.tolist()), TypeError, "numpy array"),
            (dict(image=image, preset="glowy"), ValueError, "webgpu-market"),
            (dict(image=image, strenght=1.0), TypeError, "strength"),
            (dict(image=image, knee=5.0), ValueError, "[0.0, 1.0]"),
            (dict(image=image, number_of_levels=2.5), TypeError, "an integer"),
            (dict(image=image, karis_average=1), TypeError, "True or False"),
            (dict(image=image, strength=float("nan")), TypeError, "strength"),
            (dict(image=image, tint=(1.0, 2.0)), ValueError, "3 numbers"),
            (dict(image=image, execution_mode="quick"), ValueError, "'fast'"),
            (dict(image=image, statistics="yes"), TypeError, "True or False"),
        ]
        for arguments, error, text in cases:
            with self.assertRaises(error, msg=str(arguments.keys())) as raised:
                vtkbloom.bloom(**arguments)
            message = str(raised.exception)
            self.assertIn(text, message)
            self.assertNotIn("\n", message)

    def test_vtk_prints_nothing(self):
        script = (
            "import numpy as np, vtkbloom\n"
            "image = np.ones((8, 8, 4), np.float32)\n"
            "for bad in (dict(knee=5.0), dict(preset='x'), dict(blur_radius=-7)):\n"
            "    try: vtkbloom.bloom(image, **bad)\n"
            "    except (TypeError, ValueError): pass\n"
            "try: vtkbloom.read_exr(%r)\n"
            "except OSError: pass\n" % os.path.join(CRAFTED, "dwaa-dc-short.exr")
        )
        run = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True)
        self.assertEqual(run.returncode, 0, run.stderr)
        self.assertEqual(run.stderr, "")
        self.assertEqual(run.stdout, "")

    def test_import_needs_no_numpy(self):
        script = "import sys\nsys.modules['numpy'] = None\nimport vtkbloom\nprint(callable(vtkbloom.bloom))"
        run = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True)
        self.assertEqual(run.stdout.strip(), "True", run.stderr)

    def test_every_parameter_of_the_class_is_a_keyword(self):
        keywords = vtkbloom.bloom_parameters()
        for name in ("strength", "threshold", "threshold_mode", "knee", "psf_tail_scale",
                     "number_of_levels", "tint", "level_weights", "execution_mode"):
            self.assertIn(name, keywords)
        self.assertIn("[0.0, 1.0]", keywords["knee"])


class Blur(unittest.TestCase):
    def test_same_pixels_as_the_separable_gaussian(self):
        image = frame(dtype=np.float64)
        result = vtkbloom.blur(image, 3.0, border_mode="reflect")
        reference = vtkbloom.vtkImageSeparableGaussian()
        reference.SetStandardDeviations(3.0, 3.0, 0.0)
        reference.SetBorderModeToReflect()
        np.testing.assert_array_equal(result, through_filter(reference, image))
        # Energy: reflection keeps the sum of each channel.
        np.testing.assert_allclose(result.sum(axis=(0, 1)), image.sum(axis=(0, 1)), rtol=1e-12)

    def test_bad_sigma_and_radius(self):
        for sigma in (0, -1, float("inf"), "2", True):
            with self.assertRaises(ValueError):
                vtkbloom.blur(frame(), sigma)
        with self.assertRaises(ValueError):
            vtkbloom.blur(frame(), 2.0, radius=-1)
        with self.assertRaises(TypeError):
            vtkbloom.blur(frame(), 2.0, sigma_y=1.0)


class EXR(unittest.TestCase):
    def test_round_trip(self):
        image = frame()
        with tempfile.TemporaryDirectory() as directory:
            path = os.path.join(directory, "frame.exr")
            vtkbloom.write_exr(path, image, pixel_type="float")
            np.testing.assert_array_equal(vtkbloom.read_exr(path), image)
            vtkbloom.write_exr(path, image, compression="piz")
            read = vtkbloom.read_exr(path)
            self.assertEqual(read.dtype, np.float32)
            np.testing.assert_array_equal(read, image.astype(np.float16).astype(np.float32))

    def test_rows_are_top_first_as_the_reader_stores_them(self):
        image = frame()
        with tempfile.TemporaryDirectory() as directory:
            path = os.path.join(directory, "frame.exr")
            vtkbloom.write_exr(path, image, pixel_type="float")
            reader = vtkbloom.vtkOpenEXRReader()
            reader.SetFileName(path)
            reader.Update()
            self.assertEqual(list(reader.GetDataWindow()), [0, 119, 0, 89])
            first = numpy_support.vtk_to_numpy(reader.GetOutput().GetPointData().GetScalars())[:120]
            np.testing.assert_array_equal(first, image[0])

    def test_refused_and_missing_files(self):
        with self.assertRaises(FileNotFoundError):
            vtkbloom.read_exr("/nonexistent/frame.exr")
        with self.assertRaises(OSError) as raised:
            vtkbloom.read_exr(os.path.join(CRAFTED, "dwab-ac-short.exr"))
        self.assertIn("chunk of pixels", str(raised.exception))
        with self.assertRaises(ValueError):
            vtkbloom.write_exr("/tmp/x.exr", frame(), compression="jpeg")
        with self.assertRaises(OSError):
            vtkbloom.write_exr("/nonexistent/dir/x.exr", frame())


if __name__ == "__main__":
    from unittest_main import main

    sys.exit(main())
