#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
# Run a Python script in ParaView's pvbatch with the vtk-bloom plugin loaded:
#
#   bash scripts/pvbatch.sh [-n N] SCRIPT.py [ARGS...]
#
# With N > 1 (default 1) pvbatch runs under `mpiexec -n N`: the pipeline is distributed over
# N ranks and rendering is composited with IceT. The script runs on rank 0 and sees the
# plugin's proxies through paraview.simple: Bloom, SeparableGaussian, BrightPass, PyramidDown,
# PyramidUp, the OpenEXR reader and writer, and the BloomRenderView view.
#
# The plugin is built first if it is missing (scripts/build-paraview-plugin.sh; set
# VTKBLOOM_PARAVIEW_BUILD for another build directory). Debian's ParaView renders through X
# only, so without DISPLAY the run gets a private Xvfb (scripts/lib/with-xvfb.sh). The exit status
# is pvbatch's (mpiexec's).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
ranks=1
if [ "${1:-}" = "-n" ]; then
  ranks=${2:?"pvbatch.sh: -n needs a number of ranks"}
  shift 2
fi
case $ranks in
  '' | *[!0-9]* | 0) echo "pvbatch.sh: -n needs a positive number of ranks, not '$ranks'" >&2; exit 2 ;;
esac
[ $# -ge 1 ] || { echo "usage: pvbatch.sh [-n N] SCRIPT.py [ARGS...]" >&2; exit 2; }

build=${VTKBLOOM_PARAVIEW_BUILD:-$root/build-paraview}
plugin() { ls "$build"/lib/paraview-*/plugins/VTKBloom/VTKBloom.so 2>/dev/null | head -n 1; }
if [ -z "$(plugin)" ]; then
  bash "$root/scripts/build-paraview-plugin.sh" "$build" >&2
fi
plugins=$(dirname "$(plugin)")

export PV_PLUGIN_PATH=$plugins${PV_PLUGIN_PATH:+:$PV_PLUGIN_PATH}
run=(pvbatch)
[ "$ranks" -gt 1 ] && run=(mpiexec -n "$ranks" "${run[@]}")
# ParaView 5.11 renders through X only; ParaView 6 (VTK 9.6) falls back to EGL with no display.
xvfb=()
case $plugins in
  */paraview-5.*) [ -n "${DISPLAY:-}" ] || xvfb=(bash "$root/scripts/lib/with-xvfb.sh") ;;
esac
# Open MPI's shared-memory transport needs no network; keep it off the host's interfaces.
export OMPI_MCA_btl=self,vader
exec bash "$root/scripts/lib/paraview-env.sh" "${xvfb[@]}" "${run[@]}" "$@"
