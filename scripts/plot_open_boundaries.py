"""Figures of the open-boundaries suite: the Poiseuille profile driven by a pressure difference
against the analytic one, the acoustic pulse at the probe for a fixed-pressure and a weakly
reflecting outlet, and the density along the open Turek-Hron channel during the inflow ramp.
Optional second argument: a directory of venous_valve_pressure runs (valve_wo1, valve_wo5,
valve_wo10, each an mrsph output directory) for the valve driven by pressure."""
import glob
import os
import sys

from plot_common import plt, read_csv, save, suite_dir

valve_directory = sys.argv.pop(2) if len(sys.argv) > 2 else None
directory = suite_dir()

profiles = sorted(glob.glob(os.path.join(directory, "poiseuille_profile_res*.csv")))
if profiles:
    fig, ax = plt.subplots(figsize=(5, 4))
    for path in profiles:
        d = read_csv(path)
        label = os.path.basename(path)[len("poiseuille_profile_"):-4].replace("res", "H/dp = ").replace("_", ", ")
        ax.plot(d["u"], d["y_over_H"], "o", ms=3, label=label)
    ax.plot(d["u_analytic"], d["y_over_H"], "k-", lw=1, label="G y (H - y) / (2 mu)")
    ax.set_xlabel("u / U")
    ax.set_ylabel("y / H")
    ax.set_title("Poiseuille flow driven by p_in - p_out")
    ax.legend(fontsize=7)
    save(fig, directory, "open_poiseuille_profile.png")

pulses = sorted(glob.glob(os.path.join(directory, "pulse_tau*")))
if pulses:
    fig, ax = plt.subplots(figsize=(6.5, 3.8))
    for run in pulses:
        d = read_csv(os.path.join(run, "pressure_far.csv"))
        tau = os.path.basename(run)[len("pulse_tau"):]
        label = "fixed pressure (tau = 0)" if tau == "0" else f"weakly reflecting (tau = {tau})"
        ax.plot(d["time"], d[list(d)[1]], lw=1, label=label)
    ax.set_xlabel("t")
    ax.set_ylabel("p at 3 L / 4 (rho c A = 0.5)")
    ax.set_title("acoustic pulse: incident, then its reflection from the outlet")
    ax.legend(fontsize=7)
    save(fig, directory, "open_pulse_reflection.png")

ramps = sorted(glob.glob(os.path.join(directory, "ramp_density_res*.csv")))
if ramps:
    fig, axes = plt.subplots(1, len(ramps), figsize=(5.2 * len(ramps), 3.8), squeeze=False)
    for ax, path in zip(axes[0], ramps):
        d = read_csv(path)
        for t in sorted(set(d["time"])):
            sel = [k for k in range(len(d["time"])) if d["time"][k] == t]
            line, = ax.plot([d["x"][k] for k in sel], [100 * d["mean_density_deviation"][k] for k in sel], "-", label=f"t = {t:g}")
            ax.plot([d["x"][k] for k in sel], [100 * d["largest_density_deviation"][k] for k in sel], ":", color=line.get_color())
        ax.axhline(3, color="k", lw=0.8, ls="--")
        ax.set_xlabel("x / D (inlet at 0, outlet at 25)")
        ax.set_ylabel("rho / rho0 - 1 [%]: mean (solid), largest |.| (dotted)")
        ax.set_title(os.path.basename(path)[len("ramp_density_"):-4].replace("res", "D/dp = ").replace("_c", ", c = ") + " U0")
        ax.legend(fontsize=7)
    save(fig, directory, "open_channel_ramp_density.png")

if valve_directory:
    valves = [(wo, os.path.join(valve_directory, f"valve_wo{wo}")) for wo in (1, 5, 10)]
    valves = [(wo, p) for wo, p in valves if os.path.exists(os.path.join(p, "observers", "top_tip.csv"))]
    if valves:
        fig, axes = plt.subplots(3, 1, figsize=(7, 8), sharex=True)
        for wo, run in valves:
            tip = read_csv(os.path.join(run, "observers", "top_tip.csv"))
            gap = read_csv(os.path.join(run, "observers", "leaflet_gap.csv"))
            vel = read_csv(os.path.join(run, "observers", "upstream_centre.csv"))
            axes[0].plot(tip["time"], [1e3 * v for v in tip[list(tip)[2]]], lw=1, label=f"Wo = {wo}")
            axes[1].plot(gap["time"], [1e3 * v for v in gap[list(gap)[1]]], lw=1, label=f"Wo = {wo}")
            axes[2].plot(vel["time"], vel[list(vel)[1]], lw=1, label=f"Wo = {wo}")
        axes[0].set_ylabel("top tip y displacement [mm]")
        axes[1].set_ylabel("leaflet gap [mm]")
        axes[2].set_ylabel("upstream centre u [m/s]")
        axes[2].set_xlabel("t [s]")
        axes[0].set_title("venous valve driven by a pressure difference")
        axes[0].legend(fontsize=7)
        save(fig, directory, "open_valve_pressure.png")
