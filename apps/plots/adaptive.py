#!/usr/bin/python3
"""rc2000sim adaptive.csv: error against simulated hardware time, uniform and adaptive patches.

Left: relative RMSE at the reference's patches; right: the rendered image's difference; both
against the hardware time of all a run's solves (filled markers) and of its last solve alone
(hollow). Each point is labelled with its patch count; the dashed line is the Pareto front of the
filled points (no other run is both faster and more accurate).
"""
import csv

import entry  # apps/plots/entry.py, beside this script
from pareto import pareto  # apps/plots/pareto.py

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

STYLE = {"uniform": ("o", "tab:blue"), "adaptive": ("s", "tab:orange")}



def main(csv_path, png_path):
    with open(csv_path) as f:
        rows = list(csv.DictReader(f))
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5))
    for ax, key, title in ((axes[0], "relative_rmse", "relative RMSE at the reference's patches"),
                           (axes[1], "image_difference", "image difference (relative RMSE)")):
        t = [float(r["simulated_seconds"]) for r in rows]
        e = [float(r[key]) for r in rows]
        for kind, (marker, colour) in STYLE.items():
            idx = [i for i, r in enumerate(rows) if r["kind"] == kind]
            ax.scatter([t[i] for i in idx], [e[i] for i in idx], marker=marker, color=colour, s=40,
                       label=f"{kind}, all solves")
            ax.scatter([float(rows[i]["final_simulated_seconds"]) for i in idx], [e[i] for i in idx], marker=marker,
                       facecolors="none", edgecolors=colour, s=40, label=f"{kind}, last solve")
            for i in idx:
                ax.annotate(rows[i]["patches"], (t[i], e[i]), textcoords="offset points", xytext=(5, 4), fontsize=7)
        front = pareto(list(zip(t, e)))
        ax.plot([t[i] for i in front], [e[i] for i in front], "k--", lw=0.8, label="Pareto front")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("simulated hardware seconds")
        ax.set_title(title, fontsize=10)
        ax.grid(True, which="both", lw=0.3)
    axes[0].set_ylabel("error")
    axes[0].legend(fontsize=7)
    fig.suptitle("Adaptive against uniform patches at equal patch count (labels: patches)", fontsize=10)
    fig.tight_layout()
    entry.save(fig, png_path, dpi=110)
    plt.close(fig)


if __name__ == "__main__":
    entry.run(main, "usage: adaptive.py adaptive.csv OUTPUT.png")
