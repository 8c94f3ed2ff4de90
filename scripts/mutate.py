#!/usr/bin/env python3
"""The checker's mutation score (make mutate, docs/mutation.md).

Usage: mutate.py [--build DIR] [--out DIR] [-j N] [--sample N | --mutants LIST]
                 [--group smoke|quick] [--no-equiv] [--no-full] [--resume]
                 [--min-smoke PCT] [--min-full PCT]

Runs zblend_tb_mut (zb_rop as Yosys's mutant netlist, build/tb/mutation/) against the golden model:
  1. mutant 0 (the netlist unmutated) passes every test of both groups, or the run stops: a
     netlist that is not zb_rop scores nothing; its times set each test's time limit;
  2. each mutant runs the smoke group (tb/regressions.json: what make test runs) in order, and
     is killed at the first test that fails: a mismatch, an error, a crash or the time limit;
  3. each smoke survivor goes to Yosys's equivalence flow (--equiv-scope: on its cell's module
     and that module's parent, scripts/mutant_equiv_local.py; on the whole zb_rop,
     scripts/mutant_equiv.sh): one proven equivalent to zb_rop can be killed by no test and
     leaves the score (but for those whose written reason, --reasons, says they differ);
  4. each survivor not proven equivalent runs the full group (smoke's tests, then full's); one
     with a written reason counts as a survivor without the run, unless --full-all.
Score = killed / (mutants - proven equivalent), for smoke and for full. Writes OUT/mutants.csv
(one row per mutant: its description, verdict, the test that killed it, the first report line),
OUT/summary.json and OUT/report.md, with progress on stderr. Each verdict is also appended to
OUT/journal.jsonl as it comes, so --resume carries an interrupted run on (with OUT's copy of
the testbench, so that a rebuild meanwhile changes nothing). Exit 1 when a score
is below its minimum, mutant 0 fails or a test kills a mutant that a written reason says no
test can kill; 2 on bad usage.
"""
import argparse
import concurrent.futures
import csv
import json
import os
import re
import shutil
import subprocess
import sys
import time

import regressions
from mutant_reasons import KINDS, Reasons
from zbscript import ROOT, Progress, usage_error

REPORT_LINE = re.compile(r"^(LOCKSTEP MISMATCH|MISMATCH|suite \S+ +FAIL|suite \S+: error|"
                         r"  X(4|11): rtl wrote|zblend_tb: )")


def parse_args():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--build", default="build", help="build tree (default build)")
    ap.add_argument("--out", default="out/mutate", help="output directory (default out/mutate)")
    ap.add_argument("-j", "--jobs", type=int, default=os.cpu_count() or 1)
    ap.add_argument("--sample", type=int, help="every k-th mutant, k = count / N: N of them")
    ap.add_argument("--mutants", help="mutants to run, e.g. 1-50,77 (default all)")
    ap.add_argument("--group", default="smoke", choices=["smoke", "quick"],
                    help="the first group (default smoke: what make test runs; quick: its "
                    "fast part, for the CI-sized sample)")
    ap.add_argument("--netlist", default="core", choices=["core", "layers"],
                    help="core (default): the 1200 mutants of zb_rop without the layers unit; "
                    "layers: the layers unit's sample (make mutate-layers: a build with "
                    "ZBLEND_LAYERS_MUTANTS), its first group run with the layers tests first")
    ap.add_argument("--no-full", action="store_true", help="the first group only")
    ap.add_argument("--full-all", action="store_true",
                    help="run the full group also on survivors with a written reason (by "
                    "default they count as full-group survivors without the run)")
    ap.add_argument("--no-equiv", action="store_true",
                    help="skip the equivalence proofs of the first group's survivors "
                    "(scripts/mutant_equiv.sh); they then count as survivors")
    ap.add_argument("--equiv-limit", type=int, default=900,
                    help="seconds per equivalence proof (default 900)")
    ap.add_argument("--equiv-scope", choices=["local", "whole", "both"], default=None,
                    help="the proofs: on the mutated cell's module and its parent "
                    "(scripts/mutant_equiv_local.py), on the whole flattened zb_rop "
                    "(scripts/mutant_equiv.sh), or both (default: both; local for --netlist "
                    "layers, where the whole netlist gives no verdict)")
    ap.add_argument("--time-limit", type=float, default=0,
                    help="seconds: mutants not started by then are left out and the scores "
                    "cover those run (default: no limit); mutants run in an order spread over "
                    "the netlist")
    ap.add_argument("--resume", action="store_true",
                    help="keep the verdicts in OUT/journal.jsonl from an interrupted run with "
                    "the same netlist and run only the rest")
    ap.add_argument("--reasons", default=None,
                    help="written reasons for survivors no test can kill (default "
                    "tb/mutation/reasons.json, with --netlist layers reasons_layers.json); the "
                    "report names each survivor's")
    ap.add_argument("--min-smoke", type=float, default=0.0,
                    help="exit 1 below this smoke score, percent (default 0)")
    ap.add_argument("--min-full", type=float, default=0.0,
                    help="exit 1 below this full score, percent (default 0)")
    a = ap.parse_args()
    if a.reasons is None:
        a.reasons = os.path.join(ROOT, "tb", "mutation",
                                 "reasons_layers.json" if a.netlist == "layers" else "reasons.json")
    if a.jobs < 1:
        usage_error(f"-j {a.jobs}: 1 or more")
    return a


