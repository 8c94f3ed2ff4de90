"""The RTL simulation's speed in `make bench` (bench.py step 4, docs/bench.md): both builds of
zb_rop against Verilator's ceiling, the RTL against the golden model in CPU time, and, beside
every figure, the same run of a baseline build (scripts/bench_baseline.sh) in the same bench:
ratios measured side by side, never against figures of another day."""
import json
import os
import statistics
import time

CAD = ["--scene", "cad", "-W", "640", "-H", "480"]


def hazard(b, exe, reps):
    """Hazard stream M cycles/s and Verilator's ceiling M cycles/s of one zblend_bench_rtl."""
    cmd = [exe, "--benchmark_filter=BM_RtlHazard|BM_VerilatorCeiling",
           f"--benchmark_repetitions={reps}", "--benchmark_report_aggregates_only=true",
           "--benchmark_format=json"]
    runs = json.loads(b.run(cmd))["benchmarks"]
    med = {r["run_name"].split("/")[0]: r for r in runs
           if r.get("aggregate_name", "median") == "median"}
    return (med["BM_RtlHazard"]["cycles_per_second"] / 1e6,
            med["BM_VerilatorCeiling"]["cycles_per_second"] / 1e6, cmd)


def cpu_seconds(b, cmd, reps):
    """Median over reps of the whole process's CPU time (user + system) and its wall time."""
    cpu, wall = [], []
    for _ in range(reps):
        t0 = time.perf_counter()
        usage = b.run_usage(cmd)
        wall.append(time.perf_counter() - t0)
        cpu.append(usage.ru_utime + usage.ru_stime)
    return statistics.median(cpu), statistics.median(wall)


def speed(b, reps, baseline):
    """Adds the rows; baseline: a build directory of another commit, or None."""
    builds = [("speed build", b.exe("zblend_bench_rtl")),
              ("assertion build", b.exe("zblend_bench_rtl_assert"))]
    base = None
    if baseline:
        rev = open(os.path.join(baseline, "..", "rev")).read().strip()[:7]
        base = (f"baseline {rev}", os.path.join(baseline, "zblend_bench_rtl"))
        builds.append(base)
    cycles = {}
    for name, exe in builds:
        sim, ceiling, cmd = hazard(b, exe, reps)
        cycles[name] = sim
        b.add(f"RTL simulation, hazard stream, {name} (Verilator's ceiling in the same run "
              f"{ceiling:.1f} M cycles/s: {100 * sim / ceiling:.1f} % of it)", sim, "M cycles/s",
              "", cmd)
    if base:
        b.add(f"RTL simulation, hazard stream: speed build / {base[0]}",
              cycles["speed build"] / cycles[base[0]], "x", ">= 3.5", "the two rows above")

    zblends = [("", b.exe("zblend"))]
    if baseline:
        zblends.append((base[0], os.path.join(baseline, "zblend")))
    out = ["--out", os.path.join(b.out, "cpu.png")]
    for method, target in (("three-pass", "<= 5"), ("depth-peel-4", "<= 12")):
        wall = {}
        for name, zb in zblends:
            golden = [zb, "render"] + CAD + ["-m", method, "--no-error", "-q"] + out
            rtl = golden + ["--backend", "rtl"]
            g_cpu, _ = cpu_seconds(b, golden, reps)
            r_cpu, wall[name] = cpu_seconds(b, rtl, reps)
            what = f" ({name})" if name else ""
            b.add(f"zblend render --backend rtl / golden, cad {method} 640x480, whole process "
                  f"CPU time{what}", r_cpu / g_cpu, "x", "" if name else target,
                  " ; ".join(" ".join(c) for c in (rtl, golden)))
        if baseline:
            b.add(f"zblend render --backend rtl, cad {method} 640x480, default threads, end to "
                  f"end: {base[0]} wall time / this build's", wall[base[0]] / wall[""], "x",
                  ">= 3", "the runs above")
