#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
# Run a command with DISPLAY set to a private Xvfb server, started here and stopped afterwards.
#   scripts/lib/with-xvfb.sh COMMAND [ARGS...]
# The system VTK 9.1 renders through X (GLX) only; the OSMesa build needs no display at all.
set -euo pipefail
# Xvfb chooses the display number itself (-displayfd) and writes it once it accepts clients:
# two runs started together (CI's legs) can never take the same number, as they could when
# this script tested for a free one and then started a server on it.
number_file=$(mktemp)
xvfb_pid=""
cleanup() {
  [ -n "$xvfb_pid" ] && { kill "$xvfb_pid" 2>/dev/null || true; wait "$xvfb_pid" 2>/dev/null || true; }
  rm -f "$number_file"
}
trap cleanup EXIT
exec {number_fd}>"$number_file"
Xvfb -displayfd "$number_fd" -screen 0 "${VTKBLOOM_XVFB_SCREEN:-1920x1200x24}" -nolisten tcp \
  -noreset >/dev/null 2>&1 &
xvfb_pid=$!
exec {number_fd}>&-
display=""
for _ in $(seq 1 200); do # 20 s at most
  if [ "$(wc -l <"$number_file")" -gt 0 ]; then
    display=$(head -n 1 "$number_file" | tr -dc '0-9')
    break
  fi
  kill -0 "$xvfb_pid" 2>/dev/null || break
  sleep 0.1
done
[ -n "$display" ] || { echo "with-xvfb: Xvfb did not start within 20 s (is it installed?)" >&2; exit 1; }
DISPLAY=":$display" "$@"
