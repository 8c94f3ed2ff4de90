#!/usr/bin/env python3
"""The conformance suite's strength: the suite alone as a test group on zb_rop's mutants
(make conformance-mutate; docs/conformance.md "The suite's strength").

  conformance_mutate.py --build DIR --suite DIR --out DIR [-j N] [--sample N | --mutants LIST]
                        [--resume]

The mutants are the mutation tool's sample (docs/mutation.md: build/tb/mutation/mutants.v, one
netlist with every mutant behind +zb_mutant=N, at the build's widths). The kit's testbench is
built once around that netlist with zb_rop's adapter (scripts/conformance.py, mutant 0, which
must pass every test it runs), then every mutant runs the suite's tests of the netlist's own
configuration (d24-c16: the netlist has one set of widths), the quick tier first, and is killed
by the first test whose signatures differ from the suite's, whose simulation fails (a protocol
violation, the watchdog, an error) or runs past five times its mutant-0 time (at least 10 s).
The score is the kills over the mutants not proven equivalent to zb_rop (the mutation report's
list, docs/reports/mutation_report.md "Proven equivalent"). Writes OUT/mutants.csv,
OUT/summary.json and OUT/report.md; every verdict goes to OUT/journal.jsonl as it comes, and
--resume keeps them. Exit 0 when the score is at least --target, 1 below it, 2 on bad input.
"""
import argparse
import concurrent.futures
import csv
import filecmp
import json
import os
import re
import subprocess
import sys
import time

from mutate import Journal, choose_mutants
from zbscript import ROOT, Progress, usage_error

CONFIG = "d24-c16"  # the mutant netlist's widths (a default build's)
STAGE = "conformance"  # the journal's stage (mutate.py's journal format)
PLANES = ("color", "depth", "coverage", "peel", "accum")


def parse_args():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter,
                                 epilog=__doc__.split("\n\n", 1)[1])
    ap.add_argument("--build", default=os.path.join(ROOT, "build"),
                    help="the tree with tb/mutation/mutants.v and zblend (default build/)")
    ap.add_argument("--suite", required=True, help="an exported suite (zblend conformance export)")
    ap.add_argument("--out", required=True)
    ap.add_argument("-j", "--jobs", type=int, default=os.cpu_count() or 1)
    ap.add_argument("--sample", type=int, help="every k-th mutant, k = count / N: N of them")
    ap.add_argument("--mutants", help="mutants to run, e.g. 1-50,77 (default all)")
    ap.add_argument("--equivalent", default=os.path.join(ROOT, "docs", "reports",
                                                         "mutation_report.md"),
                    help="the mutation report whose 'Proven equivalent' list leaves the score")
    ap.add_argument("--target", type=float, default=95.0, help="the score to reach (percent)")
    ap.add_argument("--resume", action="store_true", help="keep OUT/journal.jsonl's verdicts")
    a = ap.parse_args()
    if a.jobs < 1:
        usage_error(f"-j {a.jobs}: at least 1")
    return a


def count_mutants(build):
    path = os.path.join(build, "tb", "mutation", "mutations.txt")
    try:
        with open(path) as f:
            lines = [ln.rstrip("\n") for ln in f if ln.strip()]
    except OSError as e:
        usage_error(f"{path}: {e.strerror} (build the tree: cmake --build {build})")
    return lines


def proven_equivalent(path):
    """The mutant numbers under the report's 'Proven equivalent' heading."""
    out, inside = set(), False
    try:
        with open(path) as f:
            for ln in f:
                if ln.startswith("## "):
                    inside = ln.startswith("## Proven equivalent")
                elif inside:
                    m = re.match(r"- mutant (\d+):", ln)
                    if m:
                        out.add(int(m.group(1)))
    except OSError as e:
        usage_error(f"--equivalent {path}: {e.strerror}")
    return out


def instance_of(description):
    """The zb_rop instance a mutation's cell sits in ("u_depth.u_cov_plane"), or "zb_rop"."""
    m = re.search(r"-cell \$flatten((?:\\u_[a-z_0-9]+\.)+)", description)
    return m.group(1).replace("\\", "").rstrip(".") if m else "zb_rop"


