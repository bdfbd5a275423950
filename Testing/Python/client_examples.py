#!/usr/bin/python3
# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
"""The clients' own examples through vtkbloom.add_bloom at the defaults (issue 48, part 4).

Runs PyVista's docstring examples that plot, or vedo's example scripts, each in a subprocess
of its own, as their users run them, with one change made here and not in vtkbloom: the
client's show() is intercepted (pyvista.Plotter.show, vedo.Plotter.show and vedo's show()).
At each show() the client's own show() runs first (off screen, not blocking, not closing),
then the frame is rendered and grabbed twice (the plain frame: are the two the same?),
vtkbloom.add_bloom(plotter) is called, and the frame is rendered and grabbed again (the
bloomed frame), after which show() returns what it would have returned and closes the
plotter where the client would have. Frames are grabbed the client's way: PyVista's
screenshot() (the front buffer), vedo's screenshot path (vtkWindowToImageFilter, back buffer).
Markers on stderr between the phases attribute the GL errors VTK or Mesa print to the plain
or the bloomed phase. An example that fails, crashes or times out with bloom is run again
without it (the same interception, add_bloom left out), so that the clients' own failures
(no network, an interactive window needed, a missing module) are told from bloom's.

    client_examples.py --client pyvista [--sample N | --all] [--seed S] [--out DIR]
    client_examples.py --client vedo [--sample N] [--seed S] [--out DIR] [--examples DIR]

It writes DIR/results.json, DIR/summary.md (the figures, the skipped examples and why, the
examples whose bloomed frame differs from the plain frame), DIR/images/NAME/ (the plain,
bloomed, difference and changed-pixel images of those), DIR/logs/ (each run's output) and,
for PyVista, DIR/scripts/ (each docstring's examples as the script that ran). --check exits
1 when a target is missed: at least 98 % of the examples that render the same frame twice
stay within 1 % of their pixels (a pixel is changed when a channel moves by more than 8
levels), no error, no VTK error and no GL error appears with bloom that does not appear
without it, no exception is raised inside vtkbloom, every frame without light is its plain
frame within 1 level, and every bloomed frame renders the same twice where the plain one does.

scripts/client-examples.sh runs it on the host (vedo 2023.4, VTK 9.1, under Xvfb) and in the
sid root (PyVista 0.49 and vedo 2026.6, VTK 9.6, EGL)."""

import argparse
import datetime
import doctest
import importlib.util
import inspect
import json
import os
import random
import re
import shutil
import signal
import struct
import subprocess
import sys
import time
import traceback
import zlib
from pathlib import Path

VEDO_EXAMPLES = "/usr/share/doc/python3-vedo-examples/examples"
LEVELS = 8  # a pixel is changed when one of its channels moves by more than this
CHANGED_LIMIT = 0.01  # the target: at most 1 % of the pixels changed
TARGET = 0.98  # of the examples that render the same frame twice
MARK = "@@vtkbloom-harness"

# GL errors as VTK prints them (vtkOpenGLCheckErrorMacro, vtkOpenGLState) and as Mesa does.
GL_ERROR = re.compile(
    r"GL_INVALID_\w+|GL_OUT_OF_MEMORY|OpenGL errors? detected|OpenGL error|glBlitFramebuffer"
    r"|Invalid (?:operation|enum|value|framebuffer operation)|Mesa: User error",
    re.IGNORECASE,
)
# Other VTK errors, reported beside the GL errors.
# Of those, VTK's errors (vtkErrorMacro's "ERROR: In ...", vtkLogger's "ERR|"), as normalize()
# leaves them; not its warnings.
# The pass's own warning where it cannot keep the background out of the frame that blooms.
TRANSLUCENT_WARNING = "Translucent geometry without depth peeling"
VTK_ERROR_LINE = re.compile(r"^ERROR\b|\bERR\|")
VTK_ERROR = re.compile(r"^(?:ERROR|\d{4}-\d\d-\d\d .*ERR)|\bvtk\w+ \(0x[0-9a-f]+\): ", re.IGNORECASE)
# A failure that is the client's own: what needs the network, a module, a window.
NETWORK = re.compile(
    r"URLError|ConnectionError|ConnectionRefused|NewConnectionError|Max retries exceeded"
    r"|name resolution|ProxyError|Failed to establish|HTTPError|gaierror|Network is unreachable"
    r"|could not download|cannot download|pooch|urlopen|\bdownload\w*\(|_load_font",  # vedo fetches its fonts
    re.IGNORECASE,
)


# ------------------------------------------------------------------------------------------
# Images: numpy frames compared, and written as PNG with zlib (no imaging module needed).


def write_png(path, image):
    import numpy as np

    image = np.ascontiguousarray(image, dtype=np.uint8)
    if image.ndim == 2:
        image = np.repeat(image[:, :, None], 3, axis=2)
    height, width, channels = image.shape
    rows = np.concatenate([np.zeros((height, 1), np.uint8), image.reshape(height, -1)], axis=1)

    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)

    header = struct.pack(">IIBBBBB", width, height, 8, {3: 2, 4: 6}[channels], 0, 0, 0)
    Path(path).write_bytes(
        b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header)
        + chunk(b"IDAT", zlib.compress(rows.tobytes(), 6)) + chunk(b"IEND", b"")
    )


def compare(plain, bloomed):
    """How the bloomed frame differs from the plain one: the fraction of pixels changed by more
    than LEVELS in a channel, the largest difference, and two hints at the cause: the share of
    changed pixels that are brighter with bloom (light glows; a wrong composite need not be
    brighter) and the share that are thin, with no 3 x 3 block of changed pixels around them
    (the edges of lines, text and anti-aliased surfaces)."""
    import numpy as np

    channels = min(plain.shape[-1], bloomed.shape[-1])
    a = plain[..., :channels].astype(np.int16)
    b = bloomed[..., :channels].astype(np.int16)
    difference = np.abs(b - a).max(axis=-1)
    changed = difference > LEVELS
    count = int(changed.sum())
    result = {
        "changed_fraction": count / changed.size,
        "changed_pixels": count,
        "max_diff": int(difference.max()),
        "brighter_share": None,
        "thin_share": None,
    }
    if count:
        brighter = (b[..., :3].sum(axis=-1) > a[..., :3].sum(axis=-1)) & changed
        result["brighter_share"] = float(brighter.sum()) / count
        core = changed.copy()
        core[1:, :] &= changed[:-1, :]
        core[:-1, :] &= changed[1:, :]
        core[:, 1:] &= changed[:, :-1]
        core[:, :-1] &= changed[:, 1:]
        core[0, :] = core[-1, :] = False
        core[:, 0] = core[:, -1] = False
        result["thin_share"] = 1.0 - float(core.sum()) / count
    return result


