#!/usr/bin/env bash
# Builds what the tests need and runs them with CTest (unit tests, and a load check of every scene).
# The last lines are CTest's closing summary. Pass "sanitize" to run them under ASan + UBSan.
set -euo pipefail
cd "$(dirname "$0")/.."
preset="${1:-release}"
scripts/build.sh "$preset"
ctest --preset "$preset" -j "$(nproc)"
