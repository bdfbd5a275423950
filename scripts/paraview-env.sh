#!/usr/bin/env bash
# Make Debian 12's ParaView 5.11 usable beside Debian's VTK 9.1, then run a command in that
# environment:
#
#   bash scripts/paraview-env.sh [COMMAND [ARGS...]]
#
# The set-up is idempotent and cached:
# - apt: paraview-dev (ParaView's libraries, CMake package, pvbatch, and the VTK 9.2 it carries),
#   Open MPI, and the Qt development packages its CMake package asks for, all without
#   recommends. With recommends apt would remove libvtk9-dev and python3-vtk9.
# - python3-paraview conflicts with python3-vtk9 (both install dist-packages/vtkmodules), so it
#   is unpacked, not installed, into ~/.cache/vtk-bloom/paraview-python.
# - ParaView's CMake package checks that its Python modules and pvpython exist where the package
#   would have put them, and a plugin's wrapping reads the hierarchy files that come with them.
#   Three links that no Debian package owns point there: /usr/lib/python3/dist-packages/paraview,
#   /usr/bin/pvpython and /usr/lib/x86_64-linux-gnu/vtk/hierarchy/ParaView.
#
# COMMAND then runs in a private mount namespace in which /usr/lib/python3/dist-packages/
# vtkmodules is ParaView's (VTK 9.2) instead of VTK 9.1's, with PYTHONPATH set to the unpacked
# package. Nothing outside that namespace changes, so the project's VTK 9.1 build, its tests and
# /usr/bin/python3's `import vtk` keep working beside it.
set -euo pipefail

cache=${VTKBLOOM_CACHE:-$HOME/.cache/vtk-bloom}
pvpy=$cache/paraview-python
dist=/usr/lib/python3/dist-packages

SUDO=""
[ "$(id -u)" -ne 0 ] && SUDO="sudo"

packages=(paraview-dev openmpi-bin qtbase5-dev qttools5-dev libqt5svg5-dev libqt5x11extras5-dev
  qtxmlpatterns5-dev-tools libqt5opengl5-dev xvfb xauth)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "paraview-env: installing ${missing[*]}" >&2
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -q >&2
  $SUDO apt-get install -y -q --no-install-recommends "${missing[@]}" >&2
fi
for p in libvtk9-dev python3-vtk9; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    echo "paraview-env: $p is gone; run scripts/install-deps.sh again" >&2
    exit 1
  fi
done

if [ ! -x "$pvpy/usr/bin/pvpython3.11" ]; then
  echo "paraview-env: unpacking python3-paraview into $pvpy" >&2
  tmp=$(mktemp -d)
  (cd "$tmp" && apt-get download python3-paraview >&2)
  rm -rf "$pvpy.tmp" && mkdir -p "$pvpy.tmp"
  dpkg -x "$tmp"/python3-paraview_*.deb "$pvpy.tmp"
  rm -rf "$tmp" "$pvpy" && mv "$pvpy.tmp" "$pvpy"
fi

# A link is made only where nothing is, or where a link of ours already is.
link() {
  local target=$1 name=$2
  if [ -L "$name" ] || [ ! -e "$name" ]; then
    $SUDO ln -sfn "$target" "$name"
  elif [ "$(readlink -f "$name")" != "$(readlink -f "$target")" ]; then
    echo "paraview-env: $name exists and is not ours; not replacing it" >&2
    exit 1
  fi
}
link "$pvpy$dist/paraview" "$dist/paraview"
link "$pvpy/usr/bin/pvpython3.11" /usr/bin/pvpython
# The wrapping hierarchy files of ParaView's VTK, which a plugin's wrapped modules read.
link "$pvpy/usr/lib/x86_64-linux-gnu/vtk/hierarchy/ParaView" /usr/lib/x86_64-linux-gnu/vtk/hierarchy/ParaView

[ $# -eq 0 ] && exit 0

export PYTHONPATH=$pvpy$dist${PYTHONPATH:+:$PYTHONPATH}
# Open MPI refuses root unless told, and must not look for more slots than the cores.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
exec $SUDO unshare -m -- /bin/sh -c '
  mount --bind "$1" "$2" || exit 1
  shift 2
  exec "$@"' paraview-env "$pvpy$dist/vtkmodules" "$dist/vtkmodules" "$@"
