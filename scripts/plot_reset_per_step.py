"""Figure of reports/pressure.md section 41: the summation's reset once per advection step, the paper's
(a whole reset each step) and scaled by the advection CFL below 0.25 (a fraction CFL / 0.25 each step).
Left: the pressure-driven open channel (Re = 100, L = 10 H, H/dp = 20, c = 10 U, datum 0), flow rate in
the middle half against time, means over one time unit of snapshots every 0.5, from t = 30. Right: the Taylor-Green
vortex (Re = 200, L/dp = 40, c = 10 U), nu_eff / nu from the mode amplitude against the advection CFL,
with the paper's cached pair geometry and with the pressure pass refreshed.

Reads DIRECTORY/diagnosis/reset_per_step_channel.csv (advection_cfl, reset, time, flow_rate_error,
transverse_velocity_rms) and DIRECTORY/diagnosis/reset_per_step_vortex.csv (advection_cfl, pair_geometry,
reset, nu_eff_over_nu, advection_steps); writes DIRECTORY/pressure_reset_per_step.png.
Usage: /usr/bin/python3 scripts/plot_reset_per_step.py reports/pressure
"""
from plot_common import read_diagnosis_rows, log_x_axis, plt, save, suite_dir

directory = suite_dir()


def read(name):
    return read_diagnosis_rows(directory, name)


channel, vortex = read("reset_per_step_channel.csv"), read("reset_per_step_vortex.csv")
fig, (left, right) = plt.subplots(1, 2, figsize=(12, 5.4), constrained_layout=True)
for key in dict.fromkeys((r["advection_cfl"], r["reset"]) for r in channel):
    rows = [r for r in channel if (r["advection_cfl"], r["reset"]) == key]
    starts = sorted({int(float(r["time"])) for r in rows if 30.0 <= float(r["time"]) < 60.0})
    means, noise = [], 0.0
    for t0 in starts:
        window = [r for r in rows if t0 <= float(r["time"]) < t0 + 1]
        means.append(100.0 * sum(float(r["flow_rate_error"]) for r in window) / len(window))
    late = [float(r["transverse_velocity_rms"]) for r in rows if float(r["time"]) >= 50.0]
    noise = sum(late) / len(late)
    style = "--" if "without" in key[1] else "-"
    left.plot([t + 0.5 for t in starts], means, style, lw=1.0,
              label=f"CFL {key[0]}, reset {key[1]} (v_rms {noise:.4f} U at t >= 50)")
left.axhline(0.0, color="k", lw=0.6)
left.set_ylim(-12, 2)
left.set_xlabel("t (H / U)")
left.set_ylabel("flow rate error in the middle half (%), one-unit means")
left.set_title("pressure-driven open channel, Re = 100, 10 H, H/dp = 20, c = 10 U", fontsize=9)
left.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.13), ncol=2)
for (geometry, reset), style in zip([("cached", "paper"), ("cached", "scaled"), ("refreshed", "paper"), ("refreshed", "scaled")],
                                    ["o--", "o-", "s--", "s-"]):
    rows = sorted((r for r in vortex if r["pair_geometry"] == geometry and r["reset"] == reset),
                  key=lambda r: float(r["advection_cfl"]))
    right.plot([float(r["advection_cfl"]) for r in rows], [float(r["nu_eff_over_nu"]) for r in rows], style, ms=4,
               label=f"pair geometry {geometry}, reset {reset}")
log_x_axis(right, [0.03125, 0.0625, 0.125, 0.25], ["0.031", "0.0625", "0.125", "0.25"], base=2)
right.axhline(1.0, color="k", lw=0.6)
right.set_xlabel("advection CFL")
right.set_ylabel("nu_eff / nu")
right.set_title("Taylor-Green vortex, Re = 200, L/dp = 40, c = 10 U", fontsize=9)
right.legend(fontsize=7)
save(fig, directory, "pressure_reset_per_step.png")
