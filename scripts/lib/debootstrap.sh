# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
# Sourced by scripts/sid-root.sh and scripts/test-deb.sh: a minimal Debian root made without
# touching the host's packages.
#
#   debootstrap_into SUITE TARGET TAG
#
# fetches debootstrap from SUITE's own archive as a .deb, with a private apt state (the host's
# apt lists and sources are not touched), runs it unpacked (--variant=minbase) into TARGET,
# which is made anew, and lets apt in TARGET use an archive whose Release file carries a
# Valid-Until earlier than the clock (sid's can). TAG starts the progress lines on stderr;
# debootstrap's own log is printed only when it fails.
debootstrap_into() {
  local suite=$1 target=$2 tag=$3 mirror=http://deb.debian.org/debian sudo="" tmp
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  tmp=$(mktemp -d)
  mkdir -p "$tmp/lists/partial" "$tmp/cache/archives/partial"
  echo "deb $mirror $suite main" >"$tmp/sources.list"
  local apt_opts=(-o "Dir::State::Lists=$tmp/lists" -o "Dir::Etc::SourceList=$tmp/sources.list"
    -o "Dir::Etc::SourceParts=/dev/null" -o "Dir::Cache=$tmp/cache"
    -o "Acquire::Check-Valid-Until=false" -o "APT::Sandbox::User=root")
  echo "$tag: fetching debootstrap ($suite)" >&2
  apt-get "${apt_opts[@]}" update -q >/dev/null &&
    (cd "$tmp" && apt-get "${apt_opts[@]}" download debootstrap >/dev/null) &&
    dpkg -x "$tmp"/debootstrap_*.deb "$tmp/debootstrap" || { rm -rf "$tmp"; return 1; }
  echo "$tag: debootstrap --variant=minbase $suite into $target" >&2
  $sudo rm -rf "$target"
  if ! $sudo env DEBOOTSTRAP_DIR="$tmp/debootstrap/usr/share/debootstrap" \
    "$tmp/debootstrap/usr/sbin/debootstrap" --variant=minbase \
    --keyring=/usr/share/keyrings/debian-archive-keyring.gpg "$suite" "$target" "$mirror" \
    >"$tmp/debootstrap.log" 2>&1; then
    tail -n 20 "$tmp/debootstrap.log" >&2
    rm -rf "$tmp"
    return 1
  fi
  rm -rf "$tmp"
  echo 'Acquire::Check-Valid-Until "false";' |
    $sudo tee "$target/etc/apt/apt.conf.d/99vtkbloom" >/dev/null
}
