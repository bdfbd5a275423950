# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
"""The gallery's table and figure (run by scripts/gallery.sh; not by hand).

    /usr/bin/python3 scripts/lib/gallery-figure.py OUT FIGURE.png DOC.md

OUT is TestBloomPassGallery's output folder: gallery.csv (one row per configuration),
png/NAME.png (the plain frame | the defaults with one lamp) and debug/NAME-plain-before.png (the
plain frame | the earlier defaults). FIGURE.png gets, for three configurations, a row: the plain
frame, the earlier defaults, the defaults with the lamp. DOC.md gets the table between
<!-- gallery:begin --> and <!-- gallery:end -->.
"""
import csv
import os
import sys

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkIOImage import vtkPNGReader, vtkPNGWriter

out, figure, doc = sys.argv[1:4]
SHOWN = ('white_background', 'annotation_widgets', 'viewports_2x2')


def load(path):
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    width, height, _ = image.GetDimensions()
    pixels = vtk_to_numpy(image.GetPointData().GetScalars())
    return pixels.reshape(height, width, -1)[..., :3]


def halves(path):
    both = load(path)
    half = both.shape[1] // 2
    return both[:, :half], both[:, half:]


def save(pixels, path):
    height, width, _ = pixels.shape
    image = vtkImageData()
    image.SetDimensions(width, height, 1)
    image.GetPointData().SetScalars(
        numpy_to_vtk(np.ascontiguousarray(pixels).reshape(-1, 3), deep=1))
    writer = vtkPNGWriter()
    writer.SetFileName(path)
    writer.SetInputData(image)
    writer.Write()


def figure_rows():
    rows = []
    for name in SHOWN:
        before_path = os.path.join(out, 'debug', name + '-plain-before.png')
        after_path = os.path.join(out, 'png', name + '.png')
        if not (os.path.exists(before_path) and os.path.exists(after_path)):
            continue
        plain, before = halves(before_path)
        _, after = halves(after_path)
        gap = np.full((plain.shape[0], 6, 3), 255, np.uint8)
        rows.append(np.concatenate([plain, gap, before, gap, after], axis=1))
    # Narrower rows are centred on the widest.
    width = max(row.shape[1] for row in rows)
    padded = [np.pad(row, ((0, 6), ((width - row.shape[1]) // 2,
                                    width - row.shape[1] - (width - row.shape[1]) // 2), (0, 0)),
                     constant_values=255)
              for row in rows]
    # PNG rows are stored bottom first: the first configuration goes on top.
    return np.concatenate(padded[::-1], axis=0)


def table():
    lines = ['| configuration | earlier defaults: pixels > 8 levels off | defaults: pixels > 8 '
             'levels off | defaults: largest difference (levels) | one lamp: mean glow around '
             'it (levels) | annotations\' opaque pixels under the glow (levels) |',
             '|---|---:|---:|---:|---:|---:|']
    with open(os.path.join(out, 'gallery.csv')) as f:
        for row in csv.DictReader(f):
            lines.append('| %s | %.1f %% | %.1f %% | %s | %.0f | %s |' % (
                row['configuration'].replace('_', ' '), float(row['before_pct_over_8']),
                float(row['after_pct_over_8']), row['after_max_levels'],
                float(row['glow_ring_levels']), row['annotations_max_levels']))
    return '\n'.join(lines)


save(figure_rows(), figure)
text = open(doc).read()
begin, end = '<!-- gallery:begin -->', '<!-- gallery:end -->'
head, rest = text.split(begin, 1)
_, tail = rest.split(end, 1)
open(doc, 'w').write(head + begin + '\n' + table() + '\n' + end + tail)
print('gallery: wrote', figure, 'and the table of', doc)
