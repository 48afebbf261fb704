#!/usr/bin/python3
"""Plots of rc2000sim sweep.csv, written into OUTPUT_FOLDER:

lanes_b<bits>_<driver>.png        simulated time (solid) and FPGA busy time (dashed) against lanes,
                                  one panel per device, one colour per bank count, the bottleneck
                                  of each simulated point as its marker
heatmap_<device>_b<bits>_<driver>.png
                                  simulated time over lanes x banks, bottleneck letter in each cell,
                                  configurations that cannot exist in grey
energy_b<bits>_<driver>.png       energy per lighting step (top) and energy-delay product (bottom)
                                  against lanes, one panel per device, one colour per bank count
pareto_b<bits>.png                simulated time against energy of every simulated configuration,
                                  one colour per device, marker per driver, the Pareto front (no other configuration
                                  is both faster and cheaper: the CSV's pareto_time_energy) joined
                                  and ringed
axis_<path>.png                   for each swept profile field (and host), the fastest configuration
                                  (over lanes and banks) against the field's value, one line per
                                  device, width, driver and the other fields' values; marker: its
                                  bottleneck; with energy, beside it the least energy per step

Rows without energy (a profile without an energy table: the CSV's energy_missing says which) are
left out of the energy plots; when no row has energy the energy plots are not drawn and a line on
stderr says why.

A study's extra axes (docs/studies.md) are the columns between "concurrent" and "status"; each
combination of their values gets its own lanes and heat-map files, named with the values.
"""
import csv
import math
import os
import re
import sys

import entry  # apps/plots/entry.py, beside this script

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402

# bottleneck -> (letter in heat maps, marker in line plots, description)
BOTTLENECKS = {
    "fpga_lanes": ("L", "o", "FPGA: lanes at full rate"),
    "fpga_result_bank": ("R", "s", "FPGA: result bank (read-modify-write)"),
    "fpga_ray_bank": ("B", "D", "FPGA: ray bank bandwidth"),
    "fpga_other": ("F", "P", "FPGA: other"),
    "host_compute": ("H", "^", "host compute"),
    "host_driver": ("D", "v", "host driver CPU"),
    "pci": ("P", "X", "PCI transfers"),
}


# Extra columns that are design choices (the Pareto front chooses among them), not settings.
DESIGN_COLUMNS = ("host", "cards", "card_split", "card_bus")


def driver(row):
    return "concurrent" if row["concurrent"] == "1" else "serial"


def slug(name):
    base = os.path.basename(name)
    if base.endswith(".json"):
        base = base[:-5]
    return re.sub(r"[^A-Za-z0-9_.-]", "_", base)


def ordered(values):
    """The distinct values in first-seen order (a dict: linear in the rows, whatever the count)."""
    return list(dict.fromkeys(values))


def software_seconds(rows):
    """The software-only time of the width, recovered from any simulated row's speedup."""
    for r in rows:
        if r["status"] == "ok" and r["speedup_vs_software"]:
            return float(r["simulated_seconds"]) * float(r["speedup_vs_software"])
    return None


