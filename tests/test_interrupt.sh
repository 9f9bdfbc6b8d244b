#!/usr/bin/env bash
# SIGINT during `mrsph run`: a checkpoint and a summary marked incomplete are written, the exit
# status is 4; `mrsph restart` then finishes the run (exit 0).
set -u
mrsph="$1"; scene="$2"
out=$(mktemp -d)
"$mrsph" run "$scene" --out "$out" --quiet --end-time 200 --threads 1 &
pid=$!
sleep 3
kill -INT "$pid"
wait "$pid"; status=$?
[ "$status" -eq 4 ] || { echo "expected exit 4 after SIGINT, got $status"; exit 1; }
[ -f "$out/checkpoint.bin" ] || { echo "no checkpoint written"; exit 1; }
grep -q '"interrupted": true' "$out/summary.json" || { echo "summary not marked interrupted"; exit 1; }
grep -q '"completed": false' "$out/summary.json" || { echo "summary not marked incomplete"; exit 1; }
t=$(/usr/bin/python3 -c "import json; print(json.load(open('$out/summary.json'))['time_reached'])")
"$mrsph" restart "$out/checkpoint.bin" --out "$out/restarted" --quiet --end-time "$(/usr/bin/python3 -c "print($t + 0.5)")" --threads 1
status=$?
[ "$status" -eq 0 ] || { echo "restart failed with $status"; exit 1; }
grep -q '"completed": true' "$out/restarted/summary.json" || { echo "restarted run not complete"; exit 1; }
rm -rf "$out"
echo "interrupt at t = $t, checkpoint, restart: ok"
