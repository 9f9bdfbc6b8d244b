#!/usr/bin/env bash
# Fuzzes the scene reader with libFuzzer (+ ASan + UBSan) for a bounded time (default 120 s).
# Seeds: every committed scene and the malformed-scene corpus. Findings (crashes, sanitizer reports,
# leaks, inputs over 60 s, memory over 2 GB) are written to build/sanitize/fuzz-findings/ and make the script fail.
#   scripts/fuzz_scene.sh [SECONDS]
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-120}"
scripts/build.sh sanitize scene_fuzzer  # the sanitizer tests' build: only the fuzzer's own file is new
corpus=build/sanitize/fuzz-corpus; findings=build/sanitize/fuzz-findings
mkdir -p "$corpus" "$findings"
cp verification/scenes/*.json tests/bad_scenes/*.json "$corpus"/
ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  build/sanitize/scene_fuzzer "$corpus" -dict=tests/fuzz/scene.dict -max_total_time="$seconds" -max_len=4096 \
  -timeout=60 -rss_limit_mb=2048 -artifact_prefix="$findings/" -print_final_stats=1 2>&1 | tail -25
# libFuzzer's artifacts: crash-, leak-, timeout- and oom- files are findings; slow-unit- files (an
# input over 10 s, well inside the 60 s limit) are reported but do not fail the run.
count=$(find "$findings" -type f \( -name 'crash-*' -o -name 'leak-*' -o -name 'timeout-*' -o -name 'oom-*' \) | wc -l)
slow=$(find "$findings" -type f -name 'slow-unit-*' | wc -l)
echo "fuzz_scene: $seconds s, corpus $(ls "$corpus" | wc -l) inputs, findings: $count, slow inputs (> 10 s): $slow"
[ "$count" -eq 0 ]
