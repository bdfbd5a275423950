#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
# Pack ParaView 6.1, VTK 9.6 and the vtk-bloom plugin from the Debian sid root
# (scripts/sid-root.sh) for a GPU machine that renders through EGL and has nothing else:
# scripts/paraview-gpu-run.sh runs the plugin's checks and the benchmark there.
#
#   bash scripts/paraview-gpu-pack.sh [DEST]        (default DEST: .pvgpack in the checkout;
#                                                    .git/info/exclude it)
#
# Writes DEST/paraview-gpu.tar.xz (xz -9e with the x86 filter), or, if that is over
# $VTKBLOOM_PV_LIMIT_MB (default 56: a device call carries 64 MiB with the checkout), the same
# files split into DEST/paraview-gpu-1.tar.xz and -2 for two calls (VTKBLOOM_PV_PARTS=2: the
# two parts at once, without trying one archive). Steps, each logged under
# .pvgpack-work/ (ignored):
#
# 1. build: in the sid root, the project's modules, Python package and vtk-bloom tool against
#    VTK 9.6 (build-sid-gpu/: no tests, no benchmarks) and the plugin against ParaView 6.1
#    (build-paraview-sid-gpu/), both for paraview-gpu-run.sh;
# 2. trace: paraview-gpu-run.sh's own steps (info, tests: the whole of run_tests.py, devices on 2
#    ranks, bench on 1 and 2 ranks at 320x240, 3 frames) in the sid root on Mesa's llvmpipe,
#    under strace -f (what every process opened and executed) and with the loader's log
#    (LD_DEBUG=files,reloc,bindings: which object's code ran);
# 3. stage: scripts/lib/paraview_gpu_pack.py copies what the trace read from the sid root, at
#    the same paths: the programs, the libraries their used objects name (ldd's list, as the
#    loader resolved it), Python and its modules, Open MPI's components, the data files. A
#    library that is loaded only because another names it, and whose code never ran in the
#    trace, becomes a stub (its SONAME and versions, the symbols bound to it at load time, each
#    function a trap that names itself and aborts): GDAL, FFmpeg, Viskores' filters and the like.
#    No Qt, no GUI, no OpenGL loader and no Mesa (the GPU machine's own). The stubs are
#    assembled in the sid root; the project's files are stripped;
# 4. check: paraview-gpu-run.sh unpacks the archive into a fresh root and runs the same steps
#    there on llvmpipe (Mesa from the sid root standing in for the machine's OpenGL), so that a
#    file the pack lacks fails here, not on the GPU machine;
# 5. compress.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
dest=${1:-$root/.pvgpack}
work=$root/.pvgpack-work
sid=$(bash "$root/scripts/sid-root.sh")
limit_mb=${VTKBLOOM_PV_LIMIT_MB:-56}
log() { echo "paraview-gpu-pack: $*" >&2; }
mkdir -p "$work" "$dest"
sid_run() { bash "$root/scripts/sid-root.sh" bash -c "cd '$root' && $1"; }

# 1. build
log "building build-sid-gpu and build-paraview-sid-gpu in the sid root"
sid_run "export CCACHE_BASEDIR='$root'
  cmake -S . -B build-sid-gpu -G Ninja -DCMAKE_C_COMPILER_LAUNCHER=ccache \
    -DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF \
    -DVTKBLOOM_BUILD_BENCHMARKS=OFF -DVTKBLOOM_WARNINGS_AS_ERRORS=ON >/dev/null
  nice -n 10 cmake --build build-sid-gpu -- -j\${VTKBLOOM_JOBS:-2}
  VTKBLOOM_JOBS=\${VTKBLOOM_JOBS:-2} nice -n 10 bash scripts/build-paraview-plugin.sh build-paraview-sid-gpu" \
  >"$work/build.log" 2>&1 || { tail -n 30 "$work/build.log"; exit 1; }

