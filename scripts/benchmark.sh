#!/usr/bin/env bash
# The chain speed suite of issue 5 in one command:
#   bash scripts/benchmark.sh [extra Google Benchmark arguments, e.g. --benchmark_min_time=2]
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
"$build/bin/BloomChainSpeed" --benchmark_min_time=1 "$@" | tee "$build/benchmark.txt"
