#!/usr/bin/python3
# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
"""Tests of the vtkbloom Python package: parameters, presets, errors, numpy round trips and
the bloom statistics, checked against independent numpy computations."""

import math
import os
import tempfile
import sys
import unittest

import numpy as np
from vtkmodules.vtkCommonCore import reference, vtkCommand
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkImagingCore import vtkImageCast, vtkRTAnalyticSource
from vtkmodules.util import numpy_support

import vtkbloom

REC709 = np.array([0.2126, 0.7152, 0.0722])


def image_from_array(array):
    """(H, W, C) numpy array -> vtkImageData, row 0 first."""
    h, w, c = array.shape
    image = vtkImageData()
    image.SetDimensions(w, h, 1)
    flat = np.ascontiguousarray(array).reshape(h * w, c)
    scalars = numpy_support.numpy_to_vtk(flat, deep=True)
    scalars.SetName("scalars")
    image.GetPointData().SetScalars(scalars)
    return image


def array_from_image(image):
    w, h, _ = image.GetDimensions()
    scalars = image.GetPointData().GetScalars()
    return numpy_support.vtk_to_numpy(scalars).reshape(h, w, scalars.GetNumberOfComponents())


class ErrorCounter:
    def __init__(self, obj):
        self.count = 0
        obj.AddObserver(vtkCommand.ErrorEvent, self)

    def __call__(self, obj, event):
        self.count += 1


def hdr_scene(h=45, w=80, seed=7):
    """A dim random field with a few bright discs, RGBA float32."""
    rng = np.random.default_rng(seed)
    rgb = rng.uniform(0.0, 0.3, size=(h, w, 3))
    yy, xx = np.mgrid[0:h, 0:w]
    for cx, cy, r, v in ((15, 10, 4, 20.0), (60, 30, 6, 3.0), (79, 0, 5, 150.0)):
        rgb[(xx - cx) ** 2 + (yy - cy) ** 2 <= r * r] = v
    alpha = rng.uniform(0.2, 1.0, size=(h, w, 1))
    return np.concatenate([rgb, alpha], axis=2).astype(np.float32)


def smoothstep(e0, e1, x):
    t = np.clip((x - e0) / (e1 - e0), 0.0, 1.0)
    return t * t * (3.0 - 2.0 * t)


class Package(unittest.TestCase):
    def test_classes_are_importable(self):
        for name in ("vtkImageBloom", "vtkImageBloomThreshold", "vtkImagePyramidDown",
                     "vtkImagePyramidUp", "vtkImageSeparableGaussian", "vtkOpenEXRReader",
                     "vtkOpenEXRWriter"):
            self.assertTrue(hasattr(vtkbloom, name), name)
        self.assertIn("vtkImageBloom", str(vtkbloom.vtkImageBloom()))

    def test_parameters_round_trip(self):
        bloom = vtkbloom.vtkImageBloom()
        bloom.SetThreshold(1.25)
        bloom.SetKnee(0.3)
        bloom.SetNumberOfLevels(3)
        bloom.SetStrength(0.7)
        bloom.SetTint(1.0, 0.5, 0.25)
        bloom.SetLevelWeight(2, 0.4)
        self.assertEqual(bloom.GetThreshold(), 1.25)
        self.assertEqual(bloom.GetKnee(), 0.3)
        self.assertEqual(bloom.GetNumberOfLevels(), 3)
        self.assertEqual(bloom.GetTint(), (1.0, 0.5, 0.25))
        self.assertEqual(bloom.GetLevelWeight(2), 0.4)
        self.assertEqual(bloom.GetLevelWeight(0), 1.0)
        bloom.SetKnee(5.0)  # clamped to [0, 1]
        self.assertEqual(bloom.GetKnee(), 1.0)

    def test_presets(self):
        bloom = vtkbloom.vtkImageBloom()
        self.assertTrue(bloom.SetPreset("crt-halfres"))
        self.assertEqual(bloom.GetThreshold(), 0.8)
        self.assertEqual(bloom.GetStrength(), 1.5)
        self.assertTrue(bloom.SetPreset("mip-atlas"))
        self.assertEqual(bloom.GetCompositeMode(), vtkbloom.vtkImageBloom.LERP)
        errors = ErrorCounter(bloom)
        self.assertFalse(bloom.SetPreset("no-such-preset"))
        self.assertEqual(errors.count, 1)
        self.assertEqual(bloom.GetStrength(), 0.52)  # unchanged by the failed call

    def test_shared_parameters(self):
        # One vtkBloomParameters, shared by two filters: an edit through either reaches both,
        # and the old enum names are the parameters' values.
        first, second = vtkbloom.vtkImageBloom(), vtkbloom.vtkImageBloom()
        parameters = vtkbloom.vtkBloomParameters()
        first.SetParameters(parameters)
        second.SetParameters(first.GetParameters())
        first.SetStrength(0.25)
        self.assertEqual(second.GetStrength(), 0.25)
        self.assertEqual(parameters.GetStrength(), 0.25)
        self.assertEqual(vtkbloom.vtkImageBloom.LERP, vtkbloom.vtkBloomParameters.LERP)
        self.assertIn("ping-pong", parameters.GetPresetNamesList())
        image = image_from_array(np.full((9, 16, 4), 2.0, np.float32))
        for bloom in (first, second):
            bloom.SetInputData(image)
            bloom.Update()
        np.testing.assert_array_equal(array_from_image(first.GetOutput()),
                                      array_from_image(second.GetOutput()))

    def test_documented_constant(self):
        # PRESETS.md: webgpu-market turns a constant 0.5 into 0.607421875.
        bloom = vtkbloom.vtkImageBloom()
        bloom.SetPreset("webgpu-market")
        bloom.SetInputData(image_from_array(np.full((9, 16, 4), 0.5, np.float32)))
        bloom.Update()
        out = array_from_image(bloom.GetOutput())
        np.testing.assert_allclose(out[..., :3], 0.607421875, rtol=1e-6)
        np.testing.assert_array_equal(out[..., 3], 0.5)


