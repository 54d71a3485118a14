#!/usr/bin/env bash
# Installs what is missing, builds in Release with warnings as errors, and runs every test
# (unit, command-line and the viewer's end-to-end tests under Xvfb) with ctest.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release -j"$(nproc)"
ctest --preset release -j"$(nproc)"
