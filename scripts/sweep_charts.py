#!/usr/bin/env python3
"""Charts one sweep of `zblend sweep` from its CSV (docs/sweeps.md).

usage: sweep_charts.py NAME CSV PNG, NAME one of orbit, depth, layers, alpha, samples, offset,
wboit.
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


def chart_order(rows, fig):
    """Submission order against K: each method's error by layer count, a colour a method and a
    dash an order (near first solid, far first dashed, shuffled dotted)."""
    dashes = {"near first": "-", "far first": "--", "shuffled": ":"}
    colours = plt.get_cmap("tab10").colors
    methods = list(OrderedDict.fromkeys(r["method"].split(" (")[0] for r in rows))
    panels = [("rmse", "RMSE (8-bit units)"), ("delta_e_mean", "mean CIEDE2000")]
    axes = fig.subplots(1, 2)
    for ax, (col, label) in zip(axes, panels):
        for name, (xs, ys) in series(rows, "method", "layers", col).items():
            method, order = name[:-1].split(" (")
            ax.plot(xs, ys, marker=".", label=name, linestyle=dashes[order],
                    color=colours[methods.index(method) % 10])
        ax.set_xlabel("transparent layers N")
        ax.set_ylabel(label)
        ax.grid(True, alpha=0.3)
    handles, labels = axes[0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="center right", fontsize="small")
    fig.suptitle("Order: error against the reference by layer count and submission order "
                 "(a colour a method; solid near first, dashed far first, dotted shuffled)")


def chart_samples(rows, fig):
    method_panels(rows, "samples", "coverage samples per pixel", fig, logx=True, by_scene=True)
    fig.suptitle("Samples: error against the supersampled reference by coverage samples")


def value_label(v):
    """A knob's value as a tick label: 'none' for no clamp, 2^k for the large powers of two."""
    if v == "inf":
        return "none"
    x = float(v)
    if x >= 1024 and x == int(x) and int(x) & (int(x) - 1) == 0:
        return f"2^{int(x).bit_length() - 1}"
    return v


def chart_offset(rows, fig):
    """Per knob: the tilted plate's mean shares over the tilts, and each built-in's, against
    the knob's value (a category axis: the values include 0 and 'none'). Last panel: against
    the tilt, the first polygon offset and the plans' default."""
    knobs = []
    for r in rows:
        if r["knob"] not in knobs:
            knobs.append(r["knob"])
    scenes = []
    for r in rows:
        if r["scene"] != "tilt" and r["scene"] not in scenes:
            scenes.append(r["scene"])
    axes = list(fig.subplots(2, 3).flat)
    shares = (("hidden_drawn_share", "hidden drawn", "#d62728"),
              ("visible_missing_share", "visible missing", "#1f77b4"))
    for ax, knob in zip(axes, knobs):
        sel = [r for r in rows if r["knob"] == knob]
        values = []
        for r in sel:
            if r["value"] not in values:
                values.append(r["value"])
        xs = range(len(values))
        for key, label, colour in shares:
            tilt = [[100 * float(r[key]) for r in sel if r["value"] == v and r["scene"] == "tilt"]
                    for v in values]
            ax.plot(xs, [sum(t) / len(t) for t in tilt], marker="o", color=colour,
                    label=f"plate, mean of tilts: {label}")
            for i, sc in enumerate(scenes):
                ys = [100 * float(r[key]) for v in values for r in sel
                      if r["value"] == v and r["scene"] == sc]
                ax.plot(xs, ys, marker=".", color=colour, alpha=0.6,
                        linestyle=["--", ":", "-."][i % 3], label=f"{sc}: {label}")
        for i, v in enumerate(values):
            if any(r["default"] == "1" for r in sel if r["value"] == v):
                ax.axvline(i, color="green", lw=1.5, alpha=0.6, label="the plans' default")
        ax.set_xticks(list(xs))
        ax.set_xticklabels([value_label(v) for v in values], rotation=45, fontsize=7)
        ax.set_yscale("symlog", linthresh=0.1)
        ax.set_ylim(bottom=0)
        ax.set_xlabel({"units": "constant (units), slope 1.0, no clamp",
                       "slope": "slope factor, 2 units, no clamp",
                       "clamp": "clamp (units), 2 units + 1.0 x slope",
                       "faces": "units beyond the edge's own faces"}.get(knob, knob))
        ax.set_ylabel("share of edge pixels (%)")
        ax.grid(True, alpha=0.3)
    ax = axes[len(knobs)]
    default = [(r["knob"], r["value"]) for r in rows if r["default"] == "1"][:1]
    for (knob, value), style, name in ((("slope", "1"), "--", "2 + 1.0 x slope"),
                                       *((d, "-", "the plans' default") for d in default)):
        sel = [r for r in rows if r["knob"] == knob and r["value"] == value and r["scene"] == "tilt"]
        for key, label, colour in shares:
            ax.plot([float(r["tilt_deg"]) for r in sel], [100 * float(r[key]) for r in sel],
                    marker=".", color=colour, linestyle=style, label=f"{name}: {label}")
    ax.set_yscale("symlog", linthresh=0.1)
    ax.set_ylim(bottom=0)
    ax.set_xlabel("plate tilt (degrees)")
    ax.set_ylabel("share of edge pixels (%)")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=7)
    handles, labels = axes[0].get_legend_handles_labels()
    for extra in axes[1:len(knobs)]:
        for h, l in zip(*extra.get_legend_handles_labels()):
            if l not in labels:
                handles.append(h)
                labels.append(l)
    axes[-1].axis("off")
    axes[-1].legend(handles, labels, loc="center", fontsize=8)
    fig.suptitle("Hidden-line offset: hidden edges drawn (leak) and visible ones missing (gaps), "
                 "against the exact line reference")


