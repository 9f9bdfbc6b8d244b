#!/usr/bin/env bash
# Every malformed scene in bad_scenes/ must be refused by `mrsph check` with exit status 1 and a
# message containing the text of its .expect file (the key and what was expected). Never a crash
# (another status), never acceptance.
set -u
mrsph="$1"; dir="$(dirname "$0")/bad_scenes"
failures=0; count=0
for scene in "$dir"/*.json; do
  count=$((count + 1))
  expect="$(cat "${scene%.json}.expect")"
  message="$("$mrsph" check "$scene" 2>&1 >/dev/null)"; status=$?
  if [ "$status" -ne 1 ]; then
    echo "FAIL $(basename "$scene"): exit status $status, expected 1 ($message)"; failures=$((failures + 1))
  elif [[ "$message" != *"$expect"* ]]; then
    echo "FAIL $(basename "$scene"): message '$message' lacks '$expect'"; failures=$((failures + 1))
  fi
done
echo "$((count - failures)) of $count malformed scenes refused with the expected message"
[ "$failures" -eq 0 ]
