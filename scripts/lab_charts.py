#!/usr/bin/env python3
"""Charts of the methods lab (docs/lab.md): error against cost, Pareto front marked.

Usage: lab_charts.py LAB_SUMMARY_CSV OUT_DIR [BEAT]

Reads the per-family means `zblend lab` writes (lab_summary.csv, Pareto flags included: the
front is computed and tested in C++, app/lab/lab.cpp) and writes OUT_DIR/main.png (every scene,
error against cycles or fragments), OUT_DIR/main-bytes.png (against memory bytes),
OUT_DIR/main-port-bytes.png (against the tile port's bytes per pixel, per schedule) and
OUT_DIR/family-FAMILY.png for each family. From lab.csv beside the summary, OUT_DIR/tile-beat.png:
tile cycles as a share of streaming cycles against the tile port's width, over every scene, per
method (BEAT, zb_rop's width, is marked). From lab_lines.csv, OUT_DIR/hidden-line.png: the
hidden-line methods against the exact line reference, per scene and on average against cost.
Each PNG is written beside its target and renamed.
"""
import csv
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.ticker import EngFormatter  # noqa: E402

ERROR_FLOOR = 0.01  # a mean delta E of 0 is drawn here, on the log axis


def path_name(name):
    """As lab::path_name: one safe path component."""
    out = re.sub(r"[^A-Za-z0-9._-]", "_", name)
    return "_" + out if out in ("", ".", "..") else out


