#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
# Build and pack what a GPU machine needs to run vtk-bloom's rendering tests, the frame-time
# benchmark and the vtk-bloom tool, from the EGL VTK (scripts/build-egl-vtk.sh). The GPU machine
# then needs no compiler and no VTK, only the GL loaders (glvnd) and its own driver's EGL vendor;
# scripts/gpu-run.sh runs everything there.
#
#   bash scripts/gpu-pack.sh [DEST]     writes DEST/vtk-bloom-gpu.tar.xz and a copy of
#                                       gpu-run.sh (default DEST: .gpupack in the checkout;
#                                       ignore it in git)
#
# The project is built in build-egl/ (the build of `bash scripts/test.sh --egl`). The tarball
# holds, at their absolute paths on this machine, the twelve executables, the CTest files of the
# build (so that ctest runs the rendering tests there as here), the test data they read (the
# baselines in Testing/Data and the shared presets and EXR images), and under
# /opt/vtk-bloom-gpu/lib every library `ldd` names except glibc's, the C++ runtime's and the GL
# loaders' (the GPU machine's own). /opt/vtk-bloom-gpu/env records the paths for gpu-run.sh.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
dest=${1:-$root/.gpupack}
build=$root/build-egl
bins=(TestBloomPass TestBloomPassHardCases TestBloomPassRegion TestBloomPassMotion
  TestBloomPassSoak TestBloomPassGallery TestBloomPassLight TestBloomPassTiles
  TestBloomPassFrameCost BloomPassFrameTime ShaderStageThroughput vtk-bloom)
log() { echo "gpu-pack: $*" >&2; }

prefix=$(bash "$root/scripts/build-egl-vtk.sh" | tail -n 1)
launcher=()
command -v ccache >/dev/null 2>&1 &&
  launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
log "building ${bins[*]} against $prefix in $build"
cmake -S "$root" -B "$build" -G Ninja "${launcher[@]}" -DCMAKE_BUILD_TYPE=Release \
  -DVTKBLOOM_WARNINGS_AS_ERRORS=ON -DVTKBLOOM_WRAP_PYTHON=OFF -DBUILD_TESTING=ON \
  -DVTK_DIR="$prefix/lib/cmake/vtk-9.1" >/dev/null
cmake --build "$build" --target "${bins[@]}" -- -j"$(nproc)"
shared=$(sed -n 's/^VTKBLOOM_SHARED_DATA_DIR:PATH=//p' "$build/CMakeCache.txt")

stage=$(mktemp -d)
trap 'rm -rf "$stage"' EXIT
opt=$stage/opt/vtk-bloom-gpu
mkdir -p "$opt/lib" "$stage$build/bin"
for b in "${bins[@]}"; do
  cp "$build/bin/$b" "$stage$build/bin/"
done
# CTest's files: every CTestTestfile.cmake and the tests gtest_discover_tests listed.
(cd / && find "${build#/}" \( -name CTestTestfile.cmake -o -name '*_include.cmake' \
  -o -name '*_tests.cmake' \) -print0 | tar --null -T - -cf -) | tar -C "$stage" -xf -
# Test data, at the paths compiled into the tests.
mkdir -p "$stage$root/Testing" "$stage$shared/exr"
cp -a "$root/Testing/Data" "$stage$root/Testing/"
if [ -d "$shared" ]; then
  cp -a "$shared/presets" "$stage$shared/"
  cp -a "$shared"/exr/TestImages_* "$stage$shared/exr/"
else
  log "warning: no shared data in $shared; the tests that read it will fail there (CI=true)"
fi
# Libraries: the project's, VTK's and the system ones they need, not glibc, libstdc++ or GL.
skip='^(libc|libm|libstdc\+\+|libgcc_s|ld-linux-x86-64|libpthread|libdl|librt|libGL|libEGL|libOpenGL|libGLdispatch|libGLX|libGLESv1_CM|libGLESv2)\.'
for b in "${bins[@]}"; do
  ldd "$build/bin/$b" | awk '/=> \// { print $3 }'
done | sort -u | while read -r lib; do
  base=$(basename "$lib")
  [[ $base =~ $skip ]] || cp -L "$lib" "$opt/lib/$base"
done
strip --strip-unneeded "$stage$build"/bin/* "$opt"/lib/* 2>/dev/null || true
cat >"$opt/env" <<ENV
VTKBLOOM_GPU_BUILD=$build
VTKBLOOM_GPU_SOURCE=$root
VTKBLOOM_GPU_COMMIT=$(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo unknown)$(git -C "$root" diff --quiet HEAD 2>/dev/null || echo +)
VTKBLOOM_GPU_VTK=$prefix
ENV
mkdir -p "$dest"
(cd "$stage" && tar -cJf "$dest/vtk-bloom-gpu.tar.xz" -- *)
cp "$root/scripts/gpu-run.sh" "$dest/"
log "wrote $dest/vtk-bloom-gpu.tar.xz ($(du -h "$dest/vtk-bloom-gpu.tar.xz" | cut -f1))"
