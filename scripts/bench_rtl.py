"""The RTL simulation's speed in `make bench` (bench.py step 4, docs/bench.md): both builds of
zb_rop against Verilator's ceiling, the RTL against the golden model in CPU time, and, beside
every figure, the same runs of a baseline build (scripts/bench_baseline.sh) and of the speed build
with PGO (scripts/pgo.sh) in the same bench: ratios measured side by side, never against
figures of another day."""
import json
import os
import re
import shlex
import shutil
import statistics
import subprocess
import time

CAD = ["--scene", "cad", "-W", "640", "-H", "480"]


def hazard(b, exe, reps):
    """Hazard stream M cycles/s and Verilator's ceiling M cycles/s of one zblend_bench_rtl."""
    med, cmd = b.google_benchmark(exe, "BM_RtlHazard|BM_VerilatorCeiling", reps)
    med = {name.split("/")[0]: r for name, r in med.items()}
    return (med["BM_RtlHazard"]["cycles_per_second"] / 1e6,
            med["BM_VerilatorCeiling"]["cycles_per_second"] / 1e6, cmd)


def instructions(b, exe):
    """Instructions one iteration of BM_RtlHazard takes under valgrind's cachegrind (its
    whole process), and its fragments per clock: a count that does not move with the machine's
    load, so two builds' ratio is exact where their wall clocks are not. None without
    valgrind."""
    if not shutil.which("valgrind"):
        return None
    cmd = ["valgrind", "--tool=cachegrind", "--cache-sim=no", "--cachegrind-out-file=/dev/null",
           exe, "--benchmark_filter=BM_RtlHazard", "--benchmark_min_time=0",
           "--benchmark_format=json"]
    proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    refs = re.search(r"I\s+refs:\s+([\d,]+)", proc.stderr)
    if proc.returncode != 0 or not refs:
        raise SystemExit(f"bench: error: `{shlex.join(cmd)}` exited {proc.returncode}:\n"
                         f"{proc.stderr[-2000:]}")
    run = json.loads(proc.stdout)["benchmarks"][0]
    if run["iterations"] != 1:
        raise SystemExit(f"bench: error: `{shlex.join(cmd)}` ran {run['iterations']} iterations, "
                         "not one")
    return int(refs.group(1).replace(",", "")), run["fragments_per_clock"], cmd


def cpu_seconds(b, cmd, reps):
    """Median over reps of the whole process's CPU time (user + system) and its wall time."""
    cpu, wall = [], []
    for _ in range(reps):
        t0 = time.perf_counter()
        usage = b.run_usage(cmd)
        wall.append(time.perf_counter() - t0)
        cpu.append(usage.ru_utime + usage.ru_stime)
    return statistics.median(cpu), statistics.median(wall)


def speed(b, reps, baseline, pgo):
    """Adds the rows; baseline: a build directory of another commit, or None; pgo: a build
    directory of scripts/pgo.sh, or None."""
    def exe(build, name):
        path = os.path.join(build, name)
        if not os.access(path, os.X_OK):
            raise SystemExit(f"bench: error: {path} is missing (make bench builds it)")
        return path

    this, with_pgo = "speed build", "speed build with PGO"
    builds = [(this, b.exe("zblend_bench_rtl"))]
    zblends = [(this, b.exe("zblend"))]
    if pgo:
        builds.append((with_pgo, exe(pgo, "zblend_bench_rtl")))
        zblends.append((with_pgo, exe(pgo, "zblend")))
    builds.append(("assertion build", b.exe("zblend_bench_rtl_assert")))
    base = None
    if baseline:
        with open(os.path.join(baseline, "..", "rev")) as f:
            base = f"baseline {f.read().strip()[:7]}"
        builds.append((base, exe(baseline, "zblend_bench_rtl")))
        zblends.append((base, exe(baseline, "zblend")))
    ours = [name for name, _ in zblends if name != base]

    cycles = {}
    for name, path in builds:
        sim, ceiling, cmd = hazard(b, path, reps)
        cycles[name] = sim
        b.add(f"RTL simulation, hazard stream, {name} (Verilator's ceiling in the same run "
              f"{ceiling:.1f} M cycles/s: {100 * sim / ceiling:.1f} % of it)", sim, "M cycles/s",
              "", cmd)
    if base:
        for name in ours:
            b.add(f"RTL simulation, hazard stream: {name} / {base}", cycles[name] / cycles[base],
                  "x", ">= 3.5", "the rows above")
        # The same stimulus and cycles on both builds: their instructions' ratio is the ratio
        # per simulated cycle, free of the machine's load.
        this_count, base_count = instructions(b, builds[0][1]), instructions(b, builds[-1][1])
        if this_count and base_count:
            if this_count[1] != base_count[1]:
                raise SystemExit(f"bench: error: the hazard stream takes {1 / this_count[1]:.4f} "
                                 f"cycles a fragment on the {this}, {1 / base_count[1]:.4f} on "
                                 f"{base}: instructions per cycle need the same cycles")
            for (name, count) in ((this, this_count), (base, base_count)):
                b.add(f"RTL simulation, hazard stream, {name}: instructions, one iteration "
                      "(valgrind, whole process)", count[0] / 1e9, "G", "", count[2])
            b.add(f"RTL simulation, hazard stream: instructions per simulated cycle, {this} / "
                  f"{base}", this_count[0] / base_count[0], "x", "<= 1", "the rows above")

    out = ["--out", os.path.join(b.out, "cpu.png")]
    # The golden render takes a few tens of ms of CPU, start-up included: its ratio moves from
    # run to run, so these take the median of at least five.
    cpu_reps = max(reps, 5)
    for method, target in (("three-pass", "<= 5"), ("depth-peel-4", "<= 12")):
        wall = {}
        for name, zb in zblends:
            golden = [zb, "render"] + CAD + ["-m", method, "--no-error", "-q"] + out
            g_cpu, _ = cpu_seconds(b, golden, cpu_reps)
            # Both schedules of the RTL driver (docs/rtl.md "Schedules"); a baseline from before
            # them runs its one (pass-major), the like of this build's pass schedule.
            for schedule in ((None,) if name == base else ("pass", "tile")):
                rtl = golden + ["--backend", "rtl"] + (["--schedule", schedule] if schedule else [])
                r_cpu, w = cpu_seconds(b, rtl, cpu_reps)
                if schedule in (None, "pass"):
                    wall[name] = w
                what = f", {schedule} schedule" if schedule else ""
                b.add(f"zblend render --backend rtl / golden, cad {method} 640x480{what}, whole "
                      f"process CPU time ({name})", r_cpu / g_cpu, "x", "" if name == base else target,
                      " ; ".join(" ".join(c) for c in (rtl, golden)))
        if base:
            for name in ours:
                b.add(f"zblend render --backend rtl, cad {method} 640x480, default threads, end "
                      f"to end (pass schedule): {base} wall time / {name}'s", wall[base] / wall[name], "x",
                      ">= 3", "the runs above")
