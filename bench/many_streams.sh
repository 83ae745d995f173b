#!/usr/bin/env bash
# Many streams: N concurrent `scbt track` processes, each pinned to its own core, must each keep
# their single-stream speed (within 10 %). Usage:
#   bench/many_streams.sh SCBT_BINARY DATASET_DIR [N] [SEQUENCE] [MAX_FRAMES] [ROUNDS]
# Each round runs the sequence alone on each core 0..N-1 in turn, then on all N cores at once.
# Per core, the slow-down is the median over rounds of its concurrent mean tracking time per
# frame (total_ms from --csv, decoding excluded) against the median of its own lone runs: cores
# of a virtual machine need not be equally fast, and its speed drifts from minute to minute, so
# a core is compared with itself, in alternation. The process CPU time per frame (cpu_ms,
# decoding included) and the load average tell stream interference from time-sharing with
# other jobs on a shared machine.
set -euo pipefail
scbt=${1:?scbt binary}
dataset=${2:?dataset folder}
n=${3:-$(nproc)}
sequence=${4:-Bowl}
max_frames=${5:-0}
rounds=${6:-5}
frames="$dataset/OriginalVideosAVI/$sequence"
init="$dataset/GroundTruthByPolygons/${sequence}_TrackingGroundTruth.txt"
[[ -x "$scbt" ]] || { echo "many_streams.sh: $scbt is not an executable" >&2; exit 2; }
[[ "$n" =~ ^[1-9][0-9]*$ && "$n" -le "$(nproc)" ]] ||
  { echo "many_streams.sh: N must be 1..$(nproc) (one stream per core), got $n" >&2; exit 2; }
[[ "$rounds" =~ ^[1-9][0-9]*$ ]] || { echo "many_streams.sh: ROUNDS must be >= 1, got $rounds" >&2; exit 2; }
[[ -d "$frames" ]] || { echo "many_streams.sh: no frames folder $frames" >&2; exit 2; }
[[ -f "$init" ]] || { echo "many_streams.sh: no ground truth $init" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

mean_ms() {  # mean of the total_ms column of a track CSV
  awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "total_ms") c = i; next }
           { s += $c; k++ } END { printf "%.4f", s / k }' "$1"
}

run() {  # core, tag
  /usr/bin/time -f "%U %S" -o "$work/$2.time" taskset -c "$1" "$scbt" track "$frames" \
    --init "$init" -o "$work/$2.txt" --csv "$work/$2.csv" --max-frames "$max_frames" -q
}

cpu_ms() {  # process CPU time per tracked frame: tag
  local frames
  frames=$(($(wc -l < "$work/$1.csv") - 1))
  awk -v f="$frames" '{ printf "%.4f", 1000 * ($1 + $2) / f }' "$work/$1.time"
}

median() {  # of the numbers on standard input
  sort -g | awk '{ v[NR] = $1 } END { print (NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2) }'
}

echo "sequence=$sequence streams=$n rounds=$rounds; load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
for ((r = 1; r <= rounds; ++r)); do
  for ((i = 0; i < n; ++i)); do
    run "$i" "alone$i"
    m=$(mean_ms "$work/alone$i.csv")
    echo "$m" >> "$work/alone$i.list"
    echo "round=$r alone core=$i mean_ms=$m cpu_ms=$(cpu_ms "alone$i")"
  done
  pids=()
  for ((i = 0; i < n; ++i)); do
    run "$i" "together$i" &
    pids+=($!)
  done
  for pid in "${pids[@]}"; do wait "$pid"; done
  for ((i = 0; i < n; ++i)); do
    m=$(mean_ms "$work/together$i.csv")
    echo "$m" >> "$work/together$i.list"
    echo "round=$r together core=$i mean_ms=$m cpu_ms=$(cpu_ms "together$i")"
  done
done

worst=-1000
for ((i = 0; i < n; ++i)); do
  alone=$(median < "$work/alone$i.list")
  together=$(median < "$work/together$i.list")
  slow=$(awk -v t="$together" -v a="$alone" 'BEGIN { printf "%.1f", 100 * (t / a - 1) }')
  echo "core=$i median_alone_ms=$alone median_together_ms=$together" \
    "fps_together=$(awk -v m="$together" 'BEGIN { printf "%.0f", 1000 / m }') slowdown_pct=$slow"
  worst=$(awk -v a="$worst" -v b="$slow" 'BEGIN { print (b > a ? b : a) }')
done
echo "worst slow-down: ${worst} % (target: <= 10 %)"
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