def lanes_plot(rows, bits, drv, out):
    devices = ordered(r["device"] for r in rows)
    banks = sorted({int(r["banks"]) for r in rows if r["status"] == "ok"})
    colours = plt.cm.viridis([i / max(len(banks) - 1, 1) for i in range(len(banks))])
    legend_inches = 3.2  # room on the right for the legend, whatever the number of panels
    width = 4.6 * len(devices) + legend_inches
    fig, axes = plt.subplots(1, len(devices), figsize=(width, 4.2), sharey=True, squeeze=False)
    used = set()
    for ax, device in zip(axes[0], devices):
        for colour, b in zip(colours, banks):
            pts = sorted((int(r["lanes"]), r) for r in rows
                         if r["device"] == device and int(r["banks"]) == b and r["status"] == "ok")
            if not pts:
                continue
            lanes = [p[0] for p in pts]
            ax.plot(lanes, [float(p[1]["simulated_seconds"]) for p in pts], "-", color=colour, lw=1.2)
            ax.plot(lanes, [float(p[1]["fpga_busy_seconds"]) for p in pts], "--", color=colour, lw=0.9)
            for lane, r in pts:
                kind = r["bottleneck"]
                used.add(kind)
                ax.plot(lane, float(r["simulated_seconds"]), BOTTLENECKS.get(kind, ("?", "*", kind))[1],
                        color=colour, ms=5, mec="k", mew=0.4)
        software = software_seconds(r for r in rows if r["device"] == device)
        if software:
            ax.axhline(software, color="grey", ls=":", lw=1)
        ax.set_title(device, fontsize=10)
        ax.set_xlabel("lanes")
        ax.set_ylim(bottom=0)
        ax.grid(True, lw=0.3)
    axes[0][0].set_ylabel("seconds")
    handles = [Line2D([], [], color=c, lw=1.5, label=f"{b} banks") for c, b in zip(colours, banks)]
    handles += [Line2D([], [], color="k", ls="-", label="simulated"),
                Line2D([], [], color="k", ls="--", label="FPGA busy"),
                Line2D([], [], color="grey", ls=":", label="software alone")]
    handles += [Line2D([], [], ls="", marker=BOTTLENECKS[k][1], color="w", mec="k", label=BOTTLENECKS[k][2])
                for k in BOTTLENECKS if k in used]
    fig.legend(handles=handles, loc="center right", fontsize=8)
    fig.suptitle(f"Simulated and FPGA busy time against lanes ({bits}-bit, {drv} driver); marker: bottleneck",
                 fontsize=10)
    fig.tight_layout(rect=(0, 0, 1 - legend_inches / width, 0.95))
    entry.save(fig, os.path.join(out, f"lanes_b{bits}_{drv}.png"), dpi=110)
    plt.close(fig)


def has_energy(row):
    return row["status"] == "ok" and row.get("energy_joules", "") != ""


def bank_colours(rows):
    banks = sorted({int(r["banks"]) for r in rows})
    return banks, plt.cm.viridis([i / max(len(banks) - 1, 1) for i in range(len(banks))])


def energy_plot(rows, bits, drv, out):
    """Energy per step and energy-delay product against lanes: one column of panels per device."""
    rows = [r for r in rows if has_energy(r)]
    devices = ordered(r["device"] for r in rows)
    banks, colours = bank_colours(rows)
    legend_inches = 1.3
    width = 4.2 * len(devices) + legend_inches
    fig, axes = plt.subplots(2, len(devices), figsize=(width, 7.0), sharex="col", squeeze=False)
    quantities = [("energy_per_step_joules", "joules per lighting step"),
                  ("energy_delay_product_joule_seconds", "energy-delay product (J s)")]
    for column, device in enumerate(devices):
        for row_index, (key, label) in enumerate(quantities):
            ax = axes[row_index][column]
            for colour, b in zip(colours, banks):
                pts = sorted((int(r["lanes"]), float(r[key])) for r in rows
                             if r["device"] == device and int(r["banks"]) == b and r[key] != "")
                if pts:
                    ax.plot([p[0] for p in pts], [p[1] for p in pts], "-o", color=colour, lw=1.2, ms=3.5)
            ax.set_ylim(bottom=0)
            ax.grid(True, lw=0.3)
            if column == 0:
                ax.set_ylabel(label)
            if row_index == 0:
                ax.set_title(device, fontsize=10)
            else:
                ax.set_xlabel("lanes")
    handles = [Line2D([], [], color=c, lw=1.5, marker="o", ms=3.5, label=f"{b} banks") for c, b in zip(colours, banks)]
    fig.legend(handles=handles, loc="center right", fontsize=8)
    fig.suptitle(f"Energy per step and energy-delay product against lanes ({bits}-bit, {drv} driver)", fontsize=10)
    fig.tight_layout(rect=(0, 0, 1 - legend_inches / width, 0.96))
    entry.save(fig, os.path.join(out, f"energy_b{bits}_{drv}.png"), dpi=110)
    plt.close(fig)