# ---- Set-up: the netlist, the written reasons, the mutants to run, the groups ----------------

NETLISTS = {  # --netlist: its testbench and its folder under BUILD/tb/mutation
    "core": ("zblend_tb_mut", ""),
    "layers": ("zblend_tb_mut_layers", "layers"),
}


def netlist_dir(build, netlist):
    return os.path.join(build, "tb", "mutation", NETLISTS[netlist][1])


def read_netlist(build, netlist):
    """The mutant testbench and the netlist's mutants, one description each (Yosys's mutate
    command, BUILD/tb/mutation[/layers]/mutations.txt)."""
    name = NETLISTS[netlist][0]
    tb = os.path.join(build, name)
    listing = os.path.join(netlist_dir(build, netlist), "mutations.txt")
    how = ("make build, or cmake --build {build} --target zblend_tb_mut" if netlist == "core" else
           "make mutate-layers, or configure with -DZBLEND_LAYERS_MUTANTS=ON and cmake --build "
           "{build} --target zblend_tb_mut_layers")
    for f in (tb, listing):
        if not os.path.exists(f):
            usage_error(f"{f} is missing: build it first ({how.format(build=build)})")
    with open(listing) as f:
        return tb, [ln.strip() for ln in f if ln.strip()]


def load_reasons(path, descriptions):
    try:
        reasons = Reasons(path)
    except (OSError, ValueError) as err:
        usage_error(f"--reasons: {err}")
    reasons.count(descriptions)
    return reasons


def choose_mutants(a, count):
    """The mutants of --sample (spread evenly), of --mutants, or all."""
    if a.sample is not None and a.mutants:
        usage_error("--sample and --mutants: choose one")
    if a.sample is not None:
        if not 1 <= a.sample <= count:
            usage_error(f"--sample {a.sample}: choose 1 to {count}")
        step = count / a.sample
        return sorted({int(i * step) + 1 for i in range(a.sample)})
    if a.mutants:
        return parse_mutants(a.mutants, count)
    return list(range(1, count + 1))


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


def load_groups(first):
    try:
        groups = regressions.load()
    except regressions.RegressionError as err:
        usage_error(str(err))
    tests = groups[first] + groups["full"]
    if any(t["tool"] != "tb" for t in tests):
        usage_error(f"tb/regressions.json: groups {first} and full may hold zblend_tb tests only")
    return groups[first], tests


def own_testbench(tb, out, resume):
    """The run's own copy of the testbench, so that a rebuild meanwhile changes nothing;
    --resume goes on with the copy its journal came from."""
    own = os.path.join(out, os.path.basename(tb))
    if not (resume and os.path.exists(own)):
        shutil.copy2(tb, own)
    return own


