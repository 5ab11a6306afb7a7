#!/usr/bin/env bash
# Fuzz smoke run: builds the fuzz targets (clang, libFuzzer, ASan + UBSan) into BUILD_DIR,
# replays every input under tests/fuzz/regressions/, then fuzzes each target for SECONDS from
# the generated seed corpus. Exits 0 with no finding, 1 on any crash, sanitizer report or
# time-out, 77 (skip) without clang's libFuzzer.
# Usage: smoke.sh BUILD_DIR [SECONDS]
set -u
build=$1 seconds=${2:-30}
here=$(cd "$(dirname "$0")" && pwd)
if ! command -v clang++ >/dev/null; then echo "skip: clang++ is not installed"; exit 77; fi
cmake -S "$here" -B "$build" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=Release >"$build.log" 2>&1 &&
  cmake --build "$build" -j2 >>"$build.log" 2>&1 || { tail -20 "$build.log"; echo "FAIL: the fuzz targets do not build"; exit 1; }
python3 "$here/make_seeds.py" "$build/seeds" || exit 1
failures=0
for kind in mesh field; do
  target="$build/${kind}_reader_fuzz"
  if [ -d "$here/regressions/$kind" ] && [ -n "$(ls -A "$here/regressions/$kind")" ]; then
    "$target" "$here/regressions/$kind"/* >"$build/$kind.replay.log" 2>&1 ||
      { tail -30 "$build/$kind.replay.log"; echo "FAIL: a $kind regression input fails again"; failures=$((failures + 1)); }
  fi
  rm -rf "$build/corpus/$kind" "$build/artifacts/$kind" && mkdir -p "$build/corpus/$kind" "$build/artifacts/$kind"
  "$target" "$build/corpus/$kind" "$build/seeds/$kind" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
    -artifact_prefix="$build/artifacts/$kind/" >"$build/$kind.fuzz.log" 2>&1 ||
    { tail -30 "$build/$kind.fuzz.log"; echo "FAIL: fuzzing the $kind reader found $(ls "$build/artifacts/$kind")"; failures=$((failures + 1)); }
  echo "$kind reader: $(grep -o 'Done [0-9]* runs in [0-9]* second(s)' "$build/$kind.fuzz.log")"
done
[ $failures -eq 0 ] || exit 1
echo "fuzz smoke: no finding"
