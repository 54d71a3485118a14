#!/usr/bin/env bash
# The main job: install what is missing, build in Release, then open the viewer on the lab's box
# where a display exists, or render the box headless to out/cornell.png otherwise.
# Extra arguments go to the viewer or renderer (e.g. a mesh path and options).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release -j"$(nproc)"
if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ] && [ -x build/release/src/viewer/raylab ]; then
    exec build/release/src/viewer/raylab "$@"
fi
mkdir -p out
build/release/src/cli/raylab-render "$@" -o out/cornell.png
echo "raylab: no display; rendered $(pwd)/out/cornell.png"
