#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
# Install every Debian 12 package vtk-bloom needs to build, test and run.
#
#   bash scripts/install-deps.sh
#
# Idempotent: packages already present are skipped by apt itself.
set -euo pipefail

# The package names below are Debian 12's. The sid root (scripts/sid-root.sh) installs its own.
if ! grep -q '^12\.' /etc/debian_version 2>/dev/null; then
  echo "install-deps: not Debian 12 ($(cat /etc/debian_version 2>/dev/null)); nothing installed"
  exit 0
fi

packages=(
  build-essential cmake ninja-build pkg-config ccache
  libvtk9-dev vtk9 python3-vtk9 python3-numpy python3-pytest
  libopenexr-dev libimath-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  xvfb xauth clang-format libcli11-dev libfftw3-dev valgrind zlib1g-dev python3-vedo
  python3-vedo-examples lintian
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages already installed"
  exit 0
fi

SUDO=""
[ "$(id -u)" -ne 0 ] && SUDO="sudo"
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
$SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
