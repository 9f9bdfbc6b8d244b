"""Shared helpers for the figure scripts: read a suite's summary and CSVs, save figures.

Run with Debian's /usr/bin/python3 (python3-matplotlib). Each script takes the suite directory,
writes PNG files into it and prints one line 'figure: NAME.png' per figure for the harness.
"""
import csv
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def suite_dir():
    if len(sys.argv) != 2:
        sys.exit(f"usage: {sys.argv[0]} SUITE_DIRECTORY")
    return sys.argv[1]


def load_summary(directory):
    with open(os.path.join(directory, "summary.json")) as f:
        return json.load(f)


def project_reference(name):
    """A reference file the project typed in from a paper (reference-data/NAME), parsed as JSON."""
    project = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    with open(os.path.join(project, "reference-data", name)) as f:
        return json.load(f)


def read_csv(path):
    """Columns of a CSV with a header line, as lists of floats keyed by column name."""
    with open(path) as f:
        rows = list(csv.reader(f))
    header, data = rows[0], rows[1:]
    return {name: [float(r[k]) for r in data] for k, name in enumerate(header)}


def read_diagnosis_rows(directory, name):
    """The rows of DIRECTORY/diagnosis/NAME (a CSV with a header line), as dicts of strings."""
    with open(os.path.join(directory, "diagnosis", name)) as f:
        return list(csv.DictReader(f))


def save(fig, directory, name):
    path = os.path.join(directory, name)
    tmp = path + ".tmp.png"
    fig.savefig(tmp, dpi=130, bbox_inches="tight")
    os.replace(tmp, path)  # atomic: never a half-written figure
    plt.close(fig)
    print(f"figure: {name}")


def log_x_axis(ax, ticks, labels, base=10):
    """A logarithmic x axis with exactly these ticks and labels."""
    ax.set_xscale("log", base=base)
    ax.minorticks_off()
    ax.set_xticks(ticks)
    ax.set_xticklabels(labels)
