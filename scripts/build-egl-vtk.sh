#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
# Build Debian's own VTK 9.1 source with EGL (vtkEGLRenderWindow; no X, no OSMesa) into a cached
# prefix.
#
#   bash scripts/build-egl-vtk.sh               prints the prefix on its last line
#
# The prefix is $VTKBLOOM_EGL_PREFIX, or ~/.cache/vtk-bloom/vtk-9.1-egl (work tree
# $VTKBLOOM_EGL_WORK, or ~/.cache/vtk-bloom/egl-build). When the prefix already holds an
# installed VTK, nothing is built. The first build takes about 20 minutes on two cores; ccache
# makes later rebuilds take seconds. scripts/lib/build-debian-vtk.sh does the work and says why its
# steps are needed.
#
# The same build renders on a GPU's EGL driver (NVIDIA's, through glvnd; scripts/gpu-pack.sh)
# and, on a machine with no GPU, on Mesa's EGL with llvmpipe (`bash scripts/test.sh --egl`).
set -euo pipefail
exec bash "$(dirname "${BASH_SOURCE[0]}")/lib/build-debian-vtk.sh" egl
