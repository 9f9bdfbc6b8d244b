"""Figure of the momentum suite: |P(t) - P(0)| / |P(0)| for each schedule, and the momentum
the solid exchanged with the fluid."""
import os

from plot_common import load_summary, plt, read_csv, save, suite_dir

directory = suite_dir()
summary = load_summary(directory)
fig, (ax, ax2) = plt.subplots(1, 2, figsize=(10, 4))
for run in summary["runs"]:
    name = run["config"]["schedule"]
    d = read_csv(os.path.join(directory, f"momentum_{name}.csv"))
    p0 = (d["px"][0] ** 2 + d["py"][0] ** 2) ** 0.5
    drift = [max(1e-17, ((x - d["px"][0]) ** 2 + (y - d["py"][0]) ** 2) ** 0.5 / p0) for x, y in zip(d["px"], d["py"])]
    ax.semilogy(d["time"], drift, label=f"{name} (max {run['metrics']['momentum_drift']:.1e})")
    ax2.plot(d["time"], [x / p0 for x in d["solid_px"]], label=name)
ax.set_xlabel("t")
ax.set_ylabel("|P(t) - P(0)| / |P(0)|, fluid + solid")
ax.set_title("Total momentum of a closed FSI box")
ax.legend(fontsize=7)
ax2.set_xlabel("t")
ax2.set_ylabel("solid momentum P_x / |P(0)|")
ax2.set_title("Momentum handed from the disc to the fluid")
ax2.legend(fontsize=7)
save(fig, directory, "momentum.png")
