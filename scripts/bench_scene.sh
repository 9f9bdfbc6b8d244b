#!/usr/bin/env bash
# Times a scene: runs it N times (default 3) with the given thread count and prints the median wall
# time, the step counts and particle-updates per second as JSON. Quote medians: these machines are
# shared and noisy.
#   scripts/bench_scene.sh SCENE [THREADS] [RUNS] [--set k=v ...]
set -euo pipefail
cd "$(dirname "$0")/.."
scene="$1"; threads="${2:-2}"; runs="${3:-3}"; shift $(( $# < 3 ? $# : 3 ))
out=$(mktemp -d)
times=()
for k in $(seq 1 "$runs"); do
  build/release/solver/mrsph run "$scene" --threads "$threads" --quiet --out "$out/run$k" "$@" >/dev/null
  times+=("$(/usr/bin/python3 -c "import json; print(json.load(open('$out/run$k/summary.json'))['cost']['wall_s'])")")
done
/usr/bin/python3 - "$out/run1/summary.json" "$threads" "${times[@]}" <<'PY'
import json, statistics, sys
summary = json.load(open(sys.argv[1]))
threads = int(sys.argv[2])
times = [float(t) for t in sys.argv[3:]]
cost = summary["cost"]
particles = sum(cost["particles"].values())
median = statistics.median(times)
print(json.dumps({
    "scene": summary["scene"], "threads": threads, "runs": len(times), "wall_s": times,
    "median_wall_s": median, "particles": cost["particles"], "steps": cost["steps"],
    "particle_updates_per_s": particles * cost["steps"]["acoustic"] / median,
}, indent=2))
PY
rm -rf "$out"