def build_testbench(a):
    """conformance.py on mutant 0 over the configuration's tests: builds the testbench around
    the netlist and proves the unmutated netlist passes; returns (binary, {test: seconds})."""
    mut = os.path.join(a.build, "tb", "mutation", "mutants.v")
    dut = [os.path.join(ROOT, "rtl", "zb_pkg.sv"), mut,
           os.path.join(ROOT, "tb", "mutation", "zb_rop_mutant.sv"),
           os.path.join(ROOT, "conformance", "sv", "zb_conf_adapter.sv")]
    base = os.path.join(a.out, "mutant0")
    with open(os.path.join(a.suite, "manifest.json")) as f:
        # The netlist is zb_rop without the layers unit (docs/mutation.md): no layers tests.
        tests = [t for t in json.load(f)["tests"]
                 if t["config"] == CONFIG and "blend.layers" not in t["features"]]
    cmd = [sys.executable, os.path.join(ROOT, "scripts", "conformance.py"), "--suite", a.suite,
           "--sim", "verilator", "--out", base, "-j", str(a.jobs), "--define", "ZB_CONF_NO_LAYERS",
           "--dut"] + dut + [
           "--tests", ",".join(t["name"] for t in tests),
           "--zblend", os.path.join(a.build, "zblend")]
    print(f"conformance-mutate: mutant 0 (the netlist unmutated) on {len(tests)} tests",
          file=sys.stderr, flush=True)
    p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    with open(os.path.join(a.out, "mutant0.log"), "w") as f:
        f.write(p.stdout)
    if p.returncode != 0:
        print(p.stdout[-3000:], file=sys.stderr)
        print("conformance-mutate: mutant 0 does not pass the suite: nothing can be scored",
              file=sys.stderr)
        sys.exit(1)
    with open(os.path.join(base, "results.json")) as f:
        secs = {r["name"]: r["seconds"] for r in json.load(f)["tests"]}
    binary = os.path.join(base, "build", f"verilator-{CONFIG}", "zb_conf_tb")
    quick = [t["name"] for t in tests if t.get("tier") == "quick"]
    order = quick + [t["name"] for t in tests if t["name"] not in quick]
    return binary, secs, order


def run_mutant(n, a, binary, order, secs):
    """Runs mutant n's tests until one kills it: (n, killed by or "", why, seconds)."""
    t0 = time.time()
    d = os.path.join(a.out, "runs", str(n))
    os.makedirs(d, exist_ok=True)
    for name in order:
        for plane in PLANES:
            try:
                os.remove(os.path.join(d, f"got.{plane}.hex"))
            except FileNotFoundError:
                pass
        cmd = [binary, f"+stream={os.path.join(a.suite, name, 'stream.hex')}", f"+out={d}",
               "+timing=0", "+resident=1", "+gap=0", "+seed=1", f"+zb_mutant={n}"]
        limit = max(10.0, 5 * secs[name])
        try:
            p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                               timeout=limit)
        except subprocess.TimeoutExpired:
            return n, name, f"past the time limit ({limit:.0f} s)", time.time() - t0
        done = any(ln.startswith("zb_conf: done:") for ln in p.stdout.splitlines())
        if p.returncode != 0 or not done:
            first = next((ln for ln in p.stdout.splitlines() if ln.startswith(
                ("zb_conf: PROTOCOL", "zb_conf: WATCHDOG", "zb_conf: FAILED", "%Error"))),
                f"exit {p.returncode}")
            return n, name, first, time.time() - t0
        for plane in PLANES:
            got = os.path.join(d, f"got.{plane}.hex")
            want = os.path.join(a.suite, name, f"expect.{plane}.hex")
            if not os.path.exists(got) or not filecmp.cmp(got, want, shallow=False):
                return n, name, f"{plane} plane differs", time.time() - t0
    return n, "", "", time.time() - t0


