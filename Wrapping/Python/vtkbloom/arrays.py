# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
"""numpy in, numpy out: bloom, blur, read and write HDR frames without building a pipeline.

    import numpy as np
    import vtkbloom

    frame = vtkbloom.read_exr("render.exr")            # H x W x C float32, row 0 at the top
    glow = vtkbloom.bloom(frame, preset="webgpu-market", strength=0.6)
    vtkbloom.write_exr("bloomed.exr", glow)

An image is an H x W x 3 or H x W x 4 array of float32 or float64. The result has the same
shape and dtype. A C-contiguous float32 (or float64) array is handed to VTK without a copy,
and the result is a view of VTK's output, not a copy of it.

Keyword arguments are the parameters' names in snake_case (``vtkBloomParameters``'s
``SetStrength`` is ``strength``, ``SetPSFTailScale`` is ``psf_tail_scale``); an enumeration
also takes its value's name (``threshold_mode="excess"`` for ``SetThresholdModeToExcess``).
They are read from the classes themselves, so that every parameter the C++ has is here, with
the range the C++ declares. An unknown keyword, a value outside its range, a wrong shape or
dtype raises ``TypeError`` or ``ValueError`` with one line that says what is accepted; nothing
is converted silently, and no VTK error is printed.
"""

import math
import os
import re

__all__ = ["bloom", "blur", "read_exr", "write_exr", "bloom_parameters", "blur_parameters"]


def _snake(name):
    name = re.sub(r"([A-Z]+)([A-Z][a-z])", r"\1_\2", name)
    return re.sub(r"([a-z0-9])([A-Z])", r"\1_\2", name).lower()


class _Errors:
    """Collects a VTK object's error and warning events, so that VTK prints nothing and the
    message becomes a Python exception."""

    def __init__(self, *objects):
        self.messages = []
        for obj in objects:
            for event in ("ErrorEvent", "WarningEvent"):
                obj.AddObserver(event, self._record)

    def _record(self, obj, event, data=None):
        self.messages.append(str(data) if data is not None else event)

    _record.CallDataType = 13  # VTK_STRING: the event's message arrives as a str

    def first_line(self):
        """The last message's own line (after VTK's 'ERROR: In file, line N' prefix)."""
        text = self.messages[-1].strip()
        lines = [line.strip() for line in text.splitlines() if line.strip()]
        line = lines[-1] if lines else text
        return re.sub(r"^\w+ \(0x[0-9a-fA-F]+\): ", "", line)


# ----------------------------------------------------------------------------------------------
# Parameters, read off a VTK class: every Set<Name> with a Get<Name> that the base class lacks.
class _Parameter:
    def __init__(self, obj, name):
        self.name = name
        self.keyword = _snake(name)
        self.setter = name
        default = getattr(obj, "Get" + name)()
        self.kind = type(default)
        self.size = len(default) if isinstance(default, tuple) else 0  # 0: any length
        self.low = getattr(obj, "Get%sMinValue" % name, lambda: None)()
        self.high = getattr(obj, "Get%sMaxValue" % name, lambda: None)()
        prefix = "Set%sTo" % name
        self.choices = {
            _snake(m[len(prefix):]): m for m in dir(obj) if m.startswith(prefix) and len(m) > len(prefix)
        }

    def describe(self):
        if self.choices:
            return "%s: %s" % (self.keyword, ", ".join(repr(c) for c in sorted(self.choices)))
        if self.kind is bool:
            return "%s: True or False" % self.keyword
        if self.kind is tuple:
            if self.size:
                return "%s: a sequence of %d numbers" % (self.keyword, self.size)
            return "%s: a sequence of numbers" % self.keyword
        kind = "an integer" if self.kind is int else "a number"
        if self.low is not None:
            return "%s: %s in [%s, %s]" % (self.keyword, kind, self.low, self.high)
        return "%s: %s" % (self.keyword, kind)

    def apply(self, obj, value):
        """Set `value` on `obj`, or raise with one line naming the keyword and what it takes."""
        if self.choices and isinstance(value, str):
            if value not in self.choices:
                raise ValueError("%s=%r is not one of %s" % (self.keyword, value, self.describe()))
            getattr(obj, self.choices[value])()
            return
        number = isinstance(value, (int, float)) and not isinstance(value, bool)
        if self.kind is bool:
            if not isinstance(value, bool):
                raise TypeError("%s takes True or False, not %r" % (self.keyword, value))
        elif self.kind is int:
            if not (isinstance(value, int) and not isinstance(value, bool)):
                raise TypeError("%s=%r: expected %s" % (self.keyword, value, self.describe()))
        elif self.kind is float:
            if not number or not math.isfinite(value):
                raise TypeError("%s=%r: expected %s" % (self.keyword, value, self.describe()))
        elif self.kind is tuple:
            if isinstance(value, (str, bytes)) or not hasattr(value, "__len__"):
                raise TypeError("%s=%r: expected %s" % (self.keyword, value, self.describe()))
            if not all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in value):
                raise TypeError("%s=%r: expected %s" % (self.keyword, value, self.describe()))
            values = [float(v) for v in value]
            if not all(math.isfinite(v) for v in values) or (self.size and len(values) != self.size):
                raise ValueError("%s=%r: expected %s, all finite" % (self.keyword, value, self.describe()))
            setter = getattr(obj, "Set" + self.setter)
            try:
                setter(*values)
            except TypeError:
                try:
                    setter(values)
                except TypeError:
                    raise TypeError("%s=%r: expected %s" % (self.keyword, value, self.describe())) from None
            return
        if self.low is not None and not (self.low <= value <= self.high):
            raise ValueError("%s=%r is out of range: expected %s" % (self.keyword, value, self.describe()))
        getattr(obj, "Set" + self.setter)(value)


