#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
# Run the ParaView plugin's checks and the bloom view's benchmark on a GPU node through EGL, from
# the pack of scripts/paraview-gpu-pack.sh (ParaView 6.1, VTK 9.6, Python 3.14, Open MPI and the
# plugin, as Debian sid builds them). Run it as root from the checkout's root, which holds
# .pvgpack/ (the archive, or its two parts); results go to $OUT (default: a new folder):
#
#   OUT=DIR bash scripts/paraview-gpu-run.sh [STEP...]
#
# STEP (default: info tests devices bench; a list in $STEPS works too):
#   unpack    unpack the archives in .pvgpack/ that are not unpacked yet (and apply
#             .pvgpack-overlay/*.tar.xz, below) and stop; with two
#             parts over two calls: the first call carries part 1 and runs `unpack`, the next
#             (while the machine is warm) carries part 2 and runs the steps
#   info      gpu.txt: nvidia-smi's cards, driver and topology (nvidia-smi topo -m), EGL's
#             devices and the OpenGL renderer each of them gives pvbatch
#   tests     tests.log: ParaView/Testing/run_tests.py, every part of the plugin's checks as CI
#             runs them on llvmpipe (1 to 4 ranks, all ranks on GPU 0)
#   devices   devices.md: pvbatch --sym on 1 rank, then one rank per GPU (--displays=0,...,N-1),
#             each rank's EGL device, CUDA device and GPU UUID asked of its own context and
#             nvidia-smi's process list taken while every rank holds its context; the N-rank
#             image against the 1-rank one, and against $REFERENCE/hdr-400-300.png if given
#   bench     bench.md: bloom_gpu_timing.py with one rank per GPU (or $RANKS, a list: "2 4"
#             ranks share the GPUs round-robin) at $SIZES (default 1920x1080 3840x2160
#             7680x4320), $FRAMES frames a mode (default 100); bench.jsonl: the raw records
# Besides: run.log (everything printed) and images.tar.gz (the checks' and devices' images).
# GPUS (default: the cards nvidia-smi lists) sets the ranks of devices and bench.
#
# What it does: unpacks the pack into $VTKBLOOM_PV_ROOT (default /opt/vtk-bloom-pv), a root of
# Debian sid's files in which ParaView runs as it was built (its own glibc, Python, Open MPI);
# copies the machine's OpenGL libraries into it (glvnd's libEGL, libOpenGL, libGLdispatch and the
# NVIDIA driver's EGL vendor, its libraries and nvidia-smi: the pack carries no GL loader and no
# Mesa); then runs the steps chrooted there, in a private mount namespace with /proc, /sys and
# /dev bound and a fresh /tmp, so that nothing stays mounted. Where the machine has no glvnd
# loader, .gl/*.deb (Debian's libglvnd packages, as for scripts/gpu-run.sh) are unpacked into the
# root instead of /. The checkout's scripts/ and ParaView/ are bound over the pack's copies, so
# that edited test scripts run without packing again.
#
# VTKBLOOM_PV_HOST_GL=DIR takes the OpenGL libraries and EGL vendor files from DIR instead of
# the machine's (scripts/paraview-gpu-pack.sh checks the pack that way with Mesa's llvmpipe).
set -uo pipefail