class Journal:
    """OUT/journal.jsonl: each verdict and each test's time limit as it comes; with --resume,
    those of the interrupted run (done: {(mutant, stage): entry}, limits: {test: seconds})."""

    def __init__(self, out, descriptions, resume):
        self.path = os.path.join(out, "journal.jsonl")
        self.done, self.limits = load_journal(self.path, descriptions) if resume else ({}, {})
        self.file = open(self.path, "a" if resume else "w")

    def record(self, entry):
        self.file.write(json.dumps(entry) + "\n")
        self.file.flush()


def load_journal(path, descriptions):
    """{(mutant, stage): journal entry} and {test: time limit} from a journal."""
    done, limits = {}, {}
    if not os.path.exists(path):
        usage_error(f"--resume: {path} is missing (run without --resume first)")
    with open(path) as f:
        for n, ln in enumerate(f, 1):
            try:
                e = json.loads(ln)
            except json.JSONDecodeError:
                continue  # a line cut by the interruption
            if "limit" in e:
                limits[e["limit"]] = e["seconds"]
                continue
            m = e["mutant"]
            if not 1 <= m <= len(descriptions) or descriptions[m - 1] != e["description"]:
                usage_error(f"--resume: {path}:{n}: mutant {m} is not the netlist's "
                            "(the netlist was rebuilt): run without --resume")
            e.setdefault("verdict", "killed" if e["killed_by"] else "survived")
            done[m, e["stage"]] = e
    return done, limits


# ---- Running tests and proofs on one mutant --------------------------------------------------

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

    def verdict(self, mutant, tests):
        """A test stage's work on one mutant: (verdict, killed by, seconds, report line)."""
        by, sec, line = self.run_group(mutant, tests)
        return ("killed" if by else "survived"), by, sec, line


def prove_equivalent(design, limit, mutant, scope):
    """The equivalence stage's work on one mutant: (verdict, '', seconds, the prover's last line).
    `scope` local: scripts/mutant_equiv_local.py on the cell's own module, then on its parent
    (sound: equal there for any inputs is equal in zb_rop); whole: scripts/mutant_equiv.sh on the
    flattened zb_rop; both: local, then whole."""
    t0 = time.monotonic()
    tries = []
    if scope in ("local", "both"):
        tries += [[sys.executable, os.path.join(ROOT, "scripts", "mutant_equiv_local.py"), design,
                   str(mutant), "--up", str(up), "--time-limit", str(limit)] for up in (0, 1)]
    if scope in ("whole", "both"):
        tries.append([os.path.join(ROOT, "scripts", "mutant_equiv.sh"), "--time-limit", str(limit),
                      design, str(mutant)])
    verdict, last = "no proof", ""
    for cmd in tries:
        p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        last = (p.stdout.strip().splitlines() or [""])[-1]
        if p.returncode == 0:
            return "equivalent", "", time.monotonic() - t0, last
        if p.returncode == 1:
            verdict = "not proven"
    return verdict, "", time.monotonic() - t0, last


def set_time_limits(runner, tests, journal):
    """Stage 1: mutant 0 (the netlist unmutated) passes every test; five times its time (20 s
    at least) is each test's limit. False when it fails one."""
    limits = journal.limits
    for t in tests:
        if t["name"] in limits:
            continue
        ok, sec, line = runner.run_test(0, t, limit=3600)
        print(f"mutate: mutant 0 (none): {t['name']}: {'pass' if ok else 'FAIL'} {sec:.1f} s",
              file=sys.stderr, flush=True)
        if not ok:
            print(f"mutate: FAILED: the unmutated netlist fails {t['name']}: {line}",
                  file=sys.stderr)
            return False
        limits[t["name"]] = max(20.0, 5 * sec)
        journal.record({"limit": t["name"], "seconds": limits[t["name"]]})
    runner.limits = limits
    return True


# ---- The stages over the chosen mutants ------------------------------------------------------

