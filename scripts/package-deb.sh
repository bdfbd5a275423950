#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
# Debian packages of vtk-bloom for the Debian release this runs in:
#
#   bash scripts/package-deb.sh          this machine's release (Debian 12): build-deb/*.deb
#   bash scripts/package-deb.sh --sid    Debian sid, inside the sid root (scripts/sid-root.sh):
#                                        build-deb-sid/*.deb
#
# Five packages, split as Debian splits a library (packaging/debian/control says what is in
# each): libvtkbloom0.1 (the shared libraries), libvtkbloom-dev (headers, CMake package),
# vtk-bloom (the tool), python3-vtkbloom (the Python package), paraview-vtkbloom (the ParaView
# plugin, in ParaView's own plugin directory). The steps are those of debhelper, done with
# dpkg-dev's own tools:
# 1. the project is built into BUILD/cmake (Release, Debian's hardening flags from
#    dpkg-buildflags, no RPATH: the libraries sit in the system's library directory), the
#    plugin into BUILD/paraview (in scripts/lib/paraview-env.sh's environment, as
#    scripts/build-paraview-plugin.sh does), both with ccache;
# 2. `cmake --install --strip` of both into BUILD/pkg/debian/tmp, with prefix /usr;
# 3. each package takes the paths its packaging/debian/PACKAGE.install names; a file that no
#    package takes, and that packaging/debian/not-installed does not name, fails the build;
# 4. copyright (from LICENSE) and changelog.Debian.gz in each /usr/share/doc/PACKAGE, shlibs
#    and the ldconfig trigger for the library package, md5sums;
# 5. dpkg-shlibdeps computes each package's library dependencies, dpkg-gencontrol writes its
#    control file (the version is the project's, 0.1.0-1, with ~deb12 on Debian 12), and
#    dpkg-deb builds it.
# scripts/test-deb.sh installs the packages in a clean root of the same release and tests them.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
case ${1:-} in
  '') out=$root/build-deb ;;
  --in-sid-root) out=$root/build-deb-sid ;;
  --sid) exec bash "$root/scripts/sid-root.sh" bash "$root/scripts/package-deb.sh" --in-sid-root ;;
  *) echo "usage: bash scripts/package-deb.sh [--sid]" >&2; exit 2 ;;
esac
debian=$root/packaging/debian
jobs=${VTKBLOOM_JOBS:-$(nproc)}
start=$SECONDS

bash "$root/scripts/install-deps.sh" # nothing outside Debian 12: the sid root has it all
for tool in dpkg-buildflags dpkg-shlibdeps dpkg-gencontrol dpkg-deb; do
  command -v "$tool" >/dev/null || { echo "package-deb: $tool is missing (dpkg-dev)" >&2; exit 1; }
done
multiarch=$(dpkg-architecture -qDEB_HOST_MULTIARCH)

# Debian's compiler flags (hardening: stack protector, fortify, relro, bind now), without -g
# (there is no debug-symbols package) and without the source path mapped, so that ccache shares
# the objects between clones (CCACHE_BASEDIR).
export DEB_BUILD_MAINT_OPTIONS="hardening=+all reproducible=-fixfilepath,-fixdebugpath"
export DEB_CFLAGS_MAINT_STRIP=-g DEB_CXXFLAGS_MAINT_STRIP=-g
CFLAGS="$(dpkg-buildflags --get CFLAGS) $(dpkg-buildflags --get CPPFLAGS)"
CXXFLAGS="$(dpkg-buildflags --get CXXFLAGS) $(dpkg-buildflags --get CPPFLAGS)"
LDFLAGS=$(dpkg-buildflags --get LDFLAGS)
export CFLAGS CXXFLAGS LDFLAGS
launcher=()
if command -v ccache >/dev/null; then
  launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  export CCACHE_BASEDIR=${CCACHE_BASEDIR:-$root}
fi

echo "package-deb: building the project into $out/cmake"
cmake -S "$root" -B "$out/cmake" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX=/usr \
  -DBUILD_TESTING=OFF -DVTKBLOOM_BUILD_BENCHMARKS=OFF -DCMAKE_SKIP_INSTALL_RPATH=ON \
  "${launcher[@]}"
