#!/usr/bin/env python3
"""zblend's regression runner (make regress, docs/regressions.md).

  regress.py run GROUP [-j N]        run a group of tb/regressions.json on N local processes
  regress.py list GROUP              its tests, one per line, with the command of each
  regress.py one GROUP (NAME | --index I)   one test: its log and result under OUT
  regress.py gather GROUP            JUnit XML and the HTML summary from OUT's results
  regress.py parallel GROUP [--sshloginfile F] [--resume-failed]   through GNU parallel
  regress.py slurm GROUP [--submit]  an sbatch --array job of the group; --submit runs it

Every test writes OUT/logs/NAME.log and OUT/results/NAME.json; gather (which run, parallel and
slurm --submit end with) writes OUT/junit.xml, OUT/summary.html and OUT/summary.json. A failing
suite test is run again with waves (at most --waves K): OUT/waves/NAME.fst and its GTKWave save
file. Every test's line in the summary holds the command that replays it. Exit 1 when a test
fails or has no result; 2 on bad usage.
"""
import argparse
import concurrent.futures
import html
import json
import os
import re
import shlex
import shutil
import subprocess
import sys
import time
import xml.etree.ElementTree as ET

from regressions import DEFAULT, RegressionError, load
from zbscript import ROOT, Progress, usage_error

REPORT_PREFIXES = ("LOCKSTEP MISMATCH", "MISMATCH", "FAIL ", "suite ", "zblend_tb: ", "zblend: ",
                   "replay ")


def tree(test, a):
    """The build tree of the test's RTL parameter set: BUILD, or BUILD-SET."""
    return a.build if test["rtl"] == "default" else f"{a.build.rstrip('/')}-{test['rtl']}"


def code_coverage_tree(build):
    """Whether BUILD counts lines and toggles (-DZBLEND_RTL_COVERAGE=ON)."""
    try:
        with open(os.path.join(ROOT, build, "CMakeCache.txt")) as f:
            return any(re.match(r"ZBLEND_RTL_COVERAGE:BOOL=(ON|TRUE|1)$", ln.strip())
                       for ln in f)
    except OSError:
        return False


def tb_program(a):
    """The testbench program of every tree: with --coverage on a tree that does not count
    lines and toggles, the one counting the coverage plan's bins."""
    return "zblend_tb_fcov" if a.coverage and not code_coverage_tree(a.build) else "zblend_tb"


def ensure_trees(tests, a):
    """Configures and builds the tree of every RTL parameter set the tests use beyond the
    default (what each needs: the testbench, zblend), with the set's options (and line and
    toggle coverage when BUILD counts them)."""
    need = {}
    for t in tests:
        if t["rtl"] != "default":
            need.setdefault(t["rtl"], (t["rtl_cache"], set()))[1].add(
                "zblend" if t["tool"] == "render" else tb_program(a))
    for name, (cache, targets) in sorted(need.items()):
        d = os.path.join(ROOT, tree({"rtl": name}, a))
        opts = [f"-D{k}={v}" for k, v in sorted(cache.items())]
        if code_coverage_tree(a.build):
            opts.append("-DZBLEND_RTL_COVERAGE=ON")  # a coverage run measures every set
        print(f"regress: RTL parameter set {name} ({' '.join(opts)}): building {d}",
              file=sys.stderr, flush=True)
        for cmd in (["cmake", "-S", ROOT, "-B", d, "-DCMAKE_BUILD_TYPE=Release", *opts],
                    ["cmake", "--build", d, "-j", str(a.jobs), "--target", *sorted(targets)]):
            p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
            if p.returncode != 0:
                print(p.stdout[-3000:], file=sys.stderr)
                print(f"regress: FAILED: {shlex.join(cmd)} (exit {p.returncode})",
                      file=sys.stderr)
                sys.exit(1)


def command(test, a, extra=()):
    """The test's command line, as a list (relative to the repository; renders write under
    a.out)."""
    build = tree(test, a)
    if test["tool"] == "render":
        return [os.path.join(build, "zblend"), "render", *test["args"], "-q",
                "--out-dir", os.path.join(os.path.abspath(a.out), "render", test["name"]), *extra]
    tb = a.tb or os.path.join(build, tb_program(a))
    return [tb, *shlex.split(a.tb_args), *test["args"], *extra]


def first_report_line(text):
    for ln in text.splitlines():
        if ln.startswith(REPORT_PREFIXES) and ("FAIL" in ln or "MISMATCH" in ln or
                                               "error" in ln or "FAILED" in ln):
            return ln.strip()
    return ""


