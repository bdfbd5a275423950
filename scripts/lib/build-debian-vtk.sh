#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
# Build Debian's own VTK 9.1 source for one headless OpenGL backend into a cached prefix. The
# common part of scripts/build-osmesa-vtk.sh and scripts/build-egl-vtk.sh; call those.
#
#   bash scripts/lib/build-debian-vtk.sh osmesa|egl     prints the prefix on its last line
#
#   osmesa  $VTKBLOOM_OSMESA_PREFIX or ~/.cache/vtk-bloom/vtk-9.1-osmesa: OSMesa, no X
#   egl     $VTKBLOOM_EGL_PREFIX or ~/.cache/vtk-bloom/vtk-9.1-egl: EGL (vtkEGLRenderWindow),
#           no X; renders on a GPU's EGL driver, or on Mesa's (llvmpipe) on a machine with none
#
# When the prefix already holds an installed VTK with the same module list, nothing is built. The
# first build takes about 20 minutes on two cores; ccache makes later rebuilds take seconds. In
# VTK 9.1, OSMesa and EGL cannot share one build, hence two prefixes.
#
# Why the extra steps:
#  - Debian strips VTK's bundled glew, and the system libGLEW cannot initialise without a GLX or
#    EGL context ("Missing GL version"). glew 2.2's own source, from `apt-get source glew`, is
#    compiled into VTK with GLEW_OSMESA or GLEW_EGL (scripts/lib/osmesa-vtkglew.cmake picks one) so
#    that it asks OSMesa or EGL for entry points.
#  - CMAKE_INSTALL_RPATH points at the prefix so that its libraries never resolve to the
#    system's libvtk*-9.1 with the same SONAMEs.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
backend=${1:-}
case "$backend" in
  osmesa)
    name=OSMesa
    prefix=${VTKBLOOM_OSMESA_PREFIX:-$HOME/.cache/vtk-bloom/vtk-9.1-osmesa}
    work=${VTKBLOOM_OSMESA_WORK:-$HOME/.cache/vtk-bloom/osmesa-build}
    gl_packages=(libosmesa6-dev)
    gl_args=(-DVTK_OPENGL_HAS_OSMESA=ON -DVTK_OPENGL_HAS_EGL=OFF)
    ;;
  egl)
    name=EGL
    prefix=${VTKBLOOM_EGL_PREFIX:-$HOME/.cache/vtk-bloom/vtk-9.1-egl}
    work=${VTKBLOOM_EGL_WORK:-$HOME/.cache/vtk-bloom/egl-build}
    # glvnd's headers and loaders, and Mesa's EGL vendor and llvmpipe for machines with no GPU.
    gl_packages=(libegl-dev libopengl-dev libgl-dev libgles-dev libegl-mesa0 libgl1-mesa-dri)
    gl_args=(-DVTK_OPENGL_HAS_OSMESA=OFF -DVTK_OPENGL_HAS_EGL=ON)
    ;;
  *)
    echo "usage: bash scripts/lib/build-debian-vtk.sh osmesa|egl" >&2
    exit 2
    ;;
esac
stamp="$prefix/.vtk-bloom-$backend-complete"
log() { echo "build-$backend-vtk: $*" >&2; }

# The modules the prefix must hold; a cached prefix built with another list is rebuilt (ccache
# keeps that incremental).
modules=(
  CommonCore CommonDataModel CommonExecutionModel CommonMath ImagingCore ImagingGeneral
  ImagingSources ImagingMath IOImage FiltersSources FiltersGeneral RenderingCore
  RenderingOpenGL2 InteractionStyle TestingRendering
  # `vtk-bloom render FILE`: VTK's XML and legacy readers, contours, volumes.
  IOXML IOLegacy FiltersCore FiltersGeometry RenderingVolume RenderingVolumeOpenGL2
  # The scenes users build (TestBloomPassLight, TestBloomPassGallery): text, scalar bars,
  # corner annotations, legends, 2D widgets.
  RenderingFreeType RenderingAnnotation InteractionWidgets
)
if [ -f "$stamp" ] && [ "$(cat "$stamp")" = "${modules[*]}" ]; then
  log "using the cached $name VTK in $prefix"
  echo "$prefix"
  exit 0
fi

SUDO=""
[ "$(id -u)" -ne 0 ] && SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive

# 1. Source packages come from the same archive as the binary ones: add a deb-src entry for it.
src_list=/etc/apt/sources.list.d/vtk-bloom-deb-src.sources
if [ ! -f "$src_list" ]; then
  log "adding deb-src entries for the configured Debian archive"
  tmp=$(mktemp)
  for f in /etc/apt/sources.list.d/*.sources; do
    [ -f "$f" ] || continue
    # Copy stanzas that describe Debian's archive (they carry the Debian keyring), as deb-src.
    awk 'BEGIN{RS=""; ORS="\n\n"} /debian-archive-keyring/ && /Types:[ \t]*deb/ {
           sub(/Types:[^\n]*/, "Types: deb-src"); print }' "$f" >>"$tmp"
  done
  if [ -f /etc/apt/sources.list ]; then
    grep -E '^deb[[:space:]]' /etc/apt/sources.list | grep -v cloud.google | sed 's/^deb /deb-src /' \
      >"${src_list%.sources}.list" || rm -f "${src_list%.sources}.list"
  fi
  $SUDO cp "$tmp" "$src_list"
  rm -f "$tmp"
  $SUDO apt-get update -q
