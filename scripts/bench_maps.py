"""The error maps' cost for `make bench` (docs/bench.md): `zblend render` of cad with every
method at 640x480 into an out-dir, with its error maps and with --no-error-map, runs alternated
in one bench so that the machine's drift falls on both; median wall time and the largest peak
RSS of each, and their ratios (targets: 1.3 and 1.5).
"""
import os
import shlex
import statistics
import time

RENDER = ["render", "-q", "--scene", "cad", "--method", "all", "-W", "640", "-H", "480"]


def maps(b, runs):
    out = os.path.join(b.out, "maps")
    cmds = {"with": [b.exe("zblend")] + RENDER + ["--out-dir", os.path.join(out, "with")],
            "without": [b.exe("zblend")] + RENDER + ["--out-dir", os.path.join(out, "without"),
                                                     "--no-error-map"]}
    wall = {k: [] for k in cmds}
    rss = {k: [] for k in cmds}
    for _ in range(runs):
        for k, cmd in cmds.items():
            t0 = time.perf_counter()
            usage = b.run_usage(cmd)
            wall[k].append(time.perf_counter() - t0)
            rss[k].append(usage.ru_maxrss * 1024)
    t = {k: statistics.median(v) for k, v in wall.items()}
    m = {k: max(v) for k, v in rss.items()}
    shown = {k: shlex.join(["zblend"] + c[1:]) for k, c in cmds.items()}
    b.add(f"render cad, every method, 640x480, with error maps: median of {runs}", t["with"], "s",
          "", shown["with"])
    b.add(f"the same with --no-error-map, alternated with it: median of {runs}", t["without"], "s",
          "", shown["without"])
    b.add("error maps: render time with them / without", t["with"] / t["without"], "x", "<= 1.3",
          shown["with"])
    b.add("error maps: peak RSS with them / without (largest of each)", m["with"] / m["without"],
          "x", "<= 1.5", shown["with"])
