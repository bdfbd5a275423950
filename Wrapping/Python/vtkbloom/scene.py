# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
"""Bloom for a scene in one call: a vtkRenderer, a vtkRenderWindow (every renderer), a
pyvista.Plotter (every subplot) or a vedo.Plotter.

    import pyvista as pv
    import vtkbloom

    plotter = pv.Plotter()
    lamp = plotter.add_mesh(pv.Sphere(), color="orange")
    vtkbloom.add_bloom(plotter, strength=0.8)
    vtkbloom.add_emitter(plotter, lamp)          # this actor glows, whatever its colour
    plotter.show()

Where bloom sits. vtkBloomPass blooms the linear HDR scene, so in a chain of passes it goes
above what renders the scene (the camera pass, eye-dome lighting, SSAO, depth of field, the
shadow passes) and below what resolves or maps the image for the screen (SSAA, tone mapping):
it is inserted just below the lowest of those, or at the top where there is none. VTK's FXAA
pass filters the window's framebuffer rather than its delegate's output, so it is replaced by
the renderer's own FXAA, which the pass applies after its composite.
PyVista and vedo rebuild a renderer's passes whenever one of their effects is switched on or
off; the pass is put back in its place before each render (an observer of the renderer's
StartEvent), so it survives them in any order. Nothing of PyVista's or vedo's is patched, and
neither is imported here.
"""

import ctypes
import os

__all__ = ["add_bloom", "remove_bloom", "add_emitter", "remove_emitter", "get_bloom"]

# Passes that turn the linear scene into the displayed image: bloom goes below them.
_RESOLVE = ("vtkSSAAPass", "vtkToneMappingPass")
# VTK's FXAA pass filters the window's framebuffer, not its delegate's output, so that whatever
# a pass between it and the scene does is lost. While bloom is on, it is taken out of the chain
# and the renderer's own FXAA (UseFXAA, which vtkBloomPass applies after its composite when it
# is the renderer's pass) does its work; it is put back by remove_bloom.
_FXAA = "vtkOpenGLFXAAPass"

# Each renderer's record is an attribute of the renderer: VTK keeps a wrapper's attributes
# with its C++ object when the Python wrapper goes away (a raw vtkRenderer that only its window
# holds gets a new wrapper each time it is fetched), and drops them with the renderer.
_RECORD = "_vtkbloom_record"


def _record(renderer):
    return getattr(renderer, _RECORD, None)


class _Installed:
    def __init__(self, renderer, bloom_pass):
        self.bloom = bloom_pass
        self.steps = None  # the vtkRenderStepsPass made here where the renderer had no pass
        self.saved_threshold_mode = None  # the scene's threshold mode while emitters glow
        self.fxaa = None  # the FXAA pass taken out of the chain, and the renderer's UseFXAA
        self.saved_use_fxaa = None
        self.made = {}  # the clim emitters made here, and the actor each was made from
        self.observer = renderer.AddObserver("StartEvent", self._place)

    def _place(self, renderer, event=None):
        _place(renderer, self)


def _renderers(target):
    """The vtkRenderers of `target` (duck-typed, so that PyVista and vedo stay optional)."""
    from vtkmodules.vtkRenderingCore import vtkRenderer, vtkRenderWindow

    if isinstance(target, vtkRenderer):
        return [target]
    if isinstance(target, vtkRenderWindow):
        found = []
        collection = target.GetRenderers()
        collection.InitTraversal()
        renderer = collection.GetNextItem()
        while renderer is not None:
            found.append(renderer)
            renderer = collection.GetNextItem()
        return found
    renderers = getattr(target, "renderers", None)  # pyvista.Plotter and vedo.Plotter
    if renderers is not None:
        found = [r for r in renderers if isinstance(r, vtkRenderer)]
        if found:
            return found
    raise TypeError(
        "expected a vtkRenderer, a vtkRenderWindow, a pyvista.Plotter or a vedo.Plotter, not %s"
        % type(target).__name__
    )


def _chain(renderer):
    """The renderer's passes from the top down, following image-processing delegates."""
    chain = []
    current = renderer.GetPass()
    while current is not None and current not in chain:
        chain.append(current)
        get = getattr(current, "GetDelegatePass", None)
        current = get() if get is not None else None
    return chain


def _unlink(renderer, record):
    """Take the bloom pass out of the renderer's chain, wherever it is."""
    chain = _chain(renderer)
    if record.bloom not in chain:
        return
    below = record.bloom.GetDelegatePass()
    index = chain.index(record.bloom)
    if below is record.steps:
        below = None  # the steps were ours: the renderer renders as it did without passes
    if index == 0:
        renderer.SetPass(below)
    else:
        chain[index - 1].SetDelegatePass(below)
    record.bloom.SetDelegatePass(None)