def pareto_plot(rows, bits, name, out):
    """Simulated time against energy; the front of configurations nothing beats in both."""
    rows = [r for r in rows if has_energy(r)]
    devices = ordered(r["device"] for r in rows)
    fig, ax = plt.subplots(figsize=(8.0, 5.2))
    for i, device in enumerate(devices):
        for drv, marker in (("concurrent", "o"), ("serial", "s")):
            mine = [r for r in rows if r["device"] == device and driver(r) == drv]
            if mine:
                ax.scatter([float(r["simulated_seconds"]) for r in mine], [float(r["energy_joules"]) for r in mine],
                           s=14, marker=marker, color=plt.cm.tab10(i % 10), label=f"{device}, {drv}", zorder=2)
    front = sorted((float(r["simulated_seconds"]), float(r["energy_joules"]), r) for r in rows
                   if r.get("pareto_time_energy") == "1")
    if front:
        ax.plot([f[0] for f in front], [f[1] for f in front], "-", color="k", lw=0.9, zorder=1,
                label="Pareto front (time, energy)")
        ax.scatter([f[0] for f in front], [f[1] for f in front], s=70, facecolors="none", edgecolors="k",
                   lw=1.0, zorder=3)
    # The front's points are listed under the plot: they crowd together where labels would overlap.
    names = [f"{r['device']} {r['lanes']}L {r['banks']}B {driver(r)[0]}: {t:.4g} s, {e:.4g} J" for t, e, r in front]
    shown = names[:8] + ([f"... and {len(names) - 8} more (pareto_time_energy in the CSV)"] if len(names) > 8 else [])
    listing = "Pareto front: " + ("; ".join(shown) if shown else "none")
    ax.set_xlabel("simulated seconds")
    ax.set_ylabel("joules per run")
    ax.grid(True, lw=0.3)
    ax.legend(fontsize=8, loc="lower right")
    settings = name.replace("_", " ").strip()
    ax.set_title(f"Time against energy ({bits}-bit{', ' + settings if settings else ''}); ringed: the Pareto front"
                 "\nfront: device, lanes (L), banks (B), driver (c concurrent, s serial)", fontsize=9)
    fig.text(0.01, 0.005, listing, fontsize=6.5, va="bottom", wrap=True)
    fig.tight_layout(rect=(0, 0.08, 1, 1))
    entry.save(fig, os.path.join(out, f"pareto_b{bits}{name}.png"), dpi=110)
    plt.close(fig)


def heatmap(rows, device, bits, drv, out):
    lanes = sorted({int(r["lanes"]) for r in rows})
    banks = sorted({int(r["banks"]) for r in rows})
    # Lane counts that fit nowhere in the sweep are left out (one line under the plot says so).
    fits = [n for n in lanes if any(int(r["lanes"]) == n and r["invalid_kind"] != "does_not_fit" for r in rows)]
    if not fits:
        return
    cell = {(int(r["lanes"]), int(r["banks"])): r for r in rows}
    grid = [[math.nan] * len(banks) for _ in fits]
    for i, n in enumerate(fits):
        for j, b in enumerate(banks):
            r = cell.get((n, b))
            if r and r["status"] == "ok":
                grid[i][j] = float(r["simulated_seconds"])
    fig, ax = plt.subplots(figsize=(1.0 + 0.75 * len(banks), 1.2 + 0.42 * len(fits)))
    cmap = plt.cm.viridis_r.copy()
    cmap.set_bad("0.85")
    image = ax.imshow(grid, cmap=cmap, aspect="auto", origin="lower")
    low, high = image.get_clim()
    for i, n in enumerate(fits):
        for j, b in enumerate(banks):
            r = cell.get((n, b))
            if r is None:
                continue
            colour = "k"
            if r["status"] == "ok":
                letter = BOTTLENECKS.get(r["bottleneck"], ("?",))[0]
                seconds = float(r["simulated_seconds"])
                text = f"{seconds:.4g}\n{letter}"
                # viridis_r is dark at the top of the range: white text there.
                if high > low and (seconds - low) / (high - low) > 0.6:
                    colour = "w"
            else:
                text = "fit" if r["invalid_kind"] == "does_not_fit" else "banks"
            ax.text(j, i, text, ha="center", va="center", fontsize=6.5, color=colour)
    ax.set_xticks(range(len(banks)))
    ax.set_xticklabels(banks)
    ax.set_yticks(range(len(fits)))
    ax.set_yticklabels(fits)
    ax.set_xlabel("banks")
    ax.set_ylabel("lanes")
    bar = fig.colorbar(image, ax=ax)
    bar.set_label("simulated seconds")
    ax.set_title(f"{device}, {bits}-bit, {drv}: simulated seconds", fontsize=9)
    key = "  ".join(f"{v[0]} {v[2]}" for k, v in BOTTLENECKS.items()
                    if any(r["bottleneck"] == k for r in rows))
    note = f"grey: cannot exist (banks: too few banks). {key}"
    if len(fits) < len(lanes):
        note += f"\nnot shown: {len(lanes) - len(fits)} lane count(s) that do not fit the device"
    fig.text(0.01, 0.005, note, fontsize=6, va="bottom", wrap=True)
    fig.tight_layout(rect=(0, 0.06, 1, 1))
    entry.save(fig, os.path.join(out, f"heatmap_{slug(device)}_b{bits}_{drv}.png"), dpi=110)
    plt.close(fig)