def main():
    a = parse_args()
    descriptions = count_mutants(a.build)
    chosen = choose_mutants(a, len(descriptions))
    equivalent = proven_equivalent(a.equivalent)
    a.suite, a.out = os.path.abspath(a.suite), os.path.abspath(a.out)
    os.makedirs(a.out, exist_ok=True)
    # mutate.py's journal: on --resume it refuses verdicts of another netlist.
    journal = Journal(a.out, descriptions, a.resume)
    verdicts = {m: e for (m, stage), e in journal.done.items() if stage == STAGE}
    binary, secs, order = build_testbench(a)
    todo = [n for n in chosen if n not in verdicts]
    print(f"conformance-mutate: {len(todo)} mutants to run ({len(chosen) - len(todo)} kept), "
          f"{len(order)} tests each at most, -j {a.jobs}", file=sys.stderr, flush=True)
    prog = Progress("conformance-mutate", todo, jobs=a.jobs, every=30)
    with concurrent.futures.ThreadPoolExecutor(a.jobs) as pool:
        futures = [pool.submit(run_mutant, n, a, binary, order, secs) for n in todo]
        for f in concurrent.futures.as_completed(futures):
            n, by, why, s = f.result()
            r = {"mutant": n, "description": descriptions[n - 1], "stage": STAGE,
                 "killed_by": by, "why": why, "seconds": round(s, 2)}
            verdicts[n] = r
            journal.record(r)
            prog.step(n, lambda p: f"{p.done} of {p.n} in {p.elapsed:.0f} s, about "
                                   f"{p.left:.0f} s left")
    rows = [verdicts[n] for n in chosen]
    scored = [r for r in rows if r["mutant"] not in equivalent]
    killed = [r for r in scored if r["killed_by"]]
    survivors = [r for r in scored if not r["killed_by"]]
    pct = 100.0 * len(killed) / max(len(scored), 1)
    kills = {}
    for r in killed:
        kills[r["killed_by"]] = kills.get(r["killed_by"], 0) + 1
    summary = {"mutants": len(chosen), "proven_equivalent": len(chosen) - len(scored),
               "scored": len(scored), "killed": len(killed), "survivors": len(survivors),
               "score_pct": round(pct, 2), "target_pct": a.target, "config": CONFIG,
               "tests": len(order), "kills_by_test": kills,
               "survivors_by_instance": {}}
    for r in survivors:
        place = instance_of(descriptions[r["mutant"] - 1])
        summary["survivors_by_instance"][place] = summary["survivors_by_instance"].get(place, 0) + 1
    with open(os.path.join(a.out, "summary.json"), "w") as f:
        json.dump(summary, f, indent=1)
    with open(os.path.join(a.out, "mutants.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["mutant", "equivalent", "killed_by", "why", "seconds", "description"])
        for r in rows:
            w.writerow([r["mutant"], r["mutant"] in equivalent, r["killed_by"], r["why"],
                        r["seconds"], descriptions[r["mutant"] - 1]])
    with open(os.path.join(a.out, "report.md"), "w") as f:
        f.write(f"# The conformance suite on zb_rop's mutants\n\n{len(killed)} of {len(scored)} "
                f"mutants not proven equivalent killed ({pct:.1f} %; target {a.target} %), "
                f"{len(order)} tests of {CONFIG}, {len(chosen)} mutants run.\n\n"
                "## Kills by first test\n\n")
        for t, k in sorted(kills.items(), key=lambda kv: -kv[1]):
            f.write(f"- {t}: {k}\n")
        by_place = {}
        for r in survivors:
            by_place.setdefault(instance_of(descriptions[r["mutant"] - 1]), []).append(r)
        f.write(f"\n## Survivors ({len(survivors)}) by where they sit\n\n")
        for place, rs in sorted(by_place.items(), key=lambda kv: -len(kv[1])):
            f.write(f"- {place}: {len(rs)}\n")
        for place, rs in sorted(by_place.items(), key=lambda kv: -len(kv[1])):
            f.write(f"\n### {place} ({len(rs)})\n\n")
            for r in rs:
                f.write(f"- mutant {r['mutant']}: `{descriptions[r['mutant'] - 1]}`\n")
    print(f"conformance-mutate: {len(killed)} of {len(scored)} mutants not proven equivalent "
          f"killed: {pct:.1f} % (target {a.target} %); {len(survivors)} survivors; report "
          f"{os.path.join(a.out, 'report.md')}")
    return 0 if pct >= a.target else 1


if __name__ == "__main__":
    sys.exit(main())