def _splice_out(renderer, render_pass):
    """Take `render_pass` out of the renderer's chain, linking what was above it to its
    delegate."""
    chain = _chain(renderer)
    index = chain.index(render_pass)
    below = render_pass.GetDelegatePass()
    if index == 0:
        renderer.SetPass(below)
    else:
        chain[index - 1].SetDelegatePass(below)


def _place(renderer, record):
    """Put the bloom pass where it belongs in the renderer's current chain (a no-op when it
    is there already)."""
    for render_pass in _chain(renderer):
        if render_pass.GetClassName() == _FXAA:
            _splice_out(renderer, render_pass)
            record.fxaa = render_pass
            if record.saved_use_fxaa is None:
                record.saved_use_fxaa = renderer.GetUseFXAA()
            renderer.SetUseFXAA(True)
    chain = [p for p in _chain(renderer) if p is not record.bloom]
    # The lowest pass that resolves the image, counted from the scene upwards.
    resolve = None
    for render_pass in reversed(chain):
        if render_pass.GetClassName() in _RESOLVE:
            resolve = render_pass
            break
    if resolve is None:
        above, below = None, (chain[0] if chain else None)
    else:
        above, below = resolve, resolve.GetDelegatePass()
        if below is record.bloom:  # already in place: what it delegates to
            below = record.bloom.GetDelegatePass()
    if below is None:
        if record.steps is None:
            from vtkmodules.vtkRenderingOpenGL2 import vtkRenderStepsPass

            record.steps = vtkRenderStepsPass()
        below = record.steps
    placed = (renderer.GetPass() if above is None else above.GetDelegatePass()) is record.bloom
    if placed and record.bloom.GetDelegatePass() is below:
        return
    _unlink(renderer, record)
    record.bloom.SetDelegatePass(below)
    if above is None:
        renderer.SetPass(record.bloom)
    else:
        above.SetDelegatePass(record.bloom)


def _configure(bloom_pass, preset, parameters):
    from .arrays import _bloom_table, _configure as configure_parameters
    from . import vtkBloomParameters

    if preset is not None:
        if not isinstance(preset, str) or vtkBloomParameters.CheckPresetName(preset):
            raise ValueError(
                "add_bloom(): preset=%r is not one of %s" % (preset, vtkBloomParameters.GetPresetNamesList())
            )
        bloom_pass.GetParameters().SetPreset(preset)
    table = {k: v for k, v in _bloom_table().items() if v[1] == "parameters"}
    configure_parameters(bloom_pass, table, parameters, "add_bloom")


def _check_window(renderer):
    """VTK 9.1's X window aborts the interpreter where no display opens, with no message; VTK
    9.4 and later fall back to EGL or OSMesa. Say it first, as a Python exception."""
    from vtkmodules.vtkCommonCore import vtkVersion

    window = renderer.GetRenderWindow()
    if window is None or window.GetClassName() != "vtkXOpenGLRenderWindow":
        return
    if (vtkVersion.GetVTKMajorVersion(), vtkVersion.GetVTKMinorVersion()) >= (9, 4):
        return
    display = os.environ.get("DISPLAY", "")
    problem = "DISPLAY is not set" if not display else None
    if problem is None:
        try:
            xlib = ctypes.CDLL("libX11.so.6")
            xlib.XOpenDisplay.restype = ctypes.c_void_p
            xlib.XOpenDisplay.argtypes = [ctypes.c_char_p]
            xlib.XCloseDisplay.argtypes = [ctypes.c_void_p]
            connection = xlib.XOpenDisplay(display.encode())
            if connection:
                xlib.XCloseDisplay(connection)
            else:
                problem = "DISPLAY=%s cannot be opened" % display
        except OSError:
            problem = "libX11.so.6 cannot be loaded"
    if problem is not None:
        raise RuntimeError(
            "this VTK renders through X and %s: run under xvfb-run -a, set DISPLAY, or use a "
            "VTK built for OSMesa or EGL (VTK 9.4 and later choose one by themselves)" % problem
        )


def _refresh(target):
    """A pyvista.Plotter renders again, as its own add_* and enable_* methods do, so that the
    next screenshot() shows the change (PyVista's render() waits for the first show())."""
    if type(target).__module__.split(".")[0] == "pyvista" and hasattr(target, "render"):
        target.render()


def add_bloom(target, preset=None, **parameters):
    """Bloom `target`'s scene; returns its vtkBloomPass, or a list of them for several
    renderers. Called again, it changes the parameters of the passes it made (a preset first,
    then the keywords: vtkBloomParameters' names in snake_case, see bloom_parameters()); it
    never stacks passes."""
    from . import vtkBloomPass

    passes = []
    for renderer in _renderers(target):
        _check_window(renderer)
        record = _record(renderer)
        if record is None:
            record = _Installed(renderer, vtkBloomPass())
            setattr(renderer, _RECORD, record)
        _configure(record.bloom, preset, parameters)
        _place(renderer, record)
        passes.append(record.bloom)
    _refresh(target)
    return passes[0] if len(passes) == 1 else passes


