#!/usr/bin/python3
# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
"""Bloom every OpenEXR file of a folder into another folder, with progress.

    batch_bloom.py [--preset NAME] [--strength S] [--threshold T] [--png] [--exposure E]
                   INPUT_DIR OUTPUT_DIR

Each INPUT_DIR/NAME.exr is read with vtkOpenEXRReader, bloomed with vtkImageBloom and written
to OUTPUT_DIR/NAME.exr as float32 (and, with --png, a tone-mapped OUTPUT_DIR/NAME.png). The
bloom statistics of every file are printed. A file that cannot be read or bloomed is reported
and skipped; the exit status is then 1. OUTPUT_DIR must differ from INPUT_DIR, so inputs are
never overwritten.
"""

import argparse
import pathlib
import sys
import time

import vtkbloom
from vtkmodules.util.misc import calldata_type
from vtkmodules.util.vtkConstants import VTK_STRING
from vtkmodules.vtkCommonCore import vtkCommand

from example_support import array_from_image, statistics, tone_map, write_png


class Messages:
    """Collect the error messages of the filters a file goes through."""

    def __init__(self):
        self.errors = []

    def watch(self, algorithm):
        algorithm.AddObserver(vtkCommand.ErrorEvent, self._on_error)

    # The wrappers pass the message only to callbacks that ask for a string.
    @calldata_type(VTK_STRING)
    def _on_error(self, caller, event, message=None):
        # The text is "ERROR: In file, line n\nvtkClass (0x...): message"; keep the message.
        text = (message or "").strip()
        self.errors.append("%s: %s" % (caller.GetClassName(), text.split("): ", 1)[-1]))


def make_progress_printer(label):
    """A ProgressEvent callback that prints each tenth of the way once."""
    state = {"last": -1}

    def on_progress(caller, event):
        tenth = int(caller.GetProgress() * 10.0 + 1e-9)
        if tenth > state["last"]:
            state["last"] = tenth
            print("%s %3d%%" % (label, 10 * tenth), flush=True)

    return on_progress


def bloom_file(path, output_dir, args, label):
    """Bloom one file. Returns the statistics, or raises RuntimeError with the filters' errors."""
    messages = Messages()
    reader = vtkbloom.vtkOpenEXRReader()
    reader.SetFileName(str(path))
    messages.watch(reader)
    reader.Update()
    if messages.errors:
        raise RuntimeError("; ".join(messages.errors))

    bloom = vtkbloom.vtkImageBloom()
    bloom.SetPreset(args.preset)
    if args.strength is not None:
        bloom.SetStrength(args.strength)
    if args.threshold is not None:
        bloom.SetThreshold(args.threshold)
    bloom.SetInputConnection(reader.GetOutputPort())
    bloom.AddObserver(vtkCommand.ProgressEvent, make_progress_printer(label))
    messages.watch(bloom)

    bloom.Update()
    if messages.errors:
        raise RuntimeError("; ".join(messages.errors))

    writer = vtkbloom.vtkOpenEXRWriter()
    writer.SetFileName(str(output_dir / (path.stem + ".exr")))
    writer.SetInputConnection(bloom.GetOutputPort())
    messages.watch(writer)
    if not writer.Write() or messages.errors:
        raise RuntimeError("; ".join(messages.errors) or "cannot write " + writer.GetFileName())
    if args.png:
        rgb = tone_map(array_from_image(bloom.GetOutput()), args.exposure)
        write_png(rgb, output_dir / (path.stem + ".png"))
    return bloom.GetOutput().GetDimensions(), statistics(bloom.GetOutput())


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--preset", default="webgpu-market",
        choices=vtkbloom.vtkImageBloom.GetPresetNames())
    parser.add_argument("--strength", type=float)
    parser.add_argument("--threshold", type=float)
    parser.add_argument("--png", action="store_true", help="also write tone-mapped PNGs")
    parser.add_argument("--exposure", type=float, default=1.0, help="PNG exposure")
    parser.add_argument("input_dir", type=pathlib.Path)
    parser.add_argument("output_dir", type=pathlib.Path)
    args = parser.parse_args(argv[1:])

    if not args.input_dir.is_dir():
        parser.error("%s is not a directory" % args.input_dir)
    if args.output_dir.resolve() == args.input_dir.resolve():
        parser.error("OUTPUT_DIR must differ from INPUT_DIR")
    args.output_dir.mkdir(parents=True, exist_ok=True)

    files = sorted(p for p in args.input_dir.iterdir() if p.suffix.lower() == ".exr")
    if not files:
        print("no .exr files in %s" % args.input_dir, file=sys.stderr)
        return 1
    failed = []
    for index, path in enumerate(files, start=1):
        label = "[%d/%d] %s" % (index, len(files), path.name)
        start = time.perf_counter()
        try:
            dimensions, stats = bloom_file(path, args.output_dir, args, label)
        except RuntimeError as error:
            print("%s FAILED: %s" % (label, error), file=sys.stderr, flush=True)
            failed.append(path.name)
            continue
        print("%s done: %dx%d in %.2f s, energy %.6g -> %.6g, %d bright pixels, "
            "peak %.6g -> %.6g, %d levels" % (label, dimensions[0], dimensions[1],
                time.perf_counter() - start, stats["BloomEnergyIn"], stats["BloomEnergyOut"],
                stats["BloomNumberOfBrightPixels"], stats["BloomPeakLuminanceIn"],
                stats["BloomPeakLuminanceOut"], stats["BloomNumberOfLevelsUsed"]), flush=True)
    print("bloomed %d of %d files into %s" % (len(files) - len(failed), len(files),
        args.output_dir))
    if failed:
        print("failed: %s" % ", ".join(failed), file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
