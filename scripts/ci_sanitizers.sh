#!/usr/bin/env bash
# CI: the whole test suite under AddressSanitizer + UndefinedBehaviorSanitizer (gcc, -O1), then
# `scbt track` over every frame of the dataset when it is present. Any report fails the run.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${SCBT_ASAN_BUILD:-build-asan}
flags="-O1 -g -fno-omit-frame-pointer -fsanitize=address,undefined -fno-sanitize-recover=undefined"
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="$flags" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" -DSCBT_BUILD_PYTHON=OFF -DSCBT_BUILD_ROS=OFF >/dev/null
cmake --build "$build" -j2
export ASAN_OPTIONS=detect_leaks=1:halt_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# intercept_tls_get_addr=0: with it on, LeakSanitizer's tracer crashes at exit (signal 11) on
# every run of a test whose process used ORB feature matching (tracker/scene_keyframes), reading
# dynamic TLS of OpenCV's threads; use_tls=0 instead reports a false 1,280-byte leak held in TLS.
export LSAN_OPTIONS="suppressions=$PWD/scripts/lsan_suppressions.txt:print_suppressions=0:intercept_tls_get_addr=0"
# The dataset guards run here too, with the Release build's limits (the ASan build's figures are
# the Release build's): DatasetRegression (every frame) and DatasetStress (300 frames per
# sequence under 12 conditions), about 3.5 CPU minutes together. The RSS soak is the Release
# build's job, since ASan's quarantine grows resident memory on purpose (LSan checks leaks here
# instead).
# A test that failed only by LeakSanitizer's own tracer crashing at its exit is run once more
# (scripts/lsan_tracer_crash_only.sh); any other failure or report fails the run.
log=$(mktemp)
if ! ctest --test-dir "$build" --output-on-failure -j2 \
  -E "${SCBT_ASAN_EXCLUDE:-^soak\$}" 2>&1 | tee "$log"; then
  bash scripts/lsan_tracer_crash_only.sh "$log"
  ctest --test-dir "$build" --output-on-failure --rerun-failed
fi
rm -f "$log"

dataset=${SCBT_DATASET:-../shared/scbt-dataset}
if [ -d "$dataset/OriginalVideosAVI" ]; then
  out=$(mktemp -d)
  for seq_dir in "$dataset"/OriginalVideosAVI/*/; do
    seq=$(basename "$seq_dir")
    start=$(date +%s)
    head -n 1 "$dataset/GroundTruthByPolygons/${seq}_TrackingGroundTruth.txt" >"$out/init.txt"
    "$build/src/scbt/cli/scbt" track "$seq_dir" --init "$out/init.txt" -o "$out/$seq.txt" -q
    echo "asan: $seq $(wc -l <"$out/$seq.txt") frames clean in $(($(date +%s) - start)) s"
  done
  rm -rf "$out"
elif [ "${CI:-}" = true ]; then
  echo "asan: CI=true and the dataset is missing ($dataset); set SCBT_DATASET" >&2
  exit 1
else
  echo "asan: dataset not found ($dataset): scbt track over it skipped"
fi
