#!/usr/bin/env python3
"""Two or more zblend_bench_rtl binaries against each other on the hazard stream, interleaved
(A, B, A, B, ...) so that the machine's drift falls on all of them alike (docs/bench.md).

Usage: bench_ab.py [-n RUNS] BENCH_A BENCH_B [...]
Prints each binary's median M cycles/s over RUNS runs (default 5) and its ratio to the first.
Copy a binary aside before rebuilding to keep it as A.
"""
import argparse
import json
import statistics
import subprocess
import sys


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("-n", "--runs", type=int, default=5, help="runs of each (default 5)")
    ap.add_argument("bench", nargs="+", help="zblend_bench_rtl binaries, the first the reference")
    a = ap.parse_args()
    if len(a.bench) < 2 or a.runs < 1:
        ap.error("give two binaries or more and at least one run")
    speed = {exe: [] for exe in a.bench}
    for r in range(a.runs):
        for exe in a.bench:
            cmd = [exe, "--benchmark_filter=BM_RtlHazard", "--benchmark_format=json"]
            proc = subprocess.run(cmd, capture_output=True, text=True)
            if proc.returncode != 0:
                sys.exit(f"bench_ab: error: `{' '.join(cmd)}` exited {proc.returncode}:\n"
                         f"{proc.stderr}")
            run = json.loads(proc.stdout)["benchmarks"][0]
            speed[exe].append(run["cycles_per_second"] / 1e6)
        print(f"bench_ab: run {r + 1} of {a.runs}", file=sys.stderr)
    first = statistics.median(speed[a.bench[0]])
    for exe in a.bench:
        m = statistics.median(speed[exe])
        runs = " ".join(f"{v:.2f}" for v in speed[exe])
        print(f"{m:7.3f} M cycles/s  x{m / first:.3f}  {exe}  ({runs})")


if __name__ == "__main__":
    main()
