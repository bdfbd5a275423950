#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
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
#   bash scripts/test.sh --sid     VTK 9.6 and ParaView 6.1, stock, in a Debian sid root
#                                  (scripts/sid-root.sh makes it once and caches it): the
#                                  whole suite in build-sid/ with no display (VTK picks EGL),
#                                  the tests that need a window again through X under Xvfb,
#                                  then the ParaView 6.1 plugin in build-paraview-sid/ and its
#                                  tests. Not part of the default run; .ci/run runs it.
#   bash scripts/test.sh --deb     the Debian 12 packages: scripts/package-deb.sh builds them
#                                  into build-deb/, scripts/test-deb.sh installs them with apt
#                                  in a clean Debian 12 root (made once and cached) and runs
#                                  the tool, the Python package, a find_package(VTKBloom)
#                                  consumer, the ParaView plugin in pvbatch and lintian there.
#                                  `--deb --sid`: the same for Debian sid (build-deb-sid/), where
#                                  PyVista 0.49 finds plotter.bloom and pyvista.read('x.exr')
#                                  with no import of vtkbloom. .ci/run runs both.
#   bash scripts/test.sh --asan    AddressSanitizer + UndefinedBehaviorSanitizer build in
#                                  build-asan/ (system VTK, under Xvfb)
#   bash scripts/test.sh --valgrind the hostile-file tests (damaged corpus, hostile headers,
#                                  crafted files) and the tool on those files under valgrind's
#                                  memcheck, in the X11 leg's build/ (scripts/valgrind.sh)
#   bash scripts/test.sh --fuzz [S] the OpenEXR reader's libFuzzer target for S seconds
#                                  (default 120; scripts/fuzz.sh)
# Tests whose shared data (../shared/data) is missing are skipped, except under CI=true, where
# they fail.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
mode=${1:-all}
[ "$mode" = --in-sid-root ] || bash "$root/scripts/install-deps.sh"

# Fails unless every group of tests named (the start of a ctest name, after any
# parameterization prefix, as an extended regular expression) is in the build, and every
# GoogleTest test in Testing/ is too, unless Testing/ci-legs.txt says why this leg lacks it
# (scripts/lib/check-suites.py): a target that the configuration should have made but did not
# (a module not found, a condition gone wrong) would otherwise pass by not running. ctest
# itself runs with --no-tests=error.
require_tests() {
  local leg=$1 build=$2 group names missing=()
  shift 2
  names=$(ctest --test-dir "$build" -N | sed -n 's/^ *Test *#[0-9]*: //p')
  for group in "$@"; do
    grep -Eq "(^|/)$group" <<<"$names" || missing+=("$group")
  done
  if [ ${#missing[@]} -gt 0 ]; then
    echo "test: $build has no tests ${missing[*]}, which its configuration should have built" >&2
    exit 1
  fi
  /usr/bin/python3 "$root/scripts/lib/check-suites.py" "$leg" "$build"
}

# ctest for one leg (LEG BUILD [ARGS...]; LAUNCH=xvfb: under a private Xvfb; LAUNCH=headless:
# with no DISPLAY and no WAYLAND_DISPLAY), less the tests that Testing/ci-legs.txt says the legs
# against the same code run ('covered': x11 and sid run every test), then its JUnit report
# against the skips that the list allows the leg (scripts/lib/check-skips.py): a skip nobody
# listed fails the leg as a failure would.
# VTKBLOOM_EXPECT_COMPUTE=1: every leg's context (Mesa's llvmpipe: OpenGL 4.5) runs the bloom
# pass's compute shaders, and a test binary whose context does not fails before its tests.
run_ctest() {
  local leg=$1 build=$2 launch=()
  shift 2
  case ${LAUNCH:-} in
    xvfb) launch=(bash "$root/scripts/lib/with-xvfb.sh") ;;
    headless) launch=(env -u DISPLAY -u WAYLAND_DISPLAY) ;;
  esac
  local report covered
  report="$(cd "$build" && pwd)/Testing/junit-$leg.xml" # ctest reads a relative path from BUILD
  rm -f "$report"
  covered=$(/usr/bin/python3 "$root/scripts/lib/ci_legs.py" exclude "$leg")
  [ -z "$covered" ] || set -- "$@" -E "$covered"
  VTKBLOOM_EXPECT_COMPUTE=1 "${launch[@]}" ctest --test-dir "$build" --output-on-failure \
    --no-tests=error -j"$(nproc)" --output-junit "$report" "$@"
  /usr/bin/python3 "$root/scripts/lib/check-skips.py" "$leg" "$report"
}