class Errors(unittest.TestCase):
    def test_wrong_scalar_type(self):
        for cls in (vtkbloom.vtkImageBloom, vtkbloom.vtkImageSeparableGaussian,
                    vtkbloom.vtkImageBloomThreshold, vtkbloom.vtkImagePyramidDown):
            f = cls()
            errors = ErrorCounter(f)
            f.GetExecutive().AddObserver(vtkCommand.ErrorEvent, lambda *a: None)
            f.SetInputData(image_from_array(np.ones((4, 5, 3), np.int16)))
            f.Update()
            self.assertGreaterEqual(errors.count, 1, cls.__name__)
            self.assertEqual(f.GetOutput().GetNumberOfPoints(), 0, cls.__name__)

    def test_empty_image(self):
        bloom = vtkbloom.vtkImageBloom()
        errors = ErrorCounter(bloom)
        bloom.GetExecutive().AddObserver(vtkCommand.ErrorEvent, lambda *a: None)
        bloom.SetInputData(vtkImageData())
        bloom.Update()
        self.assertGreaterEqual(errors.count, 1)
        self.assertEqual(bloom.GetOutput().GetNumberOfPoints(), 0)

    def test_damaged_exr(self):
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "bad.exr")
            with open(path, "wb") as f:
                f.write(b"v/1\x01not an exr at all")
            reader = vtkbloom.vtkOpenEXRReader()
            errors = ErrorCounter(reader)
            reader.SetFileName(path)
            reader.Update()
            self.assertEqual(errors.count, 1)
            self.assertEqual(reader.GetOutput().GetNumberOfPoints(), 0)


class NumpyAndPipelines(unittest.TestCase):
    def test_numpy_round_trip_is_exact(self):
        scene = hdr_scene()
        bloom = vtkbloom.vtkImageBloom()
        bloom.SetPreset("webgpu-market")
        bloom.SetStrength(0.0)
        bloom.SetInputData(image_from_array(scene))
        bloom.Update()
        np.testing.assert_array_equal(array_from_image(bloom.GetOutput()), scene)

    def test_exr_round_trip_is_exact(self):
        scene = hdr_scene()
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "scene.exr")
            writer = vtkbloom.vtkOpenEXRWriter()
            writer.SetFileName(path)
            writer.SetInputData(image_from_array(scene))
            self.assertEqual(writer.Write(), 1)
            reader = vtkbloom.vtkOpenEXRReader()
            reader.SetFileName(path)
            reader.Update()
            np.testing.assert_array_equal(array_from_image(reader.GetOutput()), scene)

    def test_vtkmodules_pipeline(self):
        source = vtkRTAnalyticSource()
        source.SetWholeExtent(-20, 20, -10, 10, 0, 0)
        cast = vtkImageCast()
        cast.SetOutputScalarTypeToFloat()
        cast.SetInputConnection(source.GetOutputPort())
        blur = vtkbloom.vtkImageSeparableGaussian()
        blur.SetStandardDeviations(2.0, 2.0, 0.0)
        blur.SetBorderModeToReflect()
        blur.SetInputConnection(cast.GetOutputPort())
        blur.Update()
        out = blur.GetOutput()
        self.assertEqual(out.GetExtent(), (-20, 20, -10, 10, 0, 0))
        a = numpy_support.vtk_to_numpy(cast.GetOutput().GetPointData().GetScalars())
        b = numpy_support.vtk_to_numpy(out.GetPointData().GetScalars())
        # Reflect borders conserve the sum; the blur smooths (lower variance).
        self.assertAlmostEqual(float(b.astype(np.float64).sum()) / float(a.astype(np.float64).sum()),
                               1.0, places=6)
        self.assertLess(b.std(), a.std())


