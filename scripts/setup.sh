#!/usr/bin/env bash
# The main job, from a fresh Debian 12 machine: install what is missing, build, and run the quick
# Womersley verification suite (a few seconds; results in reports/runs/<date-time>-quick/).
# Extra arguments go to `verify`, e.g.  scripts/setup.sh --suite womersley  (the full suite).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh release
args=("$@")
if [ ${#args[@]} -eq 0 ]; then args=(--suite womersley --quick); fi
refs=()
[ -d ../shared/reference-data ] && refs=(--reference-dir ../shared/reference-data)
exec build/release/verification/verify "${args[@]}" "${refs[@]}"
