#!/usr/bin/env bash
# Installs what the project needs on a fresh Debian bookworm machine (run as root) and
# fetches the MeshLab 2020.09 SDK (vcglib + MeshLab headers) from Debian's source package
# into third_party/ (ignored by git). Idempotent: a second run does nothing it need not do.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
# shellcheck source=lib/debian.bash
source "$here/scripts/lib/debian.bash"

packages=(build-essential cmake pkg-config ca-certificates xz-utils
          meshlab qtbase5-dev libqt5opengl5-dev libqt5xmlpatterns5-dev libglew-dev libeigen3-dev
          liblpsolve55-dev libgtest-dev xvfb xauth xdotool imagemagick zlib1g-dev python3 time
          clang libclang-rt-14-dev python3-numpy)

install_missing_packages setup "${packages[@]}"

sdk="$here/third_party/meshlab-2020.09"
if [ ! -f "$sdk/.complete" ]; then
  echo "setup: fetching the MeshLab 2020.09 SDK from Debian's source package" >&2
  work=$(mktemp -d)
  trap 'rm -rf "$work"' EXIT
  private_apt_source_state "$work" bookworm
  (cd "$work" && apt-get "${PRIVATE_APT[@]}" source --download-only -qq 'meshlab=2020.09+dfsg1-2' >/dev/null)
  orig=$(ls "$work"/meshlab_2020.09*.orig.tar.* | head -1)
  rm -rf "$sdk" && mkdir -p "$sdk"
  tar -xf "$orig" -C "$sdk" --strip-components=1 --wildcards '*/src/common/*' '*/vcglib/vcg/*' '*/vcglib/wrap/*' '*/vcglib/eigenlib/*' 2>/dev/null || \
    tar -xf "$orig" -C "$sdk" --strip-components=1 --wildcards '*/src/common/*' '*/vcglib/vcg/*' '*/vcglib/wrap/*'
  touch "$sdk/.complete"
fi
echo "setup: ready (SDK in $sdk)" >&2
