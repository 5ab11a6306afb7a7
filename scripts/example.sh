#!/usr/bin/env bash
# Set-up, build and run the main job on a built-in example mesh; prints where outputs went.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
example=${1:-rounded_box}
out="out/$example"
./build/bin/fcql layout --example "$example" --out "$out"
echo "outputs in $(pwd)/$out:"
ls -l "$out"
