#!/usr/bin/env bash
# Builds the libFuzzer targets (the `fuzz` preset, clang) and runs each for a time budget from its
# committed seed corpus (tests/fuzz/corpus/<name>). New inputs go to a temporary folder; a finding
# (crash, leak, timeout, out of memory) stops the run with a non-zero exit and leaves the input
# in build/fuzz/findings/ to be added to the corpus as a regression test.
#   bash scripts/fuzz.sh [SECONDS_PER_TARGET]   (default 45)
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-45}
targets=(import_stream partial_file settings_json command_line linear_image screenshot_png)

cmake --preset fuzz >/dev/null
cmake --build --preset fuzz -j"$(nproc)" --target "${targets[@]/#/fuzz_}"

findings=build/fuzz/findings
mkdir -p "$findings"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# ASan's quarantine of freed memory counts against the RSS limit; keep it small.
export ASAN_OPTIONS=quarantine_size_mb=64:detect_leaks=1
for target in "${targets[@]}"; do
    mkdir -p "$work/$target"
    echo "fuzz_$target: ${seconds} s from tests/fuzz/corpus/$target" >&2
    if ! build/fuzz/tests/fuzz/"fuzz_$target" -max_total_time="$seconds" -rss_limit_mb=4096 \
        -timeout=10 -print_final_stats=1 -artifact_prefix="$findings/$target-" \
        "$work/$target" "tests/fuzz/corpus/$target" 2>"$work/$target.log"; then
        tail -n 40 "$work/$target.log" >&2
        echo "fuzz_$target: a finding, kept in $findings" >&2
        exit 1
    fi
    grep -E "^stat::number_of_executed_units|^#[0-9]+ +DONE" "$work/$target.log" >&2 || true
done
