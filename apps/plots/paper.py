#!/usr/bin/python3
"""Plots of rc2000sim paper.csv: Table 2 (model against paper) and the sec 5.6 estimates."""
import csv
import os

import entry  # apps/plots/entry.py, beside this script
import roofline

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.patches import Patch  # noqa: E402

IMPLEMENTATIONS = ["software", "one_pipe", "two_pipes", "concurrent"]
COLOURS = {"software": "tab:grey", "one_pipe": "tab:blue", "two_pipes": "tab:orange", "concurrent": "tab:green"}


def table2(rows, out):
    scenes = []
    for r in rows:
        key = f'{r["faces"]}/{r["patches"]}'
        if key not in scenes:
            scenes.append(key)
    fig, ax = plt.subplots(figsize=(9, 4.5))
    width = 0.2
    for k, impl in enumerate(IMPLEMENTATIONS):
        xs, model, paper_x, paper = [], [], [], []
        for i, key in enumerate(scenes):
            for r in rows:
                if f'{r["faces"]}/{r["patches"]}' == key and r["implementation"] == impl:
                    xs.append(i + (k - 1.5) * width)
                    model.append(float(r["seconds"]))
                    if r["paper_seconds"]:
                        paper_x.append(xs[-1])
                        paper.append(float(r["paper_seconds"]))
        bars = ax.bar(xs, model, width, color=COLOURS[impl], label=f"{impl} (model)")
        lows = [float(r["spread_min_seconds"]) for r in rows
                if r["implementation"] == impl and r["spread_min_seconds"]]
        if lows:
            highs = [float(r["spread_max_seconds"]) for r in rows
                     if r["implementation"] == impl and r["spread_max_seconds"]]
            ax.errorbar(xs, model, yerr=[[m - lo for m, lo in zip(model, lows)], [hi - m for m, hi in zip(model, highs)]],
                        fmt="none", ecolor="k", elinewidth=0.8, capsize=2)
        if paper:
            ax.plot(paper_x, paper, "k_", markersize=14, mew=2)
    ax.plot([], [], "k_", markersize=14, mew=2, label="paper (calibration columns)")
    ax.set_yscale("log")
    ax.set_xticks(range(len(scenes)))
    ax.set_xticklabels(scenes)
    ax.set_xlabel("faces / patches")
    ax.set_ylabel("seconds")
    ax.set_title("Table 2: model (bars) and the paper's measured columns (black)")
    ax.legend(fontsize=8)
    ax.grid(True, axis="y", which="both", lw=0.3)
    fig.tight_layout()
    entry.save(fig, os.path.join(out, "table2.png"), dpi=110)


def table2_intervals(rows, out):
    """The withheld columns with their prediction intervals (variants, mechanisms, calibration errors)."""
    withheld = [r for r in rows if r.get("interval_low_seconds")]
    if not withheld:
        return
    scenes = []
    for r in withheld:
        key = f'{r["faces"]}/{r["patches"]}'
        if key not in scenes:
            scenes.append(key)
    fig, ax = plt.subplots(figsize=(9, 4.5))
    for k, impl in enumerate(["two_pipes", "concurrent"]):
        cells = [r for r in withheld if r["implementation"] == impl]
        xs = [scenes.index(f'{r["faces"]}/{r["patches"]}') + (k - 0.5) * 0.3 for r in cells]
        model = [float(r["seconds"]) for r in cells]
        lows = [float(r["interval_low_seconds"]) for r in cells]
        highs = [float(r["interval_high_seconds"]) for r in cells]
        ax.errorbar(xs, model, yerr=[[m - lo for m, lo in zip(model, lows)], [hi - m for m, hi in zip(model, highs)]],
                    fmt="o", color=COLOURS[impl], ecolor=COLOURS[impl], elinewidth=2, capsize=4,
                    label=f"{impl}: prediction and interval")
    ax.set_yscale("log")
    ax.set_xticks(range(len(scenes)))
    ax.set_xticklabels(scenes)
    ax.set_xlabel("faces / patches")
    ax.set_ylabel("seconds")
    ax.set_title("Table 2's withheld columns: predictions with their intervals")
    ax.legend(fontsize=8)
    ax.grid(True, axis="y", which="both", lw=0.3)
    fig.tight_layout()
    entry.save(fig, os.path.join(out, "table2-intervals.png"), dpi=110)


def estimates(rows, out):
    labels = [f'{r["estimate"]}, {r["device"]}' + (f' ({r["lanes"]} lanes)' if r["lanes"] != "0" else "")
              + f' [{r["rule"]}]' for r in rows]
    rates = [float(r["intersections_per_s"]) for r in rows]
    speedups = [float(r["speedup_vs_software"]) for r in rows]
    colours = ["tab:grey" if r["rule"] == "paper" else "tab:blue" for r in rows]
    fig, ax = plt.subplots(figsize=(9, 4.8))
    ax.barh(range(len(rows)), rates, color=colours)
    for i, (rate, s) in enumerate(zip(rates, speedups)):
        ax.text(rate, i, f" {s:.1f}x", va="center", fontsize=8)
    handles = [Patch(color="tab:grey", label="the paper's rule (its printed figures)"),
               Patch(color="tab:blue", label="model (wrapper, slice lanes, result bank)")]
    ax.set_yticks(range(len(rows)))
    ax.set_yticklabels(labels, fontsize=7)
    ax.invert_yaxis()
    ax.set_xscale("log")
    ax.set_xlabel("intersections per second (label: speedup over software)")
    ax.set_title("Sec 5.6: intersection rates, the paper's rule and the model")
    ax.legend(handles=handles, fontsize=8, loc="lower right")
    fig.tight_layout()
    entry.save(fig, os.path.join(out, "estimates.png"), dpi=110)


def main(csv_path, out):
    rows = list(csv.DictReader(open(csv_path)))
    scenes = [r for r in rows if r["record"] == "scene"]
    first = [lambda: table2(scenes, out), lambda: table2_intervals(scenes, out),
             lambda: estimates([r for r in rows if r["record"] == "estimate"], out)]
    second = []
    # The rooflines per device (rc2000sim paper writes roofline.csv beside paper.csv; roofline.py).
    beside = os.path.join(os.path.dirname(csv_path), "roofline.csv")
    if os.path.exists(beside):
        lines = list(csv.DictReader(open(beside)))
        second.append(lambda: roofline.draw(lines, os.path.join(out, "roofline.png")))
    # At the end of `rc2000sim paper`, nothing else runs: the figures are drawn on both cores, in
    # two groups of about equal time (measured idle: table2 0.15 s, intervals 0.15 s, estimates
    # 0.09 s; the rooflines, one panel per device, 0.34 s).
    entry.side_by_side(first, second)


if __name__ == "__main__":
    entry.run(main, "usage: paper.py paper.csv OUTPUT_FOLDER")
