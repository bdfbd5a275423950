#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
# Install the Debian packages of scripts/package-deb.sh in a clean root of the same release and
# test them there, as a user would have them after `apt install`:
#
#   bash scripts/test-deb.sh          Debian 12: build-deb/*.deb in a clean bookworm root
#   bash scripts/test-deb.sh --sid    Debian sid: build-deb-sid/*.deb in a clean sid root
#   bash scripts/test-deb.sh --prepare [--sid]   only make the clean root (.ci/run does it in
#                                     the background while the first legs build)
#
# The clean root is a debootstrap minbase of the release, made once and cached bare in
# ~/.cache/vtk-bloom/clean-root-SUITE (VTKBLOOM_CACHE): debootstrap comes from the release's
# archive as a .deb and runs unpacked, as in scripts/sid-root.sh; the host's packages are not
# touched. Each test runs in a private mount namespace on an overlay of that bare root, thrown
# away when the test exits, so that every test starts from the same clean root; the .debs apt
# downloads are kept in ~/.cache/vtk-bloom/clean-root-SUITE-archives for the next test.
# In it, scripts/lib/deb-test-in-root.sh installs the packages with apt (with no
# recommends), then, with no PYTHONPATH and no LD_LIBRARY_PATH: the tool, `import vtkbloom` and a
# numpy round trip, a find_package(VTKBloom) consumer built with CMake and run, ParaView's
# pvbatch loading the plugin by its name, and lintian on the packages. The exit status is the
# test's.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
prepare=false
if [ "${1:-}" = --prepare ]; then
  prepare=true
  shift
fi
case ${1:-} in
  '') suite=bookworm debs=$root/build-deb ;;
  --sid) suite=sid debs=$root/build-deb-sid ;;
  *) echo "usage: bash scripts/test-deb.sh [--prepare] [--sid]" >&2; exit 2 ;;
esac
cache=${VTKBLOOM_CACHE:-$HOME/.cache/vtk-bloom}
bare=$cache/clean-root-$suite
archives=$cache/clean-root-$suite-archives
mirror=http://deb.debian.org/debian
start=$SECONDS

SUDO=""
[ "$(id -u)" -ne 0 ] && SUDO="sudo"

# The bare root (scripts/lib/debootstrap.sh), with the updates and security archives a Debian 12
# system has.
source "$root/scripts/lib/debootstrap.sh"
bootstrap() {
  debootstrap_into "$suite" "$bare.tmp" test-deb || return 1
  if [ "$suite" = bookworm ]; then
    { echo "deb $mirror bookworm-updates main"
      echo "deb http://deb.debian.org/debian-security bookworm-security main"; } |
      $SUDO tee -a "$bare.tmp/etc/apt/sources.list" >/dev/null
  fi
  $SUDO rm -rf "$bare.tmp/var/cache/apt/archives"/*.deb
  $SUDO mv "$bare.tmp" "$bare"
}
[ -x "$bare/usr/bin/apt-get" ] || bootstrap
mkdir -p "$archives/partial"
if $prepare; then
  echo "test-deb: the clean $suite root is ready in $bare ($((SECONDS - start)) s)"
  exit 0
fi
ls "$debs"/*.deb >/dev/null 2>&1 || {
  echo "test-deb: no packages in $debs; run scripts/package-deb.sh${1:+ $1} first" >&2
  exit 1
}

# A fresh overlay of the bare root, in a private mount namespace: proc, sys, dev, the project
# at its own path (for the .debs and the test script), the archive cache; then chroot.
run=$(mktemp -d "$cache/clean-root-$suite-run.XXXXXX")
trap '$SUDO rm -rf "$run"' EXIT
mkdir -p "$run/upper" "$run/work" "$run/merged"
echo "test-deb: testing $(cd "$debs" && echo *.deb) in a clean $suite root"
status=0
$SUDO unshare -m --propagation private -- /bin/bash -c '
  set -e
  bare=$1 run=$2 project=$3 archives=$4
  shift 4
  root=$run/merged
  mount -t overlay overlay -o "lowerdir=$bare,upperdir=$run/upper,workdir=$run/work" "$root"
  mount -t proc proc "$root/proc"
  mount --rbind /sys "$root/sys"
  mount --rbind /dev "$root/dev"
  mount -t tmpfs tmpfs "$root/dev/shm"
  mount -t tmpfs tmpfs "$root/tmp"
  cp /etc/resolv.conf "$root/etc/resolv.conf" 2>/dev/null || true
  mkdir -p "$root$project"
  mount --bind "$project" "$root$project"
  mount --bind "$archives" "$root/var/cache/apt/archives"
  exec chroot "$root" /usr/bin/env -i HOME=/root PATH=/usr/local/bin:/usr/bin:/bin:/usr/sbin:/sbin \
    LANG=C.UTF-8 TERM="${TERM:-dumb}" /bin/bash "$@"
' test-deb "$bare" "$run" "$root" "$archives" \
  "$root/scripts/lib/deb-test-in-root.sh" "$debs" "$suite" || status=$?
if [ "$status" -eq 0 ]; then
  echo "test-deb: $suite: all passed ($((SECONDS - start)) s)"
else
  echo "test-deb: $suite: FAILED ($((SECONDS - start)) s)" >&2
fi
exit "$status"
