"""Figures of the pressure suite: drag and lift of the cylinder benchmarks against Turek & Hron and
Schaefer & Turek over
resolution and sound speed, the CFD3 lift history, the still tank's pressure profile, the submerged
cylinder's buoyancy over time, and the Taylor-Green vortex's errors over time."""
import math
import os

from plot_common import load_summary, plt, read_csv, save, suite_dir

directory = suite_dir()
summary = load_summary(directory)
refs = summary.get("cylinder_reference", {})
cylinder = [r for r in summary["runs"] if "benchmark" in r["config"]]


def value(run, name):
    return run["metrics"].get(name, math.nan) if not run["diverged"] else math.nan


st_refs = summary.get("schaefer_turek_reference", {})


def panels(name, runs):
    """(metric, reference: a value, a (low, high) band or None, the reference's label) for the two rows."""
    if name in st_refs:  # Schaefer & Turek: coefficients 2 F / (rho U^2 D), halved to the scene's F / (rho U^2 D)
        ref, label = st_refs[name], "Schaefer & Turek 1996"
        if name == "2D-1":
            return [("drag_mean", ref["drag_coefficient"] / 2, label),
                    ("pressure_difference_mean", ref["pressure_difference_Pa"] / ref["rho_U2_Pa"], label)]
        return [("drag_mean", None, label),
                ("lift_shedding_amplitude", tuple(v / 2 for v in ref["lift_coefficient_max_bounds"]), label + " (c_L,max / 2)")]
    ref, label = refs.get(name, {}), "Turek & Hron 2006"
    if name == "CFD3":
        # CFD3's amplitude: the lift's shedding component (summaries before it: the smoothed lift's percentiles).
        shedding = "lift_shedding_amplitude" if any("lift_shedding_amplitude" in r["metrics"] for r in runs) else "lift_amplitude"
        return [("drag_mean", ref.get("drag_mean"), label), (shedding, ref.get("lift_amplitude"), label)]
    return [("drag_mean", ref.get("drag"), label), ("lift_mean", ref.get("lift"), label)]


benchmarks = sorted({r["config"]["benchmark"] for r in cylinder})
if benchmarks:
    fig, axes = plt.subplots(2, len(benchmarks), figsize=(4.2 * len(benchmarks), 6.5), squeeze=False)
    for col, name in enumerate(benchmarks):
        runs = [r for r in cylinder if r["config"]["benchmark"] == name]
        for row, (metric, reference, label) in enumerate(panels(name, runs)):
            ax = axes[row][col]
            factors = sorted({round(r["config"]["sound_speed"]) for r in runs})
            for c in factors:
                pts = sorted((r["config"]["resolution"], value(r, metric)) for r in runs if round(r["config"]["sound_speed"]) == c)
                ax.plot([p[0] for p in pts], [p[1] for p in pts], "o-", label=f"c = {c} U0")
            if isinstance(reference, tuple):
                ax.axhspan(reference[0], reference[1], color="k", alpha=0.15, label=label)
            elif reference is not None:
                ax.axhline(reference, color="k", lw=0.8, ls="--", label=label)
            ax.set_xscale("log", base=2)
            ax.set_xlabel("D / dp")
            unit = " / (rho U0^2)" if metric.startswith("pressure") else " / (rho U0^2 D)"
            ax.set_ylabel(metric.replace("_", " ") + unit)
            ax.set_title(name)
            ax.legend(fontsize=7)
    fig.tight_layout()
    save(fig, directory, "pressure_cylinder_forces.png")

cfd3 = [r for r in cylinder if r["config"]["benchmark"] == "CFD3"]
if cfd3:
    fig, ax = plt.subplots(figsize=(10, 3.5))
    for r in sorted(cfd3, key=lambda r: (r["config"]["resolution"], r["config"]["sound_speed"])):
        path = os.path.join(directory, f"CFD3_res{r['config']['resolution']}_c{round(r['config']['sound_speed'])}", "forces.csv")
        if not os.path.exists(path):
            continue
        d = read_csv(path)
        ax.plot(d["time"], d["fy"], lw=0.5, label=r["case"] + f", shedding St {value(r, 'strouhal_shedding'):.3f}, amplitude {value(r, 'lift_shedding_amplitude'):.2f}")
    ax.set_xlabel("t U0 / D")
    ax.set_ylabel("lift / (rho U0^2 D)")
    ax.set_title(f"CFD3 (Turek & Hron: St {refs.get('CFD3', {}).get('strouhal', math.nan):.4f}, "
                 f"lift amplitude {refs.get('CFD3', {}).get('lift_amplitude', math.nan):.3f})")
    ax.legend(fontsize=7)
    save(fig, directory, "pressure_cfd3_lift.png")