# The groups every rendering build has (VTK with FreeType, annotations and widgets: Debian's,
# sid's and the cached OSMesa and EGL prefixes alike).
rendering_tests=('RenderingBloomPass[.]' 'RenderingBloomPassLight[.]' 'RenderingGallery[.]'
  'RenderingBloomPassTiles[.]' 'RenderingBloomPassMotion[.]' 'CommandLine[.]'
  'RenderingBloomPassCompute[.]InAnOpenGL33Context' 'RenderingBloomPassSoak[.]'
  'Rendering/RenderingGalleryRenderers[.]')
# The CPU suites every build has: the filters, the numerics, OpenEXR, the tool.
cpu_tests=('Filters' 'Numerics' 'Performance' 'OpenEXR' 'CommandLineFiles[.]' 'PresetExample[.]')
# And where the package is wrapped for Python (not in the sanitizer build, not in the cached
# prefixes' builds, whose VTK has no Python).
python_tests=('Python[.]vtkbloom' 'Python[.]arrays' 'Python[.]scene' 'Python[.]ParaViewXML'
  'Python[.]Recipe[.]' 'Python[.]ClientExamples[.]vedo' 'Docs[.]NamedPathsExist' 'Python[.]soak')

run_x11() {
  local build=$1 leg=x11
  shift
  bash "$root/scripts/configure.sh" "$build" "$@"
  local required=("${rendering_tests[@]}" "${cpu_tests[@]}")
  if grep -q '^VTKBLOOM_ENABLE_SANITIZERS:BOOL=ON' "$build/CMakeCache.txt"; then
    leg=asan
  else
    required+=("${python_tests[@]}")
  fi
  require_tests "$leg" "$build" "${required[@]}"
  echo "test: running the suite against the system VTK (X11, private Xvfb)"
  LAUNCH=xvfb run_ctest "$leg" "$build"
}

# The headless legs: the suite against Debian's VTK built for osmesa or egl (no X at all).
run_headless() {
  local backend=$1 prefix
  prefix=$(bash "$root/scripts/build-$backend-vtk.sh" | tail -n 1)
  # No Python wrapping: these VTKs are built without it (the X11 leg covers Python).
  bash "$root/scripts/configure.sh" "$root/build-$backend" -DCMAKE_BUILD_TYPE=Release \
    -DVTKBLOOM_WARNINGS_AS_ERRORS=ON -DVTKBLOOM_WRAP_PYTHON=OFF \
    -DVTK_DIR="$prefix/lib/cmake/vtk-9.1"
  require_tests "$backend" "$root/build-$backend" "${rendering_tests[@]}" "${cpu_tests[@]}"
  echo "test: running the suite against the ${backend^^} VTK (no DISPLAY, no X server)"
  LAUNCH=headless run_ctest "$backend" "$root/build-$backend"
}

# The ParaView plugin against Debian's ParaView 5.11 (its VTK 9.2): build it, then run its
# pvbatch tests, compared with the X11 leg's build (ParaView/Testing/run_tests.py).
run_paraview() {
  bash "$root/scripts/build-paraview-plugin.sh" "$root/build-paraview"
  echo "test: running the ParaView plugin's tests (pvbatch, 1 to 4 MPI ranks)"
  /usr/bin/python3 "$root/ParaView/Testing/run_tests.py" "$root/build" \
    "$root/build-paraview/Testing"
}

# VTK 9.6 and ParaView 6.1: the same steps as the legs above, run inside the sid root
# (test.sh --in-sid-root), in build folders of their own.
run_sid() {
  bash "$root/scripts/sid-root.sh" bash "$root/scripts/test.sh" --in-sid-root
}

