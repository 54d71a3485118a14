#!/usr/bin/env bash
# scripts/outside_meshes.py, whose meshes PERFORMANCE.md measures ("Meshes outside the bench"):
# it runs, and raylab-render loads each mesh it writes with the triangle count it documents.
# usage: outside_meshes_test.sh RAYLAB_RENDER PYTHON SCRIPT ASSET_DIR
set -euo pipefail
render=$1 python=$2 script=$3 assets=$4
if [[ ! -f "$assets/bunny/bun_zipper.ply" ]]; then # as the tests of the shared meshes skip
    echo "skipped: shared assets not found in $assets" >&2
    exit 77
fi
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
"$python" "$script" "$out" "$assets"
for expected in terrain:980000 sticks:60000 bunny_shuffled:69451; do
    mesh=${expected%%:*} count=${expected##*:}
    line=$("$render" "$out/$mesh.obj" --width 16 --height 16 -o "$out/$mesh.png" 2>&1 | tail -n 1)
    if [[ "$line" != *", $count triangles,"* ]]; then
        echo "$mesh.obj: expected $count triangles, raylab-render said: $line" >&2
        exit 1
    fi
done
echo "outside meshes: terrain, sticks and bunny_shuffled written and loaded"
