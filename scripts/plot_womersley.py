"""Figures of the Womersley suite: SPH profiles against the analytic ones, and the convergence."""
import os

from plot_common import load_summary, plt, read_csv, save, suite_dir

directory = suite_dir()
summary = load_summary(directory)
quick = summary["mode"] == "quick"
checked = 20 if quick else 40

numbers = [row["womersley_number"] for row in summary["convergence"]]
fig, axes = plt.subplots(1, len(numbers), figsize=(4.2 * len(numbers), 4.2), sharey=False)
for ax, wo in zip(axes, numbers):
    data = read_csv(os.path.join(directory, f"profiles_Wo{wo:g}_res{checked}.csv"))
    phases = sorted(set(data["phase"]))
    colours = plt.cm.viridis([k / max(1, len(phases) - 1) for k in range(len(phases))])
    for phase, colour in zip(phases, colours):
        if int(phase) % 2:
            continue  # every second phase keeps the panel readable
        idx = [k for k, p in enumerate(data["phase"]) if p == phase]
        y = [data["y"][k] for k in idx]
        ax.plot([data["u_analytic"][k] for k in idx], y, "-", color=colour, lw=1.2)
        ax.plot([data["u_sph"][k] for k in idx], y, "o", color=colour, ms=2.5)
    ax.set_title(f"Wo = {wo:g}, H/dp = {checked}")
    ax.set_xlabel("u / (A / rho omega)")
    ax.set_ylabel("y / H")
axes[0].plot([], [], "k-", label="analytic")
axes[0].plot([], [], "ko", ms=3, label="SPH (row means)")
axes[0].legend(loc="lower left", fontsize=8)
save(fig, directory, "womersley_profiles.png")

fig, ax = plt.subplots(figsize=(5, 4))
for row in summary["convergence"]:
    res = sorted(int(k.split("res")[1]) for k in row if k.startswith("l2_error_res"))
    err = [row[f"l2_error_res{r}"] for r in res]
    line, = ax.loglog(res, err, "o-", label=f"Wo = {row['womersley_number']:g} (order {row['observed_order']:.2f})")
    for run in summary["runs"]:  # full mode: the quadratic wall rule beside the default
        config = run.get("config", {})
        if config.get("viscous_wall_velocity") == "quadratic" and config.get("womersley_number") == row["womersley_number"]:
            ax.loglog([config["resolution"]], [run["metrics"]["l2_error"]], "s", mfc="none", color=line.get_color())
if any(run.get("config", {}).get("viscous_wall_velocity") == "quadratic" for run in summary["runs"]):
    ax.loglog([], [], "ks", mfc="none", label="quadratic wall rule")
r0 = min(res)
ax.loglog([r0, 4 * r0], [0.08, 0.08 / 16], "k--", lw=0.8, label="slope -2")
ax.set_xlabel("H / dp")
ax.set_ylabel("relative L2 error over a period")
ax.legend(fontsize=8)
ax.grid(True, which="both", alpha=0.3)
save(fig, directory, "womersley_convergence.png")
