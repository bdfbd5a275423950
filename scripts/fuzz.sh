#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
# Fuzz vtkOpenEXRReader with libFuzzer (clang from Debian's toolchain) under AddressSanitizer
# and UBSan for a bounded time.
#   bash scripts/fuzz.sh [SECONDS]      default 120
# The corpus starts from ../shared/data/exr (valid files and the Damaged/ fuzzer cases) and the
# hostile headers of the test suite (Testing/Support/vtkBloomHostileEXR.cxx); it grows in
# build-fuzz/corpus, which later runs reuse. Each input must finish within 5 s and 1 GB (the
# sanitizers' own overhead included). Findings are written to build-fuzz/findings and fail the
# script.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
seconds=${1:-120}
build=$root/build-fuzz

packages=(clang libclang-rt-14-dev)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  echo "fuzz: installing ${missing[*]}"
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

launcher=()
command -v ccache >/dev/null 2>&1 && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S "$root/Testing/Fuzz" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ "${launcher[@]}" >/dev/null
cmake --build "$build" -- -j"$(nproc)"

seeds=$build/seeds
rm -rf "$seeds"
mkdir -p "$seeds" "$build/corpus" "$build/findings"
data=$root/../shared/data/exr
if [ -d "$data" ]; then
  find "$data" -type f ! -name '*.rst' ! -name LICENSE -size -4M -exec cp {} "$seeds/" \;
elif [ "${CI:-}" = "true" ]; then
  echo "fuzz: shared test data missing under CI: $data" >&2
  exit 1
fi
"$build/MakeHostileEXR" "$seeds/hostile"
mv "$seeds"/hostile/* "$seeds/" && rmdir "$seeds/hostile"
# The crafted DWA, tiled and luminance/chroma files, and the sound files they come from.
cp "$root"/Testing/Data/EXR/Crafted/*.exr "$seeds/"
for f in "$root"/Testing/Data/EXR/Crafted/valid/*.exr; do cp "$f" "$seeds/valid-$(basename "$f")"; done
echo "fuzz: $(ls "$seeds" | wc -l) seed files, $(ls "$build/corpus" | wc -l) in the corpus," \
  "running for ${seconds} s"

export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:allocator_may_return_null=1
export LSAN_OPTIONS="suppressions=$root/Testing/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
cd "$build"
status=0
./FuzzOpenEXRReader "$build/corpus" "$seeds" -max_total_time="$seconds" -timeout=5 \
  -rss_limit_mb=1024 -malloc_limit_mb=1024 -artifact_prefix="$build/findings/" \
  -print_final_stats=1 2>&1 | grep -vE '^#[0-9]+\s+(NEW|REDUCE|pulse)' || status=$?
findings=$(ls "$build/findings" | wc -l)
echo "fuzz: corpus $(ls "$build/corpus" | wc -l) files, findings: $findings"
if [ "$findings" -gt 0 ] || [ "$status" -ne 0 ]; then
  echo "fuzz: FAILED (exit $status); reproduce with $build/FuzzOpenEXRReader $build/findings/<file>" >&2
  exit 1
fi
