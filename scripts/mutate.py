#!/usr/bin/env python3
"""The checker's mutation score (make mutate, docs/mutation.md).

Usage: mutate.py [--build DIR] [--out DIR] [-j N] [--sample N | --mutants LIST]
                 [--group smoke|quick] [--no-full] [--min-smoke PCT] [--min-full PCT]

Runs zblend_tb_mut (zb_rop as Yosys's mutant netlist, build/mutation/) against the golden model:
  1. mutant 0 (the netlist unmutated) passes every test of both groups, or the run stops: a
     netlist that is not zb_rop scores nothing; its times set each test's time limit;
  2. each mutant runs the smoke group (tb/regressions.json: what make test runs) in order, and
     is killed at the first test that fails: a mismatch, an error, a crash or the time limit;
  3. each smoke survivor runs the full group (smoke's tests, then full's).
Score = killed / mutants, for smoke and for full: survivors are not yet sorted into equivalent
mutants and gaps in the checker (docs/mutation.md). Writes OUT/mutants.csv
(one row per mutant: its description, verdict, the test that killed it, the first report line),
OUT/summary.json and OUT/report.md, with progress on stderr. Exit 1 when a score is below its
minimum or mutant 0 fails; 2 on bad usage.
"""
import argparse
import concurrent.futures
import csv
import json
import os
import re
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
REPORT_LINE = re.compile(r"^(LOCKSTEP MISMATCH|MISMATCH|suite \S+ +FAIL|suite \S+: error|"
                         r"  X(4|11): rtl wrote|zblend_tb: )")


def usage_error(msg):
    print(f"mutate.py: {msg}", file=sys.stderr)
    sys.exit(2)


def load_groups(first):
    with open(os.path.join(ROOT, "tb", "regressions.json")) as f:
        groups = json.load(f)["groups"]
    return groups[first], groups[first] + groups["full"]


def parse_mutants(spec, count):
    out = []
    for part in spec.split(","):
        m = re.fullmatch(r"(\d+)(?:-(\d+))?", part.strip())
        if not m:
            usage_error(f"--mutants: '{part}' is not N or N-M")
        lo, hi = int(m.group(1)), int(m.group(2) or m.group(1))
        if not 1 <= lo <= hi <= count:
            usage_error(f"--mutants: {part} is outside 1..{count} (the netlist's mutants)")
        out.extend(range(lo, hi + 1))
    return sorted(set(out))


class Runner:
    def __init__(self, tb, limits):
        self.tb = tb
        self.limits = limits  # test name -> seconds

    def run_test(self, mutant, test, limit=None):
        """(passed, seconds, first report line or why)."""
        cmd = [self.tb, "--mutant", str(mutant), "-q", "--mismatch-fst", "",
               *test["args"]]
        t0 = time.monotonic()
        try:
            p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                               errors="replace",
                               timeout=limit or self.limits.get(test["name"]))
        except subprocess.TimeoutExpired:
            return False, time.monotonic() - t0, "time limit"
        sec = time.monotonic() - t0
        if p.returncode == 0:
            return True, sec, ""
        line = next((ln for ln in p.stdout.splitlines() if REPORT_LINE.match(ln)), "")
        if p.returncode < 0:
            line = f"signal {-p.returncode}"
        return False, sec, line.strip() or f"exit {p.returncode}"

    def run_group(self, mutant, tests):
        """(killed_by test name or '', seconds, report line)."""
        total = 0.0
        for t in tests:
            ok, sec, line = self.run_test(mutant, t)
            total += sec
            if not ok:
                return t["name"], total, line
        return "", total, ""