profile_path = os.path.join(directory, "tank_profiles.csv")
if os.path.exists(profile_path):
    p = read_csv(profile_path)
    fig, (ax, ax_err) = plt.subplots(1, 2, figsize=(9, 4.5))
    rows = len(p["resolution"])
    refresh = p.get("refresh_pair_geometry", [0.0] * rows)
    relaxation = p.get("density_relaxation", [1.0] * rows)
    corrected = p.get("pressure_lattice_correction", [0.0] * rows)
    case = [(p["resolution"][k], p["sound_speed_factor"][k], refresh[k], relaxation[k], corrected[k]) for k in range(rows)]
    for key in sorted(set(case)):
        res, c, fresh, theta, lattice = key
        sel = [k for k in range(rows) if case[k] == key]
        depth = [p["depth_over_H"][k] for k in sel]
        paper = not fresh and theta == 1.0 and not lattice
        label = (f"H/dp = {res:g}, c = {c:g} sqrt(2gH)" + (", the paper's options" if paper else "")
                 + (", refreshed" if fresh else "") + (f", theta {theta:g}" if theta != 1.0 else "")
                 + (", M1-corrected" if lattice else ""))
        ax.plot([p["pressure_over_rho_g_H"][k] for k in sel], depth, "o-", ms=3, label=label)
        ax_err.plot([p["pressure_over_rho_g_H"][k] - p["hydrostatic_over_rho_g_H"][k] for k in sel], depth, "o-", ms=3)
    ax.plot([0, 1], [0, 1], "k--", lw=0.8, label="rho g (H - y)")
    ax.set_xlabel("p / (rho g H)")
    ax.set_ylabel("depth (H - y) / H")
    ax.invert_yaxis()
    ax.legend(fontsize=7)
    ax_err.axvspan(-0.01, 0.01, color="0.9", label="issue 17: 1 %")
    ax_err.set_xlabel("(p - rho g (H - y)) / (rho g H), mean over particles and time")
    ax_err.invert_yaxis()
    ax_err.legend(fontsize=7)
    save(fig, directory, "pressure_tank_profile.png")

submerged = [r for r in summary["runs"] if "archimedes_force" in r["config"]]
if submerged:
    fig, ax = plt.subplots(figsize=(9, 3.8))
    for r in submerged:
        cfg = r["config"]
        path = os.path.join(directory, f"buoyancy_res{cfg['resolution']}_c{cfg['sound_speed_factor']}", "cylinder_force.csv")
        if not os.path.exists(path):
            continue
        d = read_csv(path)
        ax.plot(d["time"], [f / cfg["archimedes_force"] for f in d["fy"]], lw=0.7,
                label=f"H/dp = {cfg['resolution']}, c = {cfg['sound_speed_factor']} sqrt(2gH): mean {value(r, 'buoyancy_ratio'):.4f}")
    ax.axhline(1.0, color="k", lw=0.8, ls="--", label="Archimedes, rho g pi R^2")
    ax.axvline(submerged[0]["config"]["settle_time"], color="0.6", lw=0.8, ls=":", label="means from here")
    ax.set_ylim(0.8, 1.2)
    ax.set_xlabel("t (s)")
    ax.set_ylabel("upward force on the cylinder / rho g pi R^2")
    ax.legend(fontsize=7)
    save(fig, directory, "pressure_buoyancy.png")

decay_path = os.path.join(directory, "taylor_green_decay.csv")
if os.path.exists(decay_path):
    d = read_csv(decay_path)
    # Older summaries lack the Reynolds number (all Re = 100) and the mode's amplitude.
    reynolds = d.get("Re", [100.0] * len(d["time"]))
    columns = ["velocity_l2", "energy_ratio", "pressure_l2"] + (["mode_amplitude_over_viscous"] if "mode_amplitude_over_viscous" in d else [])
    titles = ["velocity L2 error", "kinetic energy / analytic", "pressure L2 error",
              "vortex amplitude / viscous decay exp(-2 nu k^2 t)"]
    fig, axes = plt.subplots(1, len(columns), figsize=(4.3 * len(columns), 3.8))
    # Older summaries lack the advection CFL number (all the paper's 0.25).
    cfl = d.get("advection_cfl", [0.25] * len(d["time"]))
    keys = sorted(set(zip(reynolds, d["resolution"], d["sound_speed_factor"], cfl)))
    for re_, res, c, cfl_ in keys:
        sel = [k for k in range(len(d["time"])) if (reynolds[k], d["resolution"][k], d["sound_speed_factor"][k], cfl[k]) == (re_, res, c, cfl_)]
        t = [d["time"][k] for k in sel]
        label = f"Re = {re_:g}, L/dp = {res:g}, c = {c:g} U" + ("" if cfl_ == 0.25 else f", advection CFL {cfl_:g}")
        for ax, col in zip(axes, columns):
            ax.plot(t, [d[col][k] for k in sel], "o-", ms=3, label=label)
    for ax, label in zip(axes, titles):
        ax.set_xlabel("t U / L")
        ax.set_title(label, fontsize=9)
    axes[2].set_yscale("log")
    axes[0].legend(fontsize=6)
    save(fig, directory, "pressure_taylor_green.png")
