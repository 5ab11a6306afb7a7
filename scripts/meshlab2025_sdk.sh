#!/usr/bin/env bash
# Builds the MeshLab 2025.07 SDK that the FilterPlugin adapter (FCQL_BUILD_PLUGIN_2025) and the
# pymeshlab-like host link against: MeshLab's libmeshlab-common.so and its io_base plugin, from
# Debian's `meshlab` source package in sid (2025.07~dfsg), built with bookworm's Qt 5.15, in
# DOUBLE precision (MESHLAB_BUILD_WITH_DOUBLE_SCALAR): PyMeshLab always builds MeshLab so (its
# wheels report "based on MeshLab 2025.07d"), and its plugin loader refuses a plugin whose
# scalar type differs from its own.
#
# The result is cached OUTSIDE the build tree, in $FCQL_MESHLAB2025_CACHE
# (default /var/cache/fcql/meshlab-2025.07d), with a stamp file; a later run that finds the stamp
# does nothing (~0 s). The first run took 212 s on this 2-core machine (fetch ~3 s, configure
# ~5 s, meshlab-common + io_base ~3.5 min with -j2).
#
# Cache layout:
#   src/                     the unpacked orig tarball (headers: src/src/common, src/src/vcglib)
#   build/                   MeshLab's own CMake build tree
#   lib/libmeshlab-common.so lib/plugins/libio_base.so
#   .complete                stamp: version, sha256 of the tarball, build time
#
# Run as root the first time (it installs the few Debian packages MeshLab's CMake wants).
# Prints the cache folder on stdout, progress on stderr.
set -euo pipefail
# shellcheck source=lib/debian.bash
source "$(dirname "$0")/lib/debian.bash"

cache=${FCQL_MESHLAB2025_CACHE:-/var/cache/fcql/meshlab-2025.07d}
version=2025.07~dfsg
orig_sha256=d22c98d362f2a284e481af8dbfc272b2222f5b9c67b3cf8bec57d1c3161886f4
jobs=${FCQL_MESHLAB2025_JOBS:-2}

if [ -f "$cache/.complete" ] && [ -f "$cache/lib/libmeshlab-common.so" ] && [ -f "$cache/lib/plugins/libio_base.so" ]; then
  echo "meshlab2025_sdk: cached in $cache" >&2
  echo "$cache"
  exit 0
fi

# ---- Debian packages MeshLab 2025.07's CMake needs for meshlab-common + io_base (idempotent) ----
packages=(build-essential cmake ca-certificates xz-utils
          qtbase5-dev libqt5opengl5-dev libqt5xmlpatterns5-dev libglew-dev libeigen3-dev
          libglu1-mesa-dev mesa-common-dev)
install_missing_packages meshlab2025_sdk "${packages[@]}"

start=$(date +%s)
mkdir -p "$cache"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# ---- fetch the source package through a private apt state (no change to /etc/apt) ----
orig="$work/meshlab_${version}.orig.tar.xz"
echo "meshlab2025_sdk: fetching Debian's meshlab source package (sid)" >&2
private_apt_source_state "$work" sid
# Unpinned first (whatever sid has now), then the revision known to work. Only the orig tarball
# is used (the Debian patches touch neither meshlab-common nor io_base in a way that matters
# here), so a missing .dsc/.debian.tar.xz of the newest revision (seen: -4 answering 404) is fine.
(cd "$work" && apt-get "${PRIVATE_APT[@]}" source --download-only -qq meshlab >/dev/null 2>&1) || true
if [ ! -f "$orig" ]; then
  (cd "$work" && apt-get "${PRIVATE_APT[@]}" source --download-only -qq "meshlab=${version}-2" >/dev/null 2>&1) || true
fi
if [ ! -f "$orig" ]; then
  echo "meshlab2025_sdk: 'apt-get source meshlab' (sid) through this machine's configured Debian archive gave" \
       "no meshlab_${version}.orig.tar.xz; check that the archive is reachable and still carries meshlab ${version}," \
       "or put the tarball (sha256 $orig_sha256) into $cache/ and run this script again" >&2
  exit 1
fi
echo "$orig_sha256  $orig" | sha256sum -c --quiet - || {
  echo "meshlab2025_sdk: the orig tarball's sha256 differs from the one this script was written for" >&2; exit 1; }

rm -rf "$cache/src" "$cache/lib" "$cache/.complete"
mkdir -p "$cache/src"
tar -xJf "$orig" -C "$cache/src" --strip-components=1

# ---- build meshlab-common and io_base only ----
echo "meshlab2025_sdk: configuring (log: $cache/build.log)" >&2
cmake -S "$cache/src" -B "$cache/build" -DCMAKE_BUILD_TYPE=Release \
  -DMESHLAB_BUILD_ONLY_LIBRARIES=ON -DMESHLAB_BUILD_MINI=ON -DMESHLAB_BUILD_WITH_DOUBLE_SCALAR=ON \
  -DMESHLAB_PLUGINS="meshlabplugins/io_base" \
  -DMESHLAB_ALLOW_BUNDLED_SOURCE_GLEW=OFF -DVCG_ALLOW_BUNDLED_EIGEN=OFF \
  -DMESHLAB_ALLOW_OPTIONAL_EXTERNAL_LIBRARIES=OFF \
  -DOpenGL_GL_PREFERENCE=LEGACY >"$cache/build.log" 2>&1 || {
  tail -30 "$cache/build.log" >&2; exit 1; }
echo "meshlab2025_sdk: building meshlab-common and io_base with -j$jobs (~4 min on 2 cores)" >&2
cmake --build "$cache/build" -j"$jobs" --target meshlab-common io_base >>"$cache/build.log" 2>&1 || {
  tail -30 "$cache/build.log" >&2; exit 1; }

common_so=$(find "$cache/build" -name 'libmeshlab-common.so' | head -1)
io_base_so=$(find "$cache/build" -name 'libio_base.so' | head -1)
if [ -z "$common_so" ] || [ -z "$io_base_so" ]; then
  echo "meshlab2025_sdk: build finished without libmeshlab-common.so or libio_base.so" >&2; exit 1
fi
mkdir -p "$cache/lib/plugins"
cp -L "$common_so" "$cache/lib/libmeshlab-common.so"
cp -L "$io_base_so" "$cache/lib/plugins/libio_base.so"
end=$(date +%s)
printf 'version=%s\nscalar=double\nsha256=%s\nbuilt=%s\nseconds=%s\n' "$version" "$orig_sha256" "$(date -u +%FT%TZ)" "$((end - start))" \
  > "$cache/.complete"
echo "meshlab2025_sdk: done in $((end - start)) s, cached in $cache" >&2
echo "$cache"
