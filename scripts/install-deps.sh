#!/usr/bin/env bash
# Installs the Debian 12 packages the project needs, if missing. Idempotent; runs apt-get as
# root, or through sudo otherwise. Packages named as arguments are wanted too (scripts/build.sh
# sanitize asks for clang and its sanitizer runtimes).
set -euo pipefail

packages=(
  g++ cmake ninja-build pkg-config
  libeigen3-dev libtbb-dev libgsl-dev catch2 nlohmann-json3-dev libcli11-dev libfmt-dev
  python3 python3-matplotlib python3-numpy
  "$@"
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

if [ "$(id -u)" -eq 0 ]; then as_root=(); else as_root=(sudo); fi
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${as_root[@]}" apt-get update -qq
"${as_root[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