def extra_columns(header):
    """The study's own axes: the columns between "concurrent" and "status"."""
    return header[header.index("concurrent") + 1:header.index("status")]


def as_number(text):
    try:
        return float(text)
    except ValueError:
        return None


def axis_plot(rows, axis, extras, out):
    """The fastest configuration over lanes and banks against one swept field's value; with energy, a
    second panel: the least energy per step over lanes and banks."""
    others = [e for e in extras if e != axis]
    lines = ordered((r["device"], r["bits"], driver(r)) + tuple(r[e] for e in others) for r in rows)
    values = ordered(r[axis] for r in rows)
    numeric = all(as_number(v) is not None for v in values)
    if numeric:
        values = sorted(values, key=float)
    position = {v: (float(v) if numeric else i) for i, v in enumerate(values)}
    with_energy = any(has_energy(r) for r in rows)
    panels = [("simulated_seconds", "fastest simulated seconds (over lanes and banks)", lambda r: r["status"] == "ok")]
    if with_energy:
        panels.append(("energy_per_step_joules", "least joules per step (over lanes and banks)", has_energy))
    fig, axes = plt.subplots(1, len(panels), figsize=(7.5 * len(panels), 4.6), squeeze=False)
    used = set()
    for ax, (key, label, usable) in zip(axes[0], panels):
        best = {}  # (line, value) -> the best row: one pass over the rows, whatever the number of values
        for r in rows:
            if not usable(r):
                continue
            at = ((r["device"], r["bits"], driver(r)) + tuple(r[e] for e in others), r[axis])
            if at not in best or float(r[key]) < float(best[at][key]):
                best[at] = r
        for index, line in enumerate(lines):
            points = [(position[v], float(best[(line, v)][key]), best[(line, v)]["bottleneck"]) for v in values
                      if (line, v) in best]
            if not points:
                continue
            label_text = f"{line[0]}, {line[1]}-bit, {line[2]}" + "".join(f", {e}={v}" for e, v in zip(others, line[3:]))
            style = ["-", "--", ":", "-."][index % 4]  # lines that coincide stay visible
            (handle,) = ax.plot([p[0] for p in points], [p[1] for p in points], style, lw=1.2, label=label_text,
                                color=plt.cm.tab10(index % 10))
            for kind in ordered(p[2] for p in points):  # one marker artist per bottleneck, not per point
                used.add(kind)
                mine = [p for p in points if p[2] == kind]
                ax.plot([p[0] for p in mine], [p[1] for p in mine], BOTTLENECKS.get(kind, ("?", "*", kind))[1], ls="",
                        color=handle.get_color(), ms=6, mec="k", mew=0.4)
        if not numeric:
            ax.set_xticks(range(len(values)))
            ax.set_xticklabels(values)
        ax.set_xlabel(axis)
        ax.set_ylabel(label)
        ax.set_ylim(0, ax.get_ylim()[1] * 1.12)  # room above the lines for them and the legend
        ax.grid(True, lw=0.3)
    handles, _ = axes[0][0].get_legend_handles_labels()
    handles += [Line2D([], [], ls="", marker=BOTTLENECKS[k][1], color="w", mec="k", label=BOTTLENECKS[k][2])
                for k in BOTTLENECKS if k in used]
    axes[0][0].legend(handles=handles, fontsize=7, loc="lower right")
    what = "fastest and most frugal configurations" if with_energy else "fastest configuration"
    fig.suptitle(f"The {what} against {axis}; marker: its bottleneck", fontsize=10)
    fig.tight_layout(rect=(0, 0, 1, 0.95))
    entry.save(fig, os.path.join(out, f"axis_{slug(axis)}.png"), dpi=110)
    plt.close(fig)


