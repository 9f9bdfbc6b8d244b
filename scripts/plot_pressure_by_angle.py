"""Figure of reports/pressure.md section 16: where on the cylinder CFD1's and CFD2's drag changes with
resolution.

Reads DIRECTORY/diagnosis/cfd_drag_by_angle.csv (the drag of the force the fluid particles put on the
cylinder, by each particle's angle from the front stagnation point, both sides folded, 5-degree bins;
means over t = 12-24), writes DIRECTORY/pressure_cfd_drag_by_angle.png.
Usage: /usr/bin/python3 scripts/plot_pressure_by_angle.py reports/pressure
"""
import os

from plot_common import plt, read_csv, save, suite_dir

directory = suite_dir()
data = read_csv(os.path.join(directory, "diagnosis", "cfd_drag_by_angle.csv"))
rows = range(len(data["Re"]))


def cumulative(values):
    out, total = [], 0.0
    for v in values:
        total += v
        out.append(total)
    return out


fig, axes = plt.subplots(2, 2, figsize=(12, 8.4), constrained_layout=True)
for ax, change, re in zip(axes[0], axes[1], (100, 20)):
    ladder = sorted({data["D_over_dp"][k] for k in rows if data["Re"][k] == re})
    finest = [k for k in rows if data["Re"][k] == re and data["D_over_dp"][k] == ladder[-1]]
    for res in ladder:
        sel = [k for k in rows if data["Re"][k] == re and data["D_over_dp"][k] == res]
        angle = [0.5 * (data["angle_from"][k] + data["angle_to"][k]) for k in sel]
        edge = [data["angle_to"][k] for k in sel]
        width = [data["angle_to"][k] - data["angle_from"][k] for k in sel]
        # drag per degree of the folded surface
        pressure = [data["pressure_normal_drag"][k] / w for k, w in zip(sel, width)]
        viscous = [data["viscous_drag"][k] / w for k, w in zip(sel, width)]
        line, = ax.plot(angle, pressure, lw=1.2, label=f"pressure, D/dp = {res:g}")
        ax.plot(angle, viscous, lw=1.0, ls="--", color=line.get_color(), label=f"viscous, D/dp = {res:g}")
        if res != ladder[-1]:  # what the finest run no longer has, summed from the front to each angle
            for key, style, part in (("pressure_normal_drag", "-", "pressure"), ("viscous_drag", "--", "viscous")):
                excess = cumulative([data[key][k] - data[key][f] for k, f in zip(sel, finest)])
                change.plot(edge, excess, lw=1.2, ls=style, color=line.get_color(),
                            label=f"{part}, D/dp = {res:g} minus {ladder[-1]:g}")
    ax.axhline(0.0, color="k", lw=0.5)
    ax.set_xlabel("fluid particle's angle from the front stagnation point [degrees]")
    ax.set_ylabel("drag per degree / (rho U0^2 D)")
    ax.set_title(f"{'CFD2' if re == 100 else 'CFD1'} (Re = {re:g}), c = 10 U0, means over t = 12-24")
    ax.legend(fontsize=7, ncol=2)
    change.axhline(0.0, color="k", lw=0.5)
    change.set_xlabel("angle [degrees]")
    change.set_ylabel("drag from 0 to the angle, minus the finest run's")
    change.set_title("where the coarser runs' drag differs")
    change.legend(fontsize=7)
save(fig, directory, "pressure_cfd_drag_by_angle.png")
