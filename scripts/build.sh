#!/usr/bin/env bash
# Configures (once) and builds a CMake preset: release by default; pass another preset name
# (native, debug, sanitize) as the first argument.
set -euo pipefail
cd "$(dirname "$0")/.."
preset="${1:-release}"
if [ ! -f "build/$preset/build.ninja" ]; then  # a configure that failed half-way is redone
  cmake --preset "$preset" >/dev/null
fi
cmake --build --preset "$preset"