# Pictures per scene (per sweep.csv), at most: at about 0.2 s each, 40 cost seconds, like the sweep's
# own computation of a small study. A study with many combinations of its axes (a profile axis of
# 100 values made 404 pictures; 1,000 values took minutes to draw after a 3 s computation) gets its
# axis plots, which show every value, and the pictures of its first combinations; a line on stderr
# says what was not drawn (docs/outputs.md, "Plots").
MAX_PICTURES = 40


def planned_pictures(rows, extras, out):
    """The pictures of each combination of width, driver and the extra axes' values, in CSV order:
    a list of (combination, [(file, draw)]), the rows grouped once (a thousand-value axis must not
    scan every row per value)."""
    blocks = {}
    for r in rows:
        blocks.setdefault((r["bits"], driver(r), tuple(r[e] for e in extras)), []).append(r)
    settings = [e for e in extras if e not in DESIGN_COLUMNS]
    fronts = {}
    for r in rows:
        fronts.setdefault((r["bits"], tuple(r[e] for e in settings)), []).append(r)
    plan = []
    for (bits, drv, values), block in blocks.items():
        name = drv + "".join(f"_{slug(e)}={slug(v)}" for e, v in zip(extras, values))
        title = f"{bits}-bit, {drv}" + "".join(f", {e}={v}" for e, v in zip(extras, values))
        pictures = []
        if any(r["status"] == "ok" for r in block):
            pictures.append((f"lanes_b{bits}_{name}.png", lambda b=block, n=name, w=bits: lanes_plot(b, w, n, out)))
        if any(has_energy(r) for r in block):
            pictures.append((f"energy_b{bits}_{name}.png", lambda b=block, n=name, w=bits: energy_plot(b, w, n, out)))
        for device in ordered(r["device"] for r in block):
            mine = [r for r in block if r["device"] == device]
            if any(r["invalid_kind"] != "does_not_fit" for r in mine):
                pictures.append((f"heatmap_{slug(device)}_b{bits}_{name}.png",
                                 lambda m=mine, d=device, n=name, w=bits: heatmap(m, d, w, n, out)))
        plan.append((title, pictures))
    # The front chooses among designs (driver, host and cards included); each width and each
    # combination of profile settings has its own (host_sw/studies/sweep_row.h).
    for (bits, values), block in fronts.items():
        if any(has_energy(r) for r in block):
            name = "".join(f"_{slug(e)}={slug(v)}" for e, v in zip(settings, values))
            title = f"{bits}-bit front" + "".join(f", {e}={v}" for e, v in zip(settings, values))
            plan.append((title, [(f"pareto_b{bits}{name}.png",
                                  lambda b=block, n=name, w=bits: pareto_plot(b, w, n, out))]))
    return plan


def main(csv_path, out):
    with open(csv_path) as f:
        reader = csv.DictReader(f)
        rows = list(reader)
        extras = extra_columns(reader.fieldnames)
    simulated = [r for r in rows if r["status"] == "ok"]
    if simulated and not any(has_energy(r) for r in simulated):
        why = next((r.get("energy_missing", "") for r in simulated if r.get("energy_missing", "")),
                   "the CSV has no energy columns")
        print(f"sweep.py: no energy plots: {why}", file=sys.stderr)
    for axis in extras:  # the summaries: every value of every axis, drawn whatever the cap
        axis_plot(rows, axis, extras, out)
    plan = planned_pictures(rows, extras, out)
    budget = MAX_PICTURES - len(extras)
    drawn = 0
    skipped = []
    for title, pictures in plan:
        if skipped or drawn + len(pictures) > budget:  # whole combinations only, in CSV order
            skipped.append((title, pictures))
            continue
        for _, draw in pictures:
            draw()
        drawn += len(pictures)
    if skipped:
        count = sum(len(p) for _, p in skipped)
        total = len(extras) + sum(len(p) for _, p in plan)
        print(f"sweep.py: {out}: drew {total - count} of {total} pictures (at most {MAX_PICTURES} per scene; "
              f"docs/outputs.md): {len(extras)} axis plot(s), which show every value, and the pictures of the first "
              f"{len(plan) - len(skipped)} of {len(plan)} combinations; not drawn: {count} picture(s) of "
              f"{len(skipped)} combinations, from '{skipped[0][0]}' to '{skipped[-1][0]}' (sweep.csv has every row)",
              file=sys.stderr)


if __name__ == "__main__":
    entry.run(main, "usage: sweep.py sweep.csv OUTPUT_FOLDER")
