#!/usr/bin/env bash
# Run a command with DISPLAY set to a private Xvfb server, started here and stopped afterwards.
#   scripts/lib/with-xvfb.sh COMMAND [ARGS...]
# The system VTK 9.1 renders through X (GLX) only; the OSMesa build needs no display at all.
set -euo pipefail
display=""
for n in $(seq 91 140); do
  if [ ! -e "/tmp/.X11-unix/X$n" ] && [ ! -e "/tmp/.X$n-lock" ]; then
    display=$n
    break
  fi
done
[ -n "$display" ] || { echo "with-xvfb: no free display number" >&2; exit 1; }
Xvfb ":$display" -screen 0 "${VTKBLOOM_XVFB_SCREEN:-1920x1200x24}" -nolisten tcp -noreset >/dev/null 2>&1 &
xvfb_pid=$!
trap 'kill "$xvfb_pid" 2>/dev/null || true; wait "$xvfb_pid" 2>/dev/null || true' EXIT
for _ in $(seq 1 100); do
  [ -e "/tmp/.X11-unix/X$display" ] && break
  kill -0 "$xvfb_pid" 2>/dev/null || { echo "with-xvfb: Xvfb :$display failed to start" >&2; exit 1; }
  sleep 0.1
done
DISPLAY=":$display" "$@"