def _parameters(obj, base, exclude):
    found = {}
    for method in dir(obj):
        if not method.startswith("Set") or method in base:
            continue
        name = method[3:]
        if "To" in name and hasattr(obj, "Set" + name.split("To")[0]):
            continue  # an enumeration helper (SetThresholdModeToExcess)
        if name in exclude or not hasattr(obj, "Get" + name):
            continue
        try:
            parameter = _Parameter(obj, name)
        except TypeError:
            continue  # a getter that needs arguments
        if parameter.kind in (bool, int, float, tuple):
            found[parameter.keyword] = parameter
    return found


_BLOOM = None
_BLUR = None


def _bloom_table():
    """vtkBloomParameters' parameters (set on the filter's parameter object), then the
    filter's own (execution_mode, restrict_to_bright_region, ...): {keyword: (parameter, where)}."""
    global _BLOOM
    if _BLOOM is None:
        from . import vtkBloomParameters, vtkImageBloom
        from vtkmodules.vtkCommonCore import vtkObject
        from vtkmodules.vtkCommonExecutionModel import vtkImageAlgorithm

        # Set by their own arguments, or not numbers: the preset and statistics keywords, the
        # shared parameter object, a PSF given as an image, one level's weight by index.
        exclude = {"Parameters", "Preset", "ComputeStatistics", "PSFImage", "LevelWeight"}
        table = {
            k: (p, "parameters")
            for k, p in _parameters(vtkBloomParameters(), set(dir(vtkObject)), exclude).items()
        }
        own = _parameters(vtkImageBloom(), set(dir(vtkImageAlgorithm)), exclude)
        for keyword, parameter in own.items():
            table.setdefault(keyword, (parameter, "filter"))
        _BLOOM = table
    return _BLOOM


def _blur_table():
    global _BLUR
    if _BLUR is None:
        from . import vtkImageSeparableGaussian
        from vtkmodules.vtkCommonExecutionModel import vtkThreadedImageAlgorithm

        exclude = {"StandardDeviation", "StandardDeviations", "Radius"}
        table = _parameters(vtkImageSeparableGaussian(), set(dir(vtkThreadedImageAlgorithm)), exclude)
        _BLUR = {k: (p, "filter") for k, p in table.items()}
    return _BLUR


def bloom_parameters():
    """The keywords `bloom` accepts, each with what it takes: {keyword: description}."""
    return {k: p.describe() for k, (p, _) in sorted(_bloom_table().items())}


def blur_parameters():
    """The keywords `blur` accepts besides sigma and radius: {keyword: description}."""
    return {k: p.describe() for k, (p, _) in sorted(_blur_table().items())}