fi

# 2. Build dependencies: the backend's GL, the external libraries VTK links, and the tools.
packages=(
  dpkg-dev build-essential cmake ninja-build ccache "${gl_packages[@]}"
  zlib1g-dev libpng-dev libjpeg-dev libtiff-dev libdouble-conversion-dev liblz4-dev
  liblzma-dev libutfcpp-dev libexpat1-dev libeigen3-dev libfreetype-dev
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  log "installing ${missing[*]}"
  $SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

# 3. Sources: Debian's VTK 9.1 and glew 2.2.
mkdir -p "$work"
cd "$work"
if ! ls -d vtk9-*/ >/dev/null 2>&1; then
  log "fetching Debian's vtk9 source"
  apt-get source -q vtk9 >/dev/null
fi
if ! ls -d glew-*/ >/dev/null 2>&1; then
  log "fetching Debian's glew source"
  apt-get source -q glew >/dev/null
fi
vtk_src=$(cd "$(ls -d vtk9-*/ | head -n 1)" && pwd)
glew_src=$(cd "$(ls -d glew-*/ | head -n 1)" && pwd)

# 4. Put glew back into VTK's ThirdParty tree; its CMakeLists picks GLEW_OSMESA or GLEW_EGL.
vtkglew="$vtk_src/ThirdParty/glew/vtkglew"
mkdir -p "$vtkglew/src" "$vtkglew/include/GL"
cp "$glew_src/src/glew.c" "$vtkglew/src/"
cp "$glew_src"/include/GL/*.h "$vtkglew/include/GL/"
cp "$glew_src/LICENSE.txt" "$vtkglew/LICENSE.txt"
cp "$root/scripts/lib/osmesa-vtkglew.cmake" "$vtkglew/CMakeLists.txt"

# 5. Configure a minimal VTK: OpenGL through one headless backend only, system libraries where
# Debian has them.
module_args=()
for m in "${modules[@]}"; do module_args+=("-DVTK_MODULE_ENABLE_VTK_$m=YES"); done
external_args=()
for lib in zlib png jpeg tiff doubleconversion lz4 lzma utf8 expat eigen freetype; do
  external_args+=("-DVTK_MODULE_USE_EXTERNAL_VTK_$lib=ON")
done
launcher=()
command -v ccache >/dev/null 2>&1 &&
  launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
# Paths relative to the work tree, which has the same layout for OSMesa and EGL: the second
# prefix reuses most of the first one's objects (about 2 minutes instead of 20).
export CCACHE_BASEDIR=$work

build="$work/build"
log "configuring VTK from $vtk_src (log: $work/configure.log)"
cmake -S "$vtk_src" -B "$build" -G Ninja "${launcher[@]}" \
  -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_INSTALL_PREFIX="$prefix" \
  -DCMAKE_INSTALL_RPATH="$prefix/lib" \
  -DCMAKE_INSTALL_LIBDIR=lib \
  -DBUILD_SHARED_LIBS=ON \
  -DBUILD_TESTING=OFF \
  -DVTK_BUILD_ALL_MODULES=OFF \
  -DVTK_GROUP_ENABLE_Imaging=DONT_WANT -DVTK_GROUP_ENABLE_MPI=DONT_WANT \
  -DVTK_GROUP_ENABLE_Qt=DONT_WANT -DVTK_GROUP_ENABLE_Rendering=DONT_WANT \
  -DVTK_GROUP_ENABLE_StandAlone=DONT_WANT -DVTK_GROUP_ENABLE_Views=DONT_WANT \
  -DVTK_GROUP_ENABLE_Web=DONT_WANT \
  "${module_args[@]}" "${external_args[@]}" \
  "${gl_args[@]}" -DVTK_USE_X=OFF -DVTK_USE_COCOA=OFF \
  -DVTK_DEFAULT_RENDER_WINDOW_OFFSCREEN=ON \
  -DVTK_WRAP_PYTHON=OFF -DVTK_WRAP_JAVA=OFF -DVTK_ENABLE_REMOTE_MODULES=OFF \
  -DVTK_USE_MPI=OFF -DVTK_SMP_IMPLEMENTATION_TYPE=STDThread \
  >"$work/configure.log" 2>&1 || { tail -n 40 "$work/configure.log" >&2; exit 1; }

# Visible progress: Ninja prints [done/total] on every line; show one line in 50.
log "building VTK with $name (about 20 minutes on 2 cores the first time)"
cmake --build "$build" -- -j"$(nproc)" 2>&1 | tee "$work/build.log" |
  awk -v tag="build-$backend-vtk" '/^\[[0-9]+\/[0-9]+\]/ { if (++n % 50 == 0) {
         split($1, a, /[\[\/\]]/); printf "%s: %s/%s\n", tag, a[2], a[3]; fflush() } }
       /error|FAILED/ { print; fflush() }' >&2
[ "${PIPESTATUS[0]}" -eq 0 ] || { tail -n 40 "$work/build.log" >&2; exit 1; }
cmake --install "$build" >"$work/install.log" 2>&1 || { tail -n 40 "$work/install.log" >&2; exit 1; }
echo "${modules[*]}" >"$stamp"
log "installed $(du -sh "$prefix" | cut -f1) into $prefix"
echo "$prefix"
