#!/usr/bin/env bash
# Install what vtk-bloom needs, build it, and run the whole test suite.
#   bash scripts/test.sh          release build in build/
#   bash scripts/test.sh --asan   AddressSanitizer + UndefinedBehaviorSanitizer build in build-asan/
# Tests whose shared data (../shared/data) is missing are skipped, except under CI=true, where
# they fail.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$root/scripts/install-deps.sh"

build="$root/build"
args=(-DCMAKE_BUILD_TYPE=Release -DVTKBLOOM_WARNINGS_AS_ERRORS=ON)
if [ "${1:-}" = "--asan" ]; then
  build="$root/build-asan"
  args=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DVTKBLOOM_ENABLE_SANITIZERS=ON)
  export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
  export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
fi
bash "$root/scripts/configure.sh" "$build" "${args[@]}"
ctest --test-dir "$build" --output-on-failure -j"$(nproc)"
