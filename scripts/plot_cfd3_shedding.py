"""Figure of reports/pressure.md section 26: CFD3's lift and its shedding component over t = 40-200 at
c = 10, 20 and 40 U0 (D/dp = 20, the periodic channel).

Reads DIRECTORY/diagnosis/cfd3_shedding_series.csv (time; per c the lift band-passed to St 0.1-0.35 and
the lift averaged over 0.5), writes DIRECTORY/pressure_cfd3_shedding.png.
Usage: /usr/bin/python3 scripts/plot_cfd3_shedding.py reports/pressure
"""
import os

from plot_common import plt, read_csv, save, suite_dir

directory = suite_dir()
data = read_csv(os.path.join(directory, "diagnosis", "cfd3_shedding_series.csv"))
factors = [10, 20, 40]
fig, axes = plt.subplots(len(factors), 1, figsize=(11, 7), sharex=True, constrained_layout=True)
for ax, c in zip(axes, factors):
    ax.plot(data["time"], data[f"lift_smoothed_c{c}"], lw=0.5, color="0.6", label="lift averaged over 0.5")
    ax.plot(data["time"], data[f"lift_shedding_c{c}"], lw=1.0, label="its shedding component (St 0.1-0.35)")
    for sign in (1, -1):
        ax.axhline(sign * 1.0945, color="k", lw=0.7, ls="--", label="Turek & Hron's amplitude" if sign > 0 else None)
    ax.set_ylim(-2.5, 2.5)
    ax.set_ylabel(f"lift, c = {c} U0")
    ax.grid(alpha=0.3)
axes[0].legend(fontsize=7, ncol=3, loc="upper right")
axes[-1].set_xlabel("t U0 / D")
fig.suptitle("CFD3 (Re = 200, D/dp = 20): the shedding is weaker at c = 20 and 40 U0")
save(fig, directory, "pressure_cfd3_shedding.png")
