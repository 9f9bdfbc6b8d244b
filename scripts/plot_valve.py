"""Figures of the valve suite: the free end of the top leaflet and the closest distance between the
two leaflets against time for each Wo, and the leaflets (coloured by von Mises stress) with the fluid
velocity at the end of the run."""
import os

from plot_common import load_summary, plt, read_csv, save, suite_dir

directory = suite_dir()
summary = load_summary(directory)
fig, (ax_x, ax_y, ax_gap) = plt.subplots(3, 1, figsize=(9, 8.5), sharex=True)
for run in summary["runs"]:
    wo = run["config"]["womersley_number"]
    tip = read_csv(os.path.join(directory, f"Wo{wo:g}", "top_tip.csv"))
    ax_x.plot(tip["time"], [1000 * v for v in tip["dx"]], label=f"Wo = {wo:g}")
    ax_y.plot(tip["time"], [1000 * v for v in tip["dy"]], label=f"Wo = {wo:g}")
    gap_file = os.path.join(directory, f"Wo{wo:g}", "leaflet_gap.csv")
    if os.path.exists(gap_file):
        gap = read_csv(gap_file)
        ax_gap.plot(gap["time"], [1000 * v for v in gap["gap"]], label=f"Wo = {wo:g}")
period = summary["runs"][0]["config"]["inflow_period"]
t_end = summary["runs"][0]["config"]["end_time"]
k = 1
while k * period <= t_end:
    for ax in (ax_x, ax_y, ax_gap):
        ax.axvline(k * period, color="k", lw=0.5, ls=":")
    k += 1
ax_x.set_ylabel("top leaflet tip, horizontal [mm]")
ax_y.set_ylabel("top leaflet tip, vertical [mm]")
ax_gap.set_ylabel("closest leaflet particles [mm]")
ax_gap.set_xlabel("t [s] (dotted: inflow periods)")
ax_x.legend(fontsize=8)
save(fig, directory, "valve_tip.png")

runs = summary["runs"]
fig, axes = plt.subplots(len(runs), 1, figsize=(10, 3.2 * len(runs)), squeeze=False)
for ax, run in zip(axes[:, 0], runs):
    wo = run["config"]["womersley_number"]
    frame = read_csv(os.path.join(directory, f"Wo{wo:g}", "frame_end.csv"))
    fluid = [k for k, b in enumerate(frame["body"]) if b == 0]
    solid = [k for k, b in enumerate(frame["body"]) if b == 1]
    step = max(1, len(fluid) // 1500)
    sel = fluid[::step]
    ax.quiver([1000 * frame["x"][k] for k in sel], [1000 * frame["y"][k] for k in sel], [frame["u"][k] for k in sel],
              [frame["v"][k] for k in sel], color="steelblue", width=0.0015)
    sc = ax.scatter([1000 * frame["x"][k] for k in solid], [1000 * frame["y"][k] for k in solid], s=3,
                    c=[frame["von_mises"][k] / 1000 for k in solid], cmap="inferno")
    fig.colorbar(sc, ax=ax, label="von Mises [kPa]")
    ax.set_aspect("equal")
    ax.set_xlim(3, 12)
    ax.set_title(f"Wo = {wo:g}, t = {run['config']['end_time']:g} s")
save(fig, directory, "valve_leaflets.png")
