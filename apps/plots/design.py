#!/usr/bin/python3
"""rc2000sim design's pictures: design.csv (every simulated design: time against energy, banks as colour,
the Pareto front and the best marked) and roofline.csv (roofline.py)."""
import csv

import entry  # apps/plots/entry.py, beside this script
import roofline

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def front_plot(rows, png_path):
    fig, ax = plt.subplots(figsize=(7, 4.8))
    t = [float(r["simulated_seconds"]) for r in rows]
    e = [float(r["energy_joules"]) if r["energy_joules"] else float("nan") for r in rows]
    banks = [int(r["banks"]) for r in rows]
    sc = ax.scatter(t, e, c=banks, cmap="viridis", s=14, alpha=0.7)
    fig.colorbar(sc, ax=ax, label="banks")
    front = sorted((i for i, r in enumerate(rows) if r["on_front"] == "1"), key=lambda i: t[i])
    ax.scatter([t[i] for i in front], [e[i] for i in front], facecolors="none", edgecolors="k", s=40,
               label="Pareto front (time, energy, banks)")
    for i, r in enumerate(rows):
        if r["best"] == "1":
            ax.scatter([t[i]], [e[i]], marker="*", color="tab:red", s=160, label="best", zorder=3)
            ax.annotate(f'{r["lanes"]} lanes, {r["banks"]} banks, results {r["results"]}, bound {r["bound"]}'
                        + (f', stream {r["fpga_stream_limit"]}' if r["fpga_stream_limit"] else ''),
                        (t[i], e[i]), fontsize=7, xytext=(5, 5), textcoords="offset points")
    ax.set_xlabel("simulated seconds")
    ax.set_ylabel("energy, joules")
    ax.set_title(f'{rows[0]["device"]}: every simulated design' if rows else "no design")
    ax.grid(True, lw=0.3)
    ax.legend(fontsize=7)
    fig.tight_layout()
    entry.save(fig, png_path, dpi=110)


def main(csv_path, png_path):
    rows = list(csv.DictReader(open(csv_path)))
    if rows and "kind" in rows[0]:
        roofline.draw(rows, png_path)
    else:
        front_plot(rows, png_path)


if __name__ == "__main__":
    entry.run(main, "usage: design.py design.csv|roofline.csv OUTPUT.png")
