#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
# The gallery of users' configurations (issue 35), in one command:
#   bash scripts/gallery.sh [BUILD_DIR]      (default build/, configured and built already)
# Runs TestBloomPassGallery under a private Xvfb with its CSV and picture outputs on, writes
# the table into docs/rendering.md between its gallery markers, and composes
# docs/images/gallery.png (three configurations: the plain frame, the earlier defaults, the
# defaults with one lamp added) with scripts/lib/gallery-figure.py.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${1:-"$root/build"}
cmake --build "$build" --target TestBloomPassGallery -- -j"$(nproc)"
out="$build/gallery"
rm -rf "$out"
mkdir -p "$out/png" "$out/debug"
VTKBLOOM_GALLERY_CSV="$out/gallery.csv" VTKBLOOM_GALLERY_PNG_DIR="$out/png" \
  VTKBLOOM_GALLERY_DEBUG_DIR="$out/debug" \
  bash "$root/scripts/lib/with-xvfb.sh" "$build/bin/TestBloomPassGallery"
/usr/bin/python3 "$root/scripts/lib/gallery-figure.py" "$out" "$root/docs/images/gallery.png" \
  "$root/docs/rendering.md"
