#!/usr/bin/python3
"""Roofline per device (rc2000sim design and paper --docs, roofline.csv): attainable ray-face tests per
second against bank bytes moved per test, under the lanes', SRAM, PCI and host roofs, with the paper's
rule and the model's simulated designs (host_sw/studies/roofline.h defines every row)."""
import csv

import entry  # apps/plots/entry.py, beside this script

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

STYLE = {"paper": ("s", "tab:red", "paper's rule"), "design": ("o", "tab:blue", "Pareto front (simulated)"),
         "best": ("*", "tab:green", "best design (simulated)"),
         "reference": ("D", "tab:gray", "paper's two-lane design (simulated)")}
ROOFS = {"roof_lanes": "tab:purple", "roof_pci": "tab:orange", "roof_host": "tab:brown"}


def draw(rows, png_path):
    devices = list(dict.fromkeys(r["device"] for r in rows))
    fig, axes = plt.subplots(1, len(devices), figsize=(5.2 * len(devices), 4.4), squeeze=False)
    xs = [0.5, 64.0]
    for ax, device in zip(axes[0], devices):
        mine = [r for r in rows if r["device"] == device]
        for r in mine:
            y = float(r["tests_per_second"])
            if r["kind"] in ROOFS:
                ax.plot(xs, [y, y], color=ROOFS[r["kind"]], lw=1.2, label=f'{r["label"]} ({y:.3g}/s)')
            elif r["kind"] == "roof_sram":
                ax.plot(xs, [y / x for x in xs], color="tab:cyan", lw=1.2, label=f'{r["label"]} ({y / 1e9:.3g} GB/s)')
        seen = set()
        for r in mine:
            if r["kind"] not in STYLE:
                continue
            marker, colour, name = STYLE[r["kind"]]
            ax.scatter([float(r["bytes_per_test"])], [float(r["tests_per_second"])], marker=marker, color=colour,
                       s=90 if r["kind"] == "best" else 30, zorder=3, label=None if r["kind"] in seen else name)
            seen.add(r["kind"])
        ax.set_xscale("log", base=2)
        ax.set_yscale("log")
        ax.set_xlim(*xs)
        ax.set_xlabel("bank bytes moved per test")
        ax.set_ylabel("attainable tests per second")
        ax.set_title(device)
        ax.grid(True, which="both", lw=0.3)
        ax.legend(fontsize=6, loc="upper right", framealpha=0.6)
    fig.tight_layout()
    entry.save(fig, png_path, dpi=110)


def main(csv_path, png_path):
    draw(list(csv.DictReader(open(csv_path))), png_path)


if __name__ == "__main__":
    entry.run(main, "usage: roofline.py roofline.csv roofline.png")
