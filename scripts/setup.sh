#!/usr/bin/env bash
# Installs what the project needs on a fresh Debian bookworm machine (run as root) and
# fetches the MeshLab 2020.09 SDK (vcglib + MeshLab headers) from Debian's source package
# into third_party/ (ignored by git). Idempotent: a second run does nothing it need not do.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)

packages=(build-essential cmake pkg-config ca-certificates xz-utils
          meshlab qtbase5-dev libqt5opengl5-dev libqt5xmlpatterns5-dev libglew-dev libeigen3-dev
          liblpsolve55-dev libgtest-dev xvfb xauth xdotool imagemagick zlib1g-dev python3 time)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}" >&2
  if [ "$(id -u)" -ne 0 ]; then echo "setup: need root to install packages: ${missing[*]}" >&2; exit 1; fi
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

sdk="$here/third_party/meshlab-2020.09"
if [ ! -f "$sdk/.complete" ]; then
  echo "setup: fetching the MeshLab 2020.09 SDK from Debian's source package" >&2
  work=$(mktemp -d)
  trap 'rm -rf "$work"' EXIT
  mkdir -p "$work/lists/partial"
  echo "deb-src [signed-by=/usr/share/keyrings/debian-archive-keyring.gpg] http://deb.debian.org/debian bookworm main" > "$work/src.list"
  A=(-o "Dir::Etc::SourceList=$work/src.list" -o Dir::Etc::SourceParts=/dev/null -o "Dir::State::Lists=$work/lists")
  apt-get "${A[@]}" update -qq
  (cd "$work" && apt-get "${A[@]}" source --download-only -qq 'meshlab=2020.09+dfsg1-2' >/dev/null)
  orig=$(ls "$work"/meshlab_2020.09*.orig.tar.* | head -1)
  rm -rf "$sdk" && mkdir -p "$sdk"
  tar -xf "$orig" -C "$sdk" --strip-components=1 --wildcards '*/src/common/*' '*/vcglib/vcg/*' '*/vcglib/wrap/*' '*/vcglib/eigenlib/*' 2>/dev/null || \
    tar -xf "$orig" -C "$sdk" --strip-components=1 --wildcards '*/src/common/*' '*/vcglib/vcg/*' '*/vcglib/wrap/*'
  touch "$sdk/.complete"
fi
echo "setup: ready (SDK in $sdk)" >&2
