"""Figure of reports/pressure.md section 38: which pass's cached pair geometry makes the Taylor-Green vortex
(Re = 200) less viscous at the paper's advection step, and the first-order prediction of that anti-dissipation.

A pressure gradient estimated on the particles' arrangement of the list build, tau old, is to first order
(I + tau L^T) grad p, L = grad v; where the pressure balances the convective acceleration, (v . grad) v = -grad p /
rho, the error's power per unit mass is tau |grad p|^2 / rho^2 >= 0. For the vortex (u = U sin kx cos ky,
p = rho U^2 (cos 2kx + cos 2ky) / 4) that is a viscosity deficit tau U^2 / 4, with tau = dt / 2 on average over
the acoustic steps of an advection step dt: dnu / nu = dt U(t)^2 / (8 nu), U(t) = exp(-2 nu_eff k^2 t), weighted
over the fit window t = 0.125-1 as the fitted decay rate weights it. No parameter is fitted.

Rows: the scene's observers every 0.01, which cut the steps (section 39), with the reset each step and without
it; and the reset with observers every step (no step cut). Reads DIRECTORY/diagnosis/taylor_green_geometry_age.csv (L_over_dp, c_over_U, advection_cfl, density,
advection_steps, mean_dt, cached, refreshed_pressure_pass, refreshed_force_only, refreshed_riemann_term_only,
refreshed_divergence_only, refreshed_pressure_pass_and_divergence); writes DIRECTORY/pressure_taylor_green_geometry_age.png
and prints the measured and predicted gaps.
Usage: /usr/bin/python3 scripts/plot_taylor_green_geometry_age.py reports/pressure
"""
import csv
import math
import os

from plot_common import log_x_axis, plt, save, suite_dir

NU = 1.0 / 200.0  # the runs' viscosity: Re = 200 with L = U = 1
K = 2.0 * math.pi


def predicted_gap(dt, nu_eff):
    """dnu / nu of a geometry dt / 2 old on average, over the window the decay rate is fitted on."""
    times = [0.125 + 0.01 * i for i in range(88)]  # the probe's samples in the fit window
    mean_t = sum(times) / len(times)
    # The fitted slope of ln U is sum (t - mean) ln U / sum (t - mean)^2; a rate change dnu(t) enters ln U as
    # -2 k^2 times its integral, so its fitted share is that slope applied to the integral of dnu(t).
    integral, previous, cumulative = 0.0, None, []
    for t in times:
        dnu = dt * math.exp(-4.0 * nu_eff * NU * K * K * t) / 8.0
        if previous is not None:
            integral += 0.5 * (dnu + previous[1]) * (t - previous[0])
        previous = (t, dnu)
        cumulative.append(integral)
    slope = sum((t - mean_t) * y for t, y in zip(times, cumulative)) / sum((t - mean_t) ** 2 for t in times)
    return slope / NU


directory = suite_dir()
with open(os.path.join(directory, "diagnosis", "taylor_green_geometry_age.csv")) as f:
    rows = list(csv.DictReader(f))
reset = "summation each advection step (the paper's)"  # observers every 0.01: steps cut to land on them
uncut = reset + "; observers every step (no step cut)"  # the criterion's steps, the shift per unit time as intended

fig, axes = plt.subplots(1, 2, figsize=(11, 4.4), constrained_layout=True)
ax = axes[0]
variants = [("cached", "o-", "C0", "cached (the paper's)"),
            ("refreshed_pressure_pass", "D-", "C3", "pressure pass refreshed (the option)"),
            ("refreshed_force_only", "x--", "k", "pressure force only refreshed"),
            ("refreshed_riemann_term_only", "s:", "C1", "Riemann density term only refreshed"),
            ("refreshed_divergence_only", "^:", "C2", "velocity divergence only refreshed")]
for resolution, alpha in [("80", 1.0), ("40", 0.45)]:
    chosen = [r for r in rows if r["L_over_dp"] == resolution and r["c_over_U"] == "10" and r["density"] == reset]
    for key, style, color, label in variants:
        points = sorted((float(r["advection_cfl"]), float(r[key])) for r in chosen if r[key])
        x, y = zip(*points)
        ax.plot(x, y, style, color=color, ms=4, alpha=alpha, label=f"L/dp = {resolution}: {label}")
ax.axhline(1.0, color="k", lw=0.6)
log_x_axis(ax, [0.03125, 0.0625, 0.125, 0.25], ["0.031", "0.0625", "0.125", "0.25"], base=2)
ax.set_xlabel("advection CFL number (the paper's: 0.25)")
ax.set_ylabel("nu_eff / nu")
ax.set_title("Taylor-Green Re = 200, c = 10 U, reset each step: which pass's geometry", fontsize=9)
ax.legend(fontsize=6)

ax = axes[1]
print("L/dp  c   CFL      density    dt        cached  refreshed  gap     predicted")
for r in rows:
    gap = float(r["refreshed_pressure_pass"]) - float(r["cached"])
    prediction = predicted_gap(float(r["mean_dt"]), float(r["cached"]))
    on = r["density"] != "continuity only (no reset)"
    kind = "no cut" if r["density"] == uncut else "reset" if on else "no reset"
    marker = {"reset": "os", "no reset": "^v", "no cut": "+x"}[kind][0 if r["c_over_U"] == "10" else 1]
    color = "C0" if r["L_over_dp"] == "80" else "C1"
    ax.plot(prediction, gap, marker, color=color, mfc=color if kind == "reset" else "none", ms=5)
    print(f"{r['L_over_dp']:>4} {r['c_over_U']:>3} {r['advection_cfl']:>7}  {kind:8} "
          f"{float(r['mean_dt']):.5f}  {float(r['cached']):.3f}   {float(r['refreshed_pressure_pass']):.3f}    "
          f"{gap:+.3f}   {prediction:+.3f}")
limit = 0.14
ax.plot([0, limit], [0, limit], "k-", lw=0.6)
for label, marker, color, fill in [("L/dp = 80", "o", "C0", True), ("L/dp = 40", "o", "C1", True),
                                   ("c = 10 U, reset each step", "o", "0.4", True), ("c = 40 U, reset each step", "s", "0.4", True),
                                   ("c = 10 U, no reset", "^", "0.4", False), ("c = 40 U, no reset", "v", "0.4", False),
                                   ("c = 10 U, reset, no step cut (observers every step)", "+", "0.4", False),
                                   ("c = 40 U, reset, no step cut", "x", "0.4", False)]:
    ax.plot([], [], marker, color=color, mfc=color if fill else "none", label=label)
ax.set_xlabel("predicted: mean dt U^2 / (8 nu), no fitted parameter")
ax.set_ylabel("measured: nu_eff / nu refreshed - cached")
ax.set_title("The cached pressure force's anti-dissipation against its first-order prediction", fontsize=9)
ax.set_xlim(-0.005, limit)
ax.set_ylim(-0.15, limit)
ax.legend(fontsize=6.5)
save(fig, directory, "pressure_taylor_green_geometry_age.png")
