#!/usr/bin/env bash
# The main job: install what is needed, build vtk-bloom, and bloom an HDR image to PNG.
# Writes output/*.png (before and after) and prints their paths.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$root/scripts/install-deps.sh"
bash "$root/scripts/configure.sh" "$root/build" -DCMAKE_BUILD_TYPE=Release

tool="$root/build/bin/vtk-bloom"
out="$root/output"
mkdir -p "$out"
candle="$root/../shared/data/exr/ScanLines_CandleGlass.exr"
if [ -f "$candle" ]; then
  echo "main-job: blooming $candle"
  "$tool" blur --radius 0 "$candle" "$out/candle-glass-before.png"
  "$tool" image --preset webgpu-market --threshold 1.5 --strength 0.8 \
    "$candle" "$out/candle-glass-bloom.png"
  echo "main-job: wrote $out/candle-glass-before.png and $out/candle-glass-bloom.png"
fi
# A generated emissive scene needs no input data at all.
"$root/build/bin/EmissiveImage" "$out/emissive-before.exr" "$out/emissive-bloom.exr" webgpu-market
"$tool" blur --radius 0 "$out/emissive-before.exr" "$out/emissive-before.png"
"$tool" blur --radius 0 "$out/emissive-bloom.exr" "$out/emissive-bloom.png"
echo "main-job: wrote $out/emissive-before.png and $out/emissive-bloom.png"
