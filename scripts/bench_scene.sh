#!/usr/bin/env bash
# Times a scene: RUNS rounds (default 3), each running the scene once per thread count, thread
# counts in alternation so that a machine's drift touches them all alike. Prints JSON: per thread
# count the wall times, their median, particle-updates per second (particles x acoustic steps /
# median) and the parallel efficiency against the smallest count; the step counts per phase
# (advection, acoustic, solid sub-steps). Quote medians: these machines are shared and noisy.
#   scripts/bench_scene.sh SCENE [THREADS] [RUNS] [--set k=v ...]
#   THREADS: a count or a comma list, e.g. 1,2 (default 2)
# Plot the thread scaling of one or more outputs with scripts/plot_scaling.py.
set -euo pipefail
cd "$(dirname "$0")/.."
if [ $# -lt 1 ]; then sed -n '2,9p' "$0"; exit 2; fi
scene="$1"; thread_list="${2:-2}"; runs="${3:-3}"; shift $(( $# < 3 ? $# : 3 ))
IFS=, read -r -a threads <<< "$thread_list"
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for k in $(seq 1 "$runs"); do
  for t in "${threads[@]}"; do
    build/release/solver/mrsph run "$scene" --threads "$t" --quiet --out "$out/t${t}_run$k" "$@" >/dev/null
  done
done
/usr/bin/python3 - "$out" "$runs" "${threads[@]}" <<'PY'
import json, statistics, sys
out, runs, threads = sys.argv[1], int(sys.argv[2]), [int(t) for t in sys.argv[3:]]
def summary(t, k):
    return json.load(open(f"{out}/t{t}_run{k}/summary.json"))
first = summary(threads[0], 1)
cost = first["cost"]
particles = sum(cost["particles"].values())
rows, base = [], None
# Runs are deterministic for any thread count: every run must take the same steps.
all_steps = {json.dumps(summary(t, k)["cost"]["steps"]) for t in threads for k in range(1, runs + 1)}
for t in threads:
    walls = [summary(t, k)["cost"]["wall_s"] for k in range(1, runs + 1)]
    median = statistics.median(walls)
    if base is None: base = (t, median)
    speedup = base[1] / median
    rows.append({"threads": t, "wall_s": walls, "median_wall_s": median,
                 "particle_updates_per_s": particles * cost["steps"]["acoustic"] / median,
                 "speedup": speedup, "parallel_efficiency": speedup * base[0] / t})
print(json.dumps({"scene": first["scene"], "end_time": first["time_reached"], "runs": runs,
                  "particles": cost["particles"], "steps": cost["steps"],
                  "same_steps_in_every_run": len(all_steps) == 1, "by_threads": rows}, indent=2))
PY
