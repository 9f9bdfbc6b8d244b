"""Figures of the turek-hron suite: tip x(t), y(t) and the x-y trajectory of case III (with the
paper's code's curve when available), and the cases side by side."""
import os

from plot_common import load_summary, plt, read_csv, save, suite_dir

directory = suite_dir()
summary = load_summary(directory)
cases = [run["case"] for run in summary["runs"]]
main = "III" if "III" in cases else cases[0]
tip = read_csv(os.path.join(directory, f"case_{main}", "tip.csv"))
peer_path = os.path.join(directory, "peer_sphinxsys_tip.csv")
peer = read_csv(peer_path) if os.path.exists(peer_path) else None

fig, (ax_x, ax_y) = plt.subplots(2, 1, figsize=(10, 6), sharex=True)
ax_x.plot(tip["time"], tip["dx"], lw=0.8, label=f"mrsph case {main}")
ax_y.plot(tip["time"], tip["dy"], lw=0.8, label=f"mrsph case {main}")
if peer:
    ax_x.plot(peer["time"], peer["dx"], lw=0.6, alpha=0.7, label="paper's code (SPHinXsys, run here)")
    ax_y.plot(peer["time"], peer["dy"], lw=0.6, alpha=0.7, label="paper's code (SPHinXsys, run here)")
ax_x.set_ylabel("tip x displacement / D")
ax_y.set_ylabel("tip y displacement / D")
ax_y.set_xlabel("t U0 / D")
ax_x.legend(fontsize=8)
save(fig, directory, "turek_hron_tip_xy_time.png")

fig, ax = plt.subplots(figsize=(5, 5))
t0 = max(tip["time"]) / 2
sel = [k for k, t in enumerate(tip["time"]) if t >= t0]
ax.plot([tip["dx"][k] for k in sel], [tip["dy"][k] for k in sel], lw=0.6, label=f"mrsph case {main}")
if peer:
    psel = [k for k, t in enumerate(peer["time"]) if t >= t0]
    ax.plot([peer["dx"][k] for k in psel], [peer["dy"][k] for k in psel], lw=0.5, alpha=0.6, label="paper's code (run here)")
ax.set_xlabel("tip x displacement / D")
ax.set_ylabel("tip y displacement / D")
ax.set_title(f"Trajectory of S, t >= {t0:g}")
ax.legend(fontsize=8)
save(fig, directory, "turek_hron_trajectory.png")

if len(cases) > 1:
    fig, ax = plt.subplots(figsize=(10, 4))
    for run in summary["runs"]:
        d = read_csv(os.path.join(directory, f"case_{run['case']}", "tip.csv"))
        sel = [k for k, t in enumerate(d["time"]) if t >= max(d["time"]) - 30]
        ax.plot([d["time"][k] for k in sel], [d["dy"][k] for k in sel], lw=0.8,
                label=f"{run['case']}: A={run['metrics'].get('amplitude_y', float('nan')):.3f}, St={run['metrics'].get('strouhal', float('nan')):.3f}")
    ax.set_xlabel("t")
    ax.set_ylabel("tip y / D")
    ax.legend(fontsize=7, ncol=3)
    save(fig, directory, "turek_hron_cases.png")
