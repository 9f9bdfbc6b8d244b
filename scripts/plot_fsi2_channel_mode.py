"""Figure of reports/turek-hron.md, "Case I's dependence on c found": FSI2's amplitude and the drag's
component at twice the beam's frequency against where the periodic channel's first acoustic mode
lies relative to that frequency (2f); the mode as measured: the drag spectrum's peak before the beam
oscillates (t = 3-25), near c / 2L.

Reads DIRECTORY/fsi2_channel_mode.csv, writes DIRECTORY/turek_hron_channel_mode.png.
Usage: /usr/bin/python3 scripts/plot_fsi2_channel_mode.py reports/turek-hron
"""
import csv
import os

from plot_common import plt, save, suite_dir

directory = suite_dir()
with open(os.path.join(directory, "fsi2_channel_mode.csv")) as f:
    rows = [r for r in csv.DictReader(line for line in f if not line.startswith("#"))]

fig, (ax_amp, ax_drag) = plt.subplots(1, 2, figsize=(11, 4.2), constrained_layout=True)
for case, colour in (("I", "tab:blue"), ("III", "tab:orange")):
    runs = [r for r in rows if r["case"] == case and r["early_drag_peak"]]
    for r in runs:
        ratio = float(r["early_drag_peak"]) / (2.0 * float(r["f"]))
        marker = "o" if "13 D" in r["channel"] else "s"
        label = f"case {case}, c = {r['sound_speed_over_U0']} U0, {r['channel']}"
        ax_amp.plot(ratio, float(r["amplitude_y"]), marker, color=colour, label=label)
        ax_drag.plot(ratio, float(r["drag_at_2f"]), marker, color=colour)
for ax in (ax_amp, ax_drag):
    ax.axvline(1.0, color="grey", lw=0.8, ls=":")
    ax.set_xscale("log")
    ax.set_xlabel("channel's first acoustic mode (measured) over the drag's frequency 2f")
ax_amp.axhline(0.806, color="k", lw=0.8, ls="--", label="Turek & Hron (2006), A_y / D")
ax_amp.set_ylabel("A_y / D (t >= 100)")
ax_drag.set_ylabel("drag at 2f [rho U0^2 D]")
handles, labels = ax_amp.get_legend_handles_labels()
ax_drag.legend(handles, labels, fontsize=7, loc="upper right")  # the drag panel's upper right is empty
save(fig, directory, "turek_hron_channel_mode.png")
