#!/usr/bin/env bash
# CI: build the libFuzzer targets with clang (ASan + UBSan, coverage on the whole tree) and run
# each for SCBT_FUZZ_SECONDS (default 60) from its committed corpus in fuzz/corpus/<target>.
# New inputs go to the build folder, so the committed corpus only changes by hand.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${SCBT_FUZZ_BUILD:-build-fuzz}
seconds=${SCBT_FUZZ_SECONDS:-60}
CXX=clang++ cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Debug -DSCBT_BUILD_FUZZERS=ON \
  -DSCBT_BUILD_TESTS=OFF -DSCBT_BUILD_PYTHON=OFF -DSCBT_BUILD_ROS=OFF \
  -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g -fno-omit-frame-pointer -fsanitize=fuzzer-no-link,address,undefined" \
  >/dev/null
cmake --build "$build" -j2 --target fuzz_polygon_parser fuzz_tracker
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# intercept_tls_get_addr=0: see ci_sanitizers.sh (LeakSanitizer's tracer crashes after ORB matching).
export LSAN_OPTIONS="suppressions=$PWD/scripts/lsan_suppressions.txt:print_suppressions=0:intercept_tls_get_addr=0"
for target in polygon_parser tracker; do
  corpus="$build/corpus/$target"
  mkdir -p "$corpus"
  "$build/fuzz/fuzz_$target" -max_total_time="$seconds" -print_final_stats=1 -max_len=4096 \
    -timeout=10 -rss_limit_mb=2048 -artifact_prefix="$build/" "$corpus" "fuzz/corpus/$target" 2>"$build/fuzz_$target.log" || {
    tail -n 60 "$build/fuzz_$target.log"
    exit 1
  }
  echo "fuzz_$target: $(grep -E 'stat::number_of_executed_units' "$build/fuzz_$target.log") in ${seconds} s"
done
