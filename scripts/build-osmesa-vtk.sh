#!/usr/bin/env bash
# Build Debian's own VTK 9.1 source with OSMesa (no X, offscreen by default) into a cached prefix.
#
#   bash scripts/build-osmesa-vtk.sh            prints the prefix on its last line
#
# The prefix is $VTKBLOOM_OSMESA_PREFIX, or ~/.cache/vtk-bloom/vtk-9.1-osmesa. When the prefix
# already holds an installed VTK, nothing is built. The first build takes about 20 minutes on two
# cores; ccache makes later rebuilds take seconds.
#
# Why the extra steps:
#  - Debian strips VTK's bundled glew, and the system libGLEW cannot initialise without a GLX or
#    EGL context ("Missing GL version"). glew 2.2's own source, from `apt-get source glew`, is
#    compiled into VTK with GLEW_OSMESA so that it asks OSMesa for entry points.
#  - CMAKE_INSTALL_RPATH points at the prefix so that its libraries never resolve to the
#    system's libvtk*-9.1 with the same SONAMEs.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
prefix=${VTKBLOOM_OSMESA_PREFIX:-$HOME/.cache/vtk-bloom/vtk-9.1-osmesa}
work=${VTKBLOOM_OSMESA_WORK:-$HOME/.cache/vtk-bloom/osmesa-build}
stamp="$prefix/.vtk-bloom-osmesa-complete"
log() { echo "build-osmesa-vtk: $*" >&2; }

# The modules the prefix must hold; a cached prefix built with another list is rebuilt (ccache
# keeps that incremental).
modules=(
  CommonCore CommonDataModel CommonExecutionModel CommonMath ImagingCore ImagingGeneral
  ImagingSources ImagingMath IOImage FiltersSources FiltersGeneral RenderingCore
  RenderingOpenGL2 InteractionStyle TestingRendering
  # `vtk-bloom render FILE`: VTK's XML and legacy readers, contours, volumes.
  IOXML IOLegacy FiltersCore FiltersGeometry RenderingVolume RenderingVolumeOpenGL2
)
if [ -f "$stamp" ] && [ "$(cat "$stamp")" = "${modules[*]}" ]; then
  log "using the cached OSMesa VTK in $prefix"
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

# 2. Build dependencies: OSMesa, the external libraries VTK links, and the tools.
packages=(
  dpkg-dev build-essential cmake ninja-build ccache libosmesa6-dev
  zlib1g-dev libpng-dev libjpeg-dev libtiff-dev libdouble-conversion-dev liblz4-dev
  liblzma-dev libutfcpp-dev libexpat1-dev libeigen3-dev
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

# 4. Put glew back into VTK's ThirdParty tree, built with GLEW_OSMESA.
vtkglew="$vtk_src/ThirdParty/glew/vtkglew"
mkdir -p "$vtkglew/src" "$vtkglew/include/GL"
cp "$glew_src/src/glew.c" "$vtkglew/src/"
cp "$glew_src"/include/GL/*.h "$vtkglew/include/GL/"
cp "$glew_src/LICENSE.txt" "$vtkglew/LICENSE.txt"
cp "$root/scripts/osmesa-vtkglew.cmake" "$vtkglew/CMakeLists.txt"

# 5. Configure a minimal VTK: OpenGL through OSMesa only, system libraries where Debian has them.
module_args=()
for m in "${modules[@]}"; do module_args+=("-DVTK_MODULE_ENABLE_VTK_$m=YES"); done
external_args=()
for lib in zlib png jpeg tiff doubleconversion lz4 lzma utf8 expat eigen; do
  external_args+=("-DVTK_MODULE_USE_EXTERNAL_VTK_$lib=ON")
done
launcher=()
command -v ccache >/dev/null 2>&1 &&
  launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)

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
  -DVTK_OPENGL_HAS_OSMESA=ON -DVTK_USE_X=OFF -DVTK_USE_COCOA=OFF \
  -DVTK_DEFAULT_RENDER_WINDOW_OFFSCREEN=ON -DVTK_OPENGL_HAS_EGL=OFF \
  -DVTK_WRAP_PYTHON=OFF -DVTK_WRAP_JAVA=OFF -DVTK_ENABLE_REMOTE_MODULES=OFF \
  -DVTK_USE_MPI=OFF -DVTK_SMP_IMPLEMENTATION_TYPE=STDThread \
  >"$work/configure.log" 2>&1 || { tail -n 40 "$work/configure.log" >&2; exit 1; }

# Visible progress: Ninja prints [done/total] on every line; show one line in 50.
log "building VTK with OSMesa (about 20 minutes on 2 cores the first time)"
cmake --build "$build" -- -j"$(nproc)" 2>&1 | tee "$work/build.log" |
  awk '/^\[[0-9]+\/[0-9]+\]/ { if (++n % 50 == 0) { split($1, a, /[\[\/\]]/);
         printf "build-osmesa-vtk: %s/%s\n", a[2], a[3]; fflush() } }
       /error|FAILED/ { print; fflush() }' >&2
[ "${PIPESTATUS[0]}" -eq 0 ] || { tail -n 40 "$work/build.log" >&2; exit 1; }
cmake --install "$build" >"$work/install.log" 2>&1 || { tail -n 40 "$work/install.log" >&2; exit 1; }
echo "${modules[*]}" >"$stamp"
log "installed $(du -sh "$prefix" | cut -f1) into $prefix"
echo "$prefix"