def run_one(test, a, waves=False):
    """Runs a test; writes its log and result; returns the result."""
    out = os.path.abspath(a.out)
    name = test["name"]
    for d in ("logs", "results", "waves"):
        os.makedirs(os.path.join(out, d), exist_ok=True)
    extra = []
    if test["tool"] == "tb":
        fst = os.path.join(out, "waves", name + ".fst") if waves else ""
        extra = ["--mismatch-fst", fst]
        if a.coverage and not waves:
            os.makedirs(os.path.join(out, "coverage"), exist_ok=True)
            extra += ["--coverage-out", os.path.join(out, "coverage", name + ".dat")]
    cmd = command(test, a, extra)
    log = os.path.join(out, "logs", name + (".waves" if waves else "") + ".log")
    t0 = time.monotonic()
    with open(log, "w") as f:
        f.write("$ " + shlex.join(cmd) + "\n")
        f.flush()
        try:
            p = subprocess.run(cmd, stdout=f, stderr=subprocess.STDOUT, cwd=ROOT,
                               timeout=a.timeout or None)
            rc = p.returncode
        except subprocess.TimeoutExpired:
            rc = "timeout"
            f.write(f"\nregress.py: time limit of {a.timeout} s reached\n")
        except OSError as e:
            rc = "not run"
            f.write(f"\nregress.py: {cmd[0]}: {e.strerror}\n")
    sec = time.monotonic() - t0
    with open(log, errors="replace") as f:
        text = f.read()
    r = {"name": name, "passed": rc == 0, "exit": rc, "seconds": round(sec, 2),
         "command": shlex.join(cmd), "log": os.path.relpath(log, out),
         "report": "" if rc == 0 else (first_report_line(text) or f"exit {rc}"),
         "host": os.uname().nodename, "rtl": test["rtl"]}
    if waves:
        fst = os.path.join(out, "waves", name + ".fst")
        r["waves"] = os.path.relpath(fst, out) if os.path.exists(fst) else ""
        gtkw = os.path.splitext(fst)[0] + ".gtkw"
        r["save_file"] = os.path.relpath(gtkw, out) if os.path.exists(gtkw) else ""
    else:
        with open(os.path.join(out, "results", name + ".json"), "w") as f:
            json.dump(r, f, indent=1)
    return r


def gather(group, tests, a, started=None, why=None):
    """Reads OUT/results; writes junit.xml, summary.json, summary.html. Returns the exit code.
    why: what is known of a test that left no result, by name (parallel: its joblog line)."""
    # Every way of running ends here: the coverage of each job merged (run, parallel, Slurm).
    if a.coverage and not merge_coverage(a):
        return 1
    out = a.out
    results = []
    for t in tests:
        p = os.path.join(out, "results", t["name"] + ".json")
        if os.path.exists(p):
            with open(p) as f:
                results.append(json.load(f))
        else:
            results.append({"name": t["name"], "passed": False, "exit": "no result",
                            "seconds": 0.0, "command": shlex.join(command(t, a)),
                            "log": "", "report": "no result: " + (why or {}).get(
                                t["name"], "the test never ran or its job died"),
                            "host": ""})
    waves = {}
    wp = os.path.join(out, "waves.json")
    if os.path.exists(wp):
        with open(wp) as f:
            waves = json.load(f)
    for r in results:
        if r["name"] in waves:
            r["rerun"] = waves[r["name"]]
    failed = [r for r in results if not r["passed"]]
    total = sum(r["seconds"] for r in results)
    write_junit(os.path.join(out, "junit.xml"), group, results, total)
    summary = {"group": group, "tests": len(results), "passed": len(results) - len(failed),
               "failed": len(failed), "seconds": round(total, 1),
               "wall_seconds": round(time.monotonic() - started, 1) if started else None,
               "results": results}
    with open(os.path.join(out, "summary.json"), "w") as f:
        json.dump(summary, f, indent=1)
    write_html(os.path.join(out, "summary.html"), summary)
    wall = f" in {summary['wall_seconds']:.0f} s" if started else ""
    bad = f", {len(failed)} FAILED" if failed else ""
    print(f"regress: {group}: {summary['passed']}/{summary['tests']} passed{bad}; "
          f"{total:.0f} s of tests{wall}; {os.path.join(out, 'summary.html')}, "
          f"{os.path.join(out, 'junit.xml')}")
    for r in failed:
        print(f"regress: FAIL {r['name']}: {r['report']}")
        print(f"  replay: {r['command']}")
        if r.get("rerun", {}).get("command"):
            print(f"  with waves: {r['rerun']['command']}")
    return 1 if failed else 0


