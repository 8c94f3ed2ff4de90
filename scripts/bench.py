#!/usr/bin/env python3
"""zblend's benchmarks in one run (docs/bench.md): `make bench`.

Usage: bench.py [--build DIR] [--out DIR] [--baseline BUILD_DIR] [--pgo BUILD_DIR] [--quick]
                [--only maps|vp]

Runs, on this machine, one after another:
  1. the golden datapath alone, fragments per second per blend mode (Google Benchmark);
  2. bunny-glass at 1024x1024, three-pass: the golden model and Mesa llvmpipe, whole frames
     timed in one process (zblend_oracle --time), every timed frame checked bit for bit;
  3. peak resident memory of the golden model, the reference and the RTL on that frame;
  4. the RTL simulation: both builds' cycles per second beside Verilator's ceiling, fragments per
     clock, CPU time against the golden model's, each beside a baseline commit's build
     (--baseline, scripts/bench_baseline.sh) and the speed build with PGO (--pgo,
     scripts/pgo.sh) run in the same bench; the virtual platform, zblend_vp against zblend
     render (bench_vp.py);
  5. cost growth: render time against resolution, against triangle count, and with the frame
     growing around an object of fixed size on screen;
  6. the error maps' cost: `zblend render` with and without them, alternated (bench_maps.py);
  7. with --baseline: `zblend render` (golden) and `zblend lab` (golden only) wall time, this
     build against the baseline's, runs alternated so that the machine's drift falls on both.
Writes OUT/bench.csv (every figure with its command), OUT/bench.md (the table), OUT/growth.csv
and OUT/growth.png, and prints the table. Exit 1 when a run fails or a frame is not bit-exact.
"""
import argparse
import csv
import json
import math
import os
import platform
import shlex
import statistics
import subprocess
import sys
import time

import bench_maps
import bench_vp
import bench_rtl
import bench_scenes

SIZE = 1024
METHOD = "three-pass"


class Bench:
    def __init__(self, build, out):
        self.build = build
        self.out = out
        self.rows = []  # (figure, value, unit, target, command)

    def exe(self, name):
        path = os.path.join(self.build, name)
        if not os.access(path, os.X_OK):
            sys.exit(f"bench: error: {path} is missing; build first (make build)")
        return path

    def run(self, cmd):
        """Runs cmd; returns its stdout. Exits on failure, with its error output."""
        proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        if proc.returncode != 0:
            sys.exit(f"bench: error: `{shlex.join(cmd)}` exited {proc.returncode}:\n"
                     f"{proc.stderr}")
        return proc.stdout

    def run_rss(self, cmd):
        """Runs cmd; returns its peak RSS in bytes."""
        return self.run_usage(cmd).ru_maxrss * 1024

    def run_usage(self, cmd):
        """Runs cmd; returns its resource usage (os.wait4: subprocess would reap it first)."""
        err_path = os.path.join(self.out, "stderr.txt")
        pid = os.fork()
        if pid == 0:
            try:
                os.dup2(os.open(os.devnull, os.O_WRONLY), 1)
                os.dup2(os.open(err_path, os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o644), 2)
                os.execv(cmd[0], cmd)
            finally:
                os._exit(127)
        _, status, usage = os.wait4(pid, 0)
        code = os.waitstatus_to_exitcode(status)
        if code != 0:
            with open(err_path) as f:
                sys.exit(f"bench: error: `{shlex.join(cmd)}` exited {code}:\n{f.read()}")
        return usage

    def google_benchmark(self, path, filt, reps):
        """Runs Google Benchmark `path`'s benchmarks matching filt, reps times; returns each
        run's median (one repetition reports the run itself) by run name, and the command."""
        cmd = [path, f"--benchmark_filter={filt}", f"--benchmark_repetitions={reps}",
               "--benchmark_report_aggregates_only=true", "--benchmark_format=json"]
        medians = {r["run_name"]: r for r in json.loads(self.run(cmd))["benchmarks"]
                   if r.get("aggregate_name", "median") == "median"}
        return medians, cmd

    def add(self, figure, value, unit, target, cmd):
        self.rows.append((figure, value, unit, target, cmd if isinstance(cmd, str) else shlex.join(cmd)))


def step(n, text):
    print(f"[{n}/7] {text}", file=sys.stderr, flush=True)


