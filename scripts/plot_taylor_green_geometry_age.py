"""Figure of reports/pressure.md section 38: which pass's cached pair geometry makes the Taylor-Green vortex
(Re = 200) depend on the advection step, with the paper's density summation each step and without it, and the
first-order prediction of the cached pressure force's anti-dissipation.

A pressure gradient read on the particles' arrangement of the list build, tau old, is to first order
(I + tau L^T) grad p, L = grad v, on an arrangement that reads a linear field exactly; where the pressure balances the
convective acceleration, (v . grad) v = -grad p / rho, the error's power per unit mass is tau |grad p|^2 / rho^2 >= 0.
For the vortex (u = U sin kx cos ky, p = rho U^2 (cos 2kx + cos 2ky) / 4) that is a viscosity deficit tau U^2 / 4:
dnu / nu = tau U(t)^2 / (4 nu), tau the pressure passes' mean geometry age (half the step, time-weighted over the
steps of an output interval), U(t) = exp(-2 nu_eff k^2 t), weighted over the fit window t = 0.125-1 as the fitted
decay rate weights it. No parameter is fitted.

Rows: observers every 0.01 (the scene's), which cut the steps (section 39), with the reset each step and without it;
and the reset with observers every step (no step cut). Reads DIRECTORY/diagnosis/taylor_green_geometry_age.csv
(L_over_dp, c_over_U, advection_cfl, density, steps_cut_by_outputs, advection_steps, mean_dt, mean_geometry_age,
cached, refreshed_pressure_pass, refreshed_force_only, refreshed_riemann_term_only, refreshed_divergence_only,
refreshed_pressure_pass_and_divergence, force_at_step_middle_once_per_step); writes DIRECTORY/pressure_taylor_green_geometry_age.png and prints the
measured and predicted gaps.
Usage: /usr/bin/python3 scripts/plot_taylor_green_geometry_age.py reports/pressure
"""
import csv
import math
import os

from plot_common import log_x_axis, plt, save, suite_dir

NU = 1.0 / 200.0  # the runs' viscosity: Re = 200 with L = U = 1
K = 2.0 * math.pi


def predicted_gap(age, nu_eff):
    """dnu / nu of a geometry `age` old on average, over the window the decay rate is fitted on."""
    times = [0.125 + 0.01 * i for i in range(88)]  # the probe's samples in the fit window
    mean_t = sum(times) / len(times)
    # The fitted slope of ln U is sum (t - mean) ln U / sum (t - mean)^2; a rate change dnu(t) enters ln U as
    # -2 k^2 times its integral, so its fitted share is that slope applied to the integral of dnu(t).
    integral, previous, cumulative = 0.0, None, []
    for t in times:
        dnu = age * math.exp(-4.0 * nu_eff * NU * K * K * t) / 4.0
        if previous is not None:
            integral += 0.5 * (dnu + previous[1]) * (t - previous[0])
        previous = (t, dnu)
        cumulative.append(integral)
    slope = sum((t - mean_t) * y for t, y in zip(times, cumulative)) / sum((t - mean_t) ** 2 for t in times)
    return slope / NU


directory = suite_dir()
with open(os.path.join(directory, "diagnosis", "taylor_green_geometry_age.csv")) as f:
    rows = list(csv.DictReader(f))
reset, no_reset = "summation each advection step (the paper's)", "continuity only (no reset)"


def chosen(resolution, c, density, cut):
    return [r for r in rows if r["L_over_dp"] == resolution and r["c_over_U"] == c and r["density"] == density
            and r["steps_cut_by_outputs"].startswith(cut)]