def write_junit(path, group, results, total):
    suite = ET.Element("testsuite", name=group, tests=str(len(results)),
                       failures=str(sum(not r["passed"] for r in results)), errors="0",
                       time=f"{total:.2f}")
    for r in results:
        case = ET.SubElement(suite, "testcase", classname=f"zblend.{group}", name=r["name"],
                             time=f"{r['seconds']:.2f}")
        if not r["passed"]:
            fail = ET.SubElement(case, "failure", message=r["report"], type=str(r["exit"]))
            fail.text = f"replay: {r['command']}\nlog: {r['log']}\n"
        ET.SubElement(case, "system-out").text = f"$ {r['command']}\n"
    suites = ET.Element("testsuites", name="zblend", tests=suite.get("tests"),
                        failures=suite.get("failures"), time=suite.get("time"))
    suites.append(suite)
    ET.indent(suites)
    ET.ElementTree(suites).write(path, encoding="utf-8", xml_declaration=True)


def write_html(path, s):
    rows = []
    longest = max([r["seconds"] for r in s["results"]] + [1e-9])
    for r in sorted(s["results"], key=lambda r: (r["passed"], r["name"])):
        ok = r["passed"]
        links = [f'<a href="{html.escape(r["log"])}">log</a>'] if r["log"] else []
        rerun = r.get("rerun") or {}
        for key, label in (("waves", "waves (FST)"), ("save_file", "GTKWave save file"),
                           ("log", "log with waves")):
            if rerun.get(key):
                links.append(f'<a href="{html.escape(rerun[key])}">{label}</a>')
        bar = int(200 * r["seconds"] / longest)
        rows.append(
            f'<tr class="{"pass" if ok else "fail"}"><td>{"PASS" if ok else "FAIL"}</td>'
            f'<td>{html.escape(r["name"])}</td><td class="num">{r["seconds"]:.1f}</td>'
            f'<td><span class="bar" style="width:{bar}px"></span></td>'
            f'<td>{" · ".join(links)}</td>'
            f'<td><code>{html.escape(r["command"])}</code>'
            + (f'<div class="why">{html.escape(r["report"])}</div>' if not ok else "")
            + (f'<div class="why">with waves: <code>{html.escape(rerun["command"])}</code></div>'
               if rerun.get("command") else "") + "</td></tr>")
    rate = 100.0 * s["passed"] / max(1, s["tests"])
    wall = f", {s['wall_seconds']:.0f} s wall" if s.get("wall_seconds") else ""
    doc = f"""<!DOCTYPE html>
<html><head><meta charset="utf-8"><title>zblend regression: {html.escape(s['group'])}</title>
<style>
body {{ font: 14px sans-serif; margin: 2em; color: #222; }}
h1 {{ font-size: 20px; }}
.head {{ font-size: 16px; margin-bottom: 1em; }}
.rate {{ font-weight: bold; color: {'#1a7f37' if not s['failed'] else '#c62828'}; }}
table {{ border-collapse: collapse; }}
td, th {{ border-bottom: 1px solid #ddd; padding: 4px 8px; text-align: left; vertical-align: top; }}
tr.fail td:first-child {{ color: #c62828; font-weight: bold; }}
tr.pass td:first-child {{ color: #1a7f37; }}
td.num {{ text-align: right; font-variant-numeric: tabular-nums; }}
.bar {{ display: inline-block; height: 10px; background: #5b8def; }}
tr.fail .bar {{ background: #c62828; }}
code {{ font-size: 12px; }}
.why {{ color: #c62828; font-size: 12px; margin-top: 2px; }}
</style></head><body>
<h1>zblend regression: group <code>{html.escape(s['group'])}</code></h1>
<div class="head"><span class="rate">{rate:.1f} % passed</span> ({s['passed']} of {s['tests']}),
{s['failed']} failed; {s['seconds']:.0f} s of tests{wall}. Each line's command replays it.</div>
<table><tr><th></th><th>test</th><th>s</th><th>time</th><th>files</th><th>command</th></tr>
{chr(10).join(rows)}
</table></body></html>
"""
    with open(path, "w") as f:
        f.write(doc)