def datapath(b, reps):
    med, cmd = b.google_benchmark(b.exe("zblend_bench"), "BM_GoldenDatapath", reps)
    for name, r in sorted(med.items()):
        mode = name.split("/")[-1]
        b.add(f"golden datapath, {mode} blend", r["items_per_second"] / 1e6, "M fragments/s", "",
              cmd)


def frame(b, scene, repeat):
    oracle_dir = os.path.join(b.out, "oracle")
    cmd = [b.exe("zblend_oracle"), "--scene", scene, "-W", str(SIZE), "-H", str(SIZE),
           "-m", METHOD, "--time", "--repeat", str(repeat), "--out-dir", oracle_dir, "-q"]
    b.run(cmd)
    with open(os.path.join(oracle_dir, "oracle.csv")) as f:
        row = next(csv.DictReader(f))
    golden, gl = float(row["golden_ms"]), float(row["llvmpipe_ms"])
    what = f"bunny-glass {SIZE}x{SIZE} {METHOD}"
    b.add(f"{what}: golden model, whole frame", golden, "ms", "", cmd)
    b.add(f"{what}: llvmpipe, whole frame", gl, "ms", "", cmd)
    b.add(f"{what}: llvmpipe time / golden time", gl / golden, "x", ">= 1", cmd)
    b.add(f"{what}: bit-identical pixels, golden vs llvmpipe", float(row["identical_pct"]), "%",
          "", cmd)
    return golden


def memory(b, scene):
    base = [b.exe("zblend"), "render", "--scene", scene, "-W", str(SIZE), "-H", str(SIZE), "-q",
            "--out", os.path.join(b.out, "frame.png")]
    stats = os.path.join(b.out, "golden-stats.json")
    cmd = base + ["-m", METHOD, "--no-error", "--stats", stats]
    rss = b.run_rss(cmd)
    with open(stats) as f:
        mem = json.load(f)["memory"]
    budget = 2 * (mem["frame_bytes"] + mem["scene_bytes"])
    b.add(f"peak RSS, golden {METHOD} (frame {mem['frame_bytes'] / 2**20:.1f} MiB, scene "
          f"{mem['scene_bytes'] / 2**20:.1f} MiB)", rss / 2**20, "MiB",
          f"< {budget / 2**20:.1f} (2 x (frame + scene))", cmd)
    stats = os.path.join(b.out, "reference-stats.json")
    cmd = base + ["-m", "reference", "--stats", stats]
    rss = b.run_rss(cmd)
    with open(stats) as f:
        mem = json.load(f)["memory"]
    # The exact composite also holds a double-precision colour plane and a per-pixel sort
    # index beside the fragments (docs/bench.md): three times, not two.
    bound = 3 * (mem["frame_bytes"] + mem["scene_bytes"] + mem["fragment_bytes"])
    b.add(f"peak RSS, reference ({mem['fragments']} fragments kept, "
          f"{mem['fragment_bytes'] / 2**20:.1f} MiB)", rss / 2**20, "MiB",
          f"< {bound / 2**20:.1f} (3 x (frame + scene + fragments))", cmd)
    cmd = base + ["-m", METHOD, "--backend", "rtl", "--no-error"]
    rss = b.run_rss(cmd)
    b.add(f"peak RSS, RTL {METHOD}", rss / 2**20, "MiB", "", cmd)
    cmd = [b.exe("zblend_oracle"), "--scene", scene, "-W", str(SIZE), "-H", str(SIZE), "-m",
           METHOD, "-q"]
    rss = b.run_rss(cmd)
    b.add("peak RSS, oracle (golden model and llvmpipe in one process)", rss / 2**20, "MiB", "",
          cmd)