def plot_variants(ax, density, variants, cases, title):
    for resolution, c, alpha in cases:
        for key, style, color, label in variants:
            points = sorted((float(r["advection_cfl"]), float(r[key])) for r in chosen(resolution, c, density, "yes") if r[key])
            if points:
                x, y = zip(*points)
                ax.plot(x, y, style, color=color, ms=4, alpha=alpha, label=f"L/dp = {resolution}, c = {c} U: {label}")
    ax.axhline(1.0, color="k", lw=0.6)
    log_x_axis(ax, [0.03125, 0.0625, 0.125, 0.25], ["0.031", "0.0625", "0.125", "0.25"], base=2)
    ax.set_xlabel("advection CFL number (the paper's: 0.25)")
    ax.set_title(title, fontsize=8)
    ax.legend(fontsize=5)


fig, axes = plt.subplots(1, 3, figsize=(16, 4.8), constrained_layout=True)
plot_variants(axes[0], reset,
              [("cached", "o-", "C0", "cached (the paper's)"),
               ("refreshed_pressure_pass", "D-", "C3", "pressure pass refreshed (the option)"),
               ("refreshed_force_only", "x--", "k", "pressure force only refreshed"),
               ("refreshed_riemann_term_only", "s:", "C1", "Riemann density term only"),
               ("refreshed_divergence_only", "^:", "C2", "velocity divergence only")],
              [("80", "10", 1.0), ("40", "10", 0.45)], "reset each step (the paper's): which pass's geometry")
axes[0].set_ylabel("nu_eff / nu")
plot_variants(axes[1], no_reset,
              [("cached", "o-", "C0", "cached"),
               ("refreshed_pressure_pass", "D-", "C3", "pressure pass refreshed"),
               ("refreshed_divergence_only", "^:", "C2", "divergence only refreshed"),
               ("refreshed_pressure_pass_and_divergence", "*-", "C4", "pressure pass and divergence refreshed")],
              [("80", "10", 1.0), ("80", "40", 0.45)], "no reset (continuity equation only): force and divergence")

ax = axes[2]
print("L/dp  c   CFL      density   cut  age       cached  refreshed  gap     predicted")
for r in rows:
    gap = float(r["refreshed_pressure_pass"]) - float(r["cached"])
    prediction = predicted_gap(float(r["mean_geometry_age"]), float(r["cached"]))
    cut = r["steps_cut_by_outputs"].startswith("yes")
    kind = "reset" if r["density"] == reset and cut else "no reset" if cut else "no cut"
    marker = {"reset": "os", "no reset": "^v", "no cut": "+x"}[kind][0 if r["c_over_U"] == "10" else 1]
    color = "C0" if r["L_over_dp"] == "80" else "C1"
    ax.plot(prediction, gap, marker, color=color, mfc=color if kind == "reset" else "none", ms=5)
    print(f"{r['L_over_dp']:>4} {r['c_over_U']:>3} {r['advection_cfl']:>7}  {kind:8}  {float(r['mean_geometry_age']):.5f}  "
          f"{float(r['cached']):.3f}   {float(r['refreshed_pressure_pass']):.3f}    {gap:+.3f}   {prediction:+.3f}")
limit = 0.14
ax.plot([0, limit], [0, limit], "k-", lw=0.6)
for label, marker, color, fill in [("L/dp = 80", "o", "C0", True), ("L/dp = 40", "o", "C1", True),
                                   ("c = 10 U, reset each step", "o", "0.4", True), ("c = 40 U, reset each step", "s", "0.4", True),
                                   ("c = 10 U, no reset", "^", "0.4", False), ("c = 40 U, no reset", "v", "0.4", False),
                                   ("c = 10 U, reset, no step cut (observers every step)", "+", "0.4", False),
                                   ("c = 40 U, reset, no step cut", "x", "0.4", False)]:
    ax.plot([], [], marker, color=color, mfc=color if fill else "none", label=label)
ax.set_xlabel("predicted: tau <U^2> / (4 nu), no fitted parameter")
ax.set_ylabel("measured: nu_eff / nu, pressure pass refreshed - cached")
ax.set_title("The cached pressure force's anti-dissipation against its first-order prediction", fontsize=8)
ax.set_xlim(-0.005, limit)
ax.set_ylim(-0.15, limit)
ax.legend(fontsize=6)
save(fig, directory, "pressure_taylor_green_geometry_age.png")
