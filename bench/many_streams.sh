#!/usr/bin/env bash
# Many streams: N concurrent `scbt track` processes, each pinned to its own core, must each keep
# their single-stream speed (within 10 %). Usage:
#   bench/many_streams.sh SCBT_BINARY DATASET_DIR [N] [SEQUENCE] [MAX_FRAMES]
# Prints the mean tracking time per frame (total_ms from --csv, decoding excluded) of a lone run
# on core 0 and of each of the N concurrent runs on cores 0..N-1, and the slow-down of each.
# On a machine shared with other jobs, wall time also counts time-sharing with them; the process
# CPU time per frame (cpu_ms, decoding included) shows whether the streams slow each other down.
set -euo pipefail
scbt=${1:?scbt binary}
dataset=${2:?dataset folder}
n=${3:-$(nproc)}
sequence=${4:-Bowl}
max_frames=${5:-0}
frames="$dataset/OriginalVideosAVI/$sequence"
init="$dataset/GroundTruthByPolygons/${sequence}_TrackingGroundTruth.txt"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

mean_ms() {  # mean of the total_ms column of a track CSV
  awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "total_ms") c = i; next }
           { s += $c; k++ } END { printf "%.4f", s / k }' "$1"
}

run() {  # core, tag
  /usr/bin/time -f "%U %S" -o "$work/$2.time" taskset -c "$1" "$scbt" track "$frames" --init "$init" -o "$work/$2.txt" --csv "$work/$2.csv" \
    --max-frames "$max_frames" -q
}

cpu_ms() {  # process CPU time per tracked frame: tag
  local frames
  frames=$(($(wc -l < "$work/$1.csv") - 1))
  awk -v f="$frames" '{ printf "%.4f", 1000 * ($1 + $2) / f }' "$work/$1.time"
}

echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
run 0 single
single=$(mean_ms "$work/single.csv")
echo "streams=1 core=0 mean_ms=$single fps=$(awk -v m="$single" 'BEGIN { printf "%.0f", 1000 / m }') cpu_ms=$(cpu_ms single)"

pids=()
for ((i = 0; i < n; ++i)); do
  run "$i" "stream$i" &
  pids+=($!)
done
for pid in "${pids[@]}"; do wait "$pid"; done

worst=0
for ((i = 0; i < n; ++i)); do
  m=$(mean_ms "$work/stream$i.csv")
  slow=$(awk -v m="$m" -v s="$single" 'BEGIN { printf "%.1f", 100 * (m / s - 1) }')
  echo "streams=$n core=$i mean_ms=$m fps=$(awk -v m="$m" 'BEGIN { printf "%.0f", 1000 / m }') slowdown_pct=$slow cpu_ms=$(cpu_ms "stream$i")"
  worst=$(awk -v a="$worst" -v b="$slow" 'BEGIN { print (b > a ? b : a) }')
done
echo "worst slow-down: ${worst} % (target: <= 10 %)"
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