def rtl(b, reps):
    med, cmd = b.google_benchmark(b.exe("zblend_bench_rtl"), "BM_RtlHazard|BM_CadThreePassRtl",
                                  reps)
    for name, r in med.items():
        if name.startswith("BM_RtlHazard"):
            b.add("RTL simulation, hazard stream, speed build", r["items_per_second"] / 1e6,
                  "M fragments/s", "", cmd)
            # Runs on 1-4 pixels: each waits for the interlock (docs/rtl.md), by design.
            b.add("RTL cycles per fragment, hazard stream", 1 / r["fragments_per_clock"],
                  "cycles", "", cmd)
        elif name.startswith("BM_CadThreePassRtl"):
            # .../models:N
            args = dict(p.split(":") for p in name.split("/")[1:] if ":" in p)
            how = f"{args['models']} model{'s' if args['models'] != '1' else ''}, speed build"
            b.add(f"RTL simulation time / golden time (one thread), cad three-pass 640x480, {how}",
                  r["rtl_over_golden"], "x", "", cmd)
            b.add(f"RTL simulation, cad three-pass 640x480, {how}",
                  r["fragments_per_second"] / 1e6, "M fragments/s", "", cmd)
            if "fragments_per_clock" in r and args["models"] == "1":
                b.add("RTL cycles per fragment, cad three-pass 640x480",
                      1 / r["fragments_per_clock"], "cycles", "1", cmd)


def render_rtl(b, reps):
    """`zblend render --backend rtl`, cad three-pass 640x480, end to end (scene, raster, RTL,
    PNG): fragments per wall-clock second, median of reps, by --threads."""
    stats = os.path.join(b.out, "rtl-render-stats.json")
    for threads in (1, os.cpu_count() or 1):
        cmd = [b.exe("zblend"), "render", "--scene", "cad", "-m", METHOD, "--backend", "rtl",
               "--no-error", "-q", "--threads", str(threads), "--stats", stats,
               "--out", os.path.join(b.out, "rtl-render.png")]
        times = []
        for _ in range(reps):
            t0 = time.perf_counter()
            b.run(cmd)
            times.append(time.perf_counter() - t0)
        with open(stats) as f:
            frags = json.load(f)["methods"][0]["total"]["fragments_in"]
        b.add(f"zblend render --backend rtl, cad {METHOD} 640x480, end to end, --threads {threads}",
              frags / statistics.median(times) / 1e6, "M fragments/s", "", cmd)


def cosim(b):
    """Wall time per fragment of the golden-RTL co-simulation: SystemC against plain C++."""
    cmd = [b.exe("zblend_systemc"), "--scene", "cad", "--method", METHOD]
    out = b.run(cmd)
    row = next(line.split() for line in out.splitlines() if line.startswith(METHOD))
    b.add(f"co-simulation wall time per fragment, cad {METHOD} 640x480: SystemC modules",
          float(row[-1]), "ns", "", cmd)
    stats = os.path.join(b.out, "cosim-stats.json")
    for lockstep in (True, False):
        cmd = [b.exe("zblend"), "render", "--scene", "cad", "-m", METHOD, "--backend", "both",
               "--no-error", "-q", "--threads", "1", "--stats", stats,
               "--out", os.path.join(b.out, "cosim.png")] + ([] if lockstep else ["--no-lockstep"])
        ns = []
        for _ in range(3):
            b.run(cmd)
            with open(stats) as f:
                m = json.load(f)["methods"][0]
            ns.append(m["host_ms"] * 1e6 / m["total"]["fragments_in"])
        what = "lock-step (every write) and end of pass" if lockstep else "end of pass only"
        b.add(f"co-simulation wall time per fragment, cad {METHOD} 640x480: plain C++ testbench, "
              f"one model, {what}, median of 3", statistics.median(ns), "ns", "", cmd)


def host_ms(b, scene, w, h, reps, camera=None):
    """Median `host_ms` of zblend render over reps runs, and the fragments and triangles."""
    stats = os.path.join(b.out, "growth-stats.json")
    cmd = [b.exe("zblend"), "render", "--scene", scene, "-W", str(w), "-H", str(h), "-m", METHOD,
           "--no-error", "-q", "--stats", stats, "--out", os.path.join(b.out, "growth.png.tmp.png")]
    if camera:
        cmd += ["--camera", camera]
    times = []
    for _ in range(reps):
        b.run(cmd)
        with open(stats) as f:
            s = json.load(f)
        times.append(s["methods"][0]["host_ms"])
    return statistics.median(times), s["methods"][0]["total"]["fragments_in"], s["triangles"], cmd


