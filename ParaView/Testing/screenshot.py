# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
"""SaveScreenshot that fails: a test's screenshot that was not written stops the script with
a non-zero exit, instead of leaving the check that reads it to be skipped."""
import os


def save(path, view, **kwargs):
    from paraview.simple import SaveScreenshot

    if os.path.exists(path):
        os.remove(path)
    if not SaveScreenshot(path, view, **kwargs) or not os.path.isfile(path):
        raise SystemExit("SaveScreenshot did not write %s" % path)
