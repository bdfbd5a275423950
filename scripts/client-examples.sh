#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
# The clients' own examples through vtkbloom.add_bloom at the defaults (issue 48, part 4):
#
#   bash scripts/client-examples.sh [OPTIONS]        vedo 2023.4 on Debian 12 (VTK 9.1, Xvfb)
#   bash scripts/client-examples.sh --sid [OPTIONS]  PyVista 0.49 and vedo 2026.6 in the sid
#                                                    root (VTK 9.6, EGL; scripts/sid-root.sh)
#
# OPTIONS go to Testing/Python/client_examples.py: --client pyvista|vedo (default: vedo on the
# host, both in sid), --sample N or --all (default: a sample of 100 of PyVista's docstrings,
# every vedo example), --seed S, --check (exit 1 when a target is missed), --only NAME...
# Each example runs in a subprocess of its own, one at a time, niced: at each show() the plain
# frame is grabbed twice, then bloomed (see the harness's docstring). The results are in
# build/client-examples/CLIENT-VERSION/ (sid: build-sid/...): summary.md, results.json, the
# images of the frames that differ, and each run's log. A sweep of every vedo example takes
# about 15 to 30 minutes on two cores, PyVista's sample of 100 about 8.
#
# The package is taken from build/ (sid: build-sid/), as built by scripts/test.sh; --build
# brings that build up to date first (cmake --build), and a build folder without it is
# configured and built (scripts/configure.sh).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
where=host
build_first=no
args=()
clients=()
while [ $# -gt 0 ]; do
  case "$1" in
    --sid) where=sid ;;
    --in-sid-root) where=in-sid-root ;;
    --build) build_first=yes ;;
    --client) clients+=("$2"); shift ;;
    --client=*) clients+=("${1#--client=}") ;;
    *) args+=("$1") ;;
  esac
  shift
done
client_args=()
for c in "${clients[@]}"; do client_args+=(--client "$c"); done
[ "$build_first" = yes ] && client_args+=(--build)

if [ "$where" = sid ]; then
  exec bash "$root/scripts/sid-root.sh" bash "$root/scripts/client-examples.sh" --in-sid-root \
    "${client_args[@]}" "${args[@]}"
fi

if [ "$where" = host ]; then
  build=$root/build
  python=/usr/bin/python3 # Debian's, with python3-vtk9 (not a pyenv python3 first on PATH)
  [ ${#clients[@]} -gt 0 ] || clients=(vedo)
  run=(bash "$root/scripts/lib/with-xvfb.sh") # VTK 9.1 renders through X only
  # Xvfb, python3-vedo and its examples come with the project's dependencies.
  if ! command -v Xvfb >/dev/null 2>&1 || ! dpkg -s python3-vedo-examples >/dev/null 2>&1; then
    bash "$root/scripts/install-deps.sh"
  fi
else
  build=$root/build-sid
  python=python3
  [ ${#clients[@]} -gt 0 ] || clients=(pyvista vedo)
  run=(env -u DISPLAY -u WAYLAND_DISPLAY) # no X in the root: VTK 9.6 picks EGL
fi

package=$build/lib/python3/dist-packages
if [ ! -d "$package/vtkbloom" ]; then
  extra=()
  [ "$where" = in-sid-root ] && extra=(-DCMAKE_BUILD_TYPE=Release)
  bash "$root/scripts/configure.sh" "$build" "${extra[@]}"
elif [ "$build_first" = yes ]; then
  cmake --build "$build" -- -j"$(nproc)"
fi

status=0
for client in "${clients[@]}"; do
  version=$("$python" -c "import $client; print($client.__version__)")
  out=$build/client-examples/$client-$version
  echo "client-examples: $client $version -> $out" >&2
  start=$(date +%s)
  PYTHONPATH=$package nice -n 10 "${run[@]}" "$python" \
    "$root/Testing/Python/client_examples.py" --client "$client" --out "$out" "${args[@]}" ||
    status=$?
  echo "client-examples: $client $version took $(($(date +%s) - start)) s" >&2
done
exit $status
