#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
# The bloom view under pvbatch at scale: time per frame for 1, 2 and 4 ranks at 1920x1080 and
# 3840x2160, bloom off, over IceT's 8-bit composite and over its float composite
# (ParaView/Benchmarks/bloom_view_timing.py), as a Markdown table on stdout.
#
#   bash scripts/paraview-benchmark.sh [FRAMES]      (default 20 frames a mode)
#
# llvmpipe on this machine: every rank renders on the CPU, so ranks share its cores.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
frames=${1:-20}
echo "| ranks | size | mode | median ms | mean ms | p99 ms | max ms | frames |"
echo "|---:|---|---|---:|---:|---:|---:|---:|"
for size in "1920 1080" "3840 2160"; do
  for ranks in 1 2 4; do
    set -- $size
    timeout 1200 bash "$root/scripts/pvbatch.sh" -n "$ranks" \
      "$root/ParaView/Benchmarks/bloom_view_timing.py" "$1" "$2" "$frames" 2>/dev/null |
      awk '$1 == "timing" { printf "| %s | %sx%s | %s | %s | %s | %s | %s | %s |\n", $2, $3, $4, $5, $6, $7, $8, $9, $10 }'
  done
done
