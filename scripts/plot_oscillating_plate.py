"""Figures of the oscillating-plate suite: tip deflection with the theoretical period marked,
energy conservation, and the period against resolution."""
import os

from plot_common import load_summary, plt, read_csv, save, suite_dir

directory = suite_dir()
summary = load_summary(directory)


def stem(run):
    c = run["config"]
    mat = "nh" if c["material"] == "neo_hookean" else "svk"
    b0 = "_b0" if c.get("gradient_correction") == "first_order" else ""
    return f"plate_{mat}_res{c['resolution']}_vf{c['Vf']:g}_nu{c['poisson_ratio']:g}{b0}"


linear = [r for r in summary["runs"] if r["config"]["Vf"] == 0.01 and abs(r["config"]["poisson_ratio"] - 0.3975) < 1e-9
          and r["config"].get("gradient_correction") != "first_order"]
fig, ax = plt.subplots(figsize=(8, 4))
for run in linear:
    tip = read_csv(os.path.join(directory, stem(run), "tip.csv"))
    style = "-" if run["config"]["material"] == "saint_venant_kirchhoff" else "--"
    ax.plot(tip["time"], tip["dy"], style, lw=1, label=run["case"])
period = linear[0]["metrics"]["period_theory"]
t_end = max(read_csv(os.path.join(directory, stem(linear[0]), "tip.csv"))["time"])
k = 1
while k * period <= t_end:
    ax.axvline(k * period, color="k", lw=0.6, ls=":")
    k += 1
ax.set_xlabel("t [s]")
ax.set_ylabel("tip deflection [m]")
ax.set_title(f"Tip deflection, Vf = 0.01 (dotted: Euler-Bernoulli period {period:.4f} s)")
ax.legend(fontsize=7, ncol=2)
save(fig, directory, "plate_tip_deflection.png")

fig, ax = plt.subplots(figsize=(8, 4))
for run in summary["runs"]:
    e = read_csv(os.path.join(directory, stem(run) + "_energy.csv"))
    e0 = e["total"][0]
    ax.plot(e["time"], [(x - e0) / e0 for x in e["total"]], lw=1, label=run["case"])
ax.set_xlabel("t [s]")
ax.set_ylabel("(E - E0) / E0, E = kinetic + strain")
ax.set_title("Energy without damping")
ax.legend(fontsize=7, ncol=2)
save(fig, directory, "plate_energy.png")

fig, ax = plt.subplots(figsize=(5, 4))
for row in summary["convergence"]:
    res = sorted(int(key.split("res")[1]) for key in row if key.startswith("period_res"))
    ax.plot(res, [row[f"period_res{r}"] for r in res], "o-", label=row["material"])
    if "extrapolated" in row:
        ax.axhline(row["extrapolated"], ls="--", lw=0.8, color="C0",
                   label=f"Richardson ({ {'saint_venant_kirchhoff': 'SVK', 'neo_hookean': 'NH'}.get(row['material'], row['material'])}): {row['extrapolated']:.4f} s, order {row['observed_order']:.2f}")
b0 = [r for r in summary["runs"] if r["config"].get("gradient_correction") == "first_order"]
if b0:
    ax.plot([r["config"]["resolution"] for r in b0], [r["metrics"]["period"] for r in b0], "s--", color="gray",
            label="SVK, paper's B0 weights")
ax.axhline(summary["convergence"][0]["period_theory"], color="k", lw=1, label="Euler-Bernoulli")
ax.set_xscale("log", base=2)
ax.set_xlabel("H / dp")
ax.set_ylabel("period [s]")
ax.legend(fontsize=7)
save(fig, directory, "plate_period_convergence.png")
