"""Figure of reports/pressure.md sections 31-32: Schaefer & Turek's 2D-2 (Re = 100) lift amplitude against
the fluid's resolution D/dp (the default scheme and the Riemann momentum dissipation on; h = 1.3, 1.6 and 2.0 dp), and at
D/dp = 20 against the transport-velocity coefficient alpha, with the lift's particle-scale noise.

Reads DIRECTORY/diagnosis/schaefer_turek_2d2_wake.csv (run, variant, D_over_dp, h_over_dp,
transport_velocity_alpha, riemann_momentum, Re, ..., lift_shedding_amplitude, ..., lift_rms_2-10, ...), the bounds from reference-data/schaefer_turek_cylinder.json;
writes DIRECTORY/pressure_schaefer_turek_wake.png.
Usage: /usr/bin/python3 scripts/plot_schaefer_turek_wake.py reports/pressure
"""
import csv
import os

from plot_common import plt, project_reference, save, suite_dir

directory = suite_dir()
with open(os.path.join(directory, "diagnosis", "schaefer_turek_2d2_wake.csv")) as f:
    rows = [r for r in csv.DictReader(f) if r["Re"] == "100"]
low, high = project_reference("schaefer_turek_cylinder.json")["2D-2"]["lift_coefficient_max_bounds"]


def series(riemann_momentum, h_over_dp):
    points = sorted((float(r["D_over_dp"]), float(r["lift_shedding_amplitude"])) for r in rows
                    if r["riemann_momentum"] == riemann_momentum and r["h_over_dp"] == h_over_dp
                    and r["variant"].startswith(("default", "Riemann")))  # the scenes' settings otherwise
    return list(zip(*points)) if points else ([], [])


fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4.6), constrained_layout=True)
for h_over_dp, style in [("1.3", "o-"), ("1.6", "s--"), ("2.0", "^:")]:
    for riemann_momentum, label, color in [("off", "default (Riemann dissipation in continuity only)", "C0"),
                                           ("on", "Riemann momentum dissipation on", "C1")]:
        x, y = series(riemann_momentum, h_over_dp)
        if x:
            left.plot(x, y, style, color=color, ms=4, label=f"{label}, h = {h_over_dp} dp")
left.axhspan(low, high, color="k", alpha=0.15, label="Schaefer & Turek c_L,max")
left.set_xlabel("D / dp")
left.set_ylabel("c_L amplitude (shedding band), t = 40-60")
left.set_xticks([20, 30, 40])
left.set_title("2D-2, c = 10 U0", fontsize=9)
left.legend(fontsize=6.5, loc="upper center", bbox_to_anchor=(0.5, -0.16), ncol=2)

alpha_rows = [r for r in rows if r["D_over_dp"] == "20" and r["h_over_dp"] == "1.3" and "alpha" in r["variant"]]
alpha = sorted((float(r["transport_velocity_alpha"]), float(r["lift_shedding_amplitude"]), float(r["lift_rms_2-10"]))
               for r in alpha_rows)
a, amplitude, noise = zip(*alpha)
right.plot(a, amplitude, "o-", ms=4, label="c_L amplitude (shedding band)")
right.plot(a, noise, "s--", ms=4, label="c_L rms at f = 2-10 (particle noise)")
right.axhspan(low, high, color="k", alpha=0.15)
right.set_xlabel("transport-velocity coefficient alpha")
right.set_title("2D-2, D/dp = 20, c = 10 U0", fontsize=9)
right.legend(fontsize=7)
save(fig, directory, "pressure_schaefer_turek_wake.png")
