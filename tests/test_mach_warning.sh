#!/usr/bin/env bash
# A run whose fluid goes faster than Mach 0.5 completes (exit 0) with a warning on stderr naming the
# Mach number; a run below it gives none. A periodic box streaming uniformly at 0.6 c and at 0.2 c.
set -u
mrsph="$1"
dir=$(mktemp -d)
box() {
  cat > "$dir/box.json" <<JSON
{ "parameters": {"dp": 0.05, "c": 10},
  "domain": {"lower": [0, 0], "upper": [1, 1], "periodic": [true, true]},
  "fluid": {"dp": "dp", "region": {"rectangle": {"lower": [0, 0], "upper": [1, 1]}}, "density": 1, "sound_speed": "c",
            "initial_velocity": {"type": "expression", "u": "$1 * c", "v": "0"}},
  "end_time": 0.05 }
JSON
  "$mrsph" run "$dir/box.json" --out "$dir/out" --quiet --threads 1 2> "$dir/stderr"
}
box 0.6; status=$?
[ "$status" -eq 0 ] || { echo "Mach 0.6: expected exit 0, got $status"; cat "$dir/stderr"; exit 1; }
grep -q "warning: the fluid reached Mach 0.60" "$dir/stderr" || { echo "Mach 0.6: no warning"; cat "$dir/stderr"; exit 1; }
box 0.2; status=$?
[ "$status" -eq 0 ] || { echo "Mach 0.2: expected exit 0, got $status"; exit 1; }
[ ! -s "$dir/stderr" ] || { echo "Mach 0.2: unexpected output on stderr"; cat "$dir/stderr"; exit 1; }
rm -rf "$dir"
echo "Mach warning above 0.5, none at 0.2: ok"