def rerun_with_waves(failed, tests, a):
    """Runs up to a.waves failing suite tests again with waves; records them in waves.json."""
    by_name = {t["name"]: t for t in tests}
    chosen = [r for r in failed if by_name[r["name"]]["tool"] == "tb"][:a.waves]
    done = {}
    for r in chosen:
        print(f"regress: {r['name']}: again with waves", file=sys.stderr, flush=True)
        w = run_one(by_name[r["name"]], a, waves=True)
        done[r["name"]] = {"command": w["command"], "waves": w.get("waves", ""),
                           "save_file": w.get("save_file", ""), "log": w["log"]}
    if done:
        with open(os.path.join(a.out, "waves.json"), "w") as f:
            json.dump(done, f, indent=1)


def cmd_run(group, tests, a):
    started = time.monotonic()
    last = {}
    try:
        with open(os.path.join(a.out, "summary.json")) as f:
            last = {r["name"]: r["seconds"] for r in json.load(f)["results"]}
    except (OSError, ValueError, KeyError):
        pass
    shutil.rmtree(os.path.join(a.out, "results"), ignore_errors=True)
    shutil.rmtree(os.path.join(a.out, "coverage"), ignore_errors=True)
    for stale in ("waves.json",):
        if os.path.exists(os.path.join(a.out, stale)):
            os.remove(os.path.join(a.out, stale))
    ensure_trees(tests, a)
    print(f"regress: {group}: {len(tests)} tests on {a.jobs} processes; {a.out}/",
          file=sys.stderr, flush=True)
    # A line per finished test: its verdict and the time left, the tests not yet done at their
    # times in OUT's last summary where it has them.
    prog = Progress("regress", [t["name"] for t in tests], jobs=a.jobs, known=last)
    results, n_failed = [], 0
    with concurrent.futures.ThreadPoolExecutor(a.jobs) as pool:
        futs = [pool.submit(run_one, t, a) for t in tests]
        for fut in concurrent.futures.as_completed(futs):
            r = fut.result()
            results.append(r)
            n_failed += not r["passed"]
            prog.step(r["name"], lambda p: f"[{p.done}/{p.n}] {'PASS' if r['passed'] else 'FAIL'} "
                      f"{r['name']} {r['seconds']:.1f} s; {n_failed} failed; {p.elapsed:.0f} s "
                      f"elapsed, about {p.left:.0f} s left")
    failed = [r for r in results if not r["passed"]]
    if failed and a.waves:
        rerun_with_waves(failed, tests, a)
    return gather(group, tests, a, started)


def merge_coverage(a):
    """verilator_coverage: every test's counts (OUT/coverage/) into OUT/merged.dat, the sources
    annotated in OUT/annotated/. False when no test wrote any."""
    cov = os.path.join(a.out, "coverage")
    runs = sorted(os.path.join(cov, f) for f in os.listdir(cov) if f.endswith(".dat")) \
        if os.path.isdir(cov) else []
    if not runs:
        print("regress: --coverage: no test wrote coverage: does the group run suites, and "
              "is the testbench built (zblend_tb_fcov, or zblend_tb in a code coverage tree)?",
              file=sys.stderr)
        return False
    merged = os.path.join(a.out, "merged.dat")
    subprocess.run(["verilator_coverage", "--write", merged, *runs], check=True)
    subprocess.run(["verilator_coverage", "--annotate", os.path.join(a.out, "annotated"), merged],
                   check=True, stdout=subprocess.DEVNULL)
    print(f"regress: coverage of {len(runs)} tests merged: {merged}; sources annotated in "
          f"{os.path.join(a.out, 'annotated')}/", file=sys.stderr)
    return True


def one_command(group, a, index):
    """The runner's own command for one test of the group (what each job of parallel or
    Slurm runs), from the repository, with this run's options."""
    cmd = ["python3", os.path.join(ROOT, "scripts", "regress.py"), "one", group,
           "--index", index, "--file", os.path.abspath(a.file), "--build", os.path.abspath(a.build),
           "--out", os.path.abspath(a.out)]
    if a.tb:
        cmd += ["--tb", os.path.abspath(a.tb)]
    if a.tb_args:
        cmd += ["--tb-args", a.tb_args]
    if a.timeout:
        cmd += ["--timeout", str(a.timeout)]
    if a.coverage:
        cmd.append("--coverage")
    return cmd


