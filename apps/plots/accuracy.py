#!/usr/bin/python3
"""Plot rc2000sim accuracy.csv.

Left: radiosity error and differing visibility decisions against the fixed-point width. Right: the
same errors for every fixed-point width and floating-point format against the bytes one intersection
moves (sec 5.6(a)'s count), the paper's sec 6 question: does a float format's narrower word buy
accuracy per byte?
"""
import csv

import entry  # apps/plots/entry.py, beside this script

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

FLOOR = 1e-9  # log axes: an exact match is drawn at the floor


def value(r, key):
    return max(float(r[key]), FLOOR)


def differ(r):
    return max(int(r["decisions_differ"]) / max(int(r["segments"]), 1), FLOOR)


def main(csv_path, png_path):
    with open(csv_path) as f:
        rows = list(csv.DictReader(f))
    fixed = [r for r in rows if r["arithmetic"].startswith("fixed:")]
    floats = [r for r in rows if r["arithmetic"].startswith("float:")]
    fig, (left, right) = plt.subplots(1, 2, figsize=(12, 4.4))

    bits = [int(r["bits"]) for r in fixed]
    left.semilogy(bits, [value(r, "relative_rmse") for r in fixed], "o-", label="patch radiosity RMSE / mean")
    left.semilogy(bits, [value(r, "relative_max_error") for r in fixed], "s-", label="max patch error / mean")
    left.semilogy(bits, [differ(r) for r in fixed], "^-", label="visibility decisions that differ")
    left.axhline(FLOOR, color="grey", lw=0.5)
    left.set_xlabel("fractional bits of the fixed-point pipeline")
    left.set_ylabel("relative to double-precision visibility")
    left.set_xticks(bits)
    left.set_title("Fixed-point width (points at 1e-9: identical)", fontsize=10)
    left.grid(True, which="both", lw=0.3)
    left.legend(fontsize=8)

    for group, marker, name in ((fixed, "o", "fixed point"), (floats, "D", "floating point")):
        x = [float(r["bytes_per_intersection"]) for r in group]
        rmse = [value(r, "relative_rmse") for r in group]
        (points,) = right.semilogy(x, rmse, marker, ls="", label=f"{name}: RMSE / mean")
        # The best a kind does at each bandwidth: the lower envelope, as a step line.
        best = {}
        for xi, e in zip(x, rmse):
            best[xi] = min(best.get(xi, e), e)
        xs = sorted(best)
        right.semilogy(xs, [best[v] for v in xs], "-", color=points.get_color(), lw=0.8, alpha=0.6)
        right.semilogy(x, [differ(r) for r in group], marker, ls="", mfc="none", color=points.get_color(),
                       label=f"{name}: decisions that differ")
        for r, xi, e in zip(group, x, rmse):
            right.annotate(r["arithmetic"].split(":")[1], (xi, e), textcoords="offset points", xytext=(5, -3),
                           fontsize=7)
    right.axhline(FLOOR, color="grey", lw=0.5)
    right.set_xlabel("bytes per intersection (three coordinates read, one result bit written)")
    right.set_title("Error against bandwidth: fixed widths and float formats (E,M)", fontsize=10)
    right.grid(True, which="both", lw=0.3)
    right.legend(fontsize=8)
    fig.tight_layout()
    entry.save(fig, png_path, dpi=120)


if __name__ == "__main__":
    entry.run(main, "usage: accuracy.py accuracy.csv accuracy.png")