cmake --build "$out/cmake" -j "$jobs"
echo "package-deb: building the ParaView plugin into $out/paraview"
# As scripts/build-paraview-plugin.sh, with prefix /usr: ParaView's own plugin directory,
# lib/<multiarch>/paraview-X.Y/plugins. The plugin's libraries sit beside it: $ORIGIN finds them.
bash "$root/scripts/lib/paraview-env.sh"
bash "$root/scripts/lib/paraview-env.sh" cmake -S "$root/ParaView" -B "$out/paraview" -G Ninja \
  -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX=/usr '-DCMAKE_INSTALL_RPATH=$ORIGIN' \
  "${launcher[@]}"
bash "$root/scripts/lib/paraview-env.sh" cmake --build "$out/paraview" -j "$jobs"

work=$out/pkg
rm -rf "$work" "$out"/*.deb
mkdir -p "$work/debian"
tmp=$work/debian/tmp
DESTDIR=$tmp cmake --install "$out/cmake" >/dev/null
DESTDIR=$tmp cmake --install "$out/paraview" >/dev/null
# Stripped as dh_strip strips: no symbol table, no .comment and .note sections.
find "$tmp" -type f -name '*.so*' -exec strip --remove-section=.comment --remove-section=.note \
  --strip-unneeded {} +
strip --remove-section=.comment --remove-section=.note "$tmp"/usr/bin/*

packages=$(sed -n 's/^Package: *//p' "$debian/control")
upstream=$(sed -n 's/^CMAKE_PROJECT_VERSION:STATIC=//p' "$out/cmake/CMakeCache.txt")
soversion=${upstream%.*}
grep -qx "libvtkbloom$soversion" <<<"$packages" || {
  echo "package-deb: the libraries' SONAME version is $soversion: rename libvtkbloom* in" \
    "packaging/debian/control (and its .install file)" >&2
  exit 1
}

# The version and the changelog: 0.1.0-1 in sid, 0.1.0-1~deb12 in Debian 12, so that an upgrade
# to the next release takes its own package.
. /etc/os-release
release=$(cut -d. -f1 /etc/debian_version)
if [[ $release =~ ^[0-9]+$ ]]; then
  version=$upstream-1~deb$release distribution=$VERSION_CODENAME
else
  version=$upstream-1 distribution=unstable
fi
commit=$(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo unknown)
date=$(git -C "$root" log -1 --format=%cD 2>/dev/null || date -R)
maintainer=$(sed -n 's/^Maintainer: *//p' "$debian/control")
cp "$debian/control" "$work/debian/control"
cat >"$work/debian/changelog" <<EOF
vtk-bloom ($version) $distribution; urgency=medium

  * Built by scripts/package-deb.sh from commit $commit.

 -- $maintainer  $date
EOF
# DEP-5 copyright from LICENSE: its copyright line, then the licence text itself.
{
  echo "Format: https://www.debian.org/doc/packaging-manuals/copyright-format/1.0/"
  echo "Upstream-Name: vtk-bloom"
  echo
  echo "Files: *"
  echo "Copyright: $(sed -n 's/^Copyright (c) *//p' "$root/LICENSE" | head -n 1)"
  echo "License: BSD-3-Clause"
  echo
  echo "License: BSD-3-Clause"
  sed -n '/^Redistribution/,$p' "$root/LICENSE" | sed -e 's/^$/./' -e 's/^/ /'
} >"$work/debian/copyright"

# 3. Each package takes its paths out of debian/tmp (as dh_install does).
for pkg in $packages; do
  dest=$work/debian/$pkg
  mkdir -p "$dest"
  while read -r pattern; do
    [ -n "$pattern" ] || continue
    matches=$(cd "$tmp" && compgen -G "$pattern" || true)
    [ -n "$matches" ] || { echo "package-deb: $pkg.install: nothing matches $pattern" >&2; exit 1; }
    for path in $matches; do
      mkdir -p "$dest/$(dirname "$path")"
      mv "$tmp/$path" "$dest/$path"
    done
  done <"$debian/$pkg.install"
done
# What no package took (as dh_missing --fail-missing does).
while read -r pattern; do
  [ -n "$pattern" ] && [ "${pattern:0:1}" != "#" ] || continue
  (cd "$tmp" && for path in $pattern; do [ -e "$path" ] && rm -rf "$path"; done)
done <"$debian/not-installed"
left=$(cd "$tmp" && find . ! -type d | sort)
if [ -n "$left" ]; then
  echo "package-deb: installed, but in no package (packaging/debian/*.install, not-installed):" >&2
  echo "$left" >&2
  exit 1
