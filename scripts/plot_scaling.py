"""Wall time against threads from scripts/bench_scene.sh outputs (one JSON per scene).
    /usr/bin/python3 scripts/plot_scaling.py OUT.png BENCH.json [BENCH.json ...]"""
import json
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    fig, ax = plt.subplots(figsize=(5, 3.6))
    all_threads = set()
    for path in sys.argv[2:]:
        bench = json.load(open(path))
        rows = bench["by_threads"]
        threads = [r["threads"] for r in rows]
        all_threads.update(threads)
        median = [r["median_wall_s"] for r in rows]
        line, = ax.plot(threads, median, "o-", label=f"{bench['scene']} (to t = {bench['end_time']:g})")
        ideal = [median[0] * threads[0] / t for t in threads]
        ax.plot(threads, ideal, ":", color=line.get_color(), lw=1)
    ax.set_xscale("log", base=2)
    ax.set_xticks(sorted(all_threads), [str(t) for t in sorted(all_threads)])
    ax.minorticks_off()
    ax.set_yscale("log")
    ax.set_xlabel("threads")
    ax.set_ylabel("median wall time [s]")
    ax.set_title("thread scaling (dotted: ideal)", fontsize=10)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(sys.argv[1], dpi=130)


if __name__ == "__main__":
    main()