# 2. trace
if [ ! -s "$work/trace.db" ] || [ "${VTKBLOOM_PV_RETRACE:-0}" = 1 ]; then
  log "tracing paraview-gpu-run.sh's steps in the sid root (llvmpipe; several minutes)"
  rm -rf "$work/ld" "$work/trace-out" "$work/trace-work" "$work/trace.db"
  mkdir -p "$work/ld"
  command -v strace >/dev/null || { log "needs strace (apt-get install strace)"; exit 1; }
  nice -n 10 strace -f -qq --seccomp-bpf -e trace=open,openat,execve,newfstatat,statx,stat,access \
    -e signal=none -s 512 -o "$work/strace.log" \
    bash "$root/scripts/sid-root.sh" bash -c "cd '$root' &&
      LD_DEBUG=files,reloc,bindings LD_DEBUG_OUTPUT='$work/ld/ld' VTKBLOOM_PV_DEVICES=1 \
      VTKBLOOM_PV_WORK='$work/trace-work' SIZES=320x240 FRAMES=3 \
      bash scripts/paraview-gpu-run.sh --inside '$root' '$work/trace-out' 2 info tests devices bench" \
    >"$work/trace.log" 2>&1 || log "the traced run had failures (see $work/trace.log); packing what it read"
  log "reading the loader's logs ($(du -sh "$work/ld" | cut -f1))"
  find "$work/ld" -name 'ld.*' -print0 | xargs -0 -n 20 /usr/bin/python3 \
    "$root/scripts/lib/paraview_gpu_pack.py" scan "$work/trace.db" >"$work/scan.log"
  tail -n 1 "$work/scan.log" >&2
fi

# 3. stage
stage=$work/stage
rm -rf "$stage" && mkdir -p "$stage"
commit=${VTKBLOOM_PV_COMMIT:-$(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo unknown)}
[ -n "${VTKBLOOM_PV_COMMIT:-}" ] || git -C "$root" diff --quiet HEAD -- . 2>/dev/null || commit="$commit+"
cat >"$work/extra.txt" <<EXTRA
# Read by the steps only on a GPU machine, or by the loader, or needed to enter the root.
/lib64/ld-linux-x86-64.so.2
/usr/bin/env
/bin/bash
/etc/ld.so.conf
/etc/ld.so.conf.d
/etc/nsswitch.conf
/etc/passwd
/etc/group
/etc/hosts
/etc/debian_version
/usr/sbin/ldconfig
EXTRA
rm -rf "$work/stubs"
/usr/bin/python3 "$root/scripts/lib/paraview_gpu_pack.py" stage "$sid" "$work/trace.db" \
  "$work/strace.log" "$stage" "$work/extra.txt" "$work/stubs" "$root/build-sid-gpu/bin" \
  "$root/build-sid-gpu/lib" "$root/build-paraview-sid-gpu/lib" | tee "$work/stage.log" >&2
# The project: its scripts and ParaView tests, the two builds' outputs that run there.
for p in scripts ParaView build-sid-gpu/bin/vtk-bloom build-sid-gpu/lib/libvtk*.so* \
  build-sid-gpu/lib/python3 build-paraview-sid-gpu/lib/paraview-6.1/plugins; do
  for f in $root/$p; do
    mkdir -p "$stage$(dirname "$f")"
    cp -a "$f" "$stage$(dirname "$f")/"
  done
done
find "$stage$root" -name __pycache__ -prune -exec rm -rf {} +
# The stubs, assembled in the sid root; the project's objects stripped there.
sid_run "bash '$work/stubs/build.sh' &&
  find '$stage$root' -type f \\( -name '*.so*' -o -name vtk-bloom \\) -exec strip --strip-unneeded {} +" \
  >"$work/stubs.log" 2>&1 || { tail -n 20 "$work/stubs.log"; exit 1; }
"$sid/usr/sbin/ldconfig" -r "$stage" 2>/dev/null || true
du -sh "$stage" >&2

