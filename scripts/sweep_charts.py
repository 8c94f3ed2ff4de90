#!/usr/bin/env python3
"""Charts one sweep of `zblend sweep` from its CSV (docs/sweeps.md).

usage: sweep_charts.py NAME CSV PNG, NAME one of orbit, depth, layers, alpha, samples.
The PNG is written beside its target and renamed, so a failed run leaves no partial file.
"""
import csv
import os
import re
import sys
from collections import OrderedDict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402 (after the backend is chosen)


WIREFRAME = ("hidden-line", "hidden-line-dim")


def read_rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def series(rows, key, x, y, scale=1.0):
    """{series name: ([x], [y])}, series in order of first appearance."""
    out = OrderedDict()
    for r in rows:
        xs, ys = out.setdefault(r[key], ([], []))
        xs.append(float(r[x]))
        ys.append(float(r[y]) * scale)
    return out


def style(i):
    """A distinct colour and dash for up to 20 lines."""
    colours = plt.get_cmap("tab20").colors
    return {"color": colours[(2 * i) % 20 if i < 10 else (2 * i + 1) % 20],
            "linestyle": ["-", "--", "-.", ":"][i % 4]}


def method_panels(rows, x, xlabel, fig, logx=False, by_scene=False):
    """Four error measures against the swept parameter, one line per method (and scene)."""
    panels = [("rmse", "RMSE (8-bit units)", 1.0),
              ("delta_e_mean", "mean CIEDE2000", 1.0),
              ("max_abs", "largest channel error (8-bit units)", 1.0),
              ("share_over_16", "pixels off by more than 16/255 (%)", 100.0)]
    # The wireframe methods' error against a shaded image is about 150 and measures nothing
    # but that (README); drawn, they would flatten every other line.
    wire = [r for r in rows if r["method"] in WIREFRAME]
    rows = [r for r in rows if r["method"] not in WIREFRAME]
    if by_scene:
        for r in rows:
            r["series"] = f"{r['method']} on {r['scene']}"
    axes = list(fig.subplots(2, 2).flat)
    for ax, (col, label, scale) in zip(axes, panels):
        lines = series(rows, "series" if by_scene else "method", x, col, scale)
        for i, (name, (xs, ys)) in enumerate(lines.items()):
            ax.plot(xs, ys, marker=".", label=name, **style(i))
        if logx:
            ax.set_xscale("log", base=2)
            ticks = sorted({float(r[x]) for r in rows})
            ax.set_xticks(ticks, [f"{t:g}" for t in ticks])
        ax.set_xlabel(xlabel)
        ax.set_ylabel(label)
        ax.grid(True, alpha=0.3)
    handles, labels = axes[0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="center right", fontsize="small")
    if wire:
        rmse = sum(float(r["rmse"]) for r in wire) / len(wire)
        return f" (hidden-line methods not drawn: wireframes, mean RMSE {rmse:.0f})"
    return ""


def chart_orbit(rows, fig):
    ax = fig.subplots()
    lines = series(rows, "method", "angle_deg", "popping", 100.0)
    means = {name: sum(ys) / len(ys) for name, (_, ys) in lines.items()}
    for i, name in enumerate(sorted(lines, key=lambda n: -means[n])):
        xs, ys = lines[name]
        ax.plot(xs, ys, label=f"{name} (mean {means[name]:.2f}%)", linewidth=1, **style(i))
    ax.set_xlabel("camera angle (degrees)")
    ax.set_ylabel("popping pixels (%)")
    ax.set_xlim(0, 360)
    ax.grid(True, alpha=0.3)
    ax.legend(loc="center left", bbox_to_anchor=(1.02, 0.5), fontsize="small")
    fig.suptitle("Orbit: pixels whose change from the last frame exceeds the reference's")


def chart_depth(rows, fig):
    ax = fig.subplots()
    for r in rows:
        r["series"] = ("reference (exact sort)" if r["method"] == "reference"
                       else f"opaque, {r['depth_bits']} bits")
    lines = series(rows, "series", "separation", "error", 100.0)
    for i, (name, (xs, ys)) in enumerate(lines.items()):
        extra = {"color": "black", "linewidth": 2.5, "alpha": 0.5} if name.startswith("ref") else style(i)
        ax.plot(xs, ys, marker=".", label=name, **extra)
    ax.set_xscale("log")
    ax.set_xlabel("separation of the two quads along their normal (world units)")
    ax.set_ylabel("near quad's pixels showing the far quad (%)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
    fig.suptitle("Depth: z-fighting of two parallel opaque quads, by depth buffer width")


def chart_layer_family(name, rows, fig):
    """layers or alpha: the other parameter is fixed; the scene's name layers-N-aP says it."""
    n, p = re.fullmatch(r"layers-(\d+)-a(\d+)", rows[0]["scene"]).groups()
    if name == "layers":
        note = method_panels(rows, "layers", "transparent layers N", fig)
        fig.suptitle(f"Layers: error against the reference by layer count, alpha {int(p) / 100:.2f}"
                     + note)
    else:
        note = method_panels(rows, "alpha", "alpha of each layer", fig)
        fig.suptitle(f"Alpha: error against the reference by layer alpha, {n} layers" + note)


def chart_samples(rows, fig):
    method_panels(rows, "samples", "coverage samples per pixel", fig, logx=True, by_scene=True)
    fig.suptitle("Samples: error against the supersampled reference by coverage samples")


CHARTS = {
    "orbit": chart_orbit,
    "depth": chart_depth,
    "layers": lambda rows, fig: chart_layer_family("layers", rows, fig),
    "alpha": lambda rows, fig: chart_layer_family("alpha", rows, fig),
    "samples": chart_samples,
}


def main(argv):
    if len(argv) != 4:
        sys.exit(__doc__.strip().splitlines()[2])
    name, csv_path, png_path = argv[1:]
    if name not in CHARTS:
        sys.exit(f"sweep_charts: unknown sweep '{name}' ({', '.join(CHARTS)})")
    rows = read_rows(csv_path)
    if not rows:
        sys.exit(f"sweep_charts: {csv_path}: no rows")
    panels = name in ("layers", "alpha", "samples")
    fig = plt.figure(figsize=(14, 8) if panels else (11, 5.5))
    CHARTS[name](rows, fig)
    fig.tight_layout(rect=(0, 0, 0.86 if panels else 1, 1))
    tmp = png_path + ".tmp.png"
    try:
        fig.savefig(tmp, dpi=100)
        os.replace(tmp, png_path)
    finally:
        if os.path.exists(tmp):
            os.remove(tmp)


if __name__ == "__main__":
    main(sys.argv)