def _configure(obj, table, parameters, function):
    for keyword, value in parameters.items():
        if keyword not in table:
            raise TypeError(
                "%s() got an unknown keyword %r; it accepts: %s"
                % (function, keyword, ", ".join(sorted(table)))
            )
        parameter, where = table[keyword]
        parameter.apply(obj.GetParameters() if where == "parameters" else obj, value)


# ----------------------------------------------------------------------------------------------
# Images: numpy <-> vtkImageData without copies.
def _check_image(image, function):
    import numpy as np

    if not isinstance(image, np.ndarray):
        raise TypeError("%s() takes a numpy array, not %s" % (function, type(image).__name__))
    if image.dtype not in (np.float32, np.float64):
        raise TypeError(
            "%s() takes a float32 or float64 array, not %s (convert it explicitly, e.g. "
            "image.astype(np.float32) / 255 for 8-bit colour)" % (function, image.dtype)
        )
    if image.ndim != 3 or image.shape[2] not in (3, 4) or image.shape[0] < 1 or image.shape[1] < 1:
        raise ValueError(
            "%s() takes an H x W x 3 or H x W x 4 array, not one of shape %s" % (function, image.shape)
        )


def _image_from_array(image):
    """A vtkImageData whose scalars are `image`'s memory (a copy only where it is not
    C-contiguous). Row 0 of the array is row 0 (j = 0) of the image."""
    import numpy as np
    from vtkmodules.util.numpy_support import numpy_to_vtk
    from vtkmodules.vtkCommonDataModel import vtkImageData

    height, width, components = image.shape
    flat = np.ascontiguousarray(image).reshape(height * width, components)
    scalars = numpy_to_vtk(flat, deep=False)  # keeps a reference to `flat`
    scalars.SetName("Image")
    data = vtkImageData()
    data.SetDimensions(width, height, 1)
    data.GetPointData().SetScalars(scalars)
    return data


def _array_from_image(data, components, dtype):
    from vtkmodules.util.numpy_support import vtk_to_numpy

    width, height, _ = data.GetDimensions()
    scalars = data.GetPointData().GetScalars()
    result = vtk_to_numpy(scalars).reshape(height, width, components)
    if result.dtype != dtype:
        raise RuntimeError("VTK returned %s for a %s image" % (result.dtype, dtype))
    return result


def _run(algorithm, errors, function):
    algorithm.Update()
    if errors.messages:
        raise ValueError("%s(): %s" % (function, errors.first_line()))
    return algorithm.GetOutput()


def bloom(image, preset=None, statistics=False, **parameters):
    """Bloom an H x W x 3 or 4 float32/float64 image; returns an array of the same shape and
    dtype (and, with statistics=True, a dict of the filter's statistics beside it).

    preset: one of vtkBloomParameters.GetPresetNames(), applied before the keywords.
    parameters: vtkImageBloom's and vtkBloomParameters' parameters in snake_case; see
    bloom_parameters() for every keyword and its range.
    """
    from . import vtkBloomParameters, vtkImageBloom

    _check_image(image, "bloom")
    filter_ = vtkImageBloom()
    errors = _Errors(filter_, filter_.GetParameters())
    if preset is not None:
        problem = vtkBloomParameters.CheckPresetName(str(preset)) if isinstance(preset, str) else "x"
        if problem:
            raise ValueError(
                "bloom(): preset=%r is not one of %s" % (preset, vtkBloomParameters.GetPresetNamesList())
            )
        filter_.SetPreset(preset)
    _configure(filter_, _bloom_table(), parameters, "bloom")
    if not isinstance(statistics, bool):
        raise TypeError("bloom(): statistics takes True or False, not %r" % (statistics,))
    filter_.SetComputeStatistics(statistics)
    filter_.SetInputData(_image_from_array(image))
    output = _run(filter_, errors, "bloom")
    result = _array_from_image(output, image.shape[2], image.dtype)
    if not statistics:
        return result
    fields = output.GetFieldData()
    stats = {}
    for i in range(fields.GetNumberOfArrays()):
        array = fields.GetArray(i)
        if array is not None and array.GetName().startswith("Bloom"):
            value = array.GetTuple1(0)
            stats[_snake(array.GetName()[len("Bloom"):])] = (
                int(value) if array.GetName().startswith("BloomNumberOf") else value
            )
    return result, stats


