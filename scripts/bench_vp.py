"""The virtual platform's speed for `make bench` (docs/bench.md, docs/systemc.md): zblend_vp on
cad three-pass 640x480 against its yardstick, whole processes run in turn so that the machine's
drift falls on both, the median of the per-pair ratios (three times the step's repetitions for
the golden inside, twice for the RTL inside). Golden inside against `zblend render
--threads 1` (target: at most 2, half the speed); RTL inside against `zblend render --backend rtl
--threads 1` (target: at most 1.2), and against the same with `--schedule pass`, the RTL
inside's schedule (no target: the platform's own cost).
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

    def vp_cmd(extra, png):
        return [b.exe("zblend_vp")] + scene + extra + ["--no-check", "-q", "--out", f"{out}/{png}"]

    def render_cmd(extra, png):
        return ([b.exe("zblend"), "render", "-q"] + scene + extra +
                ["--threads", "1", "--out", f"{out}/{png}"])

    rtl = ["--inside", "rtl"]
    # Each: the platform, its yardstick, the target, the pairs (more than the other steps: the
    # ratios are near their targets and the machine noisy; a golden pair takes 50 ms, an RTL
    # one 0.65 s). The RTL inside runs the pass schedule (a pass's cycles annotated as it ends),
    # where zblend render's default is the tile schedule, which takes fewer cycles: the same
    # schedule on both sides shows the platform's own cost.
    pairs = {
        "golden inside": (vp_cmd([], "vp.png"), render_cmd([], "render.png"), "<= 2", runs * 3),
        "rtl inside": (vp_cmd(rtl, "vp-rtl.png"),
                       render_cmd(["--backend", "rtl"], "render-rtl.png"), "<= 1.2", runs * 2),
        "rtl inside, yardstick --schedule pass": (
            vp_cmd(rtl, "vp-rtl.png"),
            render_cmd(["--backend", "rtl", "--schedule", "pass"], "render-rtl-pass.png"), "",
            runs * 2),
    }
    for inside, (vp_run, yard_cmd, target, n) in pairs.items():
        ratios, vp_s, yard_s = [], [], []
        for _ in range(n):
            t0 = time.perf_counter()
            b.run(vp_run)
            t1 = time.perf_counter()
            b.run(yard_cmd)
            t2 = time.perf_counter()
            vp_s.append(t1 - t0)
            yard_s.append(t2 - t1)
            ratios.append((t1 - t0) / (t2 - t1))
        shown = shlex.join(["zblend_vp"] + vp_run[1:])
        b.add(f"zblend_vp, {inside}, cad {METHOD} 640x480, whole process: median of {n}",
              statistics.median(vp_s), "s", "", shown)
        b.add(f"its yardstick, alternated with it: median of {n}", statistics.median(yard_s),
              "s", "", shlex.join(["zblend"] + yard_cmd[1:]))
        b.add(f"zblend_vp, {inside} / its yardstick (median of the pairs' ratios)",
              statistics.median(ratios), "x", target, shown)
