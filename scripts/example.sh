#!/usr/bin/env bash
# Set-up, build and run the main job on a built-in example mesh; prints where outputs went.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
example=${1:-rounded_box}
out="out/$example"
./build/bin/fcql run --example "$example" --out "$out"
./build/bin/fcql render "$out" --view both --size 480 --out "$out/picture.png"
echo "outputs in $(pwd)/$out:"
ls -l "$out"
