#!/usr/bin/env bash
# Configures (once) and builds a CMake preset: release by default; pass another preset name
# (native, debug, sanitize) as the first argument; further arguments name the targets to build.
set -euo pipefail
cd "$(dirname "$0")/.."
preset="${1:-release}"
target=()
[ $# -ge 2 ] && target=(--target "${@:2}")
# The sanitize preset builds with clang (ASan + UBSan tests and the libFuzzer scene target).
[ "$preset" = sanitize ] && scripts/install-deps.sh clang libclang-rt-14-dev
# A sanitize tree configured before it moved to clang (with gcc, no fuzzer target) is configured anew.
if [ "$preset" = sanitize ] && [ -f build/sanitize/CMakeCache.txt ] &&
   ! grep -q "^MRSPH_FUZZ:BOOL=ON" build/sanitize/CMakeCache.txt; then
  echo "build.sh: build/sanitize was configured before it moved to clang; configuring it again" >&2
  rm -rf build/sanitize
fi
if [ ! -f "build/$preset/build.ninja" ]; then  # a configure that failed half-way is redone
  cmake --preset "$preset" >/dev/null
fi
cmake --build --preset "$preset" "${target[@]}"
