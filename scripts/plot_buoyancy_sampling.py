"""Figure of reports/pressure.md section 19: a submerged cylinder's buoyancy as the force observer
read it before (the last advection step before each output) and after (the average over the
observer interval), for six output intervals at each sound speed; and, for one run, both readings
over time.

Reads DIRECTORY/diagnosis/buoyancy_sampling.csv and buoyancy_sampling_c30_series.csv, writes
DIRECTORY/pressure_buoyancy_sampling.png.
Usage: /usr/bin/python3 scripts/plot_buoyancy_sampling.py reports/pressure
"""
import math
import os

from plot_common import plt, read_csv, save, suite_dir

directory = suite_dir()
runs = read_csv(os.path.join(directory, "diagnosis", "buoyancy_sampling.csv"))
series = read_csv(os.path.join(directory, "diagnosis", "buoyancy_sampling_c30_series.csv"))
rows = range(len(runs["sound_speed_factor"]))

fig, (ax, ax_t) = plt.subplots(1, 2, figsize=(12, 5.4), constrained_layout=True)
styles = [("cylinder_last_step_sample", 1, "last advection step before each output (before)", "x", "tab:red", -0.6),
          ("cylinder_interval_average", 1, "average over the observer interval (now)", "o", "tab:blue", 0.0),
          ("cylinder_interval_average", 0, "average over the interval, the paper's wall clip and lattice moment", "s", "tab:gray", 0.6)]
for column, options, label, marker, colour, offset in styles:
    pts = [(runs["sound_speed_factor"][k] + offset, 100 * (runs[column][k] - 1)) for k in rows
           if runs["rest_state_and_measured_moment"][k] == options and not math.isnan(runs[column][k])]
    ax.plot([p[0] for p in pts], [p[1] for p in pts], marker, color=colour, label=label, fillstyle="none")
ax.axhline(0, color="k", lw=0.8)
ax.set_xlabel("c / sqrt(2 g H)")
ax.set_ylabel("buoyancy / (rho g pi R^2) - 1  [%]")
ax.set_title("H/dp = 40, mean over t = 1.5-3 s; six output intervals (4-6 ms) per c")
ax.legend(fontsize=8, loc="upper center", bbox_to_anchor=(0.5, -0.14), ncol=1)

ax_t.plot(series["time"], [100 * (v - 1) for v in series["cylinder_last_step_sample"]], color="tab:red", lw=0.6,
          label="last advection step before each output")
ax_t.plot(series["time"], [100 * (v - 1) for v in series["cylinder_interval_average"]], color="tab:blue", lw=0.6,
          label="average over the interval")
ax_t.axhline(0, color="k", lw=0.8)
ax_t.set_xlabel("t [s]")
ax_t.set_ylabel("buoyancy / (rho g pi R^2) - 1  [%]")
ax_t.set_title("the same run (c = 30, output every 5 ms), both readings")
ax_t.set_ylim(-10, 15)
ax_t.legend(fontsize=8, loc="upper center", bbox_to_anchor=(0.5, -0.14), ncol=2)
save(fig, directory, "pressure_buoyancy_sampling.png")
