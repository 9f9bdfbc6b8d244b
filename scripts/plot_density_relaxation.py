"""Figure of reports/pressure.md section 11: the summation's reset relaxed (fluid.density_relaxation).

Reads DIRECTORY/diagnosis/density_relaxation_tank.csv (the still tank's depth bins, worst bin and
noise per setting) and DIRECTORY/diagnosis/density_relaxation_cfd3_lift.csv (CFD3's lift averaged
over 0.5, t = 40-80, D/dp = 20), writes DIRECTORY/pressure_density_relaxation.png.
Usage: /usr/bin/python3 scripts/plot_density_relaxation.py reports/pressure
"""
import os

from plot_common import plt, project_reference, read_csv, save, suite_dir

CFD3_LIFT_AMPLITUDE = project_reference("turek_hron_cfd.json")["CFD3"]["lift_amplitude"]  # Turek & Hron (2006)

directory = suite_dir()
tank = read_csv(os.path.join(directory, "diagnosis", "density_relaxation_tank.csv"))
lift = read_csv(os.path.join(directory, "diagnosis", "density_relaxation_cfd3_lift.csv"))

fig, (noise, profile, history) = plt.subplots(1, 3, figsize=(15, 4.2), gridspec_kw={"width_ratios": [1, 1, 2]})
rows = range(len(tank["density_relaxation"]))
sampled = [k for k in rows if tank["snapshot_interval"][k] == 0.1]
for refresh, corrected, marker in ((0, 0, "o"), (1, 0, "s"), (0, 1, "^"), (1, 1, "D")):
    sel = sorted((k for k in sampled if (tank["refresh_pair_geometry"][k], tank["pressure_lattice_correction"][k]) == (refresh, corrected)),
                 key=lambda k: tank["density_relaxation"][k])
    if not sel:
        continue
    label = "summation as is" if not (refresh or corrected) else ", ".join(
        name for name, on in (("refreshed geometry", refresh), ("M1-corrected", corrected)) if on)
    theta = [tank["density_relaxation"][k] for k in sel]
    noise.plot(theta, [tank["noise_percent"][k] for k in sel], marker=marker, label=label)
    profile.plot(theta, [tank["worst_bin_percent"][k] for k in sel], marker=marker, label=label)
for ax, criterion, title in ((noise, 2.0, "pressure noise, % of rho g H"), (profile, 1.0, "worst depth bin, % of rho g H")):
    ax.set_xscale("log")
    ax.axhline(criterion, color="k", ls="--", lw=0.8, label=f"issue 17: {criterion:g} %")
    ax.set_xlabel("density_relaxation theta (1: the paper's)")
    ax.set_title(f"still tank H/dp = 40: {title}", fontsize=9)
    ax.legend(fontsize=7)
noise.set_yscale("log")

for column, style, label in (("lift_summation_c20", "C0-", "summation, c = 20 U0"),
                             ("lift_relaxation_0.1_c20", "C1-", "theta = 0.1, c = 20 U0"),
                             ("lift_summation_c40", "C0:", "summation, c = 40 U0"),
                             ("lift_relaxation_0.1_c40", "C1:", "theta = 0.1, c = 40 U0"),
                             ("lift_relaxation_0.1_c20_acoustic_cfl_0.15", "C2-", "theta = 0.1, c = 20 U0, acoustic CFL 0.15")):
    history.plot(lift["time"], lift[column], style, lw=0.9, label=label)
for sign in (1, -1):
    history.axhline(sign * CFD3_LIFT_AMPLITUDE, color="k", ls="--", lw=0.8, label="Turek & Hron amplitude" if sign > 0 else None)
history.set_xlabel("t (D / U0)")
history.set_ylabel("lift (rho U0^2 D), averaged over 0.5")
history.set_title("CFD3, D/dp = 20, periodic channel", fontsize=9)
history.legend(fontsize=7, ncol=2, loc="lower left")
save(fig, directory, "pressure_density_relaxation.png")