class Stages:
    """The chosen mutants' rows, filled in stage by stage: each stage's work runs on -j threads
    (verdicts the journal already holds kept), and mutants not started by --time-limit are
    'not run'."""

    def __init__(self, chosen, descriptions, journal, jobs, deadline):
        self.rows = {m: {"mutant": m, "description": descriptions[m - 1], "smoke": "",
                         "equiv": "", "full": "", "killed_by": "", "report": "",
                         "seconds": 0.0, "reason": ""}
                     for m in chosen}
        self.descriptions, self.journal = descriptions, journal
        self.jobs, self.deadline = jobs, deadline

    def apply(self, m, column, verdict, by, sec, line):
        r = self.rows[m]
        r["seconds"] += sec
        r[column] = verdict
        if by:
            r["killed_by"] = by
        if line and (by or column == "equiv"):
            r["report"] = line if by else f"equivalence: {line}"

    def run(self, name, work, mutants, column):
        """Runs work(m) on each of mutants; sets rows[m][column]; returns those not settled
        (survived, not proven, no proof)."""
        done = self.journal.done
        for m in mutants:  # verdicts kept from the journal (--resume)
            if (m, column) in done:
                e = done[m, column]
                self.apply(m, column, e["verdict"], e["killed_by"], e["seconds"], e["report"])
        todo = [m for m in mutants if (m, column) not in done]
        if len(todo) < len(mutants):
            print(f"mutate: {name}: {len(mutants) - len(todo)} verdicts kept from "
                  f"{self.journal.path}", file=sys.stderr)
        what = "proven equivalent" if column == "equiv" else "killed"
        prog = Progress("mutate", todo, every=5)
        settled = 0

        def before_deadline(m):
            if self.deadline is not None and time.monotonic() > self.deadline:
                return None
            return work(m)
        with concurrent.futures.ThreadPoolExecutor(self.jobs) as pool:
            futs = {pool.submit(before_deadline, m): m for m in todo}
            for fut in concurrent.futures.as_completed(futs):
                m = futs[fut]
                if fut.result() is None:  # past --time-limit
                    self.rows[m][column] = "not run"
                    continue
                verdict, by, sec, line = fut.result()
                self.journal.record({"mutant": m, "stage": column, "verdict": verdict,
                                     "killed_by": by, "seconds": sec, "report": line,
                                     "description": self.descriptions[m - 1]})
                self.apply(m, column, verdict, by, sec, line)
                settled += verdict in ("killed", "equivalent")
                prog.step(m, lambda p: f"{name}: {p.done}/{p.n} mutants, {settled} {what}, "
                          f"{p.elapsed:.0f} s, about {p.left:.0f} s left")
        return [m for m in mutants
                if self.rows[m][column] in ("survived", "not proven", "no proof")]


def run_stages(a, st, runner, chosen, smoke, full, reason_of):
    """Stages 2 to 4 on the chosen mutants, in an order spread over the netlist (so that a time
    limit leaves out mutants from all over it): the first group, the equivalence proofs of its
    survivors, the full group on those not proven equivalent."""
    count = len(st.descriptions)
    order = sorted(chosen, key=lambda m: ((m - 1) * 7919) % count)
    survivors = st.run(a.group, lambda m: runner.verdict(m, smoke), order, "smoke")
    if not a.no_equiv and survivors:
        # A survivor whose written reason says it differs (the port contract, a count beyond
        # any run) is not equivalent: the prover would only spend its time limit on it.
        differ = [m for m in survivors
                  if (reason_of[m] or {}).get("kind", "equivalent") != "equivalent"]
        for m in differ:
            st.rows[m]["equiv"] = "not tried"
        design = os.path.join(netlist_dir(a.build, a.netlist), "design.il")
        scope = a.equiv_scope or ("local" if a.netlist == "layers" else "both")
        survivors = st.run("equivalence",
                           lambda m: prove_equivalent(design, a.equiv_limit, m, scope),
                           [m for m in survivors if m not in differ], "equiv") + differ
    if not a.no_full and survivors:
        # A survivor with a written reason is one no test can kill: it counts as a full-group
        # survivor without the run (which only lowers the score if the reason is wrong), unless
        # --full-all. Its smoke run has already checked the reason against the smoke group.
        reasoned = [] if a.full_all else [m for m in survivors if reason_of[m]]
        for m in reasoned:
            st.rows[m]["full"] = "survived (reason)"
        st.run("full", lambda m: runner.verdict(m, full[len(smoke):]),
               [m for m in survivors if m not in reasoned], "full")