def cmd_parallel(group, tests, a):
    """GNU parallel: one job per test, on this machine or the hosts of --sshloginfile (which
    must see the repository, the build and OUT at the same paths); --joblog in OUT, so
    --resume-failed runs only what failed or never ran."""
    if not shutil.which("parallel"):
        usage_error("GNU parallel is missing: run scripts/setup.sh (Debian package 'parallel')")
    ensure_trees(tests, a)
    started = time.monotonic()
    if not a.resume_failed:  # else a job that dies (a host down) would show an earlier result
        shutil.rmtree(os.path.join(a.out, "results"), ignore_errors=True)
        shutil.rmtree(os.path.join(a.out, "coverage"), ignore_errors=True)
    os.makedirs(a.out, exist_ok=True)
    joblog = os.path.join(a.out, "joblog")
    cmd = ["parallel", "--will-cite", "--joblog", joblog, "--halt", "never", "--line-buffer", "-j",
           str(a.jobs)]
    if a.sshloginfile:  # parallel runs from the repository: a relative FILE is the caller's
        special = a.sshloginfile in (".", "..", "-")  # GNU parallel's own lists and stdin
        cmd += ["--sshloginfile", a.sshloginfile if special else os.path.abspath(a.sshloginfile)]
    if a.resume_failed:
        cmd += ["--resume-failed"]
    cmd += [shlex.join(one_command(group, a, "{}")), ":::", *map(str, range(len(tests)))]
    print(f"regress: {group}: {len(tests)} tests through GNU parallel; joblog {joblog}",
          file=sys.stderr, flush=True)
    subprocess.run(cmd, cwd=ROOT)
    why = {tests[i]["name"]: w for i, w in job_endings(joblog).items() if 0 <= i < len(tests)}
    return gather(group, tests, a, started, why)


def job_endings(joblog):
    """GNU parallel's joblog: how each job last ended, by test index (its sequence number less
    one: the jobs' arguments are the indices in order), e.g. 'its job on root@node7 exited 255'."""
    ends = {}
    try:
        with open(joblog) as f:
            rows = [ln.split("\t") for ln in f.read().splitlines()[1:]]
    except OSError:
        return ends
    for cols in rows:
        if len(cols) < 9 or not cols[0].isdigit():
            continue
        sshlogin, code, sig = cols[1], cols[6], cols[7]
        # An sshlogin may be a whole ssh command; its last word is the host.
        host = "this machine" if sshlogin == ":" else sshlogin.split()[-1]
        w = f"its job on {host} " + (f"was killed by signal {sig}" if sig != "0" else
                                     f"exited {code}")
        if code == "255" and sshlogin != ":":
            w += " (ssh's own failure: host down or login refused?)"
        ends[int(cols[0]) - 1] = w
    return ends


