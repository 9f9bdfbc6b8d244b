"""Figures of the fish suite: head and tail positions against time, the tail trajectory, and the
centre line over the last window (the travelling wave)."""
import os

from plot_common import load_summary, plt, read_csv, save, suite_dir

directory = suite_dir()
summary = load_summary(directory)
for run in summary["runs"]:
    E = run["config"]["youngs_modulus"]
    d = os.path.join(directory, f"E{E:g}")
    head = read_csv(os.path.join(d, "head.csv"))
    tail = read_csv(os.path.join(d, "tail.csv"))
    fig = plt.figure(figsize=(12, 8))
    for k, (series, name, col) in enumerate([(head, "head", "x"), (head, "head", "y"), (tail, "tail", "x"), (tail, "tail", "y")]):
        ax = fig.add_subplot(3, 2, k + 1)
        ax.plot(series["time"], series[col], lw=0.7)
        ax.set_ylabel(f"{name} {col}")
        ax.set_xlabel("t")
    ax = fig.add_subplot(3, 2, 5)
    t0 = 20.0
    sel = [k for k, t in enumerate(tail["time"]) if t >= t0]
    ax.plot([tail["x"][k] for k in sel], [tail["y"][k] for k in sel], lw=0.5)
    ax.set_xlabel("tail x")
    ax.set_ylabel("tail y")
    ax.set_title("tail trajectory, t >= 20", fontsize=9)
    ax = fig.add_subplot(3, 2, 6)
    centre = read_csv(os.path.join(d, "centre_line.csv"))
    times = sorted(set(centre["time"]))
    for t in times[:: max(1, len(times) // 12)]:
        idx = [k for k, tt in enumerate(centre["time"]) if tt == t]
        pts = sorted((centre["x"][k], centre["y"][k]) for k in idx)
        ax.plot([p[0] for p in pts], [p[1] for p in pts], lw=0.8)
    ax.set_aspect("equal")
    ax.set_title("centre line over the last 5 time units", fontsize=9)
    fig.suptitle(f"E = {E:g}")
    fig.tight_layout()
    save(fig, directory, f"fish_E{E:g}.png")