class Progress:
    def __init__(self, what, n):
        self.what, self.n, self.done, self.t0 = what, n, 0, time.monotonic()
        self.last = 0.0

    def step(self, killed):
        self.done += 1
        now = time.monotonic()
        if now - self.last < 5 and self.done != self.n:
            return
        self.last = now
        el = now - self.t0
        eta = el / self.done * (self.n - self.done)
        print(f"mutate: {self.what}: {self.done}/{self.n} mutants, {killed} killed, "
              f"{el:.0f} s, about {eta:.0f} s left", file=sys.stderr, flush=True)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--build", default="build", help="build tree (default build)")
    ap.add_argument("--out", default="out/mutate", help="output directory (default out/mutate)")
    ap.add_argument("-j", "--jobs", type=int, default=os.cpu_count() or 1)
    ap.add_argument("--sample", type=int, help="every k-th mutant, k = count / N: N of them")
    ap.add_argument("--mutants", help="mutants to run, e.g. 1-50,77 (default all)")
    ap.add_argument("--group", default="smoke", choices=["smoke", "quick"],
                    help="the first group (default smoke: what make test runs; quick: its "
                    "fast part, for the CI-sized sample)")
    ap.add_argument("--no-full", action="store_true", help="the first group only")
    ap.add_argument("--time-limit", type=float, default=0,
                    help="seconds: mutants not started by then are left out and the scores "
                    "cover those run (default: no limit); mutants run in an order spread over "
                    "the netlist")
    ap.add_argument("--min-smoke", type=float, default=0.0,
                    help="exit 1 below this smoke score, percent (default 0)")
    ap.add_argument("--min-full", type=float, default=0.0,
                    help="exit 1 below this full score, percent (default 0)")
    a = ap.parse_args()
    if a.jobs < 1:
        usage_error(f"-j {a.jobs}: 1 or more")
    tb = os.path.join(a.build, "zblend_tb_mut")
    listing = os.path.join(a.build, "mutation", "mutations.txt")
    for f in (tb, listing):
        if not os.path.exists(f):
            usage_error(f"{f} is missing: build it first (make build, or cmake --build "
                        f"{a.build} --target zblend_tb_mut)")
    with open(listing) as f:
        descriptions = [ln.strip() for ln in f if ln.strip()]
    count = len(descriptions)
    if a.sample is not None and a.mutants:
        usage_error("--sample and --mutants: choose one")
    if a.sample is not None:
        if not 1 <= a.sample <= count:
            usage_error(f"--sample {a.sample}: choose 1 to {count}")
        step = count / a.sample
        chosen = sorted({int(i * step) + 1 for i in range(a.sample)})
    elif a.mutants:
        chosen = parse_mutants(a.mutants, count)
    else:
        chosen = list(range(1, count + 1))
    smoke, full = load_groups(a.group)
    os.makedirs(a.out, exist_ok=True)

    # 1. The unmutated netlist passes everything; its times set the limits.
    runner = Runner(tb, {})
    limits = {}
    for t in (smoke if a.no_full else full):
        ok, sec, line = runner.run_test(0, t, limit=3600)
        print(f"mutate: mutant 0 (none): {t['name']}: {'pass' if ok else 'FAIL'} {sec:.1f} s",
              file=sys.stderr, flush=True)
        if not ok:
            print(f"mutate: FAILED: the unmutated netlist fails {t['name']}: {line}",
                  file=sys.stderr)
            return 1
        limits[t["name"]] = max(20.0, 5 * sec)
    runner.limits = limits

    rows = {m: {"mutant": m, "description": descriptions[m - 1], "smoke": "", "full": "",
                "killed_by": "", "report": "", "seconds": 0.0}
            for m in chosen}

    deadline = time.monotonic() + a.time_limit if a.time_limit > 0 else None

    def run_before_deadline(m, tests):
        if deadline is not None and time.monotonic() > deadline:
            return None
        return runner.run_group(m, tests)

    def stage(name, tests, mutants, column):
        prog = Progress(name, len(mutants))
        killed = 0
        with concurrent.futures.ThreadPoolExecutor(a.jobs) as pool:
            futs = {pool.submit(run_before_deadline, m, tests): m for m in mutants}
            for fut in concurrent.futures.as_completed(futs):
                m = futs[fut]
                if fut.result() is None:  # past --time-limit
                    rows[m][column] = "not run"
                    continue
                by, sec, line = fut.result()
                r = rows[m]
                r["seconds"] += sec
                r[column] = "killed" if by else "survived"
                if by:
                    killed += 1
                    r["killed_by"], r["report"] = by, line
                prog.step(killed)
        return [m for m in mutants if rows[m][column] == "survived"]

    t0 = time.monotonic()
    # A spread order, so that a time limit leaves out mutants from all over the netlist.
    order = sorted(chosen, key=lambda m: ((m - 1) * 7919) % count)
    survivors = stage(a.group, smoke, order, "smoke")
    if not a.no_full and survivors:
        survivors = stage("full", full[len(smoke):], survivors, "full")
    for m in chosen:
        if not a.no_full and rows[m]["smoke"] == "killed":
            rows[m]["full"] = "killed"
    asked = len(chosen)
    chosen = [m for m in chosen if rows[m]["smoke"] != "not run"]
    rows = {m: rows[m] for m in chosen}

    n = len(chosen)
    smoke_killed = sum(1 for r in rows.values() if r["smoke"] == "killed")
    full_killed = sum(1 for r in rows.values() if r["full"] == "killed")
    denom = max(1, n)
    summary = {
        "mutants": n, "netlist_mutants": count, "left_out_by_time_limit": asked - n,
        "smoke_killed": smoke_killed, "smoke_score": round(100 * smoke_killed / denom, 2),
        "seconds": round(time.monotonic() - t0, 1), "jobs": a.jobs,
        "group": a.group, "smoke_tests": [t["name"] for t in smoke],
    }
    if not a.no_full:
        summary.update(full_killed=full_killed,
                       full_score=round(100 * full_killed / denom, 2),
                       full_tests=[t["name"] for t in full])
    with open(os.path.join(a.out, "mutants.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(next(iter(rows.values())).keys()))
        w.writeheader()
        for m in chosen:
            r = dict(rows[m])
            r["seconds"] = round(r["seconds"], 2)
            w.writerow(r)
    with open(os.path.join(a.out, "summary.json"), "w") as f:
        json.dump(summary, f, indent=2)
    write_report(os.path.join(a.out, "report.md"), summary, rows, chosen)

    line = (f"mutate: {n} mutants; {a.group} killed {smoke_killed} "
            f"({summary['smoke_score']} %)")
    if not a.no_full:
        line += f"; full killed {full_killed} ({summary['full_score']} %)"
    print(line + f"; {summary['seconds']} s; {a.out}/report.md")
    low = summary["smoke_score"] < a.min_smoke or (
        not a.no_full and summary["full_score"] < a.min_full)
    if low:
        print(f"mutate: FAILED: score below --min-smoke {a.min_smoke} / --min-full {a.min_full}",
              file=sys.stderr)
    return 1 if low else 0


def write_report(path, s, rows, chosen):
    by_test = {}
    for r in rows.values():
        if r["killed_by"]:
            by_test[r["killed_by"]] = by_test.get(r["killed_by"], 0) + 1
    lines = ["# Mutation score", "",
             f"{s['mutants']} mutants of zb_rop (of the netlist's {s['netlist_mutants']}; "
             f"{s['left_out_by_time_limit']} left out by --time-limit).", "",
             "| group | killed | score |", "|---|---|---|",
             f"| {s['group']} | {s['smoke_killed']} | {s['smoke_score']} % |"]
    if "full_score" in s:
        lines.append(f"| full | {s['full_killed']} | {s['full_score']} % |")
    lines += ["", "Kills by the test that made them first:", ""]
    lines += [f"- {t}: {k}" for t, k in sorted(by_test.items(), key=lambda x: -x[1])]
    survivors = [rows[m] for m in chosen if not rows[m]["killed_by"]]
    lines += ["", f"## Survivors ({len(survivors)})", ""]
    lines += [f"- mutant {r['mutant']}: `{r['description']}`" for r in survivors]
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    sys.exit(main())
