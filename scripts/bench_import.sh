#!/usr/bin/env bash
# What reading a mesh through the raylab-import helper costs against Assimp in the calling
# process: RUNS fresh processes of each way, in turn, each timing one load (first loads, as
# raylab-render and raylab-bench load). Prints the best and the median of each and their ratios.
#   bash scripts/bench_import.sh MESH [RUNS]   (default 11; needs the release build)
set -euo pipefail
cd "$(dirname "$0")/.."
mesh=${1:?usage: bash scripts/bench_import.sh MESH [RUNS]}
runs=${2:-11}
timing=build/release/src/bench/raylab-import-timing
[[ -x $timing ]] || { echo "bench_import.sh: build the release preset first ($timing)" >&2; exit 1; }

declare -A times
for ((i = 0; i < runs; ++i)); do
    for way in in-process helper; do
        read -r ms triangles < <("$timing" "$way" "$mesh")
        times[$way]+="$ms "
    done
done
summary() { tr ' ' '\n' <<<"${times[$1]}" | grep . | sort -g | awk '{v[NR]=$1} END {printf "%.1f %.1f", v[1], v[int((NR+1)/2)]}'; }
read -r inBest inMedian <<<"$(summary in-process)"
read -r helperBest helperMedian <<<"$(summary helper)"
echo "$mesh: $triangles triangles, $runs fresh processes of each"
echo "  in-process (Assimp here):  best $inBest ms, median $inMedian ms"
echo "  through raylab-import:     best $helperBest ms, median $helperMedian ms"
awk -v a="$helperBest" -v b="$inBest" -v c="$helperMedian" -v d="$inMedian" \
    'BEGIN {printf "  helper / in-process:       best %.3f, median %.3f\n", a / b, c / d}'
