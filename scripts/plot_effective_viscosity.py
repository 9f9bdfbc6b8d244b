"""Figure of reports/pressure.md section 27: the Taylor-Green vortex's effective viscosity nu_eff / nu
(Re = 200) against the sound speed, for the density rules measured, at L/dp = 20 and 40.

Reads DIRECTORY/diagnosis/taylor_green_effective_viscosity.csv (variant, resolution, Re,
sound_speed_factor, nu_eff_over_nu, ...), writes DIRECTORY/pressure_effective_viscosity.png.
Usage: /usr/bin/python3 scripts/plot_effective_viscosity.py reports/pressure
"""
import csv
import os

from plot_common import log_x_axis, plt, save, suite_dir

directory = suite_dir()
with open(os.path.join(directory, "diagnosis", "taylor_green_effective_viscosity.csv")) as f:
    rows = [r for r in csv.DictReader(f) if r["Re"] == "200"]
variants = ["default", "no reset (density_reinitialisation none)", "reset of the mean only (scratch build)"]
fig, axes = plt.subplots(1, 2, figsize=(10, 3.8), sharey=True, constrained_layout=True)
for ax, resolution in zip(axes, ["20", "40"]):
    for variant in variants:
        points = sorted((float(r["sound_speed_factor"]), float(r["nu_eff_over_nu"]))
                        for r in rows if r["variant"] == variant and r["resolution"] == resolution)
        if points:
            ax.plot(*zip(*points), "o-", ms=4, label=variant)
    ax.axhline(1.0, color="k", lw=0.8, ls="--")
    log_x_axis(ax, [10, 20, 40, 80], ["10", "20", "40", "80"])
    ax.set_xlabel("c / U")
    ax.set_title(f"Taylor-Green, Re = 200, L/dp = {resolution}", fontsize=9)
    ax.grid(alpha=0.3)
axes[0].set_ylabel("nu_eff / nu (decay of the vortex's mode, t = 0.2-2)")
axes[0].legend(fontsize=7)
save(fig, directory, "pressure_effective_viscosity.png")
