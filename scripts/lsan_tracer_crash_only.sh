#!/usr/bin/env bash
# Exit 0 when every test a ctest log (--output-on-failure) lists as failed failed only because
# LeakSanitizer's stop-the-world tracer crashed at the exit of a passing test ("Tracer caught
# signal 11 ... LeakSanitizer has encountered a fatal error", google/sanitizers#1353: a known
# intermittent crash of the tool itself, not a report), and nothing else went wrong; 1 otherwise.
# Usage: scripts/lsan_tracer_crash_only.sh CTEST_LOG
set -euo pipefail
log=$1
failed=$(sed -n '/The following tests FAILED:/,$p' "$log" | grep -cE '^[[:space:]]+[0-9]+ - ' || true)
crashes=$(grep -c 'LeakSanitizer has encountered a fatal error' "$log" || true)
reports=$(grep -cE 'ERROR: (AddressSanitizer|LeakSanitizer: detected)|runtime error:|\[  FAILED  \]' "$log" || true)
echo "lsan_tracer_crash_only: $failed failed tests, $crashes tracer crashes, $reports other reports"
[ "$failed" -gt 0 ] && [ "$reports" -eq 0 ] && [ "$crashes" -ge "$failed" ]
