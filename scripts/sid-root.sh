#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
# A Debian sid root with VTK 9.6 and ParaView 6.1, made once and cached, and a command run in it.
#
#   bash scripts/sid-root.sh                    make the root if needed; print its path
#   bash scripts/sid-root.sh COMMAND [ARGS...]  run COMMAND inside it, from the same directory
#
# The root is $VTKBLOOM_SID_ROOT, or ~/.cache/vtk-bloom/sid-root. It is made with debootstrap,
# which comes from Debian's archive as a .deb and runs unpacked: the host's packages are not
# touched. Making it takes a few minutes (about 3 on the 2-core CI machine) and 4.5 GB; later
# calls reuse it. A stamp holding the package list says it is complete; a root whose stamp
# differs is finished by apt.
#
# COMMAND runs in a private mount namespace (nothing stays mounted on the host when it exits)
# with /proc, /sys, /dev, the project and ../shared bound at the paths they have on the host,
# then chroot. The project's build folders are therefore shared with the host, so a leg must
# use build folders of its own. There is no X server in the root: VTK 9.6 renders through EGL.
set -euo pipefail

project=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cache=${VTKBLOOM_CACHE:-$HOME/.cache/vtk-bloom}
root=${VTKBLOOM_SID_ROOT:-$cache/sid-root}

packages=(
  build-essential cmake ninja-build pkg-config ccache git
  libvtk9-dev python3-vtk9 python3-numpy python3-pytest
  libopenexr-dev libimath-dev libgtest-dev libgmock-dev libbenchmark-dev libcli11-dev
  libfftw3-dev zlib1g-dev libegl-mesa0 libgl1-mesa-dri libegl-dev
  paraview-dev python3-paraview openmpi-bin xvfb xauth
  python3-pyvista python3-vedo python3-vedo-examples
  xsltproc qt6-base-dev qt6-tools-dev qt6-tools-dev-tools
)
stamp_text="${packages[*]}"

SUDO=""
[ "$(id -u)" -ne 0 ] && SUDO="sudo"

# The bare root: debootstrap of sid (scripts/lib/debootstrap.sh).
source "$project/scripts/lib/debootstrap.sh"
bootstrap() {
  debootstrap_into sid "$root.tmp" sid-root || exit 1
  $SUDO mv "$root.tmp" "$root"
}

# Runs "$@" chrooted in the root, in a private mount namespace.
enter() {
  local cwd=$PWD
  local shared
  shared=$(cd "$project/.." && pwd)/shared
  $SUDO unshare -m --propagation private -- /bin/bash -c '
    set -e
    root=$1 project=$2 shared=$3 cwd=$4 ccache_dir=$5
    shift 5
    mount -t proc proc "$root/proc"
    mount --rbind /sys "$root/sys"
    mount --rbind /dev "$root/dev"
    mount -t tmpfs tmpfs "$root/dev/shm"
    mount -t tmpfs tmpfs "$root/tmp"
    cp /etc/resolv.conf "$root/etc/resolv.conf" 2>/dev/null || true
    mkdir -p "$root$project" "$root/root"
    mount --bind "$project" "$root$project"
    if [ -d "$shared" ]; then mkdir -p "$root$shared" && mount --bind "$shared" "$root$shared"; fi
    # ccache keeps its cache on the host, so that a later run of the leg compiles nothing.
    mkdir -p "$ccache_dir" "$root/root/.ccache"
    mount --bind "$ccache_dir" "$root/root/.ccache"
    cd "$root$cwd" 2>/dev/null || cd "$root$project"
    exec chroot "$root" /usr/bin/env -i HOME=/root PATH=/usr/local/bin:/usr/bin:/bin:/usr/sbin:/sbin \
      LANG=C.UTF-8 CI="${CI:-}" TERM="${TERM:-dumb}" \
      /bin/bash -c "cd \"\$0\" && exec \"\$@\"" "$cwd" "$@"
  ' sid-root "$root" "$project" "$shared" "$cwd" "$cache/sid-ccache" "$@"
}

# ParaView 6.1.1's CMake package names its Python modules X.so, Debian ships them as
# X.cpython-3NN-<arch>.so; find_package(ParaView) fails until a link X.so sits beside each.
link_paraview_modules() {
  enter /bin/bash -c '
    for f in $(find /usr/lib/python3/dist-packages/paraview -name "*.cpython-*.so"); do
      l=${f%%.cpython-*}.so
      [ -e "$l" ] || ln -s "$(basename "$f")" "$l"
    done'
}

finish() {
  echo "sid-root: installing ${#packages[@]} packages into $root (a few minutes)" >&2
  enter /bin/bash -c 'export DEBIAN_FRONTEND=noninteractive
    apt-get update -q && apt-get install -y -q --no-install-recommends "$@" && apt-get clean' \
    apt "${packages[@]}" >&2
  link_paraview_modules
  echo "$stamp_text" | $SUDO tee "$root/.vtkbloom-stamp" >/dev/null
}

[ -x "$root/usr/bin/apt-get" ] || bootstrap
[ "$(cat "$root/.vtkbloom-stamp" 2>/dev/null)" = "$stamp_text" ] || finish

if [ $# -eq 0 ]; then
  echo "$root"
  exit 0
fi
enter "$@"