class Statistics(unittest.TestCase):
    def bloom(self, scene, preset="webgpu-market"):
        bloom = vtkbloom.vtkImageBloom()
        bloom.SetPreset(preset)
        bloom.SetInputData(image_from_array(scene))
        bloom.Update()
        return bloom

    def test_statistics_match_numpy(self):
        scene = hdr_scene()
        bloom = self.bloom(scene)
        out = array_from_image(bloom.GetOutput()).astype(np.float64)
        lum_in = scene[..., :3].astype(np.float64) @ REC709
        lum_out = out[..., :3] @ REC709
        self.assertAlmostEqual(bloom.GetEnergyIn() / lum_in.sum(), 1.0, delta=1e-6)
        self.assertAlmostEqual(bloom.GetEnergyOut() / lum_out.sum(), 1.0, delta=1e-6)
        self.assertAlmostEqual(bloom.GetPeakLuminanceIn() / lum_in.max(), 1.0, delta=1e-6)
        self.assertAlmostEqual(bloom.GetPeakLuminanceOut() / lum_out.max(), 1.0, delta=1e-6)
        # webgpu-market: smoothstep knee, T 0.8, knee 0.4; a pixel is bright when its bright
        # pass keeps a value > 0.
        factor = smoothstep(0.4, 1.2, lum_in)
        bright = np.any(scene[..., :3] * factor[..., None] > 0, axis=2)
        self.assertEqual(bloom.GetNumberOfBrightPixels(), int(bright.sum()))
        self.assertGreater(bloom.GetNumberOfBrightPixels(), 0)
        self.assertEqual(bloom.GetNumberOfLevelsUsed(), 5)
        self.assertGreater(bloom.GetEnergyOut(), bloom.GetEnergyIn())

    def test_energies_are_exact_sums(self):
        # The energies are the exact sums of the pixels' luminances, rounded once: math.fsum
        # (exact, correctly rounded) of L computed in float64 in the filter's order,
        # (0.2126 R + 0.7152 G) + 0.0722 B, to the last bit. Each row holds pixels p and -p
        # (whose luminances cancel exactly) and a few values 1e-20 to 1e-30, so any rounding
        # before the end shows; rows are longer than 2048 pixels; most rows are copied by the
        # additive composite (only one lamp blooms), and a lerp composites every row.
        rng = np.random.default_rng(11)
        h, pairs, small = 120, 1200, 100
        rows = []
        for y in range(h):
            p = np.where(rng.uniform(size=(pairs, 3)) < 0.5, -1.0, 1.0) * rng.uniform(
                0.01, 0.3, size=(pairs, 3))
            if y == h - 3:
                p[0] = 500.0  # a lamp (its negative is dark)
            t = np.where(rng.uniform(size=(small, 3)) < 0.5, -1.0, 1.0) * 10.0 ** rng.uniform(
                -30.0, -20.0, size=(small, 3))
            rows.append(rng.permutation(np.concatenate([p, -p, t])))
        rgb = np.stack(rows)
        scene = np.concatenate([rgb, np.ones(rgb.shape[:2] + (1,))], axis=2).astype(np.float32)

        def luminance(a):
            a = a.astype(np.float64)
            return (0.2126 * a[..., 0] + 0.7152 * a[..., 1]) + 0.0722 * a[..., 2]

        for preset in ("webgpu-market", "mip-atlas"):
            bloom = self.bloom(scene, preset)
            out = array_from_image(bloom.GetOutput())
            lum_in, lum_out = luminance(scene), luminance(out)
            self.assertEqual(bloom.GetEnergyIn(), math.fsum(lum_in.ravel()), preset)
            self.assertEqual(bloom.GetEnergyOut(), math.fsum(lum_out.ravel()), preset)
            self.assertEqual(bloom.GetPeakLuminanceIn(), lum_in.max(), preset)
            self.assertEqual(bloom.GetPeakLuminanceOut(), lum_out.max(), preset)
            self.assertNotEqual(bloom.GetEnergyOut(), bloom.GetEnergyIn(), preset)
        self.assertLess(abs(bloom.GetEnergyIn()), 1e-18)  # only the small values are left
        # webgpu-market's smoothstep knee reaches down to 0.4: only the lamp is bright.
        self.assertEqual(self.bloom(scene).GetNumberOfBrightPixels(), 1)

    def test_statistics_are_field_data(self):
        bloom = self.bloom(hdr_scene(), "mip-atlas")
        fd = bloom.GetOutput().GetFieldData()
        self.assertAlmostEqual(fd.GetArray("BloomEnergyIn").GetValue(0), bloom.GetEnergyIn())
        self.assertAlmostEqual(fd.GetArray("BloomEnergyOut").GetValue(0), bloom.GetEnergyOut())
        # mip-atlas on 80x45: levels 0..6 exist (floor(log2(80)) = 6).
        self.assertEqual(fd.GetArray("BloomNumberOfLevelsUsed").GetValue(0), 7)
        # Its lerp darkens: less energy out than in.
        self.assertLess(bloom.GetEnergyOut(), bloom.GetEnergyIn())

    def test_wide_dynamic_range_energy(self):
        # Values from 1e-8 to 1e8: the compensated sums still match a float64 sum.
        rng = np.random.default_rng(3)
        exponents = rng.uniform(-8, 8, size=(64, 64, 3))
        scene = np.concatenate([10.0 ** exponents, np.ones((64, 64, 1))], axis=2).astype(np.float32)
        bloom = self.bloom(scene, "crt-halfres")
        lum_in = scene[..., :3].astype(np.float64) @ REC709
        self.assertAlmostEqual(bloom.GetEnergyIn() / lum_in.sum(), 1.0, delta=1e-9)

    def test_psf_mode_conserves_energy(self):
        # No threshold: the bright pass is the scene, so with reflect borders the output sums to
        # (1 + strength) times the input, per channel, for a PSF given from Python.
        rng = np.random.default_rng(5)
        scene = rng.uniform(0.0, 2.0, size=(48, 64, 3))
        scene[40:48, 0:6] = 50.0  # a bright patch in a corner
        bloom = vtkbloom.vtkImageBloom()
        bloom.SetBloomModeToPSF()
        bloom.SetPSFType(vtkbloom.vtkImageBloom.PSF_GAUSSIANS)
        bloom.SetPSFGaussians([1.0, 4.0], [0.5, 0.5])
        bloom.SetThresholdMode(4)  # NONE
        bloom.SetStrength(0.25)
        bloom.SetInputData(image_from_array(scene))
        bloom.Update()
        out = array_from_image(bloom.GetOutput())
        for c in range(3):
            self.assertAlmostEqual(out[..., c].sum() / scene[..., c].sum(), 1.25, delta=1e-6)
        radius = reference(0)
        psf = bloom.ComputePSF(1, radius)
        self.assertEqual(len(psf), (2 * radius.get() + 1) ** 2)
        self.assertAlmostEqual(sum(psf), 1.0, delta=1e-12)

    def test_fft_blur_matches_direct(self):
        scene = np.random.default_rng(6).uniform(0.0, 1.0, size=(120, 160, 1))
        results = []
        for mode in (vtkbloom.vtkImageSeparableGaussian.CONVOLUTION_DIRECT,
                     vtkbloom.vtkImageSeparableGaussian.CONVOLUTION_FFT):
            blur = vtkbloom.vtkImageSeparableGaussian()
            blur.SetStandardDeviations(12.0, 12.0, 0.0)
            blur.SetConvolutionMode(mode)
            blur.SetInputData(image_from_array(scene))
            blur.Update()
            self.assertEqual(blur.GetLastFFTAxes(), 3 if mode == 2 else 0)
            results.append(array_from_image(blur.GetOutput()))
        error = np.linalg.norm(results[1] - results[0]) / np.linalg.norm(results[0])
        self.assertLess(error, 1e-12)  # double input: the FFT runs in double


if __name__ == "__main__":
    from unittest_main import main

    sys.exit(main())