def blur(image, sigma, radius=None, **parameters):
    """Gaussian blur of an H x W x 3 or 4 float32/float64 image by vtkImageSeparableGaussian
    (exact against the continuous Gaussian); returns an array of the same shape and dtype.

    sigma: the standard deviation in pixels, > 0. radius: the kernel's half width in pixels
    (default: the filter's, from radius_factor x sigma). parameters: see blur_parameters().
    """
    from . import vtkImageSeparableGaussian

    _check_image(image, "blur")
    if isinstance(sigma, bool) or not isinstance(sigma, (int, float)) or not (0 < sigma <= 1e4):
        raise ValueError("blur(): sigma=%r: expected a number in (0, 10000]" % (sigma,))
    filter_ = vtkImageSeparableGaussian()
    errors = _Errors(filter_)
    filter_.SetStandardDeviations(float(sigma), float(sigma), 0.0)
    if radius is not None:
        if isinstance(radius, bool) or not isinstance(radius, int) or not (0 <= radius <= 65536):
            raise ValueError("blur(): radius=%r: expected an integer in [0, 65536]" % (radius,))
        filter_.SetRadius(radius, radius, 0)
    _configure(filter_, _blur_table(), parameters, "blur")
    filter_.SetInputData(_image_from_array(image))
    output = _run(filter_, errors, "blur")
    return _array_from_image(output, image.shape[2], image.dtype)


def read_exr(path, part=None, layer=None):
    """Read an OpenEXR file into an H x W x C array (row 0 at the top of the image): float32,
    or uint32 where every channel is UINT. C is 3 or 4 for RGB(A) and luminance/chroma files,
    else the layer's first channels (at most 4). Raises FileNotFoundError, or OSError with the
    reader's one-line reason for a file it refuses (damaged, hostile, over its limits)."""
    from . import vtkOpenEXRReader
    from vtkmodules.util.numpy_support import vtk_to_numpy

    path = os.fspath(path)
    if not os.path.exists(path):
        raise FileNotFoundError(2, "No such file", path)
    reader = vtkOpenEXRReader()
    errors = _Errors(reader)
    reader.SetFileName(path)
    if part is not None:
        if isinstance(part, str):
            reader.SetPartName(part)
        elif isinstance(part, int) and not isinstance(part, bool) and part >= 0:
            reader.SetPartIndex(part)
        else:
            raise ValueError("read_exr(): part=%r: expected a part's index (>= 0) or name" % (part,))
    if layer is not None:
        reader.SetLayer(str(layer))
    reader.Update()
    if errors.messages:
        raise OSError("read_exr(%r): %s" % (path, errors.first_line()))
    output = reader.GetOutput()
    width, height, _ = output.GetDimensions()
    scalars = output.GetPointData().GetScalars()
    return vtk_to_numpy(scalars).reshape(height, width, scalars.GetNumberOfComponents())


def write_exr(path, image, pixel_type="half", compression="zip"):
    """Write an H x W x 3 or 4 float32/float64 array (row 0 at the top) as an OpenEXR file:
    pixel_type "half" or "float", compression as vtkOpenEXRWriter names them ("none", "rle",
    "zips", "zip", "piz", "pxr24", "b44", "b44a", "dwaa", "dwab"). The file is replaced only
    once it is complete."""
    from . import vtkOpenEXRWriter

    _check_image(image, "write_exr")
    writer = vtkOpenEXRWriter()
    errors = _Errors(writer)
    types = {"half": writer.PIXEL_TYPE_HALF, "float": writer.PIXEL_TYPE_FLOAT}
    codecs = ["none", "rle", "zips", "zip", "piz", "pxr24", "b44", "b44a", "dwaa", "dwab"]
    if pixel_type not in types:
        raise ValueError("write_exr(): pixel_type=%r is not 'half' or 'float'" % (pixel_type,))
    if compression not in codecs:
        raise ValueError("write_exr(): compression=%r is not one of %s" % (compression, ", ".join(codecs)))
    writer.SetPixelType(types[pixel_type])
    writer.SetCompression(codecs.index(compression))
    writer.SetFileName(os.fspath(path))
    writer.SetInputData(_image_from_array(image))
    if writer.Write() != 1 or errors.messages:
        raise OSError("write_exr(%r): %s" % (os.fspath(path), errors.first_line() if errors.messages else "not written"))
