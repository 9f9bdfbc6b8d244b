"""Figure of reports/pressure.md section 28: Schaefer & Turek's 2D-1 drag against the kernel's width
h / dp and against the outlet's pressure datum, and 2D-2's lift amplitude against D/dp and h / dp.

Reads DIRECTORY/diagnosis/schaefer_turek_cylinder.csv (benchmark, D_over_dp, h_over_dp, c_over_U0,
variant, cD_mean, cL_amplitude, ...), writes DIRECTORY/pressure_schaefer_turek.png.
Usage: /usr/bin/python3 scripts/plot_schaefer_turek.py reports/pressure
"""
import csv
import os
import re

from plot_common import plt, project_reference, save, suite_dir

# The benchmark's values as the project typed them in (reference-data/schaefer_turek_cylinder.json).
_benchmark = project_reference("schaefer_turek_cylinder.json")
DRAG_2D1 = _benchmark["2D-1"]["drag_coefficient"]  # John & Matthies (2001)
LIFT_MAX_2D2 = tuple(_benchmark["2D-2"]["lift_coefficient_max_bounds"])  # Schaefer & Turek (1996)

directory = suite_dir()
with open(os.path.join(directory, "diagnosis", "schaefer_turek_cylinder.csv")) as f:
    rows = list(csv.DictReader(f))


def pick(benchmark, c, variant=None, **fixed):
    out = []
    for r in rows:
        if r["benchmark"] != benchmark or r["c_over_U0"] != c:
            continue
        if variant is not None and not re.fullmatch(variant, r["variant"]):
            continue
        if all(r[k] == v for k, v in fixed.items()):
            out.append(r)
    return out


def drag_panel(ax, xlabel, title):
    ax.axhline(DRAG_2D1, color="k", lw=0.8, ls="--", label="Schaefer & Turek")
    ax.set_xlabel(xlabel)
    ax.set_ylabel("2D-1 drag coefficient c_D")
    ax.set_title(title)
    ax.legend(fontsize=7)


fig, axes = plt.subplots(1, 3, figsize=(13, 3.8), constrained_layout=True)
ax = axes[0]
for res in ["10", "20"]:
    pts = sorted((float(r["h_over_dp"]), float(r["cD_mean"])) for r in pick("2D-1", "10", "", D_over_dp=res))
    ax.plot([p[0] for p in pts], [p[1] for p in pts], "o-", label=f"D/dp = {res}")
pts = [(float(r["h_over_dp"]), float(r["cD_mean"])) for r in pick("2D-1", "10", "", D_over_dp="40")]
ax.plot([p[0] for p in pts], [p[1] for p in pts], "s", label="D/dp = 40")
drag_panel(ax, "h / dp", "2D-1 (Re = 20), c = 10 U0")

ax = axes[1]
for h in ["1.3", "1.6"]:
    pts = []
    for r in pick("2D-1", "40", r"(outlet pressure -?\d+)?", D_over_dp="10", h_over_dp=h):
        m = re.search(r"outlet pressure (-?\d+)", r["variant"])
        pts.append((float(m.group(1)) if m else 0.0, float(r["cD_mean"])))
    pts.sort()
    ax.plot([p[0] for p in pts], [p[1] for p in pts], "o-", label=f"h = {h} dp")
drag_panel(ax, "outlet pressure / (rho U0^2)", "2D-1, D/dp = 10, c = 40 U0: the datum")

ax = axes[2]
pts = sorted((float(r["D_over_dp"]), float(r["cL_amplitude"])) for r in pick("2D-2", "10", "", h_over_dp="1.3"))
ax.plot([p[0] for p in pts], [p[1] for p in pts], "o-", label="h = 1.3 dp, c = 10 U0")
for r in pick("2D-2", "10", "", D_over_dp="20"):
    if r["h_over_dp"] != "1.3":
        ax.plot(float(r["D_over_dp"]), float(r["cL_amplitude"]), "s", label=f"h = {r['h_over_dp']} dp")
for r in pick("2D-2", "40", ""):
    ax.plot(float(r["D_over_dp"]), float(r["cL_amplitude"]), "^", label="c = 40 U0")
ax.axhspan(*LIFT_MAX_2D2, color="k", alpha=0.15, label="Schaefer & Turek c_L,max")
ax.set_xlabel("D / dp")
ax.set_ylabel("2D-2 lift amplitude (c_L)")
ax.set_title("2D-2 (Re = 100)")
ax.legend(fontsize=7)
save(fig, directory, "pressure_schaefer_turek.png")