# ------------------------------------------------------------------------------------------
# Inside the root (the chroot), or inside the sid root for the pack's trace: the steps.
inside() {
  local src=$1 out=$2 gpus=$3
  shift 3
  export VTKBLOOM_PARAVIEW_BUILD=$src/build-paraview-sid-gpu
  export VTK_DEFAULT_OPENGL_WINDOW=vtkEGLRenderWindow
  export PYTHONUNBUFFERED=1
  local work=${VTKBLOOM_PV_WORK:-/tmp/pvgpu}
  mkdir -p "$work" "$out"
  cd "$src" || return 1
  local status=0 ranks displays
  # --displays for N ranks: 0,1,...,N-1, one EGL device each (modulo VTKBLOOM_PV_DEVICES, the
  # devices there are: 1 for the pack's trace on llvmpipe, where Mesa has one).
  displays() {
    local n=$1 i list=""
    for ((i = 0; i < n; i++)); do list+=${list:+,}$((i % ${VTKBLOOM_PV_DEVICES:-$gpus})); done
    echo "$list"
  }
  for step in "$@"; do
    case $step in
      info)
        echo "== info: EGL and OpenGL as pvbatch sees them"
        pvbatch --version 2>&1 | tail -n 1
        bash scripts/pvbatch.sh ParaView/Testing/bloom_gpu_devices.py "$work/info" 64 64 0 2>&1 |
          grep '^device ' | tee -a "$out/gpu.txt"
        ;;
      tests)
        echo "== tests: run_tests.py (every rank on GPU 0)"
        local begin=$SECONDS
        /usr/bin/python3 ParaView/Testing/run_tests.py "$src/build-sid-gpu" "$work/tests" 2>&1 |
          tee "$out/tests.log"
        [ "${PIPESTATUS[0]}" -eq 0 ] || status=1
        echo "run_tests.py: $((SECONDS - begin)) s" | tee -a "$out/tests.log"
        ;;
      devices)
        echo "== devices: one rank per GPU"
        : >"$out/devices.md"
        for ranks in 1 "$gpus"; do
          local dir=$work/devices-$ranks
          rm -rf "$dir" && mkdir -p "$dir"
          bash scripts/pvbatch.sh -n "$ranks" --sym --opengl-window-backend=EGL \
            --displays="$(displays "$ranks")" --displays-assignment-mode=round-robin \
            ParaView/Testing/bloom_gpu_devices.py \
            "$dir" 400 300 8 >"$dir/pvbatch.log" 2>&1 &
          local job=$! waited=0
          # nvidia-smi while every rank holds its context (each writes its JSON, then waits).
          while [ "$(ls "$dir"/device-*.json 2>/dev/null | wc -l)" -lt "$ranks" ] &&
            kill -0 "$job" 2>/dev/null && [ $waited -lt 240 ]; do
            sleep 0.5
            waited=$((waited + 1))
          done
          sleep 1
          if command -v nvidia-smi >/dev/null; then
            nvidia-smi >"$dir/nvidia-smi.txt" 2>&1
            nvidia-smi --query-gpu=index,uuid,pci.bus_id --format=csv >"$dir/gpus.csv" 2>&1
          fi
          wait "$job" || status=1
          grep -E '^device |bloom_gpu_devices:' "$dir/pvbatch.log"
        done
        /usr/bin/python3 ParaView/Testing/bloom_gpu_report.py devices "$work/devices-1" \
          "$work/devices-$gpus" ${REFERENCE:+"$REFERENCE"} | tee "$out/devices.md"
        [ "${PIPESTATUS[0]}" -eq 0 ] || status=1
        ;;
      bench)
        echo "== bench: ${RANKS:-$gpus} rank(s) on $gpus GPU(s), ${SIZES:-1920x1080 3840x2160 7680x4320}, ${FRAMES:-100} frames"
        : >"$out/bench.jsonl"
        for ranks in ${RANKS:-$gpus}; do
          for size in ${SIZES:-1920x1080 3840x2160 7680x4320}; do
            timeout 900 bash scripts/pvbatch.sh -n "$ranks" --opengl-window-backend=EGL \
              --displays="$(displays "$ranks")" --displays-assignment-mode=round-robin \
              ParaView/Testing/bloom_gpu_timing.py \
              "${size%x*}" "${size#*x}" "${FRAMES:-100}" 2>&1 | grep '^timing-json ' |
              sed "s/^timing-json {/{\"gpus\": $gpus, /" | tee -a "$out/bench.jsonl"
          done
        done
        /usr/bin/python3 ParaView/Testing/bloom_gpu_report.py bench "$out/bench.jsonl" |
          tee "$out/bench.md"
        ;;
      *) echo "paraview-gpu-run: unknown step '$step'" >&2; status=2 ;;
    esac
  done
  # The images: the checks' and the devices' PNGs, with their names (not the 2x and 4x
  # screenshots of the scale checks, whose figures are in tests.log: the size limit of a file
  # that comes back from the device tool).
  (cd "$work" && find . -name '*.png' ! -name '.rank-*' ! -path './tests/scale-*' -print0 |
    tar --null -T - -czf "$out/images.tar.gz") 2>/dev/null
  return $status
}

if [ "${1:-}" = --inside ]; then
  shift
  inside "$@"
  exit $?
fi

