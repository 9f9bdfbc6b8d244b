#!/usr/bin/env bash
# Builds what the tests need and runs them with CTest (unit tests, and a load check of every scene).
# The last lines are CTest's closing summary. Pass "sanitize" to run them under ASan + UBSan.
set -euo pipefail
cd "$(dirname "$0")/.."
preset="${1:-release}"
if [ "$preset" = sanitize ]; then
  # Only what CTest runs: the solver program and the unit tests (not the suites or `verify`, which
  # no test runs; CI's sanitizer stage takes about a third less time).
  scripts/build.sh "$preset" mrsph mrsph_tests
else
  scripts/build.sh "$preset"
fi
ctest --preset "$preset" -j "$(nproc)"