fi

# A manual page from the tool's own --help (as help2man would make it).
man=$work/debian/vtk-bloom/usr/share/man/man1
mkdir -p "$man"
{
  echo ".TH VTK-BLOOM 1 \"\" \"vtk-bloom $upstream\" \"User Commands\""
  echo ".SH NAME"
  echo "vtk-bloom \\- HDR bloom and blur of OpenEXR images, bloom rendering of VTK datasets"
  echo ".SH DESCRIPTION"
  echo ".nf"
  "$out/cmake/bin/vtk-bloom" --help | sed -e 's/\\/\\e/g' -e 's/^/\\\&/'
  echo ".fi"
} | gzip -9n >"$man/vtk-bloom.1.gz"

plugin_dir=$(cd "$work/debian/paraview-vtkbloom" && echo usr/lib/*/paraview-*/plugins/VTKBloom)
lib_dir=usr/lib/$multiarch
python=$(/usr/bin/python3 -c 'import sys; print("%d.%d" % sys.version_info[:2])')
python_next=$(/usr/bin/python3 -c 'import sys; print("%d.%d" % (sys.version_info[0], sys.version_info[1] + 1))')

# 4. Documentation, permissions, maintainer files.
for pkg in $packages; do
  dest=$work/debian/$pkg
  doc=$dest/usr/share/doc/$pkg
  install -D -m 644 "$work/debian/copyright" "$doc/copyright"
  gzip -9n <"$work/debian/changelog" >"$doc/changelog.Debian.gz"
  if [ -f "$debian/$pkg.README.Debian" ]; then
    sed -e "s|@PLUGIN_DIR@|/$plugin_dir|g" "$debian/$pkg.README.Debian" >"$doc/README.Debian"
  fi
  # As dh_fixperms: directories 755, files (shared libraries too) 644, programs 755.
  find "$dest" -type d -exec chmod 755 {} +
  find "$dest" -type f -exec chmod 644 {} +
  [ -d "$dest/usr/bin" ] && chmod 755 "$dest"/usr/bin/*
  mkdir -p "$dest/DEBIAN"
  echo "misc:Depends=" >"$work/debian/$pkg.substvars"
done

# The library package: shlibs (what a package linking these libraries depends on) and the
# ldconfig trigger (as dh_makeshlibs).
libpkg=libvtkbloom$soversion
for lib in "$work/debian/$libpkg/$lib_dir"/*.so.*; do
  [ -L "$lib" ] && continue
  soname=$(objdump -p "$lib" | sed -n 's/^ *SONAME *//p')
  echo "${soname%%.so.*} ${soname#*.so.} $libpkg (>= $upstream)"
done >"$work/debian/$libpkg/DEBIAN/shlibs"
echo "activate-noawait ldconfig" >"$work/debian/$libpkg/DEBIAN/triggers"
chmod 644 "$work/debian/$libpkg/DEBIAN/"*

# 5. Dependencies, control files, packages.
echo "python3:Depends=python3 (>= $python~), python3 (<< $python_next)" \
  >>"$work/debian/python3-vtkbloom.substvars"
cd "$work"
for pkg in $packages; do
  elves=$(find "debian/$pkg" -type f \( -name '*.so*' -o -path '*/usr/bin/*' \) | sort)
  if [ -n "$elves" ]; then
    # Libraries of packages being built are found in their trees: the shared libraries, and
    # the plugin's own libraries beside it.
    # shellcheck disable=SC2086
    dpkg-shlibdeps -T"debian/$pkg.substvars" -l"debian/$libpkg/$lib_dir" \
      -l"debian/paraview-vtkbloom/$plugin_dir" $elves
  fi
  dpkg-gencontrol -p"$pkg" -P"debian/$pkg" -T"debian/$pkg.substvars"
  (cd "debian/$pkg" && find . -type f ! -path './DEBIAN/*' -printf '%P\0' | LC_ALL=C sort -z |
    xargs -0r md5sum >DEBIAN/md5sums)
  dpkg-deb --root-owner-group -Zxz --build "debian/$pkg" "$out/" >/dev/null
done
echo "package-deb: $((SECONDS - start)) s; Debian $(cat /etc/debian_version), version $version:"
ls -l "$out"/*.deb