def viewport_rectangles(plotter, shape):
    """Each renderer's rectangle of pixels in a frame of `shape` (rows from the top) as a pair of
    slices, where the plotter has more than one renderer: a viewport that loses its content is
    judged on its own pixels, not diluted by the window's."""
    renderers = [r for r in getattr(plotter, "renderers", []) if hasattr(r, "GetSize")]
    window = renderers[0].GetRenderWindow() if renderers else None
    if len(renderers) < 2 or window is None:
        return []
    width, height = window.GetSize()
    if width <= 0 or height <= 0:
        return []
    sx, sy = shape[1] / float(width), shape[0] / float(height)
    rectangles = []
    for renderer in renderers:
        (x, y), (w, h) = renderer.GetOrigin(), renderer.GetSize()
        rows = slice(int(round(shape[0] - (y + h) * sy)), int(round(shape[0] - y * sy)))
        columns = slice(int(round(x * sx)), int(round((x + w) * sx)))
        if rows.stop - rows.start > 0 and columns.stop - columns.start > 0:
            rectangles.append((rows, columns))
    return rectangles


def light_in(plotter):
    """Whether the last bloomed frame had light: some pass of the plotter ran its chain. A pass
    skips the chain exactly when no value of its scene exceeds the threshold (at the defaults,
    1: display white), so a frame without light is left as the renderer drew it, and any change
    there is the pass's fault."""
    import vtkbloom

    passes = vtkbloom.get_bloom(plotter)
    passes = passes if isinstance(passes, list) else [passes]
    return any(p is not None and not p.GetLastFrame().GetBloomSkipped() for p in passes)