def settle(rows, chosen, reason_of, no_full):
    """A mutant the first group killed is killed in the full group too; each survivor gets its
    written reason. Returns the wrong reasons: those covering a mutant a test killed."""
    for m in chosen:
        if not no_full and rows[m]["smoke"] == "killed":
            rows[m]["full"] = "killed"
    wrong = []
    for m in chosen:
        r = rows[m]
        e = reason_of[m]
        if e and r["killed_by"]:
            wrong.append(f"{e['id']} (mutant {m}, killed by {r['killed_by']})")
        elif not r["killed_by"] and r["equiv"] != "equivalent" and r["smoke"] != "not run":
            r["reason"] = e["id"] if e else ""
    return wrong


# ---- The scores and the report ---------------------------------------------------------------

def score(a, rows, asked, count, smoke, full, reasons, wrong, seconds):
    """summary.json's content, and the survivors (not killed, not proven equivalent)."""
    n = len(rows)
    smoke_killed = sum(1 for r in rows.values() if r["smoke"] == "killed")
    full_killed = sum(1 for r in rows.values() if r["full"] == "killed")
    equivalent = sum(1 for r in rows.values() if r["equiv"] == "equivalent")
    denom = max(1, n - equivalent)  # the score is over the mutants not proven equivalent
    left = [r for r in rows.values() if not r["killed_by"] and r["equiv"] != "equivalent"]
    summary = {
        "mutants": n, "netlist_mutants": count, "left_out_by_time_limit": asked - n,
        "proven_equivalent": equivalent, "equivalence_checked": not a.no_equiv,
        "smoke_killed": smoke_killed, "smoke_score": round(100 * smoke_killed / denom, 2),
        "seconds": seconds, "jobs": a.jobs,
        "group": a.group, "smoke_tests": [t["name"] for t in smoke],
        "survivors": len(left), "survivors_with_reason": sum(1 for r in left if r["reason"]),
        "reasons_file": os.path.relpath(a.reasons, ROOT), "stale_reasons": reasons.stale(),
        "wrong_reasons": wrong,
    }
    if not a.no_full:
        summary.update(full_killed=full_killed,
                       full_score=round(100 * full_killed / denom, 2),
                       full_tests=[t["name"] for t in full])
    return summary, left


