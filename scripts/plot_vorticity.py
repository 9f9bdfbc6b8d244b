"""The vorticity of a run's fluid at chosen snapshots, one panel each (a look at a wake without ParaView).

Reads RUN/snapshots/fluid.pvd and the VTP files it lists (the solver writes them in ASCII, with the
point data `vorticity`), writes OUTPUT.png. TIMES are snapshot times; the nearest written snapshot is
drawn. The colour scale is +-LIMIT (default 5 U0 / D), the window the fluid's bounding box unless
--window X0 X1 Y0 Y1 is given.
Usage: /usr/bin/python3 scripts/plot_vorticity.py RUN OUTPUT.png TIME [TIME ...] [--limit L] [--window X0 X1 Y0 Y1]
Example (reports/pressure.md section 27):
  /usr/bin/python3 scripts/plot_vorticity.py runs/cfd3 reports/pressure/pressure_cfd3_vorticity.png 95 100 170 175
"""
import argparse
import os
import re
import sys

import numpy as np

from plot_common import plt


def snapshot_list(run):
    """(time, path) of each fluid snapshot listed in RUN/snapshots/fluid.pvd."""
    pvd = os.path.join(run, "snapshots", "fluid.pvd")
    if not os.path.exists(pvd):
        sys.exit(f"{pvd}: not found (run the scene with a snapshot_interval)")
    text = open(pvd).read()
    found = re.findall(r'timestep="([^"]+)"[^>]*file="([^"]+)"', text)
    if not found:
        sys.exit(f"{pvd}: lists no snapshot")
    return [(float(t), os.path.join(run, "snapshots", f)) for t, f in found]


def read_vtp(path):
    """The points (n x 3) and the point-data arrays of one ASCII VTP file, by name."""
    arrays = {}
    for match in re.finditer(r"<DataArray([^>]*)>(.*?)</DataArray>", open(path).read(), re.S):
        name = re.search(r'Name="(\w+)"', match.group(1))
        key = name.group(1) if name else "points"
        arrays.setdefault(key, np.array(match.group(2).split(), dtype=float))
    if "vorticity" not in arrays:
        sys.exit(f"{path}: has no point data 'vorticity'")
    return arrays["points"].reshape(-1, 3), arrays["vorticity"]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("run")
    parser.add_argument("output")
    parser.add_argument("times", type=float, nargs="+")
    parser.add_argument("--limit", type=float, default=5.0)
    parser.add_argument("--window", type=float, nargs=4)
    args = parser.parse_args()
    snapshots = snapshot_list(args.run)
    fig, axes = plt.subplots(len(args.times), 1, figsize=(11, 2.3 * len(args.times)), squeeze=False,
                             constrained_layout=True)
    for ax, wanted in zip(axes[:, 0], args.times):
        time, path = min(snapshots, key=lambda s: abs(s[0] - wanted))
        points, vorticity = read_vtp(path)
        shown = ax.scatter(points[:, 0], points[:, 1], c=vorticity, s=1.0, lw=0, cmap="RdBu_r",
                           vmin=-args.limit, vmax=args.limit)
        if args.window:
            ax.set_xlim(*args.window[:2])
            ax.set_ylim(*args.window[2:])
        ax.set_aspect("equal")
        ax.set_title(f"{args.run}: t = {time:g}", fontsize=8)
    fig.colorbar(shown, ax=axes[:, 0], shrink=0.6, label="vorticity")
    fig.savefig(args.output, dpi=110)
    print(f"figure: {os.path.basename(args.output)}")


if __name__ == "__main__":
    main()
