#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
# The chain speed suite of issue 5 in one command:
#   bash scripts/benchmark.sh [extra Google Benchmark arguments, e.g. --benchmark_repetitions=9]
# Installs OpenCV's imgproc (benchmark-only; the build and the tests never need it), builds
# Release into build-bench/ and runs BloomChainSpeed, which prints every row and then the
# summary table (ratios, bandwidth bound, peak extra memory, sparse scenes) that README.md quotes.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${VTKBLOOM_BENCH_BUILD:-$root/build-bench}
if ! dpkg -s libopencv-imgproc-dev >/dev/null 2>&1 || ! dpkg -s libbenchmark-dev >/dev/null 2>&1; then
  sudo=""
  [ "$(id -u)" -ne 0 ] && sudo=sudo
  $sudo apt-get update
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y --no-install-recommends \
    libopencv-imgproc-dev libbenchmark-dev
fi
bash "$root/scripts/configure.sh" "$build" -DCMAKE_BUILD_TYPE=Release
cmake --build "$build" --target BloomChainSpeed
# Large allocations go to transparent huge pages (glibc 2.35+; a no-op elsewhere). Every row
# that allocates a frame-sized buffer per run (the OpenCV and stock-VTK chains do) would otherwise
# also measure the kernel's 4 KiB page faults, which cost about 11 us each on some virtual
# machines (400 ms for a 2160p frame). A GLIBC_TUNABLES already set is kept.
export GLIBC_TUNABLES=${GLIBC_TUNABLES:-glibc.malloc.hugetlb=1}
echo "benchmark: GLIBC_TUNABLES=$GLIBC_TUNABLES"
# Five repetitions of every row, shuffled across rows (random interleaving), each row's time the
# median: load from elsewhere on a shared machine then moves single samples, not whole rows.
"$build/bin/BloomChainSpeed" --benchmark_min_time=0.5 --benchmark_repetitions=5 \
  --benchmark_enable_random_interleaving=true "$@" |
  tee "$build/benchmark.txt"
