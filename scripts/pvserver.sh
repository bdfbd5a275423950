#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
# Run a pvpython client script against a pvserver of N ranks with the vtk-bloom plugin loaded,
# on this machine only:
#
#   bash scripts/pvserver.sh -n N SCRIPT.py [ARGS...]
#
# SCRIPT.py receives `--server PORT` first. The server and the client run in a network
# namespace of their own whose only interface is the loopback (unshare -n), so the server is
# reachable from nowhere else; ParaView/Testing/client_server.py starts the server, waits for
# it, runs the client and stops the server, every wait bounded. The plugin comes from the build
# that scripts/pvbatch.sh uses ($VTKBLOOM_PARAVIEW_BUILD, default build-paraview).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
ranks=1
if [ "${1:-}" = -n ]; then ranks=$2; shift 2; fi
[ $# -ge 1 ] || { echo "usage: pvserver.sh [-n N] SCRIPT.py [ARGS...]" >&2; exit 2; }
build=${VTKBLOOM_PARAVIEW_BUILD:-$root/build-paraview}
plugin=$(ls "$build"/lib/paraview-*/plugins/VTKBloom/VTKBloom.so 2>/dev/null | head -n 1)
[ -n "$plugin" ] || bash "$root/scripts/build-paraview-plugin.sh" "$build" >&2
plugin=$(ls "$build"/lib/paraview-*/plugins/VTKBloom/VTKBloom.so | head -n 1)
export PV_PLUGIN_PATH=$(dirname "$plugin")${PV_PLUGIN_PATH:+:$PV_PLUGIN_PATH}
export OMPI_MCA_btl=self,vader
# ParaView 5.11 renders through X only: a private Xvfb, started inside the namespace.
xvfb=()
case $plugin in
  */paraview-5.*) xvfb=(bash "$root/scripts/lib/with-xvfb.sh") ;;
esac
exec bash "$root/scripts/lib/paraview-env.sh" unshare -n "${xvfb[@]}" \
  /usr/bin/python3 "$root/ParaView/Testing/client_server.py" "$ranks" "$@"