def chart_wboit(rows, fig):
    """Left: wboit's mean error over the scenes against its weight range, a line per
    accumulation width. Then per scene: error against memory traffic, wboit at each
    accumulation width (its best weight range there) beside the patents' methods."""
    wb = [r for r in rows if r["method"] == "wboit"]
    base = [r for r in rows if r["method"] != "wboit"]
    scenes = list(OrderedDict.fromkeys(r["scene"] for r in rows))
    axes = list(fig.subplots(2, 3).flat)
    ax = axes[0]
    widths = list(OrderedDict.fromkeys(r["acc_bits"] for r in wb))
    for i, a in enumerate(widths):
        by_w = OrderedDict()
        for r in wb:
            if r["acc_bits"] == a:
                by_w.setdefault(int(r["weight_bits"]), []).append(float(r["delta_e_mean"]))
        ax.plot(list(by_w), [sum(v) / len(v) for v in by_w.values()], marker=".",
                label=f"A = {a} bits", **style(i))
    ax.set_xlabel("weight range W (F from 1 to 2^W - 1)")
    ax.set_ylabel(f"mean CIEDE2000 over the {len(scenes)} scenes")
    ax.set_title("wboit: weight range against accumulation width", fontsize=10)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    for ax, scene in zip(axes[1:], scenes):
        for i, m in enumerate(OrderedDict.fromkeys(r["method"] for r in base)):
            for r in base:
                if r["scene"] == scene and r["method"] == m:
                    ax.scatter(float(r["bytes"]) / 1e3, float(r["delta_e_mean"]), s=40,
                               color=style(i + 1)["color"], label=m, zorder=3)
        pts = []
        for a in widths:
            cand = [r for r in wb if r["scene"] == scene and r["acc_bits"] == a]
            best = min(cand, key=lambda r: float(r["delta_e_mean"]))
            pts.append((float(best["bytes"]) / 1e3, float(best["delta_e_mean"]),
                        f"{a}/{best['weight_bits']}"))
        ax.plot([p[0] for p in pts], [p[1] for p in pts], marker="s", color="black",
                label="wboit A/W", zorder=2)
        for x, y, t in pts:
            ax.annotate(t, (x, y), textcoords="offset points", xytext=(3, 3), fontsize=7)
        ax.set_xscale("log")
        ax.set_xlabel("memory traffic (kB, read + written)")
        ax.set_ylabel("mean CIEDE2000")
        ax.set_title(scene, fontsize=10)
        ax.grid(True, alpha=0.3)
    axes[1].legend(fontsize=7)
    fig.suptitle("Weighted blended OIT against the patents' methods: error and memory traffic")


CHARTS = {
    "orbit": chart_orbit,
    "depth": chart_depth,
    "layers": lambda rows, fig: chart_layer_family("layers", rows, fig),
    "alpha": lambda rows, fig: chart_layer_family("alpha", rows, fig),
    "order": chart_order,
    "samples": chart_samples,
    "offset": chart_offset,
    "wboit": chart_wboit,
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
    panels = name in ("layers", "alpha", "samples", "order")
    big = name in ("offset", "wboit")
    fig = plt.figure(figsize=(17, 10) if big else (14, 8) if panels else (11, 5.5))
    CHARTS[name](rows, fig)
    fig.tight_layout(rect=(0, 0, 0.86 if panels else 1, 0.97 if big else 1))
    tmp = png_path + ".tmp.png"
    try:
        fig.savefig(tmp, dpi=100)
        os.replace(tmp, png_path)
    finally:
        if os.path.exists(tmp):
            os.remove(tmp)


if __name__ == "__main__":
    main(sys.argv)
