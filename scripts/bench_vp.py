"""The virtual platform's speed for `make bench` (docs/bench.md, docs/systemc.md): zblend_vp on
cad three-pass 640x480 against its yardstick, whole processes run in turn so that the machine's
drift falls on both, the median of the per-pair ratios. Golden inside against `zblend render
--threads 1` (target: at most 2, half the speed); RTL inside against `zblend render --backend rtl
--threads 1` (target: at most 1.2).
"""
import os
import shlex
import statistics
import time

METHOD = "three-pass"


def vp(b, runs):
    out = os.path.join(b.out, "vp")
    os.makedirs(out, exist_ok=True)
    scene = ["--scene", "cad", "--method", METHOD, "-W", "640", "-H", "480"]
    pairs = {
        "golden": ([b.exe("zblend_vp")] + scene + ["--no-check", "-q", "--out", f"{out}/vp.png"],
                   [b.exe("zblend"), "render", "-q"] + scene +
                   ["--threads", "1", "--out", f"{out}/render.png"], "<= 2"),
        "rtl": ([b.exe("zblend_vp")] + scene + ["--inside", "rtl", "--no-check", "-q", "--out",
                                                f"{out}/vp-rtl.png"],
                [b.exe("zblend"), "render", "-q"] + scene +
                ["--backend", "rtl", "--threads", "1", "--out", f"{out}/render-rtl.png"], "<= 1.2"),
    }
    for inside, (vp_cmd, yard_cmd, target) in pairs.items():
        ratios, vp_s, yard_s = [], [], []
        for _ in range(runs):
            t0 = time.perf_counter()
            b.run(vp_cmd)
            t1 = time.perf_counter()
            b.run(yard_cmd)
            t2 = time.perf_counter()
            vp_s.append(t1 - t0)
            yard_s.append(t2 - t1)
            ratios.append((t1 - t0) / (t2 - t1))
        shown = shlex.join(["zblend_vp"] + vp_cmd[1:])
        b.add(f"zblend_vp, {inside} inside, cad {METHOD} 640x480, whole process: median of {runs}",
              statistics.median(vp_s), "s", "", shown)
        b.add(f"its yardstick, alternated with it: median of {runs}", statistics.median(yard_s),
              "s", "", shlex.join(["zblend"] + yard_cmd[1:]))
        b.add(f"zblend_vp, {inside} inside / its yardstick (median of the pairs' ratios)",
              statistics.median(ratios), "x", target, shown)
