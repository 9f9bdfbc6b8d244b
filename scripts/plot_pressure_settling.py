"""Figure of reports/pressure.md section 10: how CFD2's drag settles in the periodic channel.

Reads DIRECTORY/diagnosis/cfd2_settling.csv (drag and lift in bins of 0.25 time units, one block of
rows per run) and DIRECTORY/diagnosis/cfd2_windows.csv (means over windows per run), writes
DIRECTORY/pressure_cfd2_settling.png. Usage: /usr/bin/python3 scripts/plot_pressure_settling.py reports/pressure
"""
import math
import os

from plot_common import plt, project_reference, read_csv, save, suite_dir

TUREK_HRON_CFD2_DRAG = project_reference("turek_hron_cfd.json")["CFD2"]["drag"]  # Turek & Hron (2006)


def block_means(values, size=4):
    """Means of consecutive blocks of `size` values (a trailing partial block is dropped)."""
    return [sum(values[i:i + size]) / size for i in range(0, len(values) - size + 1, size)]


directory = suite_dir()
series = read_csv(os.path.join(directory, "diagnosis", "cfd2_settling.csv"))
windows = read_csv(os.path.join(directory, "diagnosis", "cfd2_windows.csv"))

fig, (history, ladder) = plt.subplots(1, 2, figsize=(12, 4.2), gridspec_kw={"width_ratios": [2, 1]})
shown = ((20, 10, 2), (40, 10, 2), (20, 20, 2), (20, 10, 10))  # (D/dp, c / U0, ramp time)
for res, c, ramp in shown:
    rows = [k for k in range(len(series["t_mid"]))
            if (series["resolution"][k], series["sound_speed_factor"][k], series["ramp_time"][k]) == (res, c, ramp)]
    # Means over 1 time unit (four bins): the particle-scale noise averaged out, the mode (period 2.4) kept.
    t = block_means([series["t_mid"][k] for k in rows])
    drag = block_means([series["drag"][k] for k in rows])
    label = f"D/dp = {res:g}, c = {c:g} U0" + (f", ramp over {ramp:g}" if ramp != 2 else "")
    history.plot(t, drag, lw=1.0, marker=".", ms=3, label=label)
history.axhline(TUREK_HRON_CFD2_DRAG, color="k", ls="--", lw=0.8, label="Turek & Hron")
for start, end in ((12, 24), (24, 48)):
    history.axvspan(start, end, color="0.9" if start == 12 else "0.8", zorder=0)
history.set_ylim(1.0, 1.9)
history.set_xlabel("t U0 / D")
history.set_ylabel("drag / (rho U0^2 D), means over 1")
history.set_title("CFD2: the start-up's acoustic mode (shaded: the old and the new window)")
history.legend(fontsize=7, ncol=2)

c10 = [k for k in range(len(windows["resolution"])) if windows["sound_speed_factor"][k] == 10 and windows["ramp_time"][k] == 2]
for key, marker, label in (("drag_12_24", "s", "mean over t = 12-24"), ("drag_16_24", "^", "over t = 16-24"),
                           ("drag_24_48", "o", "over t = 24-48")):
    points = [(windows["resolution"][k], windows[key][k]) for k in c10 if not math.isnan(windows[key][k])]
    ladder.plot([p[0] for p in points], [p[1] for p in points], marker=marker, ls="-", label=label)
ladder.axhline(TUREK_HRON_CFD2_DRAG, color="k", ls="--", lw=0.8, label="Turek & Hron")
ladder.set_xlabel("D / dp (c = 10 U0)")
ladder.set_ylabel("drag mean")
ladder.set_title("the resolution ladder by window")
ladder.legend(fontsize=7)
save(fig, directory, "pressure_cfd2_settling.png")