# 5. compress (the check below unpacks exactly this)
rm -f "$dest"/paraview-gpu*.tar.xz
manifest() { # what paraview-gpu-run.sh reads: the source path, the parts, the commit
  printf 'VTKBLOOM_PV_SOURCE=%s\nVTKBLOOM_PV_PARTS="%s"\nVTKBLOOM_PV_COMMIT=%s\n' \
    "$root" "$1" "$commit" >"$stage/.vtkbloom-pv"
}
pack() { # pack ARCHIVE [FILES_FROM]
  local what=(.)
  [ -z "${2:-}" ] || what=(--files-from="$2" .vtkbloom-pv)
  (cd "$stage" && tar --sort=name --owner=0 --group=0 --numeric-owner -cf - "${what[@]}") |
    xz -9e --x86 --lzma2=preset=9e,dict=192MiB -T"${VTKBLOOM_JOBS:-2}" >"$1"
}
split_parts() { # the files in two lists of about equal size
  (cd "$stage" && find . ! -type d ! -name .vtkbloom-pv -printf '%s %p\n' | sort -n) >"$work/files.txt"
  local half
  half=$(awk '{ s += $1 } END { print s / 2 }' "$work/files.txt")
  awk -v h="$half" -v w="$work" '{ s += $1; print $2 > (s <= h ? w "/part1.txt" : w "/part2.txt") }' \
    "$work/files.txt"
}
two=(paraview-gpu-1.tar.xz paraview-gpu-2.tar.xz)
if [ "${VTKBLOOM_PV_PARTS:-}" != 2 ]; then
  log "compressing (xz -9e, x86 filter)"
  manifest paraview-gpu.tar.xz
  pack "$dest/paraview-gpu.tar.xz"
  size_mb=$(($(stat -c %s "$dest/paraview-gpu.tar.xz") / 1048576))
  if [ "$size_mb" -ge "$limit_mb" ]; then
    log "one archive is $size_mb MiB, over $limit_mb: two parts"
    rm -f "$dest/paraview-gpu.tar.xz"
    VTKBLOOM_PV_PARTS=2
  fi
fi
if [ "${VTKBLOOM_PV_PARTS:-}" = 2 ]; then
  log "compressing two parts (xz -9e, x86 filter, one each on a core)"
  split_parts
  manifest "${two[*]}"
  VTKBLOOM_JOBS=1 pack "$dest/${two[0]}" "$work/part1.txt" &
  VTKBLOOM_JOBS=1 pack "$dest/${two[1]}" "$work/part2.txt"
  wait
fi
ls -la "$dest" >&2

# 4. check, on llvmpipe, from the archive
if [ "${VTKBLOOM_PV_CHECK:-1}" = 1 ]; then
  log "checking the pack: paraview-gpu-run.sh from a fresh root, Mesa standing in for the GPU"
  mesa=$work/mesa-gl
  rm -rf "$mesa" && mkdir -p "$mesa/lib" "$mesa/egl_vendor.d"
  cp "$sid"/usr/share/glvnd/egl_vendor.d/*mesa*.json "$mesa/egl_vendor.d/"
  # glvnd's loaders, Mesa's EGL and gallium driver and what they need (the pack may hold a stub
  # of it: the real one in host-gl comes first), but glibc and the C++ runtime, the pack's.
  sid_run "for f in /usr/lib/x86_64-linux-gnu/{libEGL.so.1,libOpenGL.so.0,libGLdispatch.so.0,libEGL_mesa.so.0,libgallium-*.so}; do
      echo \$f; ldd \$f | awk '/=> \\// { print \$3 }'; done | sort -u" >"$work/mesa.txt"
  while read -r f; do
    case $(basename "$f") in libc.so* | libm.so* | libstdc++* | libgcc_s* | ld-linux*) ;;
      *) cp -L "$sid$f" "$mesa/lib/" ;; esac
  done <"$work/mesa.txt"
  rm -rf "$work/check-root" "$work/check-out"
  (cd "$root" && env -u DISPLAY VTKBLOOM_PV_ROOT="$work/check-root" VTKBLOOM_PV_HOST_GL="$mesa" \
    GPUS=2 VTKBLOOM_PV_DEVICES=1 SIZES=320x240 FRAMES=3 OUT="$work/check-out" \
    PACK_DIR="$dest" bash scripts/paraview-gpu-run.sh tests devices bench) >"$work/check.log" 2>&1 ||
    log "the check had failures (the devices step's NVIDIA checks fail on llvmpipe): $work/check.log"
  grep -E '^(PASS|FAIL)|run_tests: |vtk-bloom pack: ' "$work/check-out/tests.log" \
    "$work/check-out/devices.md" "$work/check.log" | grep -v 'PASS' >&2 || true
  rm -rf "$work/check-root"
fi
log "done: $(ls "$dest")"
