#!/usr/bin/env bash
# Fetches the digitised Antoci et al. (2007) elastic-gate curves from their public source into the
# git-ignored folder reference-data/fetched/antoci2007/ and checks them against the checksums
# recorded in reference-data/antoci2007.sha256. The project does not redistribute these files.
# Source: github.com/Milad-Rakhsha/Project-Chrono, data/fsi/ref_data/, commit 4385dc51de9a...
# (see ../shared/reference-data/antoci2007/PROVENANCE.md).
#   scripts/fetch_reference_data.sh              download
#   scripts/fetch_reference_data.sh --from DIR   copy from a local directory instead (same checks)
# Then: verify --suite antoci --reference-dir reference-data/fetched
set -euo pipefail
cd "$(dirname "$0")/.."
commit=4385dc51de9a34eaf156faa8f75515133dbf8cb0
base="https://raw.githubusercontent.com/Milad-Rakhsha/Project-Chrono/$commit/data/fsi/ref_data"
dest=reference-data/fetched/antoci2007
sums=reference-data/antoci2007.sha256
from=""
if [ "${1:-}" = "--from" ]; then from="${2:?--from needs a directory}"; fi

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
while read -r _ file; do
  if [ -n "$from" ]; then
    cp "$from/$file" "$tmp/$file"
  else
    curl -fsSL --retry 3 -o "$tmp/$file" "$base/$file"
  fi
done < "$sums"
if ! (cd "$tmp" && sha256sum --check --quiet "$OLDPWD/$sums"); then
  echo "fetch_reference_data: checksum mismatch: the files differ from the recorded ones; nothing installed" >&2
  exit 1
fi
mkdir -p "$dest"
cp "$tmp"/* "$dest"/
echo "fetch_reference_data: $(wc -l < "$sums") files verified and installed in $dest"
