#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
# The command-line tool against its I/O, side by side with OpenImageIO's oiiotool, in one run:
#   bash scripts/benchmark-cli.sh [REPETITIONS]        default 9
# Installs openimageio-tools (benchmark-only), builds Release into build-bench/ (shared with
# scripts/benchmark.sh), makes a 1920x1080 float RGBA ZIP EXR from ScanLines_CandleGlass.exr
# (oiiotool --resize), and times, interleaved in a shuffled order, each repetition:
#   oiiotool IN -o OUT                     the peer: a decode and an encode of the same file
#   vtk-bloom blur --radius 0 IN OUT       the tool's copy (read, identity filter, write)
#   vtk-bloom image IN OUT                 the default bloom (FAST chain)
#   vtk-bloom image --threshold 1e6 ...    a frame with nothing above the threshold
#   vtk-bloom image --exact IN OUT         the REFERENCE (double) chain
# and prints each row's median wall time and the ratios the issue asks for. Run it on a quiet
# machine; compare ratios within one run.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${VTKBLOOM_BENCH_BUILD:-$root/build-bench}
repetitions=${1:-9}
if ! command -v oiiotool >/dev/null 2>&1; then
  sudo=""
  [ "$(id -u)" -ne 0 ] && sudo=sudo
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q --no-install-recommends \
    openimageio-tools
fi
bash "$root/scripts/install-deps.sh" >/dev/null
bash "$root/scripts/configure.sh" "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" --target vtk-bloom >/dev/null

work=$build/cli-benchmark
mkdir -p "$work"
source_image=$root/../shared/data/exr/ScanLines_CandleGlass.exr
if [ ! -f "$source_image" ]; then
  echo "benchmark-cli: $source_image is missing (../shared/data)" >&2
  exit 1
fi
oiiotool "$source_image" --resize 1920x1080 -d float --compression zip -o "$work/in.exr"

/usr/bin/python3 - "$work" "$build/bin/vtk-bloom" "$repetitions" <<'PY'
import os, random, statistics, subprocess, sys, time
work, tool, repetitions = sys.argv[1], sys.argv[2], int(sys.argv[3])
inp = os.path.join(work, "in.exr")
rows = {
    "oiiotool copy": ["oiiotool", inp, "-o", os.path.join(work, "oiio.exr")],
    "vtk-bloom blur --radius 0": [tool, "blur", "--radius", "0", "--quiet", inp,
                                  os.path.join(work, "copy.exr")],
    "vtk-bloom image": [tool, "image", "--quiet", inp, os.path.join(work, "bloom.exr")],
    "vtk-bloom image, nothing above the threshold": [
        tool, "image", "--threshold", "1e6", "--quiet", inp, os.path.join(work, "dark.exr")],
    "vtk-bloom image --exact": [tool, "image", "--exact", "--quiet", inp,
                                os.path.join(work, "exact.exr")],
}
times = {name: [] for name in rows}
for name, command in rows.items():  # one warm-up run each (page cache, libraries)
    subprocess.run(command, check=True)
for _ in range(repetitions):
    order = list(rows)
    random.shuffle(order)
    for name in order:
        start = time.perf_counter()
        subprocess.run(rows[name], check=True)
        times[name].append(time.perf_counter() - start)
median = {name: statistics.median(t) for name, t in times.items()}
copy = median["vtk-bloom blur --radius 0"]
print(f"1920x1080 float RGBA ZIP EXR ({os.path.getsize(inp) / 1e6:.1f} MB), "
      f"median of {repetitions} interleaved runs, {os.cpu_count()} cores")
print()
print("| command | median (s) | ratio | target |")
print("|---|---:|---:|---|")
targets = {
    "oiiotool copy": ("", ""),
    "vtk-bloom blur --radius 0": (f"{copy / median['oiiotool copy']:.2f}x oiiotool", "<= 1x oiiotool"),
    "vtk-bloom image": (f"{median['vtk-bloom image'] / copy:.2f}x the copy", "<= 1.3x the copy"),
    "vtk-bloom image, nothing above the threshold": (
        f"{median['vtk-bloom image, nothing above the threshold'] / copy:.2f}x the copy",
        "<= 1.1x the copy"),
    "vtk-bloom image --exact": (f"{median['vtk-bloom image --exact'] / copy:.2f}x the copy", ""),
}
for name in rows:
    ratio, target = targets[name]
    print(f"| `{name}` | {median[name]:.3f} | {ratio} | {target} |")
PY
