#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
# Run a command with DISPLAY set to a private Xvfb server, started here and stopped afterwards.
#   scripts/lib/with-xvfb.sh COMMAND [ARGS...]
# The system VTK 9.1 renders through X (GLX) only; the OSMesa build needs no display at all.
set -euo pipefail
# The first free display number that starts: another Xvfb (a concurrent run) may take a free
# number between the check and the start, so a failed start moves on to the next one.
display=""
for n in $(seq 91 140); do
  if [ -e "/tmp/.X11-unix/X$n" ] || [ -e "/tmp/.X$n-lock" ]; then
    continue
  fi
  Xvfb ":$n" -screen 0 "${VTKBLOOM_XVFB_SCREEN:-1920x1200x24}" -nolisten tcp -noreset \
    >/dev/null 2>&1 &
  xvfb_pid=$!
  for _ in $(seq 1 100); do
    if [ -e "/tmp/.X11-unix/X$n" ] && kill -0 "$xvfb_pid" 2>/dev/null; then
      display=$n
      break
    fi
    kill -0 "$xvfb_pid" 2>/dev/null || break
    sleep 0.1
  done
  [ -n "$display" ] && break
  kill "$xvfb_pid" 2>/dev/null || true
  wait "$xvfb_pid" 2>/dev/null || true
done
[ -n "$display" ] || { echo "with-xvfb: no display number from 91 to 140 would start Xvfb" >&2; exit 1; }
trap 'kill "$xvfb_pid" 2>/dev/null || true; wait "$xvfb_pid" 2>/dev/null || true' EXIT
DISPLAY=":$display" "$@"
