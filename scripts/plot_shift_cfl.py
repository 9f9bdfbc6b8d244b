"""Figure of reports/pressure.md section 35: the pressure-driven open channel (Re = 100, L = 10 H, H/dp = 20,
c = 10 U) at the scene's advection CFL 0.25, at CFL 0.06 with the paper's shift per advection step, and at
CFL 0.0625 with the shift scaled by the CFL: the particles next to the inlet coloured by pressure (t = 60),
and the pressure along the channel (means over t = 40-60) against the imposed line.

Reads DIRECTORY/diagnosis/poiseuille_shift_cfl_inlet.csv (run, x, y, pressure, buffer) and
DIRECTORY/diagnosis/poiseuille_shift_cfl_along.csv (run, x, pressure, snapshots);
writes DIRECTORY/pressure_shift_cfl.png.
Usage: /usr/bin/python3 scripts/plot_shift_cfl.py reports/pressure
"""
from plot_common import read_diagnosis_rows, plt, save, suite_dir

directory = suite_dir()


def read(name):
    return read_diagnosis_rows(directory, name)


inlet, along = read("poiseuille_shift_cfl_inlet.csv"), read("poiseuille_shift_cfl_along.csv")
runs = list(dict.fromkeys(r["run"] for r in along))
fig = plt.figure(figsize=(12, 6.4), constrained_layout=True)
grid = fig.add_gridspec(len(runs), 2, width_ratios=[1.0, 1.1])
for k, run in enumerate(runs):
    ax = fig.add_subplot(grid[k, 0])
    rows = [r for r in inlet if r["run"] == run]
    domain = [r for r in rows if r["buffer"] == "0"]
    buffer = [r for r in rows if r["buffer"] == "1"]
    points = ax.scatter([float(r["x"]) for r in domain], [float(r["y"]) for r in domain],
                        c=[float(r["pressure"]) for r in domain], s=5, cmap="viridis", vmin=0.65, vmax=0.9)
    ax.scatter([float(r["x"]) for r in buffer], [float(r["y"]) for r in buffer], s=3, c="0.6")
    ax.axvline(0.0, color="k", lw=0.6)
    ax.set_aspect("equal")
    ax.set_title(run + ", t = 60", fontsize=8)
    ax.set_ylabel("y / H")
    if k == len(runs) - 1:
        ax.set_xlabel("x / H (grey: the inlet's buffer)")
    fig.colorbar(points, ax=ax, label="p / (rho U^2)", shrink=0.8)
right = fig.add_subplot(grid[:, 1])
for run, style in zip(runs, ["o-", "s-", "^-"]):
    rows = [r for r in along if r["run"] == run]
    right.plot([float(r["x"]) for r in rows], [float(r["pressure"]) for r in rows], style, ms=2.5, lw=0.8, label=run)
right.plot([0, 10], [0.8, 0.0], "k--", lw=0.8, label="imposed: p_in = 0.8 at x = 0, p_out = 0 at x = 10 H")
right.set_xlabel("x / H")
right.set_ylabel("p / (rho U^2), domain particles, mean over t = 40-60")
right.set_title("pressure-driven open channel, Re = 100, H/dp = 20, c = 10 U", fontsize=9)
right.legend(fontsize=7)
save(fig, directory, "pressure_shift_cfl.png")