def get_bloom(target):
    """The vtkBloomPass add_bloom made for `target` (a list for several renderers), or None."""
    found = []
    for renderer in _renderers(target):
        record = _record(renderer)
        found.append(record.bloom if record is not None else None)
    return found[0] if len(found) == 1 else found


def remove_bloom(target):
    """Take the bloom away: each renderer's passes are as they were (or as its plotter has made
    them since)."""
    for renderer in _renderers(target):
        record = _record(renderer)
        if record is None:
            continue
        delattr(renderer, _RECORD)
        renderer.RemoveObserver(record.observer)
        below = record.bloom.GetDelegatePass()
        chain = _chain(renderer)
        above = chain[chain.index(record.bloom) - 1] if record.bloom in chain[1:] else None
        _unlink(renderer, record)
        if record.fxaa is not None:  # the FXAA pass back where bloom was
            renderer.SetUseFXAA(record.saved_use_fxaa)
            if below is not None and below is not record.steps:
                record.fxaa.SetDelegatePass(below)
                if above is None:
                    renderer.SetPass(record.fxaa)
                else:
                    above.SetDelegatePass(record.fxaa)
    _refresh(target)


def _actor(target, actor):
    """The vtkActor that `actor` names: itself, a vedo object's actor (vedo 2024 and later) or,
    given a string, the actor of a pyvista.Plotter of that name (add_mesh(..., name=...))."""
    if isinstance(actor, str):
        named = getattr(target, "actors", None)
        if not isinstance(named, dict) or actor not in named:
            raise KeyError("add_emitter(): the target has no actor named %r" % actor)
        return named[actor]
    return getattr(actor, "actor", actor)


def _showing(target, actor):
    """The renderers of `target` that show `actor`; where none does yet (a vedo object before
    show()), the target's current renderer."""
    renderers = _renderers(target)
    showing = [r for r in renderers if r.HasViewProp(actor)]
    if showing:
        return showing
    current = getattr(target, "renderer", None)
    return [current if current in renderers else renderers[0]]


def add_emitter(target, actor, clim=None):
    """Make `actor` glow in an LDR scene, whatever its colour, in the renderers of `target` that
    show it. With clim=(low, high) (PyVista's name for a scalar range), only where its mapped
    scalars lie in [low, high] glows: the hot spots of a temperature field.

    `actor` is a vtkActor, a vedo object, or the name of a pyvista.Plotter's actor. The pass
    then blooms its emitters only, with no threshold (vtkBloomPass::SetEmissionSourceToEmitters);
    the threshold the scene had comes back with remove_emitter. Adds bloom first where there is
    none. Returns what glows: `actor`, or with clim the emitter made from it."""
    from . import vtkImageBloomThreshold

    actor = _actor(target, actor)
    if clim is not None:
        try:
            low, high = (float(v) for v in clim)
        except (TypeError, ValueError):
            raise TypeError("add_emitter(): clim must be two numbers (low, high), not %r" % (clim,))
        if not low <= high:
            raise ValueError("add_emitter(): clim=%r must hold low <= high" % (clim,))
        mapper = actor.GetMapper() if hasattr(actor, "GetMapper") else None
        if mapper is None or mapper.GetLookupTable() is None or not mapper.GetScalarVisibility():
            raise ValueError("add_emitter(): clim needs an actor coloured by scalars (a mapper "
                             "with scalar visibility and a lookup table)")
    emitted = actor
    for renderer in _showing(target, actor):
        if _record(renderer) is None:
            add_bloom(renderer)
        record = _record(renderer)
        parameters = record.bloom.GetParameters()
        if record.saved_threshold_mode is None:
            record.saved_threshold_mode = parameters.GetThresholdMode()
        if clim is None:
            record.bloom.AddEmitter(actor)
        else:
            emitted = record.bloom.AddScalarRangeEmitter(actor, low, high)
            record.made[emitted] = actor
        record.bloom.SetEmissionSourceToEmitters()
        parameters.SetThresholdMode(vtkImageBloomThreshold.NONE)  # emitters glow at any level
    _refresh(target)
    return emitted


def remove_emitter(target, emitter):
    """Stop `emitter` glowing: what add_emitter returned, or the actor it was given (which
    removes its clim emitters too). With no emitter left, the whole scene's light blooms
    again."""
    emitter = _actor(target, emitter)
    for renderer in _renderers(target):
        record = _record(renderer)
        if record is None:
            continue
        for made, source in list(record.made.items()):
            if made is emitter or source is emitter:
                record.bloom.RemoveEmitter(made)
                del record.made[made]
        record.bloom.RemoveEmitter(emitter)
        if record.bloom.GetEmitters().GetNumberOfItems() == 0:
            record.bloom.SetEmissionSourceToScene()
            if record.saved_threshold_mode is not None:
                record.bloom.GetParameters().SetThresholdMode(record.saved_threshold_mode)
                record.saved_threshold_mode = None
    _refresh(target)