def write_outputs(out, summary, rows, chosen, left, reasons):
    """OUT/mutants.csv, OUT/summary.json, OUT/report.md."""
    with open(os.path.join(out, "mutants.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(next(iter(rows.values())).keys()))
        w.writeheader()
        for m in chosen:
            r = dict(rows[m])
            r["seconds"] = round(r["seconds"], 2)
            w.writerow(r)
    with open(os.path.join(out, "summary.json"), "w") as f:
        json.dump(summary, f, indent=2)
    write_report(os.path.join(out, "report.md"), summary, rows, chosen, left, reasons)


def write_report(path, s, rows, chosen, left, reasons):
    by_test = {}
    for r in rows.values():
        if r["killed_by"]:
            by_test[r["killed_by"]] = by_test.get(r["killed_by"], 0) + 1
    lines = ["# Mutation score", "",
             f"{s['mutants']} mutants of zb_rop (of the netlist's {s['netlist_mutants']}; "
             f"{s['left_out_by_time_limit']} left out by --time-limit); "
             f"{s['proven_equivalent']} proven equivalent, out of the score.", "",
             "| group | killed | score |", "|---|---|---|",
             f"| {s['group']} | {s['smoke_killed']} | {s['smoke_score']} % |"]
    if "full_score" in s:
        lines.append(f"| full | {s['full_killed']} | {s['full_score']} % |")
    lines += ["", "Kills by the test that made them first:", ""]
    lines += [f"- {t}: {k}" for t, k in sorted(by_test.items(), key=lambda x: -x[1])]
    item = lambda r: (f"- mutant {r['mutant']}: `{r['description']}`"
                      + (f" ({r['report']})" if r["report"] and not r["killed_by"] else ""))
    some = [rows[m] for m in chosen if rows[m]["equiv"] == "equivalent"]
    lines += ["", f"## Proven equivalent ({len(some)})", ""] + [item(r) for r in some]
    lines += ["", f"## Survivors ({len(left)}: {s['survivors_with_reason']} with a written "
              f"reason from {s['reasons_file']})"]
    for e in reasons.entries:
        mine = [r for r in left if r["reason"] == e["id"]]
        if mine:
            lines += ["", f"### {e['id']} ({len(mine)}): {KINDS[e['kind']]}", "", e["why"], ""]
            lines += [item(r) for r in mine]
    bare = [r for r in left if not r["reason"]]
    lines += ["", f"### Without a written reason ({len(bare)})", ""] + [item(r) for r in bare]
    if s["wrong_reasons"]:
        lines += ["", "**Wrong reasons** (a test killed a mutant they cover): "
                  + "; ".join(s["wrong_reasons"])]
    if s["stale_reasons"]:
        lines += ["", "Stale reasons (they match no mutant of this netlist): "
                  + ", ".join(s["stale_reasons"])]
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def conclude(a, s, wrong):
    """The run's two lines on stdout, the failures on stderr; the exit code."""
    line = (f"mutate: {s['mutants']} mutants, {s['proven_equivalent']} proven equivalent; "
            f"{a.group} killed {s['smoke_killed']} ({s['smoke_score']} % of the rest)")
    if not a.no_full:
        line += f"; full killed {s['full_killed']} ({s['full_score']} %)"
    print(line + f"; {s['seconds']} s; {a.out}/report.md")
    stale = s["stale_reasons"]
    print(f"mutate: {s['survivors']} survivors, {s['survivors_with_reason']} with a "
          f"written reason ({s['reasons_file']})"
          + (f"; stale reasons (match no mutant): {', '.join(stale)}" if stale else ""))
    if wrong:
        print(f"mutate: FAILED: written reasons that a test contradicts ({s['reasons_file']}): "
              + "; ".join(wrong), file=sys.stderr)
    low = s["smoke_score"] < a.min_smoke or (not a.no_full and s["full_score"] < a.min_full)
    if low:
        print(f"mutate: FAILED: score below --min-smoke {a.min_smoke} / --min-full {a.min_full}",
              file=sys.stderr)
    return 1 if low or wrong else 0


def main():
    a = parse_args()
    tb, descriptions = read_netlist(a.build, a.netlist)
    reasons = load_reasons(a.reasons, descriptions)
    chosen = choose_mutants(a, len(descriptions))
    smoke, full = load_groups(a.group)
    if a.netlist == "layers":  # the same tests, those of the unit first: kills come sooner
        first = [t for t in smoke if "layers" in t["name"]]
        smoke = first + [t for t in smoke if t not in first]
        full = smoke + full[len(smoke):]
    reason_of = {m: reasons.explain(descriptions[m - 1]) for m in chosen}  # entry or None
    os.makedirs(a.out, exist_ok=True)
    runner = Runner(own_testbench(tb, a.out, a.resume), {})
    journal = Journal(a.out, descriptions, a.resume)
    if not set_time_limits(runner, smoke if a.no_full else full, journal):
        return 1
    deadline = time.monotonic() + a.time_limit if a.time_limit > 0 else None
    st = Stages(chosen, descriptions, journal, a.jobs, deadline)
    t0 = time.monotonic()
    run_stages(a, st, runner, chosen, smoke, full, reason_of)
    wrong = settle(st.rows, chosen, reason_of, a.no_full)
    ran = [m for m in chosen if st.rows[m]["smoke"] != "not run"]
    rows = {m: st.rows[m] for m in ran}
    summary, left = score(a, rows, len(chosen), len(descriptions), smoke, full, reasons, wrong,
                          round(time.monotonic() - t0, 1))
    write_outputs(a.out, summary, rows, ran, left, reasons)
    return conclude(a, summary, wrong)


if __name__ == "__main__":
    sys.exit(main())
