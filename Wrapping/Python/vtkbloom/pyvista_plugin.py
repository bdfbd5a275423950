# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
"""vtkbloom where PyVista (0.49 and later) looks for plugins, with no ``import vtkbloom``.

The distribution's entry points (``vtkbloom-VERSION.dist-info/entry_points.txt``) name this
module; PyVista imports it the first time one of its names is asked for:

- ``pyvista.plotter_components``: ``plotter.bloom``, a :class:`PlotterBloom`;
- ``pyvista.accessors``: ``image.bloom`` on every ``pyvista.ImageData``, an :class:`ImageBloom`;
- ``pyvista.readers``: ``pyvista.read("frame.exr")``, by :func:`read`.

Each is a second spelling of what ``vtkbloom`` already does (``add_bloom``, ``bloom``,
``read_exr``): one implementation, PyVista's names.
"""

import os
import weakref

import pyvista

from . import arrays, scene

__all__ = ["PlotterBloom", "ImageBloom", "read"]


def _parameter_table():
    """The parameters a pass takes, {keyword: _Parameter}: vtkBloomParameters' only."""
    return {k: p for k, (p, where) in arrays._bloom_table().items() if where == "parameters"}


@pyvista.register_plotter_component("bloom")
class PlotterBloom:
    """Bloom for this plotter: ``plotter.bloom``.

    Only light glows: colour above 1 and the emitters you add, never the background or the
    annotations. The parameters read and set as attributes, with the ranges of
    ``vtkbloom.bloom_parameters()``; set before :meth:`enable`, they apply when it runs.

    Examples
    --------
    >>> import pyvista as pv
    >>> plotter = pv.Plotter(off_screen=True)
    >>> lamp = plotter.add_mesh(pv.Sphere(), color="orange")
    >>> plotter.bloom.enable(strength=0.8)
    >>> _ = plotter.bloom.add_emitter(lamp)
    >>> plotter.bloom.strength
    0.8
    >>> image = plotter.screenshot(return_img=True)
    >>> plotter.close()
    """

    def __init__(self, plotter):
        object.__setattr__(self, "_plotter", weakref.ref(plotter))
        object.__setattr__(self, "_pending", {})

    def _target(self):
        plotter = self._plotter()
        if plotter is None:
            raise RuntimeError("plotter.bloom: the plotter is gone")
        return plotter

    @property
    def passes(self):
        """The vtkBloomPass of each renderer, as a tuple (empty while bloom is off).

        Examples
        --------
        >>> import pyvista as pv
        >>> plotter = pv.Plotter(off_screen=True)
        >>> plotter.bloom.passes
        ()
        >>> plotter.bloom.enable()
        >>> [p.GetClassName() for p in plotter.bloom.passes]
        ['vtkBloomPass']
        >>> plotter.close()
        """
        found = scene.get_bloom(self._target())
        found = found if isinstance(found, list) else [found]
        return tuple(p for p in found if p is not None)

    @property
    def enabled(self):
        """Whether bloom is on.

        Examples
        --------
        >>> import pyvista as pv
        >>> plotter = pv.Plotter(off_screen=True)
        >>> plotter.bloom.enabled
        False
        >>> plotter.close()
        """
        return bool(self.passes)

    def enable(self, preset=None, **parameters):
        """Bloom the plotter's scene; called again, change its parameters.

        Parameters
        ----------
        preset : str, optional
            One of ``vtkbloom.vtkBloomParameters.GetPresetNames()``, applied first.
        **parameters
            vtkBloomParameters' parameters in snake_case (``strength``, ``threshold``, ...);
            see ``vtkbloom.bloom_parameters()``.

        Examples
        --------
        >>> import pyvista as pv
        >>> plotter = pv.Plotter(off_screen=True)
        >>> plotter.bloom.enable("webgpu-market", strength=0.5)
        >>> plotter.bloom.enabled
        True
        >>> plotter.close()
        """
        pending = dict(self._pending)
        pending.update(parameters)
        scene.add_bloom(self._target(), preset, **pending)
        self._pending.clear()

    def disable(self):
        """Take the bloom away: the plotter's passes are as they were.

        Examples
        --------
        >>> import pyvista as pv
        >>> plotter = pv.Plotter(off_screen=True)
        >>> plotter.bloom.enable()
        >>> plotter.bloom.disable()
        >>> plotter.bloom.enabled
        False
        >>> plotter.close()
        """
        scene.remove_bloom(self._target())

    def add_emitter(self, actor, clim=None):
        """Make an actor glow (turning bloom on if it is off).

        Parameters
        ----------
        actor : pyvista.Actor or str
            The actor, or the name it was added under.
        clim : sequence of two numbers, optional
            Only where its scalars lie in this range.

        Returns
        -------
        pyvista.Actor
            The actor.

        Examples
        --------
        >>> import pyvista as pv
        >>> plotter = pv.Plotter(off_screen=True)
        >>> _ = plotter.add_mesh(pv.Sphere(), color="orange", name="lamp")
        >>> _ = plotter.bloom.add_emitter("lamp")
        >>> plotter.bloom.enabled
        True
        >>> plotter.close()
        """
        if self._pending and not self.enabled:
            self.enable()
        return scene.add_emitter(self._target(), actor, clim=clim)

    def remove_emitter(self, actor):
        """The actor glows no more.

        Examples
        --------
        >>> import pyvista as pv
        >>> plotter = pv.Plotter(off_screen=True)
        >>> lamp = plotter.add_mesh(pv.Sphere(), color="orange")
        >>> _ = plotter.bloom.add_emitter(lamp)
        >>> plotter.bloom.remove_emitter(lamp)
        >>> plotter.close()
        """
        scene.remove_emitter(self._target(), actor)

    def __getattr__(self, name):
        table = _parameter_table()
        if name.startswith("_") or name not in table:
            raise AttributeError("plotter.bloom has no attribute %r; its parameters: %s"
                                 % (name, ", ".join(sorted(table))))
        if name in self._pending:
            return self._pending[name]
        passes = self.passes
        if passes:
            return _read(table[name], passes[0].GetParameters())
        from . import vtkBloomParameters

        return _read(table[name], vtkBloomParameters())

    def __setattr__(self, name, value):
        table = _parameter_table()
        if name not in table:
            raise AttributeError("plotter.bloom has no parameter %r; its parameters: %s"
                                 % (name, ", ".join(sorted(table))))
        if self.enabled:
            scene.add_bloom(self._target(), **{name: value})
            return
        from . import vtkBloomParameters

        table[name].apply(vtkBloomParameters(), value)  # the same one-line error, now
        self._pending[name] = value

    def __dir__(self):
        return sorted(set(object.__dir__(self)) | set(_parameter_table()))

    def __plotter_close__(self):
        # A closed plotter holds nothing of vtkbloom's: its passes, observers and records.
        plotter = self._plotter()
        if plotter is not None and getattr(plotter, "renderers", None) is not None:
            scene.remove_bloom(plotter)
        self._pending.clear()

    def __plotter_deep_clean__(self):
        self.__plotter_close__()