def read_summary(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    families = []
    for r in rows:
        if r["family"] not in families:
            families.append(r["family"])
    return rows, families


def cost_label(rows, key):
    if key == "bytes":
        return "mean memory traffic per frame (bytes read + written)"
    unit = rows[0]["cost_unit"] if rows else "fragments"
    return ("mean RTL cycles per frame" if unit == "rtl_cycles"
            else "mean fragments per frame")


def place_labels(fig, ax, names, xs, ys):
    """Each name beside its point, at the first of a few offsets where it overlaps no label
    placed before it (points close together otherwise print over each other)."""
    offsets = [(6, 4), (6, -11), (-6, 4), (-6, -11), (6, 15), (6, -22), (-6, 15), (-6, -22)]
    ax.set_xlim(ax.get_xlim())
    ax.set_ylim(ax.get_ylim())
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    placed = []
    for i in sorted(range(len(names)), key=lambda k: (xs[k], ys[k])):
        for dx, dy in offsets:
            t = ax.annotate(names[i], (xs[i], ys[i]), textcoords="offset points", xytext=(dx, dy),
                            fontsize=8, ha="left" if dx > 0 else "right")
            box = t.get_window_extent(renderer).expanded(1.05, 1.1)
            if not any(box.overlaps(b) for b in placed):
                placed.append(box)
                break
            t.remove()
        else:
            t = ax.annotate(names[i], (xs[i], ys[i]), textcoords="offset points", xytext=(6, 4),
                            fontsize=8)
            placed.append(t.get_window_extent(renderer))


def chart(rows, key, pareto_key, title, out_path):
    xs = [float(r[key]) for r in rows]
    ys = [max(float(r["delta_e_mean"]), ERROR_FLOOR) for r in rows]
    on_front = [r[pareto_key] == "1" for r in rows]
    fig, ax = plt.subplots(figsize=(9, 6), dpi=110)
    ax.scatter([x for x, p in zip(xs, on_front) if not p], [y for y, p in zip(ys, on_front) if not p],
               color="#999999", s=36, label="dominated", zorder=2)
    ax.scatter([x for x, p in zip(xs, on_front) if p], [y for y, p in zip(ys, on_front) if p],
               color="#d62728", s=48, label="Pareto front", zorder=3)
    front = sorted((x, y) for x, y, p in zip(xs, ys, on_front) if p)
    if front:
        # The front as a staircase: what the best method costing at most x achieves.
        sx, sy = [front[0][0]], [front[0][1]]
        for x, y in front[1:]:
            sx += [x, x]
            sy += [sy[-1], y]
        ax.plot(sx, sy, color="#d62728", linewidth=1.2, zorder=1)
    ax.set_xscale("log")
    ax.set_yscale("log")
    # Costs span about one decade: label the minor ticks too (200k, 300k, ...).
    ax.xaxis.set_major_formatter(EngFormatter(sep=""))
    ax.xaxis.set_minor_formatter(EngFormatter(sep=""))
    ax.tick_params(axis="x", which="minor", labelsize=7)
    place_labels(fig, ax, [r["method"] for r in rows], xs, ys)
    ax.set_xlabel(cost_label(rows, key) + ", log")
    ax.set_ylabel("mean CIEDE2000 against the fair reference, log")
    ax.set_title(title)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(loc="upper right", fontsize=8)
    fig.tight_layout()
    tmp = out_path + ".tmp.png"
    fig.savefig(tmp)
    plt.close(fig)
    os.replace(tmp, out_path)


TILE_TARGET = 0.15  # tile cycles at most this share of streaming cycles (docs/rtl.md)


def save(fig, out_path):
    tmp = out_path + ".tmp.png"
    fig.savefig(tmp)
    plt.close(fig)
    os.replace(tmp, out_path)


def tile_beat_chart(lab_csv, beat, out_path):
    with open(lab_csv, newline="") as f:
        rows = [r for r in csv.DictReader(f) if r.get("model_stream_cycles")]
    if not rows:
        return
    beats = sorted(int(k[len("tile_cycles_beat"):]) for k in rows[0]
                   if k.startswith("tile_cycles_beat"))
    methods = []
    for r in rows:
        if r["method"] not in methods:
            methods.append(r["method"])

    def share(sel):
        stream = sum(int(r["model_stream_cycles"]) for r in sel)
        return [sum(int(r[f"tile_cycles_beat{b}"]) for r in sel) / stream for b in beats]

    fig, ax = plt.subplots(figsize=(9, 5.5), dpi=110)
    for m in methods:
        ax.plot(beats, share([r for r in rows if r["method"] == m]), marker=".", lw=1,
                alpha=0.7, label=m)
    ax.plot(beats, share(rows), marker="o", lw=3, color="black", label="every method")
    ax.axhline(TILE_TARGET, color="red", ls="--", lw=1, label=f"target {TILE_TARGET:.0%}")
    if beat:
        ax.axvline(beat, color="grey", ls=":", lw=1, label=f"zb_rop BEAT = {beat}")
    ax.set_xscale("log", base=2)
    ax.set_xticks(beats)
    ax.set_xticklabels([str(b) for b in beats])
    ax.set_yscale("log")
    ax.yaxis.set_major_formatter(matplotlib.ticker.PercentFormatter(1.0))
    ax.set_xlabel("tile port width (pixels a beat)")
    ax.set_ylabel("tile cycles / streaming cycles")
    scenes = len({r["scene"] for r in rows})
    ax.set_title(f"Tile load and store against the port's width ({scenes} scenes, cost model)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(loc="upper right", fontsize=7, ncol=2)
    fig.tight_layout()
    save(fig, out_path)


def port_bytes_chart(lab_csv, out_path):
    """Each method's mean error (against its fair reference) against the tile port's bytes per
    pixel, under the pass schedule (open marker) and the tile schedule (filled), an arrow
    between: the external bandwidth a method costs, where main-bytes.png counts the datapath's
    accesses to the resident tile."""
    with open(lab_csv, newline="") as f:
        rows = [r for r in csv.DictReader(f) if r.get("port_bytes_tile")]
    if not rows:
        return
    methods = []
    for r in rows:
        if r["method"] not in methods:
            methods.append(r["method"])
    fig, ax = plt.subplots(figsize=(9, 6), dpi=110)
    colours = plt.get_cmap("tab20").colors
    for k, m in enumerate(methods):
        sel = [r for r in rows if r["method"] == m]
        px = len(sel)  # every run counts once
        err = max(ERROR_FLOOR, sum(float(r["fair_delta_e_mean"]) for r in sel) / px)
        per_px = {s: sum(float(r[f"port_bytes_{s}"]) / float(r["frame_pixels"]) for r in sel) / px
                  for s in ("pass", "tile")}
        c = colours[k % len(colours)]
        ax.scatter([per_px["pass"]], [err], facecolors="none", edgecolors=[c], s=46)
        ax.scatter([per_px["tile"]], [err], color=c, s=46, label=m)
        if per_px["pass"] != per_px["tile"]:
            ax.annotate("", xy=(per_px["tile"], err), xytext=(per_px["pass"], err),
                        arrowprops=dict(arrowstyle="->", color=c, lw=1))
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.xaxis.set_major_formatter(matplotlib.ticker.FormatStrFormatter("%g"))
    ax.xaxis.set_minor_formatter(matplotlib.ticker.FormatStrFormatter("%g"))
    ax.set_xlabel("tile-port bytes per pixel (loads and stores; open: pass schedule, "
                  "filled: tile schedule), log")
    ax.set_ylabel("mean delta E 2000 against the fair reference, log")
    scenes = len({r["scene"] for r in rows})
    ax.set_title(f"Error against external bandwidth ({scenes} scenes)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7, ncol=2)
    fig.tight_layout()
    save(fig, out_path)


def hidden_line_chart(lines_csv, out_path):
    """Left: per scene, each hidden-line method's hidden edge pixels drawn and visible ones
    missing (shares of the reference's edge pixels). Right: their means against cost."""
    with open(lines_csv, newline="") as f:
        rows = list(csv.DictReader(f))
    scenes = [r for r in rows if r["scene"] != "all"]
    means = [r for r in rows if r["scene"] == "all"]
    if not scenes:
        return
    methods = []
    for r in scenes:
        if r["method"] not in methods:
            methods.append(r["method"])
    names = []
    for r in scenes:
        if r["scene"] not in names:
            names.append(r["scene"])
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(14, 5.5), dpi=110,
                                 gridspec_kw={"width_ratios": [2.2, 1]})
    width = 0.8 / (2 * len(methods))
    colours = plt.get_cmap("tab10").colors
    for k, m in enumerate(methods):
        by_scene = {r["scene"]: r for r in scenes if r["method"] == m}
        for j, (key, label, hatch) in enumerate((("hidden_drawn", "hidden drawn", ""),
                                                  ("visible_missing", "visible missing", "//"))):
            xs = [i + (2 * k + j - len(methods) + 0.5) * width for i in range(len(names))]
            ys = [100 * float(by_scene[n][key]) if n in by_scene else 0 for n in names]
            ax.bar(xs, ys, width, color=colours[k % 10], hatch=hatch, alpha=0.85 if j else 1,
                   edgecolor="black", linewidth=0.3, label=f"{m}: {label}")
    ax.set_xticks(range(len(names)))
    ax.set_xticklabels(names, rotation=30, ha="right", fontsize=8)
    ax.set_ylabel("share of the reference's edge pixels (%)")
    ax.set_title("Per scene")
    ax.grid(True, axis="y", alpha=0.3)
    ax.legend(fontsize=7)
    for k, r in enumerate(means):
        c = float(r["cost"])
        for key, marker in (("hidden_drawn", "o"), ("visible_missing", "s")):
            bx.scatter([c], [100 * float(r[key])], color=colours[k % 10], marker=marker, s=48,
                       label=f"{r['method']}: {key.replace('_', ' ')}")
    bx.set_xscale("log")
    bx.xaxis.set_major_formatter(EngFormatter(sep=""))
    bx.set_xlabel(cost_label(means, "cost") + ", log")
    bx.set_ylabel("mean share over the scenes (%)")
    bx.set_title(f"Mean of {len(names)} scenes (each family once) against cost")
    bx.grid(True, which="both", alpha=0.3)
    bx.legend(fontsize=7)
    fig.suptitle("Hidden-line methods against the exact line reference")
    fig.tight_layout()
    save(fig, out_path)


def main(argv):
    if len(argv) not in (3, 4):
        print(__doc__.strip().splitlines()[2], file=sys.stderr)
        return 2
    rows, families = read_summary(argv[1])
    out_dir = argv[2]
    os.makedirs(out_dir, exist_ok=True)
    for family in families:
        fam_rows = [r for r in rows if r["family"] == family]
        scenes = max(int(r["scenes"]) for r in fam_rows)
        if family == "all":
            over = f"mean of {len(families) - 1} families ({scenes} scenes)"
            chart(fam_rows, "cost", "pareto_cost", f"Every method, {over}: error against cost",
                  os.path.join(out_dir, "main.png"))
            chart(fam_rows, "bytes", "pareto_bytes",
                  f"Every method, {over}: error against memory traffic",
                  os.path.join(out_dir, "main-bytes.png"))
        else:
            chart(fam_rows, "cost", "pareto_cost",
                  f"Family '{family}' ({scenes} scene{'s' if scenes != 1 else ''}): "
                  "error against cost",
                  os.path.join(out_dir, f"family-{path_name(family)}.png"))
    lines_csv = os.path.join(os.path.dirname(argv[1]), "lab_lines.csv")
    if os.path.exists(lines_csv):
        hidden_line_chart(lines_csv, os.path.join(out_dir, "hidden-line.png"))
    lab_csv = os.path.join(os.path.dirname(argv[1]), "lab.csv")
    if os.path.exists(lab_csv):
        tile_beat_chart(lab_csv, int(argv[3]) if len(argv) == 4 else 0,
                        os.path.join(out_dir, "tile-beat.png"))
        port_bytes_chart(lab_csv, os.path.join(out_dir, "main-port-bytes.png"))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
