#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
# The README's ParaView screenshot: the GUI under a private Xvfb, with the plugin loaded and
# ParaView/Examples/gui_scene.py run at start-up, captured as a PNG:
#
#   bash scripts/paraview-screenshot.sh [OUT.png]   (default: docs/images/paraview-gui.png)
#
# Needs xwd (x11-apps) and netpbm, which it installs, and the plugin (built if missing).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
out=${1:-$root/docs/images/paraview-gui.png}
for p in x11-apps netpbm; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" ||
    DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "$p" >&2
done
plugins=$root/build-paraview/lib/paraview-5.11/plugins/VTKBloom
[ -f "$plugins/VTKBloom.so" ] || bash "$root/scripts/build-paraview-plugin.sh" >&2
export PV_PLUGIN_PATH=$plugins
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cat >"$tmp/capture.sh" <<'CAPTURE'
set -u
# --dr: no saved settings are read or written, and no welcome dialog covers the window.
paraview --dr -qwindowgeometry "${VTKBLOOM_SCREENSHOT_GEOMETRY:-1400x860+0+0}" --script="$1" >"$3/paraview.log" 2>&1 &
gui=$!
sleep "${VTKBLOOM_SCREENSHOT_WAIT:-25}"
xwd -root -silent | xwdtopnm 2>/dev/null | pnmcut -left 0 -top 0 -width 1400 -height 860 | pnmtopng >"$2"
kill "$gui" 2>/dev/null
wait "$gui" 2>/dev/null
grep -i -E "error|traceback" "$3/paraview.log" >&2 || true
exit 0
CAPTURE
bash "$root/scripts/lib/paraview-env.sh" bash "$root/scripts/lib/with-xvfb.sh" \
  bash "$tmp/capture.sh" "$root/ParaView/Examples/gui_scene.py" "$out" "$tmp"
echo "paraview-screenshot: $out"
