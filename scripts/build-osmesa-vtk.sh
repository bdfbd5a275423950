#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
# Build Debian's own VTK 9.1 source with OSMesa (no X, offscreen by default) into a cached prefix.
#
#   bash scripts/build-osmesa-vtk.sh            prints the prefix on its last line
#
# The prefix is $VTKBLOOM_OSMESA_PREFIX, or ~/.cache/vtk-bloom/vtk-9.1-osmesa (work tree
# $VTKBLOOM_OSMESA_WORK, or ~/.cache/vtk-bloom/osmesa-build). When the prefix already holds an
# installed VTK, nothing is built. The first build takes about 20 minutes on two cores; ccache
# makes later rebuilds take seconds. scripts/lib/build-debian-vtk.sh does the work and says why its
# steps are needed.
set -euo pipefail
exec bash "$(dirname "${BASH_SOURCE[0]}")/lib/build-debian-vtk.sh" osmesa