def _read(parameter, parameters):
    """A parameter's value as the keyword takes it: a choice's name, or the number."""
    value = getattr(parameters, "Get" + parameter.name)()
    if parameter.choices:
        for choice, method in parameter.choices.items():
            probe = type(parameters)()
            getattr(probe, method)()
            if getattr(probe, "Get" + parameter.name)() == value:
                return choice
    return value


@pyvista.register_dataset_accessor("bloom", pyvista.ImageData)
class ImageBloom:
    """Bloom an image's active scalars: ``image.bloom``, on the filters ``vtkbloom.bloom`` uses.

    Examples
    --------
    >>> import numpy as np, pyvista as pv
    >>> image = pv.ImageData(dimensions=(64, 48, 1))
    >>> frame = np.zeros((image.n_points, 3), np.float32)
    >>> frame[image.n_points // 2 + 32] = 50.0
    >>> image.point_data["frame"] = frame
    >>> glow = image.bloom.apply(strength=0.5)
    >>> glow.dimensions
    (64, 48, 1)
    >>> image.bloom.statistics()["number_of_bright_pixels"] > 0
    True
    """

    def __init__(self, image):
        self._image = weakref.ref(image)

    def _frame(self, function):
        image = self._image()
        if image is None:
            raise RuntimeError("image.bloom.%s(): the image is gone" % function)
        dimensions = image.dimensions
        scalars = image.active_scalars
        if dimensions[2] != 1 or scalars is None or scalars.ndim != 2 or scalars.shape[1] not in (3, 4):
            raise ValueError("image.bloom.%s(): expected a 2-D image whose active scalars have 3 or 4 "
                             "components, not %s points of %s" % (function, dimensions, None if scalars is None
                                                                 else scalars.shape[1:] or "1"))
        # VTK's row 0 is the bottom; the numpy functions take row 0 at the top, in float.
        frame = scalars.reshape(dimensions[1], dimensions[0], scalars.shape[1])[::-1]
        return image, frame if frame.dtype.kind == "f" else frame.astype("float32")

    def _image_like(self, image, frame, name):
        out = pyvista.ImageData(dimensions=image.dimensions, spacing=image.spacing, origin=image.origin)
        out.point_data[name] = frame[::-1].reshape(-1, frame.shape[2])
        out.set_active_scalars(name)
        return out

    def apply(self, preset=None, **parameters):
        """A new image: this one bloomed (``vtkbloom.bloom``).

        Parameters
        ----------
        preset : str, optional
            A preset's name, applied first.
        **parameters
            See ``vtkbloom.bloom_parameters()``.

        Returns
        -------
        pyvista.ImageData
            The bloomed image, its scalars named as this one's.

        Examples
        --------
        >>> import numpy as np, pyvista as pv
        >>> image = pv.ImageData(dimensions=(16, 16, 1))
        >>> image.point_data["c"] = np.full((256, 3), 2.0, np.float32)
        >>> float(image.bloom.apply().point_data["c"].max()) > 2.0
        True
        """
        image, frame = self._frame("apply")
        glow = arrays.bloom(frame, preset=preset, **parameters)
        return self._image_like(image, glow, image.active_scalars_name)

    def blur(self, sigma, **parameters):
        """A new image: this one blurred by an exact Gaussian of `sigma` pixels.

        Examples
        --------
        >>> import numpy as np, pyvista as pv
        >>> image = pv.ImageData(dimensions=(16, 16, 1))
        >>> image.point_data["c"] = np.ones((256, 3), np.float32)
        >>> bool(abs(image.bloom.blur(2.0).point_data["c"].mean() - 1.0) < 1e-5)
        True
        """
        image, frame = self._frame("blur")
        return self._image_like(image, arrays.blur(frame, sigma, **parameters), image.active_scalars_name)

    def statistics(self, preset=None, **parameters):
        """The bloom filter's statistics of this image, as a dict (energy in and out, bright
        pixels, ...).

        Examples
        --------
        >>> import numpy as np, pyvista as pv
        >>> image = pv.ImageData(dimensions=(16, 16, 1))
        >>> image.point_data["c"] = np.zeros((256, 3), np.float32)
        >>> image.bloom.statistics()["number_of_bright_pixels"]
        0
        """
        _, frame = self._frame("statistics")
        return arrays.bloom(frame, preset=preset, statistics=True, **parameters)[1]


