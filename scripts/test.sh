#!/usr/bin/env bash
# Installs what is missing, builds in Release with warnings as errors, and runs every test with
# ctest: unit tests, the command-line tests, the viewer's end-to-end tests in a real window under
# Xvfb and the Slurm scripts on a real single-node Slurm. Then builds the same tests (without the
# viewer, whose GL driver is not instrumented) with AddressSanitizer + UndefinedBehaviorSanitizer
# (LeakSanitizer on) and with ThreadSanitizer and runs them again. Then fuzzes every input
# surface for a time budget (scripts/fuzz.sh; RAYLAB_FUZZ_SECONDS per target, default 45).
# RAYLAB_SKIP_ASAN=1, RAYLAB_SKIP_TSAN=1 and RAYLAB_SKIP_FUZZ=1 skip those passes.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
jobs=$(nproc)

cmake --preset release >/dev/null
cmake --build --preset release -j"$jobs"
ctest --preset release -j"$jobs"

if [ "${RAYLAB_SKIP_ASAN:-0}" != 1 ]; then
    cmake --preset asan >/dev/null
    cmake --build --preset asan -j"$jobs"
    ctest --preset asan -j"$jobs"
fi

if [ "${RAYLAB_SKIP_TSAN:-0}" != 1 ]; then
    cmake --preset tsan >/dev/null
    cmake --build --preset tsan -j"$jobs"
    ctest --preset tsan -j"$jobs"
fi

if [ "${RAYLAB_SKIP_FUZZ:-0}" != 1 ]; then
    bash scripts/fuzz.sh "${RAYLAB_FUZZ_SECONDS:-45}"
fi
