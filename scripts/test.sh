#!/usr/bin/env bash
# Install what vtk-bloom needs, build it, and run the whole test suite.
#   bash scripts/test.sh           both backends and the ParaView plugin: the system VTK 9.1 (X11)
#                                  in build/, run under a private Xvfb; the ParaView plugin in
#                                  build-paraview/, its serial and MPI tests (1 to 4 ranks) under
#                                  pvbatch; then the OSMesa VTK (built from Debian's source on
#                                  first use, see scripts/build-osmesa-vtk.sh) in build-osmesa/,
#                                  run with no display at all
#   bash scripts/test.sh --x11     only the system-VTK leg
#   bash scripts/test.sh --paraview only the ParaView leg (needs the X11 leg's build/ for the
#                                  vtk-bloom tool and Python package it compares against)
#   bash scripts/test.sh --osmesa  only the OSMesa leg
#   bash scripts/test.sh --egl     the EGL VTK (built from Debian's source on first use, see
#                                  scripts/build-egl-vtk.sh) in build-egl/, run with no display
#                                  through whichever EGL driver the machine has: Mesa's
#                                  (llvmpipe) on a machine with no GPU. Not part of the default
#                                  run.
#   bash scripts/test.sh --asan    AddressSanitizer + UndefinedBehaviorSanitizer build in
#                                  build-asan/ (system VTK, under Xvfb)
#   bash scripts/test.sh --fuzz [S] the OpenEXR reader's libFuzzer target for S seconds
#                                  (default 120; scripts/fuzz.sh)
# Tests whose shared data (../shared/data) is missing are skipped, except under CI=true, where
# they fail.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$root/scripts/install-deps.sh"
mode=${1:-all}

run_x11() {
  local build=$1
  shift
  bash "$root/scripts/configure.sh" "$build" "$@"
  echo "test: running the suite against the system VTK (X11, private Xvfb)"
  bash "$root/scripts/with-xvfb.sh" ctest --test-dir "$build" --output-on-failure -j"$(nproc)"
}

# The headless legs: the suite against Debian's VTK built for osmesa or egl (no X at all).
run_headless() {
  local backend=$1 prefix
  prefix=$(bash "$root/scripts/build-$backend-vtk.sh" | tail -n 1)
  # No Python wrapping: these VTKs are built without it (the X11 leg covers Python).
  bash "$root/scripts/configure.sh" "$root/build-$backend" -DCMAKE_BUILD_TYPE=Release \
    -DVTKBLOOM_WARNINGS_AS_ERRORS=ON -DVTKBLOOM_WRAP_PYTHON=OFF \
    -DVTK_DIR="$prefix/lib/cmake/vtk-9.1"
  echo "test: running the suite against the ${backend^^} VTK (no DISPLAY, no X server)"
  env -u DISPLAY -u WAYLAND_DISPLAY ctest --test-dir "$root/build-$backend" --output-on-failure \
    -j"$(nproc)"
}

# The ParaView plugin against Debian's ParaView 5.11 (its VTK 9.2): build it, then run its
# pvbatch tests, compared with the X11 leg's build (ParaView/Testing/run_tests.py).
run_paraview() {
  bash "$root/scripts/build-paraview-plugin.sh" "$root/build-paraview"
  echo "test: running the ParaView plugin's tests (pvbatch, 1 to 4 MPI ranks)"
  /usr/bin/python3 "$root/ParaView/Testing/run_tests.py" "$root/build" \
    "$root/build-paraview/Testing"
}

case "$mode" in
  all)
    run_x11 "$root/build" -DCMAKE_BUILD_TYPE=Release -DVTKBLOOM_WARNINGS_AS_ERRORS=ON
    run_paraview
    run_headless osmesa
    ;;
  --paraview)
    run_paraview
    ;;
  --x11)
    run_x11 "$root/build" -DCMAKE_BUILD_TYPE=Release -DVTKBLOOM_WARNINGS_AS_ERRORS=ON
    ;;
  --osmesa)
    run_headless osmesa
    ;;
  --egl)
    run_headless egl
    ;;
  --asan)
    export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
    export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
    export LSAN_OPTIONS="suppressions=$root/Testing/lsan.supp:print_suppressions=0"
    run_x11 "$root/build-asan" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DVTKBLOOM_ENABLE_SANITIZERS=ON
    ;;
  --fuzz)
    bash "$root/scripts/fuzz.sh" "${2:-120}"
    ;;
  *)
    echo "usage: bash scripts/test.sh [--x11 | --paraview | --osmesa | --egl | --asan | --fuzz [SECONDS]]" >&2
    exit 2
    ;;
esac