def cmd_slurm(group, tests, a):
    """Writes OUT/regress.sbatch: an array job, one task per test; with --submit, runs it
    (sbatch --wait) and gathers the results."""
    ensure_trees(tests, a)  # on the submitting host: the tree must be on the shared file system
    out = os.path.abspath(a.out)
    os.makedirs(os.path.join(out, "slurm"), exist_ok=True)
    script = os.path.join(out, "regress.sbatch")
    limit = f"%{a.array_limit}" if a.array_limit else ""
    lines = ["#!/bin/bash",
             f"#SBATCH --job-name=zblend-{group}",
             f"#SBATCH --array=0-{len(tests) - 1}{limit}",
             f"#SBATCH --output={out}/slurm/%A_%a.out",
             f"#SBATCH --chdir={ROOT}",
             "#SBATCH --cpus-per-task=1",
             *[f"#SBATCH {opt}" for opt in shlex.split(a.sbatch_args)],
             "# One test of the group per array task (regress.py slurm wrote this; "
             "regress.py gather reads the results).",
             shlex.join(one_command(group, a, "INDEX")).replace("INDEX", "${SLURM_ARRAY_TASK_ID}"),
             ""]
    with open(script, "w") as f:
        f.write("\n".join(lines))
    os.chmod(script, 0o755)
    print(f"regress: {group}: {script}: {len(tests)} array tasks", file=sys.stderr)
    if not a.submit:
        print(f"submit it: sbatch {script}; then: python3 scripts/regress.py gather {group} "
              f"--out {a.out}")
        return 0
    if not shutil.which("sbatch"):
        usage_error("sbatch is missing: install Slurm's client (Debian: slurm-client) or drop --submit")
    started = time.monotonic()
    shutil.rmtree(os.path.join(out, "results"), ignore_errors=True)
    shutil.rmtree(os.path.join(out, "coverage"), ignore_errors=True)
    p = subprocess.run(["sbatch", "--wait", "--parsable", script], cwd=ROOT,
                       stdout=subprocess.PIPE, text=True)
    print(f"regress: sbatch job {p.stdout.strip()} ended (exit {p.returncode})", file=sys.stderr)
    return gather(group, tests, a, started)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter,
                                 epilog="\n".join(__doc__.split("\n")[2:]))
    ap.add_argument("action", choices=["run", "list", "one", "gather", "parallel", "slurm"])
    ap.add_argument("group", help="a group of the regression file (smoke, nightly, ...)")
    ap.add_argument("name", nargs="?", help="one: the test's name")
    ap.add_argument("--file", default=DEFAULT, help="the regression file (default "
                    "tb/regressions.json)")
    ap.add_argument("--build", default="build", help="build tree with zblend_tb and zblend")
    ap.add_argument("--out", help="output directory (default out/regress/GROUP)")
    ap.add_argument("--tb", help="the testbench for suite tests (default BUILD/zblend_tb; "
                    "e.g. BUILD/zblend_tb_mut)")
    ap.add_argument("--tb-args", default="", help="arguments put first on every testbench "
                    "command (e.g. '--mutant 703')")
    ap.add_argument("-j", "--jobs", type=int, default=os.cpu_count() or 1)
    ap.add_argument("--index", type=int, help="one: the test's index in the group (0-based)")
    ap.add_argument("--waves", type=int, default=3, metavar="K",
                    help="run at most K failing tests again with waves (default 3)")
    ap.add_argument("--coverage", action="store_true",
                    help="each suite test writes its RTL coverage to OUT/coverage/ (run: merged "
                    "into OUT/merged.dat): the coverage plan's bins through zblend_tb_fcov, or on "
                    "a code coverage tree (-DZBLEND_RTL_COVERAGE=ON) lines, toggles and the bins "
                    "through zblend_tb")
    ap.add_argument("--timeout", type=float, default=0, help="seconds per test (default none)")
    ap.add_argument("--sshloginfile", help="parallel: GNU parallel's list of hosts")
    ap.add_argument("--resume-failed", action="store_true",
                    help="parallel: run again only the jobs of OUT/joblog that failed or never ran")
    ap.add_argument("--submit", action="store_true", help="slurm: sbatch --wait the job, then gather")
    ap.add_argument("--sbatch-args", default="", help="slurm: more #SBATCH options, e.g. "
                    "'--partition=rtl --time=60'")
    ap.add_argument("--array-limit", type=int, default=0,
                    help="slurm: at most this many tasks at once (default: Slurm's choice)")
    a = ap.parse_args()
    if a.jobs < 1:
        usage_error(f"-j {a.jobs}: 1 or more")
    try:
        groups = load(a.file)
    except RegressionError as e:
        usage_error(str(e))
    if a.group not in groups:
        usage_error(f"no group '{a.group}' in {a.file} (groups: {', '.join(groups)})")
    tests = groups[a.group]
    a.out = a.out or os.path.join("out", "regress", a.group)
    if a.tb and any(t["rtl"] != "default" for t in tests):
        usage_error(f"--tb names one testbench; group {a.group} runs RTL parameter sets "
                    f"({', '.join(sorted({t['rtl'] for t in tests}))}), each its own")
    if a.action == "list":
        for i, t in enumerate(tests):
            print(f"{i}\t{t['name']}\t{shlex.join(command(t, a))}")
        return 0
    if a.action == "one":
        if (a.name is None) == (a.index is None):
            usage_error("one: give the test's NAME or --index I")
        if a.index is not None:
            if not 0 <= a.index < len(tests):
                usage_error(f"--index {a.index}: the group has tests 0 to {len(tests) - 1}")
            t = tests[a.index]
        else:
            t = next((t for t in tests if t["name"] == a.name), None)
            if t is None:
                usage_error(f"no test '{a.name}' in group {a.group} (regress.py list {a.group})")
        r = run_one(t, a)
        print(f"regress: {'PASS' if r['passed'] else 'FAIL'} {t['name']} {r['seconds']:.1f} s"
              + (f": {r['report']}" if not r["passed"] else ""))
        return 0 if r["passed"] else 1
    if a.action == "gather":
        return gather(a.group, tests, a)
    if a.action == "run":
        return cmd_run(a.group, tests, a)
    if a.action == "parallel":
        return cmd_parallel(a.group, tests, a)
    return cmd_slurm(a.group, tests, a)


if __name__ == "__main__":
    sys.exit(main())