def save_images(folder, stem, plain, bloomed):
    import numpy as np

    folder.mkdir(parents=True, exist_ok=True)
    channels = min(plain.shape[-1], bloomed.shape[-1], 3)
    a = plain[..., :channels].astype(np.int16)
    b = bloomed[..., :channels].astype(np.int16)
    difference = np.abs(b - a)
    changed = difference.max(axis=-1) > LEVELS
    marked = (a * 0.35).astype(np.uint8)
    marked[changed] = (255, 0, 255)
    # A close-up around the median changed pixel: plain, bloomed, difference x 4, 4 times larger.
    rows, columns = changed.nonzero()
    if len(rows):
        y, x = int(sorted(rows)[len(rows) // 2]), int(sorted(columns)[len(columns) // 2])
        top, left = max(0, min(y - 48, a.shape[0] - 96)), max(0, min(x - 48, a.shape[1] - 96))
        window = (slice(top, top + 96), slice(left, left + 96))
        strip = np.concatenate([plain[window][..., :channels], bloomed[window][..., :channels],
                                np.clip(difference[window] * 4, 0, 255).astype(np.uint8)], axis=1)
        zoom = np.repeat(np.repeat(strip, 4, axis=0), 4, axis=1)
    else:
        zoom = None
    names = {}
    for kind, image in (
        ("plain", plain[..., :channels]),
        ("bloom", bloomed[..., :channels]),
        ("diff", np.clip(difference * 4, 0, 255)),  # |bloom - plain| x 4
        ("changed", marked),  # the plain frame darkened, changed pixels in magenta
        ("zoom", zoom),
    ):
        if image is None:
            continue
        path = folder / ("%s-%s.png" % (stem, kind))
        write_png(path, image)
        names[kind] = str(path)
    return names


# ------------------------------------------------------------------------------------------
# The child: one example, with the client's show() intercepted.


class Child:
    def __init__(self, args):
        self.args = args
        self.client = args.client
        self.bloom = args.mode == "bloom"
        self.images = Path(args.images)
        self.result = {
            "mode": args.mode,
            "shows": [],
            "show_calls": 0,
            "bloom_added": 0,
            "exception": None,
            "finished": False,
            "versions": {},
        }
        self.bloomed = set()  # id() of the plotters add_bloom was called on
        self.depth = 0  # > 0 inside vedo's show(), whose own Plotter.show() calls pass through
        self.started = time.time()

    def mark(self, phase):
        # Straight to the file descriptor, so that the marker lands between VTK's own lines.
        bloom_on = 1 if (phase == "bloom" and self.bloom) or (self.bloomed and phase != "plain") else 0
        os.write(2, ("\n%s phase=%s show=%d bloom=%d\n" % (MARK, phase, self.result["show_calls"], bloom_on)).encode())

    def save(self):
        self.result["elapsed"] = time.time() - self.started
        tmp = self.args.result + ".tmp"
        with open(tmp, "w") as f:
            json.dump(self.result, f, indent=1)
        os.replace(tmp, self.args.result)

    # Frames, each client's way.
    def grab(self, plotter):
        import numpy as np

        if self.client == "pyvista":
            plotter.render()
            return np.array(plotter.screenshot(return_img=True))
        from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter
        from vtkmodules.util.numpy_support import vtk_to_numpy

        # vedo's screenshot(asarray=True), on this plotter's window (vedo's own goes to the
        # last plotter made): the back buffer, after a render.
        plotter.window.Render()
        grab = vtkWindowToImageFilter()
        grab.SetInput(plotter.window)
        grab.ReadFrontBufferOff()
        grab.ShouldRerenderOff()
        grab.Update()
        image = grab.GetOutput()
        width, height, _ = image.GetDimensions()
        scalars = image.GetPointData().GetScalars()
        pixels = vtk_to_numpy(scalars).reshape(height, width, scalars.GetNumberOfComponents())
        return np.ascontiguousarray(pixels[::-1])

    def at_show(self, plotter):
        """After the client's own show(): the plain frame twice, then bloom."""
        import vtkbloom
        from vtkmodules.vtkCommonCore import vtkObject

        index = self.result["show_calls"]
        compared = index <= self.args.shows
        # vedo switches VTK's warnings off for the whole process (GlobalWarningDisplayOff when
        # a Plotter is made); on, they say which GL calls failed, in both phases alike.
        vtkObject.GlobalWarningDisplayOn()
        record = {"show": index, "plotter": type(plotter).__name__}
        if compared:
            self.result["shows"].append(record)
            self.mark("plain")
            if id(plotter) in self.bloomed:  # bloomed at an earlier show(): off for its plain frame
                vtkbloom.remove_bloom(plotter)
                self.bloomed.discard(id(plotter))
            plain = self.grab(plotter)
            again = self.grab(plotter)
            record["size"] = list(plain.shape)
            record["plain_identical"] = bool(plain.shape == again.shape and (plain == again).all())
            if not record["plain_identical"] and plain.shape == again.shape:
                record["plain_repeat"] = compare(plain, again)
        if self.bloom and id(plotter) not in self.bloomed:
            self.mark("bloom")
            try:
                vtkbloom.add_bloom(plotter)
            except BaseException as error:
                record["error"] = "add_bloom: %s: %s" % (type(error).__name__, error)
                self.save()
                raise
            self.bloomed.add(id(plotter))
            self.result["bloom_added"] += 1
        if compared:
            self.mark("bloom" if self.bloom else "plain")
            bloomed = self.grab(plotter)
            repeat = self.grab(plotter)
            if self.bloom:
                record["light"] = light_in(plotter)
            record["bloom_stable"] = bool(bloomed.shape == repeat.shape and (bloomed == repeat).all())
            if bloomed.shape != plain.shape:
                record["error"] = "the bloomed frame is %s, the plain frame %s" % (bloomed.shape, plain.shape)
            else:
                record.update(compare(plain, bloomed))
                # Each renderer's viewport on its own: the worst one's share is the frame's.
                parts = [compare(plain[r], bloomed[r]) for r in viewport_rectangles(plotter, plain.shape)]
                if parts:
                    record["viewports"] = [part["changed_fraction"] for part in parts]
                    worst = max(range(len(parts)), key=lambda i: parts[i]["changed_fraction"])
                    if parts[worst]["changed_fraction"] > record["changed_fraction"]:
                        record["changed_fraction"] = parts[worst]["changed_fraction"]
                        record["worst_viewport"] = worst
                if record["max_diff"] > LEVELS:
                    record["images"] = save_images(self.images, "show%d" % index, plain, bloomed)
            self.save()
        self.mark("script")

    # The clients' show(), intercepted.
    def patch_pyvista(self):
        import pyvista as pv

        pv.OFF_SCREEN = True
        self.result["versions"]["pyvista"] = pv.__version__
        original = pv.Plotter.show
        signature = inspect.signature(original)
        child = self

        def show(self, *args, **kwargs):
            bound = signature.bind(self, *args, **kwargs)
            arguments = bound.arguments
            auto_close = arguments.get("auto_close")
            if auto_close is None:  # as PyVista decides it
                auto_close = False if arguments.get("interactive_update") else self._theme.auto_close
            arguments["auto_close"] = False  # closed below, after the frames
            arguments["interactive"] = False
            child.result["show_calls"] += 1
            child.mark("client")
            value = original(*bound.args, **bound.kwargs)
            child.at_show(self)
            if auto_close:
                self.close()
            return value

        pv.Plotter.show = show

    def patch_vedo(self):
        import vedo

        vedo.settings.default_backend = "vtk"
        self.result["versions"]["vedo"] = vedo.__version__
        plotter_class = vedo.Plotter
        child = self

        # Every Plotter off screen (no interactor, nothing blocks): vedo's show() passes its
        # own offscreen=False, and vedo 2026 makes a new Plotter when the flags differ, so
        # both are set.
        original_init = plotter_class.__init__
        init_signature = inspect.signature(original_init)

        def init(self, *args, **kwargs):
            bound = init_signature.bind(self, *args, **kwargs)
            bound.arguments["offscreen"] = True
            original_init(*bound.args, **bound.kwargs)

        plotter_class.__init__ = init

        original_method = plotter_class.show

        def method(self, *args, **kwargs):
            if child.depth:
                return original_method(self, *args, **kwargs)
            kwargs["interactive"] = False
            child.result["show_calls"] += 1
            child.mark("client")
            value = original_method(self, *args, **kwargs)
            child.at_show(self)
            return value

        plotter_class.show = method

        original_function = vedo.show

        def function(*args, **kwargs):
            kwargs["offscreen"] = True
            kwargs["interactive"] = False
            nested = child.depth > 0
            if not nested:
                child.result["show_calls"] += 1
                child.mark("client")
            child.depth += 1
            try:
                value = original_function(*args, **kwargs)
            finally:
                child.depth -= 1
            if not nested:
                plotter = value if isinstance(value, plotter_class) else getattr(vedo, "plotter_instance", None)
                if plotter is None and hasattr(vedo, "current_plotter"):
                    plotter = vedo.current_plotter()
                if plotter is not None and getattr(plotter, "window", None) is not None:
                    child.at_show(plotter)
            return value

        for name, module in list(sys.modules.items()):
            if name.split(".")[0] == "vedo" and module is not None:
                if module.__dict__.get("show") is original_function:
                    setattr(module, "show", function)
        import vedo.plotter

        vedo.plotter.show = function
        vedo.show = function

    def run(self):
        import numpy as np
        from vtkmodules.vtkCommonCore import vtkVersion

        random.seed(self.args.seed)
        np.random.seed(self.args.seed)
        self.result["versions"]["vtk"] = vtkVersion.GetVTKVersion()
        import vtkbloom

        self.result["versions"]["vtkbloom"] = os.path.dirname(vtkbloom.__file__)
        if self.client == "pyvista":
            self.patch_pyvista()
        else:
            self.patch_vedo()
        script = os.path.abspath(self.args.script)
        sys.argv = [script]
        sys.path.insert(0, os.path.dirname(script))
        # A doctest runs in a copy of its module's namespace (doctest.DocTestFinder's globs).
        namespace = None
        if self.args.globals:
            namespace = dict(vars(importlib.import_module(self.args.globals)))
        self.save()  # a crash before the first show() leaves this much
        self.mark("script")
        import runpy

        try:
            runpy.run_path(script, init_globals=namespace, run_name="__main__")
        except SystemExit as stop:
            if stop.code not in (None, 0):
                self.failed(stop)
        except BaseException as error:  # noqa: BLE001 -- every failure is a result here
            self.failed(error)
        self.result["finished"] = True
        self.save()
        sys.stdout.flush()
        sys.stderr.flush()
        # VTK and the clients tear down at exit: a crash there is seen as the return code.

    def failed(self, error):
        self.result["exception"] = {
            "type": type(error).__name__,
            "message": str(error)[:500],
            "traceback": "".join(traceback.format_exception(type(error), error, error.__traceback__))[-4000:],
            "after_bloom": bool(self.result["bloom_added"]),
            "in_vtkbloom": raised_in_vtkbloom(error),
        }


def known_dark_off(pairs):
    """--known-dark-off NAME=LEVELS ...: {name: levels}."""
    known = {}
    for pair in pairs:
        name, _, levels = pair.rpartition("=")
        if not name or not levels.isdigit():
            raise SystemExit("client_examples: --known-dark-off %r: expected NAME=LEVELS" % pair)
        known[name] = int(levels)
    return known


def raised_in_vtkbloom(error):
    """Whether the exception came from vtkbloom's own code (a frame of its package in the
    traceback): ours to fix, whatever the example does without bloom."""
    try:
        import vtkbloom

        package = os.path.dirname(os.path.abspath(vtkbloom.__file__)) + os.sep
    except (ImportError, AttributeError, TypeError):
        return False
    frames = traceback.extract_tb(error.__traceback__)
    return any(os.path.abspath(frame.filename).startswith(package) for frame in frames)


# ------------------------------------------------------------------------------------------
# The examples: vedo's scripts, PyVista's docstrings.


def code_text(source):
    """The names and string literals of a script, without its comments and module docstring:
    what the static checks read (a link in a comment needs no network)."""
    import io
    import tokenize

    parts = []
    try:
        tokens = list(tokenize.generate_tokens(io.StringIO(source).readline))
    except (tokenize.TokenError, IndentationError, SyntaxError):
        return source
    docstring = True
    for token in tokens:
        if token.type in (tokenize.COMMENT, tokenize.NL, tokenize.NEWLINE, tokenize.ENCODING):
            continue
        if docstring and token.type == tokenize.STRING:
            docstring = False
            continue
        docstring = False
        parts.append(token.string)
    return " ".join(parts)


def static_skip(source):
    """Why an example is skipped before it runs, or None. A download elsewhere fails at run
    time (the children's proxy is a dead port) and is counted there."""
    if re.search(r"\bdataurl\b|\bdownload\w*", code_text(source)):
        return "needs the network (downloads its data)"
    if re.search(r"^\s*(?:import|from)\s+(?:PyQt5|PyQt6|PySide2|PySide6|qtpy|wx|napari|trame|k3d)\b",
                 source, re.M):
        return "interaction only (a Qt, wx, napari or trame window)"
    return None


def vedo_examples(folder):
    found = []
    for path in sorted(Path(folder).rglob("*.py")):
        if path.name in ("__init__.py", "_optional.py") or "__pycache__" in path.parts:
            continue
        source = path.read_text(errors="replace")
        found.append({"name": str(path.relative_to(folder)), "script": str(path), "source": source})
    return found


PLOTS = re.compile(r"\.plot\(|\.show\(|\bplot\(|\bplot_(?!over_)\w+\(")


def pyvista_examples(out):
    """Each docstring of PyVista's modules whose doctest examples plot, as one script: the
    examples of one docstring share their names, as under doctest (and PyVista's own
    `pytest --doctest-modules`). The docstrings are read from the imported modules, after
    PyVista fills in its docstring templates; lines marked `doctest: +SKIP` are left out, as
    doctest leaves them out."""
    import pkgutil
    import warnings

    try:
        import pyvista
    except ImportError:
        raise SystemExit("client_examples: PyVista is not installed for %s" % sys.executable)
    finder = doctest.DocTestFinder(exclude_empty=True)
    scripts = out / "scripts"
    shutil.rmtree(scripts, ignore_errors=True)
    scripts.mkdir(parents=True)
    found, seen = [], set()
    modules = [pyvista.__name__] + [m.name for m in pkgutil.walk_packages(pyvista.__path__, "pyvista.")]
    for name in sorted(set(modules)):
        if name.rsplit(".", 1)[-1] in ("conftest", "__main__"):
            continue
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                module = importlib.import_module(name)
            tests = finder.find(module)
        except Exception:  # noqa: BLE001 -- a module that needs what is not installed
            continue
        for test in sorted(tests, key=lambda t: t.name):
            source = "".join(e.source for e in test.examples if not e.options.get(doctest.SKIP))
            if not source or not PLOTS.search(source) or source in seen:
                continue
            seen.add(source)
            example = {"name": test.name, "source": source, "line": (test.lineno or 0) + 1, "module": name}
            path = scripts / (safe(test.name) + ".py")
            path.write_text("# %s (%s, line %d): its doctest examples\n%s"
                            % (test.name, os.path.relpath(test.filename or "?", os.path.dirname(pyvista.__path__[0])),
                               example["line"], source))
            example["script"] = str(path)
            found.append(example)
    return found


def safe(name):
    return re.sub(r"[^A-Za-z0-9_.-]+", "_", name).strip("_")


# ------------------------------------------------------------------------------------------
# The parent: run each example, read its output, sum up.


def phases(log):
    """GL errors and other VTK errors and warnings of a run's output, by phase: plain (nothing
    bloomed yet, or the plain grabs) or bloom. A GL error is its message and, where VTK prints
    its stack, the innermost four calls (up to the first in vtkBloom), so that an error VTK's
    own pass raises under the bloom pass, as it does without it, is the same error, and one
    raised by the bloom pass's own calls is a new one."""
    found = {"plain": {"gl": [], "vtk": []}, "bloom": {"gl": [], "vtk": []}}
    phase, event = "plain", None

    def close():
        if event is not None:
            found[event["phase"]]["gl"].append(" <- ".join([event["message"]] + event["frames"]))

    for line in log.splitlines():
        normal = normalize(line)
        frame = re.match(r"\s*0x[0-9a-fA-F]+ : (.*?) \[", line)
        if event is not None and frame:
            name = frame.group(1).split("(")[0].strip()
            done = len(event["frames"]) >= 4 or any("vtkBloom" in f for f in event["frames"])
            if not done and name not in ("???",) and "GetProgramStack" not in name:
                event["frames"].append(name)
            continue
        if event is not None and (re.match(r"\s*\d+ : \(\d+\)", line) or not normal
                                  or "stack trace" in normal):
            if re.match(r"\s*\d+ : \(\d+\)", line):
                event["message"] += " " + normal
            continue
        close()
        event = None
        if line.startswith(MARK):
            phase = "bloom" if "bloom=1" in line.split() else "plain"
        elif normal and GL_ERROR.search(line):
            event = {"phase": phase, "message": normal, "frames": []}
        elif normal and VTK_ERROR.search(line):
            found[phase]["vtk"].append(normal)
    close()
    return found


def normalize(line):
    """A line without what changes from run to run: addresses, times, colour codes."""
    line = re.sub(r"\x1b\[[0-9;]*m", "", line)
    line = re.sub(r"0x[0-9a-fA-F]+", "0x?", line)
    line = re.sub(r"^\d{4}-\d\d-\d\d[ T][0-9:.,]+\s*", "", line)  # vtkLogger's prefix: time,
    line = re.sub(r"^\(\s*[0-9.]+s\)\s*\[[^]]*\]\s*", "", line)  # uptime and thread
    return line.strip()


def run_child(example, mode, args, out, python, env, timeout):
    key = safe(example["name"])
    result_path = out / "runs" / ("%s.%s.json" % (key, mode))
    log_path = out / "logs" / ("%s.%s.log" % (key, mode))
    work = out / "work" / key
    for path in (result_path.parent, log_path.parent, work):
        path.mkdir(parents=True, exist_ok=True)
    if result_path.exists():
        result_path.unlink()
    command = [
        python, os.path.abspath(__file__), "--child", "--client", args.client, "--mode", mode,
        "--script", example["script"], "--result", str(result_path),
        "--images", str(out / "images" / key), "--seed", str(args.seed), "--shows", str(args.shows),
    ]
    if example.get("module"):
        command += ["--globals", example["module"]]
    started = time.time()
    with open(log_path, "w") as log:
        process = subprocess.Popen(command, cwd=work, env=env, stdout=log, stderr=subprocess.STDOUT,
                                   stdin=subprocess.DEVNULL, start_new_session=True)
        try:
            rc = process.wait(timeout=timeout)
            timed_out = False
        except subprocess.TimeoutExpired:
            timed_out = True
            os.killpg(process.pid, signal.SIGKILL)  # the child's own process group
            rc = process.wait()
    elapsed = time.time() - started
    text = log_path.read_text(errors="replace")
    try:
        result = json.loads(result_path.read_text())
    except (OSError, ValueError):
        result = {"shows": [], "exception": None, "finished": False, "show_calls": 0, "bloom_added": 0, "versions": {}}
    result.update(rc=rc, timed_out=timed_out, wall=elapsed, log=str(log_path), errors=phases(text))
    if not result.get("exception") and not timed_out and (rc != 0 or not result.get("finished")):
        tail = [line for line in text.splitlines() if line.strip() and not line.startswith(MARK)][-3:]
        result["exception"] = {"type": "crash", "message": "exit status %d; %s" % (rc, " | ".join(tail))[:500],
                               "traceback": "", "after_bloom": bool(result.get("bloom_added"))}
    return result


def short_warning(line):
    """The bloom pass's warning in a few words: what it found."""
    text = re.sub(r".*?vtkBloomPass \(0x\?\): ", "", line)
    return text.split(":")[0].split(" (")[0].strip()[:80]


def failure(run):
    """One line for a failed run, or None."""
    if run["timed_out"]:
        return "took more than %.0f s" % run["wall"]
    error = run.get("exception")
    if error:
        return "%s: %s" % (error["type"], error["message"].strip().splitlines()[0] if error["message"].strip() else "")
    return None


def own_reason(run):
    """Why a run without bloom fails: the client's own reason, as a category."""
    if run["timed_out"]:
        return "slow (over the time limit without bloom)"
    error = run.get("exception") or {}
    text = "%s %s %s" % (error.get("type", ""), error.get("message", ""), error.get("traceback", ""))
    if NETWORK.search(text):
        return "needs the network (at run time)"
    if error.get("type") in ("ModuleNotFoundError", "ImportError"):
        return "needs a module that is not installed"
    if re.search(r"interactor|timer|RenderWindowInteractor|iren\b", text):
        return "interaction only (needs an interactive window)"
    if error.get("type") == "crash":
        return "crashes without bloom"
    return "fails without bloom (%s)" % error.get("type", "error")


def judge(example, args, out, python, env):
    started = time.time()
    # With bloom an animation's every frame costs more (llvmpipe on two cores: up to twice):
    # the bloomed run has twice the time limit, the plain run the limit itself.
    bloom = run_child(example, "bloom", args, out, python, env, 2 * args.timeout)
    example["bloom"] = bloom
    example["plain"] = None
    problem = failure(bloom)
    gl_only = sorted(set(bloom["errors"]["bloom"]["gl"]) - set(bloom["errors"]["plain"]["gl"]))
    vtk_only = sorted(set(bloom["errors"]["bloom"]["vtk"]) - set(bloom["errors"]["plain"]["vtk"]))
    # The same example without bloom where bloom may be to blame: a failure once a plotter was
    # bloomed, or errors seen only after it (later frames of an animation may have their own);
    # the bloom pass's own warnings need no second run.
    others = [line for line in vtk_only if "vtkBloom" not in line]
    if (problem and (bloom["timed_out"] or (bloom.get("exception") or {}).get("after_bloom"))) or gl_only or others:
        plain = run_child(example, "plain", args, out, python, env, args.timeout)
        example["plain"] = plain
        seen_gl = set(plain["errors"]["plain"]["gl"]) | set(plain["errors"]["bloom"]["gl"])
        seen_vtk = set(plain["errors"]["plain"]["vtk"]) | set(plain["errors"]["bloom"]["vtk"])
        gl_only = [line for line in gl_only if line not in seen_gl]
        vtk_only = [line for line in vtk_only if line not in seen_vtk]
    shows = [s for s in bloom["shows"] if "changed_fraction" in s or "error" in s]
    verdict = {"frames": len(shows), "gl_bloom_only": gl_only, "vtk_bloom_only": vtk_only,
               "gl_plain": sorted(set(bloom["errors"]["plain"]["gl"])),
               "pass_warnings": sorted({short_warning(line) for line in vtk_only if "vtkBloomPass" in line})}
    if problem and (bloom.get("exception") or {}).get("in_vtkbloom"):
        verdict["bloom_failure"] = "raised in vtkbloom: " + problem  # ours, whatever the plain run does
    elif problem:
        plain = example["plain"]
        if plain is None:  # it failed before anything was bloomed
            verdict["own_failure"] = own_reason(bloom)
        elif failure(plain) and (plain["timed_out"] or (plain.get("exception") or {}).get("type")
                                 == (bloom.get("exception") or {}).get("type")):
            verdict["own_failure"] = own_reason(plain)
        elif bloom["timed_out"]:
            verdict["bloom_failure"] = "more than twice as slow with bloom (over %d s; %.0f s without)" % (
                2 * args.timeout, plain["wall"])
        else:
            verdict["bloom_failure"] = problem
    if shows:
        verdict["deterministic"] = all(s.get("plain_identical") for s in shows)
        worst = max(shows, key=lambda s: (s.get("changed_fraction", 2.0), s.get("max_diff", 0)))
        verdict["worst_show"] = worst["show"]
        verdict["changed_fraction"] = worst.get("changed_fraction", 1.0)
        verdict["max_diff"] = max(s.get("max_diff", 255) for s in shows)
        verdict["within"] = all(s.get("changed_fraction", 1.0) <= CHANGED_LIMIT for s in shows)
        # Light: some bloomed frame had a value above the threshold (a highlight above display
        # white, which the 8-bit plain frame clips). Without it the frame must be the plain one.
        verdict["light"] = any(s.get("light") for s in shows)
        # A frame that renders the same twice without bloom must do so with it.
        verdict["bloom_stable"] = all(s.get("bloom_stable", False) for s in shows if s.get("plain_identical"))
    example["verdict"] = verdict
    example["seconds"] = time.time() - started
    return example


def versions(python, client, env):
    """The client's and VTK's versions, and a check that the children find vtkbloom and the
    client from another folder (they run in a scratch folder of their own)."""
    code = ("import json, vtkbloom, %s; from vtkmodules.vtkCommonCore import vtkVersion; "
            "print(json.dumps({'client': %s.__version__, 'vtk': vtkVersion.GetVTKVersion()}))" % (client, client))
    done = subprocess.run([python, "-c", code], env=env, capture_output=True, text=True, timeout=120, cwd="/")
    try:
        return json.loads(done.stdout.strip().splitlines()[-1])
    except (IndexError, ValueError):
        raise SystemExit("client_examples: %s cannot import vtkbloom and %s (PYTHONPATH=%s):\n%s"
                         % (python, client, env.get("PYTHONPATH", ""), done.stderr[-2000:]))


def build_info():
    info = {}
    try:
        spec = importlib.util.find_spec("vtkbloom")
        folder = Path(list(spec.submodule_search_locations)[0])
        info["vtkbloom"] = str(folder)
        info["extensions"] = {
            p.name: datetime.datetime.fromtimestamp(p.stat().st_mtime).isoformat(timespec="seconds")
            for p in sorted(folder.glob("vtk*.so"))
        }
    except (AttributeError, TypeError, IndexError):
        pass
    try:
        root = Path(__file__).resolve().parents[2]
        info["commit"] = subprocess.run(["git", "-C", str(root), "describe", "--always", "--dirty"],
                                        capture_output=True, text=True, timeout=30).stdout.strip()
    except (OSError, subprocess.SubprocessError):
        pass
    return info


def summarize(report):
    """The figures: skipped before running (over every example found), then over those run."""
    before = {}
    for e in report["population"]:
        if e["skip"]:
            before.setdefault(e["skip"], []).append(e["name"])
    chosen = report["examples"]
    # Skipped at run time: what fails without bloom before its first frame, and what takes
    # longer than the limit without bloom (its first frames may have been compared).
    def skipped(v):
        return v.get("own_failure") and (not v["frames"] or v["own_failure"].startswith("slow"))

    at_run = {}
    for e in chosen:
        if skipped(e["verdict"]):
            at_run.setdefault(e["verdict"]["own_failure"], []).append(e["name"])
    run = [e for e in chosen if not skipped(e["verdict"])]
    framed = [e for e in run if e["verdict"]["frames"]]
    groups = {
        "no_frame": [e for e in run if not e["verdict"]["frames"]],
        "own_after_frame": [e for e in framed if e["verdict"].get("own_failure")],
        "deterministic": [e for e in framed if e["verdict"].get("deterministic")],
        "bloom_failures": [e for e in run if e["verdict"].get("bloom_failure")],
        "gl": [e for e in run if e["verdict"]["gl_bloom_only"]],
        "vtk": [e for e in run if e["verdict"]["vtk_bloom_only"]],
        "gl_plain": [e for e in run if e["verdict"].get("gl_plain")],
        "differ": sorted((e for e in framed if e["verdict"].get("max_diff", 0) > LEVELS),
                         key=lambda e: -e["verdict"].get("changed_fraction", 0)),
        "nondeterministic": [e for e in framed if not e["verdict"].get("deterministic")],
    }
    within = [e for e in groups["deterministic"] if e["verdict"].get("within")]
    share = len(within) / len(groups["deterministic"]) if groups["deterministic"] else 0.0
    # Where no frame had light, the bloomed frame is the plain one within a level.
    dark = [e for e in groups["deterministic"] if not e["verdict"].get("light")]
    dark_off = [e for e in dark if e["verdict"].get("max_diff", 255) > 1]
    # Where the pass warned that it cannot keep the background out (translucent geometry
    # without depth peeling: docs/rendering.md), the frame is the pass's, not the window's own:
    # listed, and not held to the 1-level target. Every other dark frame is.
    warned = [e for e in dark_off if any(TRANSLUCENT_WARNING in w for w in e["verdict"].get("pass_warnings", []))]
    # Open defects named on the command line, each with the bound it must stay within.
    known = report.get("known_dark_off", {})
    bounded = [e for e in dark_off if e not in warned and e["verdict"].get("max_diff", 255) <= known.get(e["name"], -1)]
    dark_off = [e for e in dark_off if e not in warned and e not in bounded]
    groups["dark_off"] = dark_off
    groups["dark_off_warned"] = warned + bounded
    run_names = {e["name"] for e in run}
    groups["known_not_run"] = sorted(name for name in known if name not in run_names)
    groups["unstable"] = [e for e in groups["deterministic"] if not e["verdict"].get("bloom_stable")]
    # VTK's errors (not its warnings) that appear only with bloom.
    groups["vtk_errors"] = [e for e in run if any(VTK_ERROR_LINE.search(line) for line in e["verdict"]["vtk_bloom_only"])]
    report["figures"] = {
        "found": len(report["population"]),
        "skipped_before_running": {k: len(v) for k, v in sorted(before.items())},
        "chosen": len(chosen),
        "skipped_at_run_time": {k: len(v) for k, v in sorted(at_run.items())},
        "run": len(run),
        "no_frame": len(groups["no_frame"]),
        "with_frames": len(framed),
        "deterministic": len(groups["deterministic"]),
        "no_error_with_bloom": len(run) - len(groups["bloom_failures"]),
        "errors_with_bloom_only": len(groups["bloom_failures"]),
        "client_errors_after_a_frame": len(groups["own_after_frame"]),
        "within_1_percent": len(within),
        "within_share_of_deterministic": share,
        "gl_errors_with_bloom_only": len(groups["gl"]),
        "gl_errors_without_bloom": len(groups["gl_plain"]),
        "vtk_errors_with_bloom_only": len(groups["vtk"]),
        "differ": len(groups["differ"]),
        "differ_with_light": sum(1 for e in groups["differ"] if e["verdict"].get("light")),
        "without_light": len(dark),
        "without_light_off_by_more_than_1_level": len(dark_off),
        "without_light_off_where_the_pass_warned": len(groups["dark_off_warned"]),
        "bloom_unstable": len(groups["unstable"]),
        "vtk_error_lines_with_bloom_only": len(groups["vtk_errors"]),
        # Every target the summary prints is enforced.
        "target_met": (share >= TARGET and not groups["bloom_failures"] and not groups["gl"]
                       and not dark_off and not groups["unstable"] and not groups["vtk_errors"]
                       and not groups["known_not_run"]),
    }
    return before, at_run, groups


def names(examples, limit=6):
    shown = ", ".join("`%s`" % (e if isinstance(e, str) else e["name"]) for e in examples[:limit])
    return shown + (", ..." if len(examples) > limit else "")


def markdown(report, out):
    before, at_run, groups = summarize(report)
    f = report["figures"]
    lines = [
        "# %s %s through vtkbloom.add_bloom (defaults)" % (report["client"], report["versions"]["client"]),
        "",
        "VTK %s; vtkbloom from `%s` (commit %s); %s; %s (seed %d); time limit %d s per run without bloom, twice that with; the "
        "first %d show() calls of each example compared; %s, %.0f s in all."
        % (report["versions"]["vtk"], report["build"].get("vtkbloom", "?"), report["build"].get("commit", "?"),
           report["source"], report["selection"], report["seed"], report["timeout"], report["shows"],
           report["date"], report["seconds"]),
        "",
        "**The extension modules were rebuilt during the run**: its examples ran against two "
        "builds; run it again." if report["build"].get("changed_during_the_run") else "",
        "",
        "| | examples |",
        "|---|---:|",
        "| found | %d |" % f["found"],
        "| skipped before running (below) | %d |" % sum(f["skipped_before_running"].values()),
        "| chosen to run | %d |" % f["chosen"],
        "| skipped at run time: fail without bloom before any frame, or slow (below) | %d |" % sum(f["skipped_at_run_time"].values()),
        "| **run** | **%d** |" % f["run"],
        "| ... reached no show() (no frame to compare) | %d |" % f["no_frame"],
        "| ... with frames compared | %d |" % f["with_frames"],
        "| **render the same frame twice** (deterministic) | **%d** of %d |" % (f["deterministic"], f["with_frames"]),
        "| **run with no error with bloom** | **%d** of %d |" % (f["no_error_with_bloom"], f["run"]),
        "| ... of which fail later, without bloom too (the client's own error, after a frame) | %d |"
        % f["client_errors_after_a_frame"],
        "| **within 1 %% of the pixels** (> %d levels), of the deterministic (target >= 98 %%) | **%d of %d = %.1f %%** |"
        % (LEVELS, f["within_1_percent"], f["deterministic"], 100 * f["within_share_of_deterministic"]),
        "| **GL errors with bloom and not without** (target: none) | **%d** |" % f["gl_errors_with_bloom_only"],
        "| GL errors without bloom (VTK's or the client's own; below) | %d |" % f["gl_errors_without_bloom"],
        "| other VTK errors and warnings with bloom and not without | %d |" % f["vtk_errors_with_bloom_only"],
        "| ... **of which VTK errors** (target: none) | **%d** |" % f["vtk_error_lines_with_bloom_only"],
        "| **bloomed frame differs between two renders** where the plain one does not (target: none) | **%d** |"
        % f["bloom_unstable"],
        "| bloomed frame differs from the plain frame (some pixel > %d levels) | %d |" % (LEVELS, f["differ"]),
        "| ... of which have light (a value above the threshold: the pass ran its chain) | %d |" % f["differ_with_light"],
        "| deterministic, with no light in any frame | %d |" % f["without_light"],
        "| ... **of which any pixel is more than 1 level off** (target: none) | **%d** |"
        % f["without_light_off_by_more_than_1_level"],
        "| ... and more than 1 level off where the pass warned of translucency without depth peeling, or "
        "an open defect named with its bound (below) | %d |" % f["without_light_off_where_the_pass_warned"],
        "",
        "## Skipped, and why",
        "",
        "| when | reason | examples | |",
        "|---|---|---:|---|",
    ]
    for when, table in (("before running", before), ("at run time", at_run)):
        for reason, listed in sorted(table.items()):
            lines.append("| %s | %s | %d | %s |" % (when, reason, len(listed), names(listed)))
    lines += ["", "## Frames that differ", "",
              "Changed: the share of pixels with a channel more than %d levels from the plain frame "
              "(the worst show() of the example); brighter: the share of those brighter with bloom; "
              "thin: the share with no 3 x 3 block of changed pixels around them (edges of lines, "
              "text, anti-aliasing)." % LEVELS, "",
              "| example | show | changed | max | brighter | thin | light | same frame twice | the pass warns | images |",
              "|---|---:|---:|---:|---:|---:|---|---|---|---|"]
    for e in groups["differ"]:
        v = e["verdict"]
        worst = next(s for s in e["bloom"]["shows"] if s["show"] == v["worst_show"])
        images = worst.get("images") or next((s.get("images") for s in e["bloom"]["shows"] if s.get("images")), None)
        link = os.path.relpath(os.path.dirname(images["plain"]), out) if images else ""
        lines.append("| `%s` | %d | %.3f %% | %d | %s | %s | %s | %s | %s | %s |" % (
            e["name"], v["worst_show"], 100 * v["changed_fraction"], v["max_diff"],
            "%.0f %%" % (100 * worst["brighter_share"]) if worst.get("brighter_share") is not None else "",
            "%.0f %%" % (100 * worst["thin_share"]) if worst.get("thin_share") is not None else "",
            "yes" if v.get("light") else "no", "yes" if v.get("deterministic") else "no",
            "; ".join(v.get("pass_warnings", [])), link))
    sections = (
        ("Errors with bloom only", groups["bloom_failures"],
         lambda e: "%s (log: %s)" % (e["verdict"]["bloom_failure"], os.path.relpath(e["bloom"]["log"], out))),
        ("GL errors with bloom only", groups["gl"], lambda e: "; ".join(e["verdict"]["gl_bloom_only"][:4])),
        ("GL errors without bloom (the same with it)", groups["gl_plain"],
         lambda e: "; ".join(line[:300] for line in e["verdict"]["gl_plain"][:3])),
        ("The client's own errors after a frame (without bloom too)", groups["own_after_frame"],
         lambda e: e["verdict"]["own_failure"] + ": " + (failure(e["bloom"]) or "")),
    )
    for title, listed, line in sections:
        lines += ["", "## " + title, ""]
        lines += ["- `%s`: %s" % (e["name"], line(e)) for e in listed] or ["None."]
        if title.startswith("GL errors with bloom"):
            by_message = {}
            for e in groups["vtk"]:
                for message in e["verdict"]["vtk_bloom_only"]:
                    by_message.setdefault(message, []).append(e["name"])
            lines += ["", "## Other VTK errors and warnings with bloom only", ""]
            lines += ["- %d examples: %s (%s)" % (len(listed_), message[:400], names(listed_, 4))
                      for message, listed_ in sorted(by_message.items(), key=lambda m: -len(m[1]))] or ["None."]
    lines += ["", "## No light, yet more than 1 level off", "",
              "\n".join("- `%s`: %d levels, %.3f %% of the pixels > %d" % (
                  e["name"], e["verdict"]["max_diff"], 100 * e["verdict"]["changed_fraction"], LEVELS)
                  for e in groups["dark_off"]) or "None."]
    lines += ["", "## No light, more than 1 level off, where the pass warned (translucency without depth peeling) "
              "or an open defect is named with its bound (--known-dark-off)", "",
              "\n".join("- `%s`: %d levels, %.3f %% of the pixels > %d" % (
                  e["name"], e["verdict"]["max_diff"], 100 * e["verdict"]["changed_fraction"], LEVELS)
                  for e in groups["dark_off_warned"]) or "None."]
    if groups["known_not_run"]:
        lines += ["", "**Named with --known-dark-off and not run** (the check fails): %s" % names(groups["known_not_run"], 1000)]
    lines += ["", "## Not the same frame twice without bloom", "", names(groups["nondeterministic"], 1000) or "None."]
    lines += ["", "## Ran, but reached no show()", "", names(groups["no_frame"], 1000) or "None."]
    return "\n".join(lines) + "\n"


def parent(args):
    python = args.python or sys.executable
    env = dict(os.environ)
    # A download fails at once (a dead proxy) instead of hanging; matplotlib draws nowhere.
    for key in ("http_proxy", "https_proxy", "HTTP_PROXY", "HTTPS_PROXY"):
        env[key] = "http://127.0.0.1:9"
    env.update(PYTHONUNBUFFERED="1", PYTHONHASHSEED="0", MPLBACKEND="Agg")
    # The children run in scratch folders: a relative PYTHONPATH would not find vtkbloom there.
    env["PYTHONPATH"] = os.pathsep.join(os.path.abspath(p) for p in env.get("PYTHONPATH", "").split(os.pathsep) if p)
    if args.mesa_debug:
        env["MESA_DEBUG"] = "1"  # Mesa prints each GL error where it happens
    known = versions(python, args.client, env)
    out = Path(args.out or Path("client-examples") / ("%s-%s" % (args.client, known["client"]))).resolve()
    out.mkdir(parents=True, exist_ok=True)
    if args.client == "vedo":
        population = vedo_examples(args.examples or VEDO_EXAMPLES)
        source = "vedo's examples in `%s`" % (args.examples or VEDO_EXAMPLES)
    else:
        population = pyvista_examples(out)
        source = "PyVista's docstrings whose doctest examples plot"
    for example in population:
        example["skip"] = static_skip(example["source"])
    runnable = [e for e in population if not e["skip"]]
    if args.only:
        # A name given whole picks that example alone; a part of names, every example it is in.
        names = {e["name"] for e in runnable}
        chosen = [e for e in runnable
                  if any(o == e["name"] or (o not in names and o in e["name"]) for o in args.only)]
        selection = "only those named %s" % ", ".join(args.only)
        # A name that matches nothing (gone from this version of the client, or skipped before
        # running) would make a check pass on fewer examples than it names.
        unmatched = [o for o in args.only if not any(o in e["name"] for e in runnable)]
        if unmatched and args.check:
            print("client_examples: --only names no runnable example: %s" % ", ".join(unmatched),
                  file=sys.stderr)
            return 1
    elif args.sample and args.sample < len(runnable):
        chosen = sorted(random.Random(args.seed).sample(runnable, args.sample), key=lambda e: e["name"])
        selection = "a sample of %d of the %d not skipped before running" % (args.sample, len(runnable))
    else:
        chosen = runnable
        selection = "all %d not skipped before running" % len(runnable)
    if args.list:
        for e in population:
            print("%-72s %s" % (e["name"], e["skip"] or ("run" if e in chosen else "-")))
        return 0
    for folder in ("runs", "logs", "images", "work"):  # this run's, not an earlier one's
        shutil.rmtree(out / folder, ignore_errors=True)
    built = build_info()
    started = time.time()
    for number, example in enumerate(chosen, 1):
        judge(example, args, out, python, env)
        v = example["verdict"]
        if v.get("bloom_failure"):
            state = "ERROR WITH BLOOM: " + v["bloom_failure"]
        elif v["frames"]:
            worst = next(s for s in example["bloom"]["shows"] if s["show"] == v["worst_show"])
            state = "changed %.3f %% (%d pixels) max %d%s" % (
                100 * v["changed_fraction"], worst.get("changed_pixels", -1), v["max_diff"],
                "" if v.get("deterministic") else " (not the same frame twice)")
            if v.get("own_failure"):
                state += "; then " + v["own_failure"]
        else:
            state = v.get("own_failure") or "no frame"
        if v["gl_bloom_only"]:
            state += "; GL ERRORS WITH BLOOM ONLY"
        print("[%d/%d] %-60s %5.1f s  %s" % (number, len(chosen), example["name"][-60:], example["seconds"], state),
              flush=True)
    report = {
        "client": args.client,
        "versions": known,
        "build": built,
        "source": source,
        "seed": args.seed,
        "selection": selection,
        "timeout": args.timeout,
        "shows": args.shows,
        "date": datetime.datetime.now().isoformat(timespec="seconds"),
        "seconds": time.time() - started,
        "population": [{"name": e["name"], "skip": e["skip"]} for e in population],
        "known_dark_off": known_dark_off(args.known_dark_off),
        "examples": [{k: v for k, v in e.items() if k not in ("source", "skip")} for e in chosen],
    }
    if build_info().get("extensions") != built.get("extensions"):
        report["build"]["changed_during_the_run"] = build_info().get("extensions")
    text = markdown(report, out)
    (out / "summary.md").write_text(text)
    (out / "results.json").write_text(json.dumps(report, indent=1))
    print(text)
    print("client_examples: %s" % out)
    if args.check and not report["figures"]["target_met"]:
        print("client_examples: a target is missed (see above)", file=sys.stderr)
        return 1
    # Examples named one by one must each have been compared: none may drop out as the client's
    # own failure (a missing module, the network) and leave the check to the others.
    uncompared = [e["name"] for e in chosen if not e["verdict"]["frames"] or e["verdict"].get("own_failure")]
    if args.check and args.only and uncompared:
        print("client_examples: not compared: %s" % ", ".join(uncompared), file=sys.stderr)
        return 1
    return 0


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--client", choices=("pyvista", "vedo"), required=True)
    parser.add_argument("--sample", type=int, default=None,
                        help="run N examples drawn with --seed (default: 100 for pyvista, all for vedo)")
    parser.add_argument("--all", action="store_true", help="run every example")
    parser.add_argument("--seed", type=int, default=48, help="the sample's and the examples' seed")
    parser.add_argument("--out", help="output folder (default ./client-examples/CLIENT-VERSION)")
    parser.add_argument("--examples", help="vedo's examples folder (default %s)" % VEDO_EXAMPLES)
    parser.add_argument("--known-dark-off", nargs="+", default=[], metavar="NAME=LEVELS",
                        help="an open defect, bounded: the example NAME's frames without light may be "
                             "up to LEVELS off (listed apart; more fails, and so does a NAME that is not run)")
    parser.add_argument("--only", nargs="+",
                        help="run the examples named (a whole name), or whose names contain one of these")
    parser.add_argument("--timeout", type=int, default=60, help="seconds per example and run (60)")
    parser.add_argument("--shows", type=int, default=3, help="show() calls compared per example (3)")
    parser.add_argument("--no-mesa-debug", dest="mesa_debug", action="store_false",
                        help="do not set MESA_DEBUG=1 (Mesa's own report of each GL error)")
    parser.add_argument("--check", action="store_true", help="exit 1 when a target is missed")
    parser.add_argument("--list", action="store_true", help="list the examples and what would run")
    parser.add_argument("--python", help="the Python that runs the examples (default: this one)")
    # The child's side (one example in one process).
    parser.add_argument("--child", action="store_true", help=argparse.SUPPRESS)
    parser.add_argument("--mode", choices=("bloom", "plain"), help=argparse.SUPPRESS)
    parser.add_argument("--script", help=argparse.SUPPRESS)
    parser.add_argument("--result", help=argparse.SUPPRESS)
    parser.add_argument("--images", help=argparse.SUPPRESS)
    parser.add_argument("--globals", help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.child:
        Child(args).run()
        return 0
    if args.all:
        args.sample = 0
    elif args.sample is None:
        args.sample = 100 if args.client == "pyvista" else 0
    return parent(args)


if __name__ == "__main__":
    sys.exit(main())
