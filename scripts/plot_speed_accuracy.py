"""Figure of the speed-accuracy suite: wall time against error, one panel per benchmark, the Pareto
front drawn."""
import sys

from plot_common import load_summary, plt, save, suite_dir

directory = suite_dir()
summary = load_summary(directory)
units = {"plate": "|period / Euler-Bernoulli - 1|", "gate": "RMS error of x vs experiment [mm]",
         "FSI2": "max relative error of A_y, St vs Turek-Hron"}
benchmarks = [b for b in ("plate", "gate", "FSI2")
              if any(p["benchmark"] == b and p["error"] is not None and p["wall_s"] is not None for p in summary["points"])]
if not benchmarks:  # e.g. --merge before any run is done
    sys.exit("no configuration has an error and a wall time (no run completed): no figure")
fig, axes = plt.subplots(1, len(benchmarks), figsize=(5.5 * len(benchmarks), 4.5), squeeze=False)
for ax, name in zip(axes[0], benchmarks):
    pts = [p for p in summary["points"] if p["benchmark"] == name and p["error"] is not None and p["wall_s"] is not None]
    for p in pts:
        ax.plot(p["wall_s"], p["error"], "o", color="C1" if p["pareto"] else "C0")
        ax.annotate(p["label"].split(" ", 1)[1], (p["wall_s"], p["error"]), fontsize=6, xytext=(3, 3), textcoords="offset points")
    front = sorted([p for p in pts if p["pareto"]], key=lambda p: p["wall_s"])
    ax.plot([p["wall_s"] for p in front], [p["error"] for p in front], "-", color="C1", label="Pareto front")
    # Logarithmic axes where the points span more than a decade; otherwise the log ticks crowd.
    for values, set_scale in (([p["wall_s"] for p in pts], ax.set_xscale), ([p["error"] for p in pts], ax.set_yscale)):
        if min(values) > 0 and max(values) / min(values) > 10:
            set_scale("log")
    ax.set_xlabel("wall time [s], one thread")
    ax.set_ylabel(units[name])
    ax.set_title(name)
    ax.legend(fontsize=7)
save(fig, directory, "speed_accuracy.png")
