#!/usr/bin/env bash
# Two builds of the tracker compared by the instructions they execute in Tracker::track (valgrind's
# callgrind), a count that does not move with the machine's load; compare_builds.sh gives the wall
# time. Instructions are not time (a memcpy counts a byte as one, vector code looks cheap, cache
# misses and thread wake-ups are free), so take both. Usage:
#   bench/compare_instructions.sh BASE_TRACK_FRAMES NEW_TRACK_FRAMES DATASET_DIR [MAX_FRAMES] [SEQUENCES...]
# The binaries are bench/track_frames.cc built against each checkout (target scbt_track_frames;
# for a checkout without it, copy the file there and build it the same way). MAX_FRAMES (default
# 300) per sequence, the initial one included; the two runs go in parallel. Prints per sequence
# each build's instructions per tracked frame, the new/base ratio and whether the boundaries are
# identical (checksums), then the ratio of the totals.
set -euo pipefail
base=${1:?base scbt_track_frames binary}
new=${2:?new scbt_track_frames binary}
dataset=${3:?dataset folder}
max_frames=${4:-300}
shift $(($# < 4 ? $# : 4))
command -v valgrind > /dev/null || { echo "compare_instructions.sh: valgrind is not installed" >&2; exit 2; }
for binary in "$base" "$new"; do
  [[ -x "$binary" ]] || { echo "compare_instructions.sh: $binary is not an executable" >&2; exit 2; }
done
[[ -d "$dataset/OriginalVideosAVI" ]] ||
  { echo "compare_instructions.sh: $dataset has no OriginalVideosAVI folder" >&2; exit 2; }
[[ "$max_frames" =~ ^([2-9]|[1-9][0-9]+)$ ]] ||
  { echo "compare_instructions.sh: MAX_FRAMES must be >= 2, got $max_frames" >&2; exit 2; }
sequences=("$@")
if [[ ${#sequences[@]} -eq 0 ]]; then
  for folder in "$dataset"/OriginalVideosAVI/*/; do sequences+=("$(basename "$folder")"); done
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# Instructions collected inside Tracker::track (decoding and set-up excluded), and the output line.
count() {
  local tag=$1 binary=$2 sequence=$3
  valgrind --tool=callgrind --callgrind-out-file="$work/$tag.$sequence.cg" \
    --toggle-collect='scbt::Tracker::track(*' "$binary" "$dataset" "$sequence" "$max_frames" \
    > "$work/$tag.$sequence.out" 2> "$work/$tag.$sequence.err" ||
    { echo "compare_instructions.sh: $binary failed on $sequence:" >&2; grep -v '^==' "$work/$tag.$sequence.err" | tail -5 >&2; exit 1; }
  grep -m1 -oE 'Collected : [0-9]+' "$work/$tag.$sequence.err" | grep -oE '[0-9]+' > "$work/$tag.$sequence.ir"
}

printf '%-16s %7s %14s %14s %9s  %s\n' sequence frames "base Ir/frame" "new Ir/frame" new/base boundaries
base_total=0
new_total=0
for sequence in "${sequences[@]}"; do
  count base "$base" "$sequence" &
  base_job=$!
  count new "$new" "$sequence" &
  new_job=$!
  wait "$base_job"
  wait "$new_job"
  frames=$(awk '{print $3}' "$work/base.$sequence.out")
  base_ir=$(cat "$work/base.$sequence.ir")
  new_ir=$(cat "$work/new.$sequence.ir")
  same=identical
  [[ "$(awk '{print $5}' "$work/base.$sequence.out")" == "$(awk '{print $5}' "$work/new.$sequence.out")" ]] ||
    same=DIFFERENT
  awk -v s="$sequence" -v f="$frames" -v b="$base_ir" -v n="$new_ir" -v same="$same" \
    'BEGIN { printf "%-16s %7d %14.0f %14.0f %9.4f  %s\n", s, f, b / f, n / f, n / b, same }'
  base_total=$((base_total + base_ir))
  new_total=$((new_total + new_ir))
done
awk -v b="$base_total" -v n="$new_total" 'BEGIN { printf "%-16s %7s %14s %14s %9.4f\n", "total", "", "", "", n / b }'