run_in_sid_root() {
  bash "$root/scripts/configure.sh" "$root/build-sid" -DCMAKE_BUILD_TYPE=Release \
    -DVTKBLOOM_WARNINGS_AS_ERRORS=ON
  # sid has PyVista 0.49 and vedo 2026: their tests and recipes are built there.
  require_tests sid "$root/build-sid" "${rendering_tests[@]}" "${cpu_tests[@]}" "${python_tests[@]}" \
    'Python[.]pyvista' 'Python[.]pyvista[.]plugin' 'Python[.]Recipe[.]pyvista' 'Python[.]Recipe[.]vedo' \
    'Python[.]ClientExamples[.]pyvista'
  echo "test: running the suite against VTK 9.6 (no DISPLAY: VTK chooses EGL)"
  LAUNCH=headless run_ctest sid "$root/build-sid"
  echo "test: the sid leg (its build included) took $SECONDS s"
  local start=$SECONDS
  echo "test: the tests that open a window, again against VTK 9.6 through X (private Xvfb)"
  /usr/bin/python3 "$root/scripts/lib/check-suites.py" sid-x "$root/build-sid"
  LAUNCH=xvfb run_ctest sid-x "$root/build-sid" -R '^(Rendering|CommandLineData[.]View)'
  echo "test: the sid-x leg took $((SECONDS - start)) s"
  start=$SECONDS
  bash "$root/scripts/build-paraview-plugin.sh" "$root/build-paraview-sid"
  echo "test: running the ParaView 6.1 plugin's tests (pvbatch, 1 to 4 MPI ranks)"
  VTKBLOOM_PARAVIEW_BUILD="$root/build-paraview-sid" /usr/bin/python3 \
    "$root/ParaView/Testing/run_tests.py" "$root/build-sid" "$root/build-paraview-sid/Testing"
  echo "test: the ParaView 6.1 leg took $((SECONDS - start)) s"
}

case "$mode" in
  all)
    run_x11 "$root/build" -DCMAKE_BUILD_TYPE=Release -DVTKBLOOM_WARNINGS_AS_ERRORS=ON
    echo "test: the X11 leg took $SECONDS s"
    start=$SECONDS
    run_paraview
    echo "test: the ParaView 5.11 leg took $((SECONDS - start)) s"
    start=$SECONDS
    run_headless osmesa
    echo "test: the OSMesa leg took $((SECONDS - start)) s (the VTK it builds on first use included)"
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
  --sid)
    run_sid
    ;;
  --in-sid-root)
    run_in_sid_root
    ;;
  --deb)
    case ${2:-} in
      '' | --sid) ;;
      *) echo "usage: bash scripts/test.sh --deb [--sid]" >&2; exit 2 ;;
    esac
    bash "$root/scripts/package-deb.sh" ${2:-}
    bash "$root/scripts/test-deb.sh" ${2:-}
    ;;
  --asan)
    export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
    export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
    export LSAN_OPTIONS="suppressions=$root/Testing/lsan.supp:print_suppressions=0"
    # Debug information holds the build's absolute paths, so ccache keys such objects by the
    # directory they were built in (its hash_dir), and a fresh clone (CI's) would rebuild all
    # 250 of them (about 16 minutes here). Written relative to the checkout, they are the same
    # objects in every clone, and ccache finds them.
    prefix_map="-fdebug-prefix-map=$root=."
    run_x11 "$root/build-asan" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DVTKBLOOM_ENABLE_SANITIZERS=ON \
      "-DCMAKE_C_FLAGS=$prefix_map" "-DCMAKE_CXX_FLAGS=$prefix_map"
    ;;
  --valgrind)
    bash "$root/scripts/configure.sh" "$root/build" -DCMAKE_BUILD_TYPE=Release \
      -DVTKBLOOM_WARNINGS_AS_ERRORS=ON
    bash "$root/scripts/valgrind.sh" "$root/build"
    ;;
  --fuzz)
    bash "$root/scripts/fuzz.sh" "${2:-120}"
    ;;
  *)
    echo "usage: bash scripts/test.sh [--x11 | --paraview | --osmesa | --egl | --sid | --deb [--sid] | --asan | --valgrind | --fuzz [SECONDS]]" >&2
    exit 2
    ;;
esac
