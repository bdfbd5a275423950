#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
# Build the vtk-bloom ParaView plugin (ParaView/) against the ParaView of this system: Debian
# 12's ParaView 5.11 and the VTK 9.2 it carries, beside the project's own VTK 9.1 build; or,
# inside the sid root (scripts/sid-root.sh), ParaView 6.1 on the system VTK 9.6:
#
#   bash scripts/build-paraview-plugin.sh [BUILD_DIR]     (default: build-paraview)
#
# scripts/lib/paraview-env.sh installs and sets up ParaView (cached) and runs CMake in its
# environment. The plugin is BUILD_DIR/lib/paraview-X.Y/plugins/VTKBloom/VTKBloom.so;
# scripts/pvbatch.sh loads it.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
build=${1:-build-paraview}
bash scripts/install-deps.sh
bash scripts/lib/paraview-env.sh
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
jobs=${VTKBLOOM_JOBS:-$(nproc)}
bash scripts/lib/paraview-env.sh cmake -S ParaView -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  "${launcher[@]}" ${VTKBLOOM_PARAVIEW_CMAKE_ARGS:-}
bash scripts/lib/paraview-env.sh cmake --build "$build" -j "$jobs"
plugin=$(ls "$build"/lib/paraview-*/plugins/VTKBloom/VTKBloom.so 2>/dev/null | head -n 1)
[ -n "$plugin" ] || { echo "build-paraview-plugin: no VTKBloom.so was built in $build" >&2; exit 1; }
echo "build-paraview-plugin: $plugin"