def read(path, **kwargs):
    """``pyvista.read("frame.exr")``: the file as a ``pyvista.ImageData``, its channels as point
    data named as ``vtkOpenEXRReader`` names them; a file the reader refuses (damaged, hostile,
    over its limits) raises OSError with its one-line reason.

    Examples
    --------
    >>> import numpy as np, os, tempfile, pyvista as pv, vtkbloom
    >>> path = os.path.join(tempfile.mkdtemp(), "frame.exr")
    >>> vtkbloom.write_exr(path, np.full((4, 6, 3), 2.5, np.float32), pixel_type="float")
    >>> image = pv.read(path)
    >>> image.dimensions
    (6, 4, 1)
    """
    from . import vtkOpenEXRReader

    if kwargs:
        raise TypeError("pyvista.read(%r): the OpenEXR reader takes no keywords, not %s"
                        % (path, ", ".join(sorted(kwargs))))
    path = os.fspath(path)
    if not os.path.exists(path):
        raise FileNotFoundError(2, "No such file", path)
    reader = vtkOpenEXRReader()
    errors = arrays._Errors(reader)
    reader.SetFileName(path)
    reader.Update()
    if errors.messages:
        raise OSError("pyvista.read(%r): %s" % (path, errors.first_line()))
    return pyvista.wrap(reader.GetOutput())
