"""Figure of the convergence suite: each ladder's metrics against resolution, with the Richardson
value and the grid convergence index."""
import sys

from plot_common import load_summary, plt, save, suite_dir

directory = suite_dir()
summary = load_summary(directory)
panels = [(ladder, metric, data) for ladder, metrics in summary["convergence"].items() for metric, data in metrics.items()
          if metric in ("period", "peak_x_mm", "rms_error_x_mm", "amplitude_y", "strouhal")]
if not panels:  # e.g. --merge before any ladder's runs are done
    sys.exit("no ladder has values to draw (no run of a ladder completed): no figure")
fig, axes = plt.subplots(1, len(panels), figsize=(4 * len(panels), 3.6), squeeze=False)
for ax, (ladder, metric, data) in zip(axes[0], panels):
    ax.plot(data["resolutions"], data["values"], "o-")
    if "extrapolated" in data:
        ax.axhline(data["extrapolated"], ls="--", color="gray",
                   label=f"Richardson {data['extrapolated']:.4g}, p = {data['observed_order']:.2f}, GCI {100 * data['gci']:.2f} %")
        ax.legend(fontsize=7)
    ax.set_xscale("log", base=2)
    ax.set_xlabel("thickness / dp_S")
    ax.set_title(f"{ladder}: {metric}", fontsize=9)
    if ladder == "FSI2" and "paper_table_3" in summary:
        ax.plot(summary["paper_table_3"]["resolution"], summary["paper_table_3"][metric], "ks--", ms=4, label="paper Table 3")
        ax.legend(fontsize=7)
save(fig, directory, "convergence.png")
