#!/usr/bin/env bash
# The fetch script installs files whose checksums match, and refuses a corrupted copy.
set -u
project="$1"; source_dir="$2"
[ -d "$source_dir" ] || { echo "no local copy at $source_dir: skipped"; exit 0; }
"$project/scripts/fetch_reference_data.sh" --from "$source_dir" || { echo "a good copy was refused"; exit 1; }
bad=$(mktemp -d)
cp "$source_dir"/*.txt "$bad"/
echo "0.1 99.0" >> "$bad/Ex10X.txt"
if "$project/scripts/fetch_reference_data.sh" --from "$bad" 2>/dev/null; then echo "a corrupted copy was accepted"; rm -rf "$bad"; exit 1; fi
rm -rf "$bad"
echo "fetch script: good copy installed, corrupted copy refused"
