#!/usr/bin/env bash
# Whether two builds of scbt track the same boundaries. Usage:
#   bench/compare_outputs.sh OLD_SCBT NEW_SCBT DATASET_DIR [SEQUENCES...]
# Runs `scbt track` of both binaries on every sequence of the dataset (or the ones named), with
# default options and the ground truth's first polygon as the initial boundary, and compares the
# two results files byte for byte. Prints one line per sequence and exits 1 if any differs.
set -euo pipefail
old=${1:?old scbt binary}
new=${2:?new scbt binary}
dataset=${3:?dataset folder}
shift 3
for binary in "$old" "$new"; do
  [[ -x "$binary" ]] || { echo "compare_outputs.sh: $binary is not an executable" >&2; exit 2; }
done
[[ -d "$dataset/OriginalVideosAVI" && -d "$dataset/GroundTruthByPolygons" ]] ||
  { echo "compare_outputs.sh: $dataset lacks OriginalVideosAVI/ or GroundTruthByPolygons/" >&2; exit 2; }
sequences=("$@")
if [[ ${#sequences[@]} -eq 0 ]]; then
  for folder in "$dataset"/OriginalVideosAVI/*/; do sequences+=("$(basename "$folder")"); done
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

differ=0
for name in "${sequences[@]}"; do
  frames=$dataset/OriginalVideosAVI/$name
  truth=$dataset/GroundTruthByPolygons/${name}_TrackingGroundTruth.txt
  [[ -d "$frames" && -f "$truth" ]] ||
    { echo "compare_outputs.sh: no frames or ground truth for $name" >&2; exit 2; }
  "$old" track "$frames" --init "$truth" -o "$work/$name.old.txt" --quiet
  "$new" track "$frames" --init "$truth" -o "$work/$name.new.txt" --quiet
  lines=$(wc -l < "$work/$name.new.txt")
  if cmp -s "$work/$name.old.txt" "$work/$name.new.txt"; then
    echo "$name: byte-identical ($lines frames)"
  else
    echo "$name: DIFFERENT ($(cmp "$work/$name.old.txt" "$work/$name.new.txt" | head -1))"
    differ=1
  fi
done
exit $differ
