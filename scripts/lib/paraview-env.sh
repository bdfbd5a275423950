#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
# Make ParaView usable beside the system VTK, then run a command in that environment:
#
#   bash scripts/lib/paraview-env.sh [COMMAND [ARGS...]]
#
# On Debian 12 (ParaView 5.11 beside VTK 9.1) the set-up is idempotent and cached:
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
#
# Where ParaView and its Python come as ordinary packages beside the system VTK (ParaView 6.1
# in Debian sid, built on sid's VTK 9.6; see scripts/sid-root.sh), none of that is needed:
# COMMAND runs as it is, with only the Open MPI settings below.
set -euo pipefail

# Open MPI refuses root unless told, and must not look for more slots than the cores. Open MPI
# 4 (Debian 12) reads OMPI_MCA_rmaps_base_oversubscribe; Open MPI 6 (PRRTE, sid) reads
# PRTE_MCA_rmaps_default_mapping_policy.
mpi_env() {
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
  export PRTE_ALLOW_RUN_AS_ROOT=1 PRTE_ALLOW_RUN_AS_ROOT_CONFIRM=1
  export OMPI_MCA_rmaps_base_oversubscribe=1
  export PRTE_MCA_rmaps_default_mapping_policy=:oversubscribe
}

if ! grep -q '^12\.' /etc/debian_version 2>/dev/null; then
  if ! dpkg-query -W -f='${Status}' python3-paraview 2>/dev/null | grep -q "install ok installed"; then
    echo "paraview-env: ParaView's Python (python3-paraview) is not installed here" >&2
    exit 1
  fi
  [ $# -eq 0 ] && exit 0
  mpi_env
  exec "$@"
fi

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
mpi_env
exec $SUDO unshare -m -- /bin/sh -c '
  mount --bind "$1" "$2" || exit 1
  shift 2
  exec "$@"' paraview-env "$pvpy$dist/vtkmodules" "$dist/vtkmodules" "$@"
