#!/usr/bin/env python3
"""Chart of `make bench`'s cost growth (docs/bench.md).

Usage: bench_charts.py GROWTH_CSV OUT_PNG

Three panels, log-log: render time against the frame's pixels (the scene scaled with the
frame), against the triangle count (a sphere of fixed size on screen), and against the frame's
pixels with an object of fixed size on screen. Each panel also draws what the time would be
if it grew with the fragments (dashed) and with the frame (dotted), from the first point.
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

PANELS = [
    ("resolution", "pixels", "bunny-glass, scaled with the frame"),
    ("triangles", "triangles", "sphere of fixed size, 1024x1024"),
    ("frame", "pixels", "sphere ~150 px across, frame grows"),
]


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    with open(sys.argv[1]) as f:
        rows = list(csv.DictReader(f))
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.5))
    for ax, (sweep, x_key, title) in zip(axes, PANELS):
        pts = [r for r in rows if r["sweep"] == sweep]
        x = [float(r[x_key]) for r in pts]
        t = [float(r["host_ms"]) for r in pts]
        frags = [float(r["fragments"]) for r in pts]
        ax.loglog(x, t, "o-", label="render time (three-pass)")
        ax.loglog(x, [t[0] * f / frags[0] for f in frags], "--", label="∝ fragments")
        if x_key == "pixels":
            ax.loglog(x, [t[0] * v / x[0] for v in x], ":", label="∝ frame pixels")
        if sweep == "frame":
            clear = [r for r in rows if r["sweep"] == "clear"]
            ax.loglog([float(r["pixels"]) for r in clear], [float(r["host_ms"]) for r in clear],
                      "s-", label="allocating and clearing the planes alone")
        ax.set_title(title, fontsize=10)
        ax.set_xlabel(x_key)
        ax.set_ylabel("ms")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
    fig.suptitle("zblend golden model: cost against what a scene touches")
    fig.tight_layout()
    tmp = sys.argv[2] + ".tmp.png"
    fig.savefig(tmp, dpi=100)
    os.replace(tmp, sys.argv[2])


if __name__ == "__main__":
    main()
