#!/usr/bin/env python3
"""Two or more zblend_oracle binaries against each other on one frame, alternated (A, B, A, B,
...) so that the machine's drift falls on all alike (docs/bench.md): each binary's median golden
and llvmpipe frame times, its median llvmpipe / golden, and the median of its golden time's
pair-by-pair ratio to the first binary's.

Usage: oracle_ab.py [-n ROUNDS] [--repeat N] --scene S [--method M] [--size WxH] ORACLE_A ORACLE_B [...]
Build the older commit's oracle in a worktree (cmake --build B --target zblend_oracle) and give
it first.
"""
import argparse
import os
import re
import statistics
import subprocess
import sys
import tempfile


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("-n", "--rounds", type=int, default=8, help="rounds of each (default 8)")
    ap.add_argument("--repeat", type=int, default=15, help="frames timed a run (default 15)")
    ap.add_argument("--scene", required=True, help="a scene (bunny-glass: scripts/bench_scenes.py)")
    ap.add_argument("--method", default="three-pass")
    ap.add_argument("--size", default="1024x1024")
    ap.add_argument("oracle", nargs="+", help="zblend_oracle binaries, the first the reference")
    a = ap.parse_args()
    if len(a.oracle) < 2 or a.rounds < 1:
        ap.error("give two binaries or more and at least one round")
    w, _, h = a.size.partition("x")
    row = re.compile(r"^" + re.escape(a.method) + r"\s+([\d.]+)\s+([\d.]+)\s+([\d.]+)\s*$")
    got = {o: [] for o in a.oracle}
    with tempfile.TemporaryDirectory() as tmp:
        for r in range(a.rounds):
            for o in a.oracle:
                cmd = [o, "--scene", a.scene, "--method", a.method, "--width", w, "--height", h,
                       "--time", "--repeat", str(a.repeat), "--out-dir", os.path.join(tmp, "o")]
                p = subprocess.run(cmd, capture_output=True, text=True)
                m = [row.match(ln) for ln in p.stdout.splitlines()]
                m = [x for x in m if x]
                if p.returncode != 0 or not m:
                    sys.exit(f"oracle_ab: error: `{' '.join(cmd)}` exited {p.returncode}, no "
                             f"timing row:\n{p.stdout[-2000:]}{p.stderr[-2000:]}")
                got[o].append(tuple(float(x) for x in m[-1].groups()))
            print(f"oracle_ab: round {r + 1} of {a.rounds}", file=sys.stderr, flush=True)
    ref = got[a.oracle[0]]
    print("binary, golden ms (median), llvmpipe ms (median), llvmpipe/golden (median), "
          "golden / first's (median of pairs)")
    for o in a.oracle:
        v = got[o]
        pairs = statistics.median(x[0] / y[0] for x, y in zip(v, ref))
        print(f"{o}, {statistics.median(x[0] for x in v):.2f}, {statistics.median(x[1] for x in v):.2f}, "
              f"{statistics.median(x[2] for x in v):.3f}, {pairs:.3f}")


if __name__ == "__main__":
    main()
