"""Figures of the antoci suite: free-end displacement against the experiment and the peer curves,
snapshots of case III, and the dry-bed dam-break front."""
import os

from plot_common import load_summary, plt, read_csv, save, suite_dir

directory = suite_dir()
summary = load_summary(directory)


def optional(name):
    path = os.path.join(directory, name)
    return read_csv(path) if os.path.exists(path) else None


DAMPING_STUDY = ("III-undamped", "III-undamped-instantaneous", "III-damping-0.2")

fig, (ax_x, ax_y) = plt.subplots(2, 1, figsize=(8, 7), sharex=True)
for run in summary["runs"]:
    if run["case"] == "dam break" or run["case"] in DAMPING_STUDY or run["case"].startswith("grid-"):
        continue
    d = read_csv(os.path.join(directory, f"case_{run['case']}", "tip_mm.csv"))
    ax_x.plot(d["time"], d["x_mm"], lw=1.2, label=f"mrsph case {run['case']}")
    ax_y.plot(d["time"], d["y_mm"], lw=1.2, label=f"mrsph case {run['case']}")
peer = optional("reference_sphinxsys_here.csv")
if peer:
    ax_x.plot(peer["time"], peer["x_mm"], "--", lw=1, color="gray", label="paper's code (run here)")
    ax_y.plot(peer["time"], peer["y_mm"], "--", lw=1, color="gray", label="paper's code (run here)")
for name, style, label, ax in [("reference_Antoci_x.csv", ":", "Antoci et al. SPH", ax_x),
                               ("reference_YangEtAl10X.csv", "-.", "Yang et al. SPH-FEM", ax_x),
                               ("reference_Antoci_y.csv", ":", "Antoci et al. SPH", ax_y),
                               ("reference_YangEtAl10Y.csv", "-.", "Yang et al. SPH-FEM", ax_y)]:
    d = optional(name)
    if d:
        ax.plot(d["time"], d["mm"], style, lw=1, color="k", label=label)
exp = optional("reference_experiment.csv")
if exp:
    ax_x.plot(exp["time"], exp["x_mm"], "ks", ms=5, label="experiment (Antoci et al. 2007)")
    ax_y.plot(exp["time"], exp["y_mm"], "ks", ms=5, label="experiment (Antoci et al. 2007)")
ax_x.set_ylabel("horizontal displacement of the free end [mm]")
ax_y.set_ylabel("vertical displacement [mm]")
ax_y.set_xlabel("t [s]")
ax_x.legend(fontsize=7)
save(fig, directory, "antoci_displacement.png")



def finish_tip_axes(ax):
    """The experiment's points, axis labels and legend of a plot of the free end's x against t."""
    if exp:
        ax.plot(exp["time"], exp["x_mm"], "ks", ms=5, label="experiment (Antoci et al. 2007)")
    ax.set_xlabel("t [s]")
    ax.set_ylabel("horizontal displacement of the free end [mm]")
    ax.legend(fontsize=7)


study = [run["case"] for run in summary["runs"] if run["case"] in DAMPING_STUDY]
if study:  # case III against its damping study (full mode)
    fig, ax = plt.subplots(figsize=(8, 4.5))
    for case in ["III"] + study:
        d = read_csv(os.path.join(directory, f"case_{case}", "tip_mm.csv"))
        damping = next(r["config"] for r in summary["runs"] if r["case"] == case)
        ax.plot(d["time"], d["x_mm"], lw=1.0,
                label=f"case {case} (damping {damping['solid_damping']:g}, {damping['solid_kinematics']} kinematics)")
    finish_tip_axes(ax)
    save(fig, directory, "antoci_damping.png")