# ------------------------------------------------------------------------------------------
# On the GPU machine: unpack, bring the machine's OpenGL in, enter the root.
checkout=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$checkout" || exit 1
OUT=${OUT:-$(mktemp -d)}
mkdir -p "$OUT"
OUT=$(cd "$OUT" && pwd)
exec > >(tee -a "$OUT/run.log") 2>&1
root=${VTKBLOOM_PV_ROOT:-/opt/vtk-bloom-pv}
steps=${*:-${STEPS:-info tests devices bench}}
mkdir -p "$root"

begin=$SECONDS
for archive in "${PACK_DIR:-.pvgpack}"/*.tar.xz "${PACK_DIR:-.pvgpack}"/*.tar.zst; do
  [ -f "$archive" ] || continue
  name=$(basename "$archive")
  grep -qxF "$name" "$root/.unpacked" 2>/dev/null && continue
  case $archive in
    *.zst) zstd -dc "$archive" | tar -C "$root" -xf - ;;
    *) xz -dc -T0 "$archive" | tar -C "$root" -xf - ;;
  esac || { echo "paraview-gpu-run: could not unpack $archive"; exit 1; }
  echo "$name" >>"$root/.unpacked"
  echo "paraview-gpu-run: unpacked $name ($(du -h "$archive" | cut -f1)) in $((SECONDS - begin)) s"
done
[ -f "$root/.vtkbloom-pv" ] || { echo "paraview-gpu-run: no pack unpacked in $root"; exit 1; }
# shellcheck disable=SC1091
. "$root/.vtkbloom-pv" # VTKBLOOM_PV_SOURCE, VTKBLOOM_PV_PARTS, VTKBLOOM_PV_COMMIT
for part in $VTKBLOOM_PV_PARTS; do
  if ! grep -qxF "$part" "$root/.unpacked"; then
    echo "paraview-gpu-run: $part is not unpacked yet; carry it in the next call"
    [ "$steps" = unpack ] && exit 0
    exit 3
  fi
done
# A rebuilt plugin and project libraries over the pack (.pvgpack-overlay/*.tar.xz, paths
# relative to /, as the pack's): applied on every call, so the pack need not be made again.
for overlay in .pvgpack-overlay/*.tar.xz; do
  [ -f "$overlay" ] || continue
  tar -C "$root" -xJf "$overlay" && echo "paraview-gpu-run: applied $overlay"
done
[ "$steps" = unpack ] && exit 0

# The machine's OpenGL: glvnd's loaders and the NVIDIA driver's EGL vendor, its libraries and
# nvidia-smi, copied into the root's /usr/lib/host-gl (first on its library path). A copy, not a
# folder bound in whole: the machine's libc must stay out of the root.
hostgl=$root/usr/lib/host-gl
rm -rf "$hostgl" && mkdir -p "$hostgl" "$root/usr/share/glvnd/egl_vendor.d" "$root/usr/local/bin"
rm -f "$root"/usr/share/glvnd/egl_vendor.d/*.json
gl_names='libEGL.so.1|libOpenGL.so.0|libGLdispatch.so.0|libGL.so.1|libGLX.so.0|libGLESv2.so.2'
if [ -n "${VTKBLOOM_PV_HOST_GL:-}" ]; then
  cp -a "$VTKBLOOM_PV_HOST_GL"/lib/. "$hostgl/"
  cp -a "$VTKBLOOM_PV_HOST_GL"/egl_vendor.d/. "$root/usr/share/glvnd/egl_vendor.d/"
else
  ldconfig 2>/dev/null
  libs=$(ldconfig -p | awk '{ print $NF }' | grep -E "/($gl_names)$" | sort -u)
  if [ -z "$libs" ] && ls .gl/*.deb >/dev/null 2>&1; then
    echo "paraview-gpu-run: the machine has no glvnd loader; Debian's from .gl/"
    mkdir -p "$root/var/tmp/glvnd"
    for f in .gl/*.deb; do dpkg-deb -x "$f" "$root/var/tmp/glvnd"; done
    cp -a "$root"/var/tmp/glvnd/usr/lib/x86_64-linux-gnu/lib* "$hostgl/"
  fi
  for lib in $libs; do cp -L "$lib" "$hostgl/$(basename "$lib")"; done
  # The driver's own libraries, from where its EGL vendor library is.
  vendor=$(ldconfig -p | awk '{ print $NF }' | grep -E '/libEGL_nvidia\.so\.0$' | head -n 1)
  for d in /usr/local/nvidia/lib64 /usr/local/nvidia/lib /usr/lib/x86_64-linux-gnu; do
    [ -n "$vendor" ] || { [ -e "$d/libEGL_nvidia.so.0" ] && vendor=$d/libEGL_nvidia.so.0; }
  done
  if [ -n "$vendor" ]; then
    for lib in "$(dirname "$vendor")"/lib{EGL_nvidia,GLX_nvidia,GLESv2_nvidia,nvidia-}*.so*; do
      [ -e "$lib" ] && cp -L "$lib" "$hostgl/$(basename "$lib")"
    done
  fi
  for j in /usr/share/glvnd/egl_vendor.d /etc/glvnd/egl_vendor.d \
    /usr/local/nvidia/share/glvnd/egl_vendor.d /usr/local/share/glvnd/egl_vendor.d; do
    ls "$j"/*nvidia*.json >/dev/null 2>&1 && cp "$j"/*nvidia*.json "$root/usr/share/glvnd/egl_vendor.d/" && break
  done
  # The vendor library by its name: the root finds it in host-gl, wherever the machine keeps it.
  sed -i 's|"library_path" *: *"[^"]*/\([^"/]*\)"|"library_path" : "\1"|' \
    "$root"/usr/share/glvnd/egl_vendor.d/*.json 2>/dev/null
  smi=$(command -v nvidia-smi)
  [ -n "$smi" ] && cp -L "$smi" "$root/usr/local/bin/nvidia-smi"
  {
    echo "pack: commit $VTKBLOOM_PV_COMMIT, parts: $VTKBLOOM_PV_PARTS"
    nvidia-smi --query-gpu=index,name,driver_version,memory.total,pci.bus_id,uuid --format=csv
    nvidia-smi -L
    echo
    nvidia-smi topo -m
    echo
    nvidia-smi -q | grep -iE 'Product Name|Product Architecture|Driver Version|CUDA Version|Link Width|PCIe Generation|Max|Current' | head -n 40
    echo "EGL vendor files: $(ls "$root"/usr/share/glvnd/egl_vendor.d/)"
    echo "GL libraries from the machine: $(ls "$hostgl" | tr '\n' ' ')"
  } >"$OUT/gpu.txt" 2>&1
fi
gpus=${GPUS:-$(nvidia-smi -L 2>/dev/null | grep -c '^GPU ')}
[ "${gpus:-0}" -ge 1 ] || gpus=1
echo "paraview-gpu-run: $gpus GPU(s); steps: $steps"

# The root: /proc, /sys, /dev, a fresh /tmp and /dev/shm, the results folder at /out, and the
# checkout's scripts/ and ParaView/ over the pack's copies.
src=$VTKBLOOM_PV_SOURCE
mkdir -p "$root/out" "$root/proc" "$root/sys" "$root/dev" "$root/tmp" "$root$src/scripts" \
  "$root$src/ParaView" "$root/reference"
unshare -m --propagation private -- /bin/bash -c '
  set -e
  root=$1 out=$2 checkout=$3 src=$4 reference=$5
  shift 5
  mount -t proc proc "$root/proc"
  mount --rbind /sys "$root/sys"
  mount --rbind /dev "$root/dev"
  mount -t tmpfs tmpfs "$root/tmp"
  mkdir -p "$root/dev/shm" && mount -t tmpfs tmpfs "$root/dev/shm"
  mount --bind "$out" "$root/out"
  mount --bind "$checkout/scripts" "$root$src/scripts"
  mount --bind "$checkout/ParaView" "$root$src/ParaView"
  [ -z "$reference" ] || mount --bind "$reference" "$root/reference"
  exec chroot "$root" /usr/bin/env -i HOME=/root LANG=C.UTF-8 TERM=dumb \
    PATH=/usr/local/bin:/usr/bin:/bin:/usr/sbin:/sbin LD_LIBRARY_PATH=/usr/lib/host-gl \
    SIZES="${SIZES:-}" FRAMES="${FRAMES:-}" RANKS="${RANKS:-}" REFERENCE="${reference:+/reference}" \
    VTKBLOOM_PV_DEVICES="${VTKBLOOM_PV_DEVICES:-}" \
    /bin/bash "$src/scripts/paraview-gpu-run.sh" --inside "$src" /out "$@"
' paraview-gpu-run "$root" "$OUT" "$checkout" "$src" "${REFERENCE:+$(cd "$REFERENCE" && pwd)}" \
  "$gpus" $steps
status=$?
echo "paraview-gpu-run: exit $status after $((SECONDS - begin)) s"
exit $status
