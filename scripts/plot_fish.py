"""Figures of the fish suite: per run, head and tail positions against time, the tail trajectory
and the centre line over the last window (the travelling wave); and the tail's vertical motion of
every run in one figure (the resolutions side by side); and the linear flutter theory's growth rate
against Young's modulus, where the suite computed it (full mode)."""
import os

from plot_common import load_summary, plt, read_csv, save, suite_dir


def run_directory(run):
    config = run["config"]
    return config.get("directory", f"E{config['youngs_modulus']:g}")


def title(run):
    config = run["config"]
    text = f"E = {config['youngs_modulus']:g}"
    if "dp_solid" in config:
        text += f", dp_S = {config['dp_solid']:g}, dp_F = {config['dp_fluid']:g}"
    return text


directory = suite_dir()
summary = load_summary(directory)
tails = []
for run in summary["runs"]:
    name = run_directory(run)
    d = os.path.join(directory, name)
    head = read_csv(os.path.join(d, "head.csv"))
    tail = read_csv(os.path.join(d, "tail.csv"))
    tails.append((title(run), tail))
    fig = plt.figure(figsize=(12, 8))
    for k, (series, part, col) in enumerate([(head, "head", "x"), (head, "head", "y"), (tail, "tail", "x"), (tail, "tail", "y")]):
        ax = fig.add_subplot(3, 2, k + 1)
        ax.plot(series["time"], series[col], lw=0.7)
        ax.set_ylabel(f"{part} {col}")
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
    fig.suptitle(title(run))
    fig.tight_layout()
    save(fig, directory, f"fish_{name}.png")

if len(tails) > 1:
    fig, axes = plt.subplots(len(tails), 1, figsize=(12, 2.4 * len(tails)), sharex=True)
    for ax, (label, tail) in zip(axes, tails):
        ax.plot(tail["time"], tail["y"], lw=0.6)
        ax.axhspan(4.0 - 0.58, 4.0 + 0.58, color="0.9", zorder=0, label="paper: tail amplitude 0.58 about y = 4")
        ax.set_ylabel("tail y")
        ax.set_title(label, fontsize=9)
    axes[0].legend(fontsize=8, loc="upper right")
    axes[-1].set_xlabel("t")
    fig.tight_layout()
    save(fig, directory, "fish_tail_runs.png")

sweeps = [(title(run), run["metrics"]["linear_theory"]) for run in summary["runs"]
          if "sweep" in run.get("metrics", {}).get("linear_theory", {})]
if sweeps:
    fig, (ax_g, ax_m) = plt.subplots(1, 2, figsize=(12, 4.2))
    label, theory = sweeps[0]  # the sweep depends on the run only through the drag (the tether)
    for support, style in (("tethered", "o-"), ("pinned", "s--")):
        pts = [(r["youngs_modulus"], r[support + "_growth_rate"]) for r in theory["sweep"]
               if r.get(support + "_growth_rate") is not None]
        ax_g.semilogx([p[0] for p in pts], [p[1] for p in pts], style, ms=4, label=f"{support} nose")
        critical = theory.get("critical_youngs_modulus_" + support)
        if critical:
            ax_g.axvline(critical, color="0.6", lw=0.6)
    ax_g.axhline(0.0, color="k", lw=0.6)
    ax_g.axvspan(200, 500, color="0.9", zorder=0, label="paper: E = 200 (code), 500 (text), flapping")
    ax_g.set_xlabel("Young's modulus E")
    ax_g.set_ylabel("growth rate of the least-damped mode")
    ax_g.set_title(f"linear theory, body of {label}; flutter where > 0", fontsize=9)
    ax_g.legend(fontsize=8)
    # Every run's modes at its own modulus: frequency against damping ratio.
    for run in summary["runs"]:
        modes = run.get("metrics", {}).get("linear_theory", {}).get("wetted_modes", [])
        if modes:
            ax_m.plot([m["frequency"] for m in modes], [m["damping_ratio"] for m in modes], "o", ms=5, label=title(run))
    ax_m.axvline(0.74, color="0.5", lw=0.8, ls=":", label="paper: flapping frequency 0.74")
    ax_m.axhline(0.0, color="k", lw=0.6)
    ax_m.set_xlabel("frequency of the mode in the stream")
    ax_m.set_ylabel("damping ratio (< 0: flutter)")
    ax_m.set_title("linear theory: the tethered body's modes at each run's E", fontsize=9)
    ax_m.legend(fontsize=8)
    fig.tight_layout()
    save(fig, directory, "fish_flutter_theory.png")