def growth(b, scene, reps, quick):
    rows = []
    sizes = [256, 512, 1024, 2048] + ([] if quick else [4096])
    for n in sizes:
        ms, frags, tris, cmd = host_ms(b, scene, n, n, reps)
        rows.append(("resolution", n * n, tris, frags, ms, shlex.join(cmd)))
    for slices in [16, 32, 64, 128, 256, 512] + ([] if quick else [1024]):
        path = bench_scenes.sphere(b.scene_dir, slices)
        ms, frags, tris, cmd = host_ms(b, path, SIZE, SIZE, reps, "eye=0,0,4,at=0,0,0,fov=40")
        rows.append(("triangles", SIZE * SIZE, tris, frags, ms, shlex.join(cmd)))
    # A sphere ~150 pixels across whatever the frame: fov widens with the frame.
    path = bench_scenes.sphere(b.scene_dir, 64)
    for n in sizes:
        fov = 2 * math.degrees(math.atan(0.36 * n / 256))
        ms, frags, tris, cmd = host_ms(b, path, n, n, reps, f"eye=0,0,4,at=0,0,0,fov={fov:.3f}")
        rows.append(("frame", n * n, tris, frags, ms, shlex.join(cmd)))
    # The planes alone, allocated and cleared: what grows with the frame whatever is drawn.
    med, cmd = b.google_benchmark(b.exe("zblend_bench"), "BM_FrameBuffers", reps)
    clear = {int(name.split("/")[1]): r["real_time"] for name, r in med.items()}
    for n in sizes:
        if n in clear:
            rows.append(("clear", n * n, 0, 0, clear[n], shlex.join(cmd)))
    path = os.path.join(b.out, "growth.csv")
    with open(path + ".tmp", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["sweep", "pixels", "triangles", "fragments", "host_ms", "command"])
        w.writerows(rows)
    os.replace(path + ".tmp", path)
    chart = os.path.join(os.path.dirname(os.path.abspath(__file__)), "bench_charts.py")
    subprocess.run(["/usr/bin/python3", chart, path, os.path.join(b.out, "growth.png")],
                   check=True)
    first, last = rows[0], rows[len(sizes) - 1]
    b.add(f"growth, bunny-glass {sizes[0]}^2 to {sizes[-1]}^2: time ratio (pixels x"
          f"{last[1] / first[1]:.0f}, fragments x{last[3] / first[3]:.0f})",
          last[4] / first[4], "x", "", "see growth.csv")
    fr = [r for r in rows if r[0] == "frame"]
    b.add(f"growth, fixed object in a frame {sizes[0]}^2 to {sizes[-1]}^2: time ratio "
          f"(fragments x{fr[-1][3] / fr[0][3]:.2f})", fr[-1][4] / fr[0][4], "x", "",
          "see growth.csv")
    b.add(f"fixed object in {fr[-1][1]} pixels: render time", fr[-1][4], "ms", "", fr[-1][5])
    if sizes[-1] in clear:
        b.add(f"of which allocating and clearing the {sizes[-1]}^2 planes", clear[sizes[-1]], "ms",
              "", cmd)


# The host side against a baseline commit: a golden render and a golden-only lab.
HOST_RENDER = ["render", "-q", "-s", "cad", "-W", "640", "-H", "480", "-m", METHOD]
HOST_LAB = ["lab", "-q", "--no-rtl", "--no-charts", "-j", "1",
            "--scenes", "cad,parts,layers-4-a50,crossing-quads,bunny"]


def wall_s(b, cmd):
    start = time.perf_counter()
    b.run(cmd)
    return time.perf_counter() - start


def host_against_baseline(b, baseline, reps):
    """Median wall time of each command on both builds, alternated; the ratio this / baseline."""
    with open(os.path.join(baseline, "..", "rev")) as f:
        base = f.read().strip()[:7]
    out = os.path.join(b.out, "host")
    os.makedirs(out, exist_ok=True)
    for name, args, n in [("zblend render (golden), cad three-pass 640x480", HOST_RENDER
                           + ["--out", os.path.join(out, "render.png")], 5 * reps),
                          ("zblend lab, golden only, 5 scenes", HOST_LAB
                           + ["--out-dir", os.path.join(out, "lab")], reps)]:
        times = {"this": [], "base": []}
        for _ in range(n):
            for who, build in (("base", baseline), ("this", b.build)):
                times[who].append(wall_s(b, [os.path.join(build, "zblend")] + args))
        this, then = statistics.median(times["this"]), statistics.median(times["base"])
        cmd = shlex.join(["zblend"] + args)

        def spread(runs):
            return f"runs {min(runs):.4g} to {max(runs):.4g} s"
        b.add(f"{name}: this build, median of {n} ({spread(times['this'])})", this, "s", "", cmd)
        b.add(f"{name}: baseline {base}, alternated with it ({spread(times['base'])})", then, "s",
              "", cmd)
        b.add(f"{name}: this build / baseline {base}", this / then, "x", "1 within noise", cmd)


