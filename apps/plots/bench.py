#!/usr/bin/python3
"""Pareto plot of rc2000sim bench.csv: wall time and predicted hardware time against error."""
import csv

import entry  # apps/plots/entry.py, beside this script
from pareto import pareto  # apps/plots/pareto.py

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

MARKERS = {"base": "*", "bits": "o", "arith": "P", "convergence": "s", "patch_levels": "^", "form_factor": "D"}


def label(r):
    v = r["varied"]
    if v == "bits":
        return f'{r["bits"]} bits'
    if v == "convergence":
        return f'conv {r["convergence"]}'
    if v == "patch_levels":
        return f'{r["patches"]} patches'
    if v == "form_factor":
        return r["form_factor"]
    if v == "arith":
        return r["arith"]
    return "base"



def main(csv_path, png_path):
    rows = list(csv.DictReader(open(csv_path)))
    floor = 1e-7
    err = [max(float(r["relative_rmse"]), floor) for r in rows]
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5))
    for ax, key, title in ((axes[0], "wall_seconds", "simulator wall time"),
                           (axes[1], "hardware_seconds", "predicted hardware time")):
        t = [float(r[key]) for r in rows]
        for v, m in MARKERS.items():
            idx = [i for i, r in enumerate(rows) if r["varied"] == v]
            ax.scatter([err[i] for i in idx], [t[i] for i in idx], marker=m, s=60 if v == "base" else 30, label=v)
        front = pareto(list(zip(err, t)))
        ax.plot([err[i] for i in front], [t[i] for i in front], "k--", lw=0.8, label="Pareto front")
        for i, r in enumerate(rows):
            ax.annotate(label(r), (err[i], t[i]), fontsize=6, xytext=(3, 3), textcoords="offset points")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("patch radiosity RMSE / mean, against the reference")
        ax.set_ylabel("seconds")
        ax.set_title(title)
        ax.grid(True, which="both", lw=0.3)
    axes[0].legend(fontsize=7)
    fig.tight_layout()
    entry.save(fig, png_path, dpi=110)


if __name__ == "__main__":
    entry.run(main, "usage: bench.py bench.csv pareto.png")