grid = summary.get("convergence")
if grid:  # the convergence of the specified model (full mode)
    fig, (ax_e, ax_c) = plt.subplots(1, 2, figsize=(13, 4.8))
    styles = {"2nd": "-o", "B0": "--s"}
    for dp_f in sorted({row["dp_fluid_mm"] for row in grid}, reverse=True):
        for weights in ("2nd", "B0"):
            rows = sorted((r for r in grid if r["dp_fluid_mm"] == dp_f and r["weights"] == weights
                           and r["rms_error_x_mm"] is not None), key=lambda r: r["resolution"])
            if rows:
                ax_e.plot([r["resolution"] for r in rows], [r["rms_error_x_mm"] for r in rows], styles[weights],
                          label=f"dp_F = {dp_f:g} mm, {weights} weights")
    ax_e.axhline(5.0, color="k", lw=0.8, ls=":", label="issue 5 limit (5 mm)")
    ax_e.set_xscale("log", base=2)
    ax_e.set_xticks([4, 8, 16])
    ax_e.set_xticklabels(["b/4", "b/8", "b/16"])
    ax_e.set_xlabel("solid spacing dp_S")
    ax_e.set_ylabel("RMS error of the free end's x against the experiment [mm]")
    ax_e.legend(fontsize=7)
    finest_solid = max(r["resolution"] for r in grid)
    finest_fluid = min(r["dp_fluid_mm"] for r in grid)
    for row in grid:
        if row["resolution"] == finest_solid or row["dp_fluid_mm"] == finest_fluid:
            d = read_csv(os.path.join(directory, f"case_{row['case']}", "tip_mm.csv"))
            ax_c.plot(d["time"], d["x_mm"], "--" if row["weights"] == "B0" else "-", lw=1.0,
                      label=f"dp_F = {row['dp_fluid_mm']:g} mm, b/{row['resolution']}, {row['weights']}")
    finish_tip_axes(ax_c)
    save(fig, directory, "antoci_convergence.png")

frames_path = os.path.join(directory, "case_III", "frames.csv")
if os.path.exists(frames_path):
    frames = read_csv(frames_path)
    times = sorted(set(frames["time"]))
    fig, axes = plt.subplots(2, 4, figsize=(16, 6), sharex=True, sharey=True)
    pmax = max(frames["pressure"]) or 1.0
    for ax, t in zip(axes.flat, times):
        fluid = [k for k, (tt, b) in enumerate(zip(frames["time"], frames["body"])) if tt == t and b == 0]
        gate = [k for k, (tt, b) in enumerate(zip(frames["time"], frames["body"])) if tt == t and b == 1]
        ax.scatter([frames["x"][k] for k in fluid], [frames["y"][k] for k in fluid], s=1,
                   c=[frames["pressure"][k] for k in fluid], cmap="viridis", vmin=0, vmax=pmax)
        ax.scatter([frames["x"][k] for k in gate], [frames["y"][k] for k in gate], s=1, c="red")
        ax.set_title(f"t = {t:.2f} s")
        ax.set_aspect("equal")
        ax.set_xlim(0.2, 0.52)
        ax.set_ylim(0.0, 0.16)
    save(fig, directory, "antoci_snapshots.png")

front = optional("dam_break_front.csv")
if front:
    import json
    refs = json.load(open(os.path.join(os.path.dirname(__file__), "..", "reference-data", "dam_break_front.json")))
    fig, ax = plt.subplots(figsize=(5, 4))
    ax.plot(front["T"], front["Z"], "-", label="mrsph (inviscid)")
    ax.plot(refs["martin_moyce_a_2_25in"]["T"], refs["martin_moyce_a_2_25in"]["Z"], "ks", label="Martin & Moyce 1952")
    ax.plot(refs["koshizuka_oka"]["T"], refs["koshizuka_oka"]["Z"], "k^", label="Koshizuka & Oka 1996")
    ax.set_xlim(0, max(front["T"]))
    ax.set_ylim(1, max(front["Z"]) * 1.1)
    ax.set_xlabel("t sqrt(2 g / a)")
    ax.set_ylabel("front position z / a")
    ax.legend(fontsize=8)
    save(fig, directory, "dam_break_front.png")
