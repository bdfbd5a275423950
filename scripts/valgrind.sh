#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
# The hostile-file tests under valgrind's memcheck, which reports reads of uninitialised memory
# (AddressSanitizer does not): the OpenEXR reader's suites on the damaged corpus, the generated
# hostile headers and the crafted files, then the vtk-bloom tool as the report that found
# stale heap bytes in written images ran it, on every one of those files that it reads and one
# in eight of those it refuses. Any memcheck report fails the script; leaks are left to the
# ASan leg.
#
#   bash scripts/valgrind.sh [BUILD]     BUILD: a configured and built tree (default build/)
#
# Run by `bash scripts/test.sh --valgrind` (CI's Debian 12 leg).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${1:-$root/build}
jobs=$(nproc)
work=$build/valgrind
rm -rf "$work"
mkdir -p "$work/logs" "$work/out" "$work/files/hostile"
memcheck=(valgrind --tool=memcheck --error-exitcode=99 --leak-check=no --num-callers=30 --quiet)
start=$SECONDS

echo "valgrind: the reader's suites (damaged corpus, hostile headers, crafted files)"
# (No --track-origins: its shadow memory would break the suites' own 256 MB bound; a report
# is then rerun by hand with it.) Memcheck runs a process on one core: each suite runs as two
# GoogleTest shards (each has tests in both), $jobs processes at a time.
shards=2
run_shard() {
  local suite=$1 shard=$2 name="$1.$2"
  if ! GTEST_TOTAL_SHARDS=$shards GTEST_SHARD_INDEX=$shard "${memcheck[@]}" \
    --log-file="$work/logs/$name.txt" "$build/bin/$suite" >"$work/logs/$name.out" 2>&1; then
    echo "valgrind: $suite (shard $shard of $shards) failed or memcheck reported errors:" >&2
    cat "$work/logs/$name.txt" >&2
    tail -n 30 "$work/logs/$name.out" >&2
    return 1
  fi
  # Every test ran: a skip here (missing data, say) would leave memcheck nothing to check.
  if grep -q '^\[  SKIPPED \]' "$work/logs/$name.out" ||
    ! grep -q '^\[  PASSED  \] [1-9]' "$work/logs/$name.out"; then
    echo "valgrind: $suite (shard $shard of $shards) skipped tests or ran none:" >&2
    grep -E '^\[  (SKIPPED|PASSED) ' "$work/logs/$name.out" >&2 || true
    return 1
  fi
}
export -f run_shard
export work build shards
export MEMCHECK="${memcheck[*]}"
# shellcheck disable=SC2016
for suite in TestOpenEXRDamaged TestOpenEXRHostile TestOpenEXRCrafted; do
  for ((shard = 0; shard < shards; ++shard)); do echo "$suite $shard"; done
done | xargs -P "$jobs" -L 1 bash -c 'memcheck=($MEMCHECK); run_shard "$1" "$2"' _

# The files: the crafted ones (committed, and regenerated with this OpenEXR) and the sound
# files they come from, the hostile headers and the damaged corpus.
cp "$root"/Testing/Data/EXR/Crafted/*.exr "$work/files/"
for f in "$root"/Testing/Data/EXR/Crafted/valid/*.exr; do cp "$f" "$work/files/valid-$(basename "$f")"; done
damaged=$root/../shared/data/exr/Damaged
if [ -d "$damaged" ]; then
  find "$damaged" -type f ! -name '*.rst' -exec cp {} "$work/files/" \;
elif [ "${CI:-}" = true ]; then
  echo "valgrind: shared test data missing under CI: $damaged" >&2
  exit 1
fi
"$build/bin/MakeHostileEXR" "$work/files/hostile" >/dev/null
for f in "$work"/files/hostile/*; do mv "$f" "$work/files/hostile-$(basename "$f")"; done
rmdir "$work/files/hostile"
"$build/bin/MakeCraftedEXR" "$work/files/regenerated" >/dev/null
for f in "$work"/files/regenerated/*.exr; do mv "$f" "$work/files/regenerated-$(basename "$f")"; done
rm -rf "$work/files/regenerated"
count=$(find "$work/files" -maxdepth 1 -type f | wc -l)

# Each file through `blur --radius 0` (read, write), and a file that reads through `image`
# too (read, bloom, write). A file may be refused (exit 1) or read (exit 0); memcheck's 99, a
# signal or anything else fails.
run_one() {
  local file=$1 verb name log status
  name=$(basename "$file")
  for verb in blur image; do
    log=$work/logs/$verb-$name.txt
    local args=("$verb")
    [ "$verb" = blur ] && args+=(--radius 0)
    set +e
    "${memcheck[@]}" --log-file="$log" "$build/bin/vtk-bloom" "${args[@]}" --quiet "$file" \
      "$work/out/$verb-$name.exr" >/dev/null 2>&1
    status=$?
    set -e
    if [ "$status" -ne 0 ] && [ "$status" -ne 1 ]; then
      echo "valgrind: vtk-bloom $verb $name: exit $status" >&2
      cat "$log" >&2
      return 1
    fi
    if [ -s "$log" ]; then
      echo "valgrind: vtk-bloom $verb $name: memcheck reported:" >&2
      cat "$log" >&2
      return 1
    fi
    [ "$status" -eq 0 ] || break # refused: `image` reads it the same way
  done
}
export -f run_one

# Over the suites above, which read every one of these files under memcheck, the tool adds its
# options, its error report and its writer, where the stale bytes were. So it runs under
# memcheck on every file it reads (the writer runs) and on one in eight of those it refuses
# (the refusal's report), chosen by a run without valgrind (memcheck costs about 5 s a run
# here, starting the tool's 99 libraries). A file that ends otherwise without valgrind (a
# crash) is run under memcheck too, and fails there.
selected=$work/selected.txt
reads=0 refusals=0 kept=0
while IFS= read -r -d '' file; do
  set +e
  "$build/bin/vtk-bloom" blur --radius 0 --quiet "$file" "$work/out/native.exr" >/dev/null 2>&1
  status=$?
  set -e
  if [ "$status" -eq 1 ]; then
    refusals=$((refusals + 1))
    [ $((refusals % 8)) -eq 1 ] || continue
    kept=$((kept + 1))
  else
    reads=$((reads + 1))
  fi
  printf '%s\0' "$file"
done < <(find "$work/files" -maxdepth 1 -type f -print0 | sort -z) >"$selected"
# shellcheck disable=SC2016
xargs -0 -P "$jobs" -I{} bash -c 'memcheck=($MEMCHECK); run_one "$1"' _ {} <"$selected"
echo "valgrind: no memcheck report: 3 suites on $count files; vtk-bloom blur (and image) on the" \
  "$reads it reads and $kept of the $refusals it refuses ($((SECONDS - start)) s)"