def number(value, unit):
    """Four significant digits; six for percentages, which live near 100."""
    return f"{value:.6g}" if unit == "%" else f"{value:.4g}"


def write_table(b, started):
    machine = f"{platform.node()}, {os.cpu_count()} cores, {platform.platform()}"
    path = os.path.join(b.out, "bench.csv")
    with open(path + ".tmp", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["figure", "value", "unit", "target", "command"])
        for r in b.rows:
            w.writerow([r[0], f"{r[1]:.6g}", r[2], r[3], r[4]])
    os.replace(path + ".tmp", path)
    lines = [f"zblend bench, {started}, {machine}", "",
             "| figure | value | unit | target | command |", "|---|---|---|---|---|"]
    for fig, val, unit, target, cmd in b.rows:
        lines.append(f"| {fig} | {number(val, unit)} | {unit} | {target} | `{cmd}` |")
    text = "\n".join(lines) + "\n"
    with open(os.path.join(b.out, "bench.md"), "w") as f:
        f.write(text)
    width = max(len(r[0]) for r in b.rows)
    print(f"\n{'figure':<{width}}  {'value':>10}  unit / target")
    for fig, val, unit, target, _ in b.rows:
        print(f"{fig:<{width}}  {number(val, unit):>10}  {unit}"
              f"{'  (target ' + target + ')' if target else ''}")
    print(f"\ncommands: {path}; table: {os.path.join(b.out, 'bench.md')}")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--build", default="build", help="build directory (default: build)")
    ap.add_argument("--out", default="out/bench", help="output directory (default: out/bench)")
    ap.add_argument("--baseline", help="the build directory of a baseline commit "
                    "(scripts/bench_baseline.sh), measured beside this one")
    ap.add_argument("--pgo", help="a build directory of scripts/pgo.sh (the speed build with "
                    "PGO), measured beside this one")
    ap.add_argument("--quick", action="store_true", help="fewer repetitions and sizes")
    ap.add_argument("--only", choices=["maps", "vp"],
                    help="one step alone: maps (6, the error maps' cost), vp (the virtual "
                    "platform's speed, in 4)")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    b = Bench(a.build, a.out)
    b.scene_dir = os.path.join(a.out, "scenes")
    os.makedirs(b.scene_dir, exist_ok=True)
    started = time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime())
    reps = 1 if a.quick else 3
    if a.only == "maps":
        step(6, "error maps: render with and without them")
        bench_maps.maps(b, 5 if a.quick else 15)
        write_table(b, started)
        return
    if a.only == "vp":
        step(4, "the virtual platform against zblend render")
        bench_vp.vp(b, 3 if a.quick else 7)
        write_table(b, started)
        return
    scene = bench_scenes.bunny_glass(b.scene_dir)
    step(1, "golden datapath per blend mode")
    datapath(b, reps)
    step(2, f"bunny-glass {SIZE}x{SIZE} {METHOD}: golden model against llvmpipe")
    frame(b, scene, 3 if a.quick else 9)
    step(3, "peak memory")
    memory(b, scene)
    step(4, "RTL simulation")
    bench_rtl.speed(b, reps, a.baseline, a.pgo)
    rtl(b, reps)
    render_rtl(b, reps)
    cosim(b)
    bench_vp.vp(b, 3 if a.quick else 7)
    step(5, "cost growth")
    growth(b, scene, reps, a.quick)
    step(6, "error maps: render with and without them")
    bench_maps.maps(b, 5 if a.quick else 15)
    if a.baseline:
        step(7, "render and lab against the baseline")
        host_against_baseline(b, a.baseline, 3 if a.quick else 5)
    write_table(b, started)


if __name__ == "__main__":
    main()
