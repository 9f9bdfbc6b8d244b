"""Figure of the stability suite: one panel per family, every run a cell coloured by outcome."""
from plot_common import load_summary, plt, save, suite_dir

directory = suite_dir()
summary = load_summary(directory)
rows = summary.get("map", [])
colours = {"completed": "#4caf50", "diverged": "#e53935", "timed out": "#ffb300", "error": "#757575"}
families = []
for row in rows:
    if row["config"]["family"] not in families:
        families.append(row["config"]["family"])
fig, axes = plt.subplots(len(families), 1, figsize=(11, 1.2 + 0.32 * len(rows)), squeeze=False)
for ax, family in zip(axes[:, 0], families):
    members = [r for r in rows if r["config"]["family"] == family]
    for y, r in enumerate(members):
        ax.barh(y, 1, color=colours.get(r["status"], "gray"))
        text = r["status"]
        if r["status"] == "diverged" and isinstance(r.get("divergence"), dict):
            text += f" at t = {r['divergence'].get('time', float('nan')):.3g} ({r['divergence'].get('body', '')})"
        ax.text(0.02, y, f"{r['label'].split(': ', 1)[1]}  -  {text}", va="center", fontsize=7)
    ax.set_yticks([])
    ax.set_xticks([])
    ax.set_xlim(0, 1)
    ax.set_title(family, fontsize=9, loc="left")
save(fig, directory, "stability_map.png")
