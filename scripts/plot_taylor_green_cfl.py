"""Figure of reports/pressure.md section 36: the Taylor-Green vortex's effective viscosity (Re = 200) against the
advection CFL number, with the paper's density summation once per advection step, without any reset, with the
summation relaxed by 0.05 per step, with the paper's shift per step, and with the pair geometry refreshed at each
acoustic step, at L/dp = 40 and 80, c = 10, 20, 40 U.

Reads DIRECTORY/diagnosis/taylor_green_advection_cfl.csv (run, L_over_dp, c_over_U, advection_cfl, density,
shift, nu_eff_over_nu, pair_geometry, acoustic_cfl); writes DIRECTORY/pressure_taylor_green_cfl.png.
Usage: /usr/bin/python3 scripts/plot_taylor_green_cfl.py reports/pressure
"""
import csv
import os

from plot_common import log_x_axis, plt, save, suite_dir

directory = suite_dir()
with open(os.path.join(directory, "diagnosis", "taylor_green_advection_cfl.csv")) as f:
    rows = list(csv.DictReader(f))


def series(**match):
    match.setdefault("acoustic_cfl", "0.6")  # the paper's; rows at other acoustic steps are in the table only
    points = sorted((float(r["advection_cfl"]), float(r["nu_eff_over_nu"])) for r in rows
                    if all(r[key] == value for key, value in match.items()))
    return list(zip(*points))


this_build = "scaled below CFL 0.25 (this build)"
paper_reset = "summation each advection step (the paper's)"
no_reset = "continuity only (no reset)"
cached = "cached per advection step (the paper's)"
refreshed = "refreshed at each acoustic step"
fig, axes = plt.subplots(1, 2, figsize=(11, 4.4), sharey=True, constrained_layout=True)
for ax, resolution in zip(axes, ["40", "80"]):
    for c, color in [("10", "C0"), ("20", "C1"), ("40", "C2")]:
        for density, style, label in [(paper_reset, "o-", "summation reset each step"), (no_reset, "s--", "no reset")]:
            x, y = series(L_over_dp=resolution, c_over_U=c, density=density, shift=this_build, pair_geometry=cached)
            ax.plot(x, y, style, color=color, ms=4, label=f"c = {c} U, {label}")
    for density, style, label in [(paper_reset, "D-", "reset each step"), (no_reset, "D--", "no reset")]:
        x, y = series(L_over_dp=resolution, c_over_U="10", density=density, pair_geometry=refreshed)
        ax.plot(x, y, style, color="C3", ms=3, lw=0.8, label=f"c = 10 U, pair geometry refreshed, {label}")
    if resolution == "40":
        x, y = series(L_over_dp="40", c_over_U="10", density="summation relaxed by 0.05 per step")
        ax.plot(x, y, "^:", color="C4", ms=4, label="c = 10 U, summation relaxed by 0.05 per step")
        x, y = series(L_over_dp="40", c_over_U="10", density=paper_reset, shift="0.25 per step (the paper's)")
        ax.plot(x, y, "x-", color="0.5", ms=5, label="c = 10 U, reset each step, the paper's shift per step")
    ax.axhline(1.0, color="k", lw=0.6)
    log_x_axis(ax, [0.03125, 0.0625, 0.125, 0.25], ["0.031", "0.0625", "0.125", "0.25"], base=2)
    ax.set_xlabel("advection CFL number (the paper's: 0.25)")
    ax.set_title(f"Taylor-Green vortex, Re = 200, L/dp = {resolution}, h = 1.3 dp, to t = 1", fontsize=9)
    ax.legend(fontsize=6.5)
axes[0].set_ylabel("nu_eff / nu (decay of the velocity)")
save(fig, directory, "pressure_taylor_green_cfl.png")
