#!/usr/bin/env bash
# Two builds of scbt timed against each other on a noisy machine. Usage:
#   bench/compare_builds.sh BASE_BINARY NEW_BINARY DATASET_DIR [ROUNDS] [CORE] [SEQUENCES...]
# Each round runs `scbt bench --no-compare` with both binaries, one after the other (the order
# alternating from round to round), pinned to CORE (default 0), so that both see the same minutes
# of a machine whose speed drifts (a virtual machine's can swing by 20-30 % from one minute to the
# next; one run of each says little).
# Prints, per sequence, the median over rounds of each binary's mean tracking time per frame
# (total_mean_ms), the new/base ratio of the medians, and both success rates at 10 px, which
# differ only if the change altered the tracker's output; then the mean over sequences.
set -euo pipefail
base=${1:?base scbt binary}
new=${2:?new scbt binary}
dataset=${3:?dataset folder}
rounds=${4:-3}
core=${5:-0}
shift $(($# < 5 ? $# : 5))
for binary in "$base" "$new"; do
  [[ -x "$binary" ]] || { echo "compare_builds.sh: $binary is not an executable" >&2; exit 2; }
done
[[ -d "$dataset/OriginalVideosAVI" ]] ||
  { echo "compare_builds.sh: $dataset has no OriginalVideosAVI folder" >&2; exit 2; }
[[ "$rounds" =~ ^[1-9][0-9]*$ ]] || { echo "compare_builds.sh: ROUNDS must be >= 1, got $rounds" >&2; exit 2; }
[[ "$core" =~ ^[0-9]+$ && "$core" -lt "$(nproc)" ]] ||
  { echo "compare_builds.sh: CORE must be 0..$(($(nproc) - 1)), got $core" >&2; exit 2; }
sequences=()
[[ $# -gt 0 ]] && sequences=(--sequences "$@")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

for ((r = 1; r <= rounds; ++r)); do
  # The order alternates (base new, new base, ...), so that neither always runs first.
  order=(base new)
  ((r % 2 == 0)) && order=(new base)
  for tag in "${order[@]}"; do
    binary=$base
    [[ $tag == new ]] && binary=$new
    taskset -c "$core" "$binary" bench --dataset "$dataset" --no-compare --quiet \
      --csv "$work/$tag.$r.csv" "${sequences[@]}" > /dev/null
    echo "round $r/$rounds: $tag done" >&2
  done
done

# One line per (binary, sequence, round): tag sequence total_mean_ms success_10px.
for f in "$work"/*.csv; do
  tag=$(basename "$f" | cut -d. -f1)
  awk -F, -v tag="$tag" 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
    { print tag, $c["sequence"], $c["total_mean_ms"], $c["success_10px"] }' "$f"
done | sort -k2,2 -k1,1 -k3,3g | awk '
  {
    if (!($2 in seen)) { seen[$2] = 1; order[++count] = $2 }
    key = $2 SUBSEP $1; times[key, ++n[key]] = $3; success[key] = $4
  }
  function median(key,   k) {
    k = n[key]
    return k % 2 ? times[key, (k + 1) / 2] : (times[key, k / 2] + times[key, k / 2 + 1]) / 2
  }
  END {
    printf "%-16s %12s %12s %9s %12s %12s\n", "sequence", "base ms", "new ms", "new/base", "base S@10", "new S@10"
    for (i = 1; i <= count; ++i) {
      s = order[i]; b = median(s SUBSEP "base"); m = median(s SUBSEP "new")
      printf "%-16s %12.4f %12.4f %9.3f %12.4f %12.4f\n", s, b, m, m / b, success[s SUBSEP "base"], success[s SUBSEP "new"]
      sum_b += b; sum_m += m
    }
    printf "%-16s %12.4f %12.4f %9.3f\n", "mean", sum_b / count, sum_m / count, sum_m / sum_b
  }'
