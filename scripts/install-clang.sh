#!/usr/bin/env bash
# Installs clang and its sanitizer runtimes (Debian 12: clang 14) if missing: the sanitize preset
# (ASan + UBSan tests and the libFuzzer scene target) builds with clang.
set -euo pipefail
need=()
command -v clang++ >/dev/null || need+=(clang)
dpkg-query -W -f='${Status}' libclang-rt-14-dev 2>/dev/null | grep -q "install ok installed" || need+=(libclang-rt-14-dev)
if [ ${#need[@]} -gt 0 ]; then
  if [ "$(id -u)" -eq 0 ]; then as_root=(); else as_root=(sudo); fi
  "${as_root[@]}" apt-get update -qq && "${as_root[@]}" apt-get install -y -qq "${need[@]}"
fi
