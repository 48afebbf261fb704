#!/usr/bin/python3
"""Plot rc2000sim accuracy.csv: radiosity error and differing visibility decisions per width."""
import csv

import entry  # apps/plots/entry.py, beside this script

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(csv_path, png_path):
    rows = list(csv.DictReader(open(csv_path)))
    bits = [int(r["bits"]) for r in rows]
    floor = 1e-9  # log axes: an exact match is drawn at the floor
    rmse = [max(float(r["relative_rmse"]), floor) for r in rows]
    worst = [max(float(r["relative_max_error"]), floor) for r in rows]
    differ = [max(int(r["decisions_differ"]) / max(int(r["segments"]), 1), floor) for r in rows]

    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    ax.semilogy(bits, rmse, "o-", label="patch radiosity RMSE / mean")
    ax.semilogy(bits, worst, "s-", label="max patch error / mean")
    ax.semilogy(bits, differ, "^-", label="visibility decisions that differ")
    ax.axhline(floor, color="grey", lw=0.5)
    ax.set_xlabel("fractional bits of the fixed-point pipeline")
    ax.set_ylabel("relative to float (double) visibility")
    ax.set_xticks(bits)
    ax.set_title("Fixed-point width against float (points at 1e-9: identical)")
    ax.grid(True, which="both", lw=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(png_path, dpi=120)


if __name__ == "__main__":
    entry.run(main, "usage: accuracy.py accuracy.csv accuracy.png")
