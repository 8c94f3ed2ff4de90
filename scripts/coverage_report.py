#!/usr/bin/env python3
"""The functional coverage closure report (make coverage; docs/coverage.md).

Reads a regression run made with --coverage (scripts/regress.py: OUT/coverage/TEST.dat and
OUT/results/TEST.json, each naming its RTL parameter set), maps every cover point to the bins of
the plan (tb/cov/coverage_plan.json), and writes OUT/closure.html, OUT/closure.json and
OUT/holes.txt: every bin per parameter set, its hits, the first test (in the group's order) to
hit it, the holes on top; the tests ranked by the bins each adds; the smoke group re-chosen
within its time budget.

With --conformance the run is a conformance run (scripts/conformance.py with the plan's
covers: OUT/results.json and OUT/<test>/coverage.dat): the report measures the suite's reach on
the default parameter set's bins, reach.html and reach.json. With --kit-bins
(conformance/kit_bins.json) the bins a DUT cannot reach through the kit are set apart with their
reasons and the reach is measured on the others; with --reach (`zblend conformance reach
--json`) the golden model's reach is held to zb_rop's covers, test by test (reach_check.py).

Exit status: 0 closure (every bin hit or reasoned; with --conformance, the reach at least
--min-reach percent and the golden reach agreeing); 1 holes, a reason a test contradicts, or a
cover the plan does not name; 2 bad input.
"""
import argparse
import html
import json
import os
import sys

import coverage_plan
import reach_check
import regressions
from zbscript import ROOT, usage_error


def load_run(run_dir, group, tests_file):
    """[(test, set, seconds, {path: count})] in the group's order, for the tests that wrote
    coverage."""
    order = [t["name"] for t in regressions.load(tests_file)[group]]
    out = []
    for name in order:
        dat = os.path.join(run_dir, "coverage", name + ".dat")
        res = os.path.join(run_dir, "results", name + ".json")
        if not os.path.exists(dat):
            continue
        with open(res) as f:
            r = json.load(f)
        out.append((name, r.get("rtl", "default"), r["seconds"], coverage_plan.read_dat(dat)))
    return out


def load_conformance(run_dir):
    """[(test, "default", seconds, {path: count})] of a conformance run, in the suite's order,
    for the tests that ran (a test not supported by the profile wrote no coverage)."""
    with open(os.path.join(run_dir, "results.json")) as f:
        doc = json.load(f)
    out = []
    for t in doc["tests"]:
        dat = os.path.join(run_dir, t["name"], "coverage.dat")
        if os.path.exists(dat):
            out.append((t["name"], "default", t["seconds"], coverage_plan.read_dat(dat)))
    return out


def close(entries, runs):
    """The closure: {(set, bin): {...}}, and the problems (a cover no entry names, a reason a
    test contradicts)."""
    problems = []
    paths_by_set = {}
    for _, rtl, _, pts in runs:
        paths_by_set.setdefault(rtl, set()).update(pts)
    table = {}
    for rtl, paths in sorted(paths_by_set.items()):
        named = set()
        for e in entries:
            try:
                got = coverage_plan.bins(e, paths)
            except coverage_plan.PlanError:
                if rtl not in e["sets"]:
                    continue  # a set without the entry's covers (LAYERS 0 has no layers unit)
                raise
            named.update(p for _, p in got)
            if rtl not in e["sets"]:
                continue
            for b, p in got:
                why = next((u["why"] for u in e["unreachable"] if u["re"].fullmatch(b)), None)
                table[(rtl, b)] = {"set": rtl, "bin": b, "entry": e["id"], "path": p, "hits": 0,
                                   "first": None, "tests": 0, "why": why}
        for p in sorted(paths - named):
            problems.append(f"cover {p} (set {rtl}) is in no plan entry: add it to "
                            "tb/cov/coverage_plan.json")
    for e in entries:
        for rtl in e["sets"]:
            if rtl not in paths_by_set:
                problems.append(f"plan entry {e['id']}: no test of the run used RTL parameter "
                                f"set {rtl}")
    for name, rtl, _, pts in runs:
        for (s, b), row in table.items():
            if s != rtl:
                continue
            n = pts.get(row["path"], 0)
            if n:
                row["hits"] += n
                row["tests"] += 1
                row["first"] = row["first"] or name
    for row in table.values():
        if row["why"] and row["hits"]:
            problems.append(f"{row['bin']} (set {row['set']}) is written unreachable but "
                            f"{row['first']} hits it: remove the reason")
    return table, problems


def test_bins(table, runs):
    """{test: set of (set, bin) it hits}."""
    out = {}
    for name, rtl, _, pts in runs:
        out[name] = {k for k, row in table.items() if k[0] == rtl and pts.get(row["path"], 0)}
    return out


def rank(hits, seconds):
    """Greedy: each step the test adding the most bins (the faster on a tie)."""
    left, got, out = dict(hits), set(), []
    while left:
        name = max(left, key=lambda t: (len(left[t] - got), -seconds[t]))
        new = left.pop(name) - got
        if not new:
            break
        got |= new
        out.append((name, len(new), len(got), seconds[name]))
    return out


def choose_smoke(hits, seconds, candidates, budget, keep=()):
    """The smoke set: the smallest set of candidates reaching the most bins within `budget`
    seconds (greedy by bins added per second, then every test whose bins the others already
    reach dropped); then, in the budget left, the tests of `keep` in order (the previous smoke
    group: its tests check data the plan's bins do not count, which the mutation score
    measures). Returns (tests, bins, seconds)."""
    chosen, got, spent = [], set(), 0.0
    pool = {t: hits[t] for t in candidates}
    while True:
        fits = [t for t in pool if spent + seconds[t] <= budget and pool[t] - got]
        if not fits:
            break
        t = max(fits, key=lambda t: (len(pool[t] - got) / max(seconds[t], 0.01), -seconds[t]))
        chosen.append(t)
        got |= pool.pop(t)
        spent += seconds[t]
    for t in sorted(chosen, key=lambda t: -seconds[t]):
        rest = set().union(*(hits[o] for o in chosen if o != t)) if len(chosen) > 1 else set()
        if hits[t] <= rest:
            chosen.remove(t)
    spent = sum(seconds[t] for t in chosen)
    for t in keep:
        if t in seconds and t not in chosen and spent + seconds[t] <= budget:
            chosen.append(t)
            spent += seconds[t]
    got = set().union(*(hits[t] for t in chosen)) if chosen else set()
    return chosen, got, spent


def write_html(path, summary, rows, ranking, smoke, reach=False):
    esc = html.escape
    holes = [r for r in rows if not r["hits"] and not r["why"]]
    reasoned = [r for r in rows if r["why"]]

    def bin_rows(rs):
        return "".join(
            f"<tr class='{'hole' if not r['hits'] and not r['why'] else ('why' if r['why'] else 'hit')}'>"
            f"<td>{esc(r['set'])}</td><td><code>{esc(r['bin'])}</code></td><td>{r['hits']}</td>"
            f"<td>{esc(r['first'] or '')}</td><td>{r['tests']}</td>"
            f"<td>{esc(r['why'] or '')}</td></tr>" for r in rs)
    head = ("<tr><th>set</th><th>bin</th><th>hits</th><th>first test</th><th>tests</th>"
            "<th>reason</th></tr>")
    entries = []
    for eid in summary["entries"]:
        rs = [r for r in rows if r["entry"] == eid["id"]]
        done = sum(1 for r in rs if r["hits"] or r["why"])
        entries.append(
            f"<details id='{esc(eid['id'])}'><summary><b>{esc(eid['id'])}</b>: {done} of {len(rs)} bins closed "
            f"({eid['hit']} hit, {eid['reasoned']} reasoned) &mdash; {esc(eid['about'])}; "
            f"tests: {esc(', '.join(eid['tests']))}</summary>"
            f"<table>{head}{bin_rows(rs)}</table></details>")
    summary_rows = "".join(
        f"<tr><td><a href='#{esc(e['id'])}'>{esc(e['id'])}</a></td><td>{e['bins']}</td>"
        f"<td>{e['hit']}</td><td>{e['reasoned']}</td>"
        f"<td>{e['bins'] - e['hit'] - e['reasoned']}</td>"
        f"<td>{100.0 * (e['hit'] + e['reasoned']) / max(e['bins'], 1):.1f} %</td></tr>"
        for e in summary["entries"])
    holes_html = ("<p>None.</p>" if not holes else
                  f"<table>{head}{bin_rows(holes)}</table>" if len(holes) <= 50 else
                  f"<details><summary>all {len(holes)}</summary><table>{head}{bin_rows(holes)}"
                  "</table></details>")
    rank_rows = "".join(f"<tr><td>{i + 1}</td><td>{esc(t)}</td><td>{n}</td><td>{c}</td>"
                        f"<td>{s:.1f}</td></tr>" for i, (t, n, c, s) in enumerate(ranking))
    s = summary
    title = ("the conformance suite's reach on the functional coverage plan" if reach
             else "functional coverage closure")
    smoke_html = "" if not smoke else (
        "<h2>The smoke group within its time budget</h2>"
        f"<p>Before: {esc(', '.join(smoke['before']))}: {smoke['before_bins']} bins in "
        f"{smoke['before_seconds']:.1f} s.<br>Chosen: {esc(', '.join(smoke['after']))}: "
        f"{smoke['after_bins']} bins in {smoke['after_seconds']:.1f} s (budget "
        f"{smoke['budget']:.1f} s).</p>")
    k = summary.get("kit")
    kit_html = "" if not k else (
        f"<p class='big {'good' if k['hit'] == k['reachable'] else 'bad'}'>Kit-reachable bins: "
        f"<b>{k['hit']} of {k['reachable']} ({k['pct']:.2f} %)</b>; {k['out_of_reach']} bins out "
        "of the kit's reach, each with its reason (<code>conformance/kit_bins.json</code>, shown "
        "below as reasoned where zb_rop's own tests do not hit them)"
        + ("; the golden model's reach cross-checked test by test"
           + (" <b>with disagreements</b> (above)" if summary["problems"] else ": agrees")
           if k["cross_checked"] else "") + ".</p>")
    doc = f"""<!doctype html><html><head><meta charset="utf-8">
<title>zblend {title}: {s['closed']} of {s['bins']} bins</title>
<style>
body {{ font-family: sans-serif; margin: 1.5em; }}
table {{ border-collapse: collapse; margin: 0.5em 0 1em; }}
td, th {{ border: 1px solid #ccc; padding: 2px 8px; text-align: left; font-size: 13px; }}
tr.hole td {{ background: #fde2e2; }} tr.why td {{ background: #fff6d5; }}
.big {{ font-size: 20px; }} .bad {{ color: #c62828; }} .good {{ color: #1a7f37; }}
details {{ margin: 4px 0; }}
</style></head><body>
<h1>{title[0].upper() + title[1:]}</h1>
<p class="big {'good' if s['closed'] == s['bins'] else ('' if reach else 'bad')}">{s['closed']} of {s['bins']}
bins closed ({s['closed_pct']:.2f} %): {s['hit']} hit, {s['reasoned']} unreachable with a
reason, <b>{s['holes']} holes</b></p>
{kit_html}<p>Group <code>{esc(s['group'])}</code>, {s['tests']} tests, RTL parameter sets
{esc(', '.join(s['sets']))}; plan <code>tb/cov/coverage_plan.json</code>, {len(s['entries'])}
entries.</p>
{''.join(f'<p class="bad">{esc(p)}</p>' for p in s['problems'])}
<table><tr><th>entry</th><th>bins</th><th>hit</th><th>reasoned</th><th>holes</th>
<th>closed</th></tr>{summary_rows}</table>
<h2>{'Not reached' if reach else 'Holes'} ({len(holes)})</h2>
{holes_html}
<h2>Plan entries</h2>
{''.join(entries)}
<h2>Unreachable, with reasons ({len(reasoned)})</h2>
<table>{head}{bin_rows(reasoned)}</table>
<h2>Tests ranked by the bins they add</h2>
<table><tr><th>rank</th><th>test</th><th>new bins</th><th>bins so far</th><th>seconds</th></tr>
{rank_rows}</table>
{smoke_html}
</body></html>
"""
    with open(path, "w") as f:
        f.write(doc)


def smoke_choice(groups, smoke_group, hits, seconds, runs):
    """The smoke group before (its tests in this run, their bins and seconds) and the set
    chosen within its time."""
    before = [t["name"] for t in groups[smoke_group] if t["name"] in seconds]
    budget = sum(seconds[n] for n in before)
    candidates = [n for n, rtl, _, _ in runs if rtl == "default"]
    after, after_bins, after_s = choose_smoke(hits, seconds, candidates, budget, before)
    before_bins = set().union(*(hits[n] for n in before)) if before else set()
    return {"before": before, "before_bins": len(before_bins), "before_seconds": budget,
            "after": after, "after_bins": len(after_bins), "after_seconds": after_s,
            "budget": budget}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter,
                                 epilog=__doc__.split("\n\n", 1)[1])
    ap.add_argument("run", help="the run's output directory (regress.py --coverage, or with "
                    "--conformance conformance.py's)")
    ap.add_argument("--group", default="coverage", help="the group that ran (default coverage)")
    ap.add_argument("--smoke", default="smoke",
                    help="the group whose time budget the chosen smoke set keeps (default smoke)")
    ap.add_argument("--conformance", action="store_true",
                    help="RUN is a conformance run: measure the suite's reach")
    ap.add_argument("--kit-bins", help="with --conformance: the kit-unreachable bins "
                    "(conformance/kit_bins.json)")
    ap.add_argument("--reach", help="with --conformance: the golden reach (zblend conformance "
                    "reach --json) to cross-check")
    ap.add_argument("--min-reach", type=float, default=0.0,
                    help="with --kit-bins: fail below this percent of kit-reachable bins hit")
    ap.add_argument("--plan", default=coverage_plan.DEFAULT, help="the coverage plan")
    ap.add_argument("--tests-file", default=regressions.DEFAULT, help="the regression file")
    ap.add_argument("--out", help="where the report goes (default: the run's directory)")
    a = ap.parse_args()
    out = a.out or a.run
    try:
        entries = coverage_plan.load(a.plan)
        if a.conformance:
            for e in entries:  # the suite runs zb_rop at the default parameters
                e["sets"] = [x for x in e["sets"] if x == "default"]
            runs = load_conformance(a.run)
        else:
            groups = regressions.load(a.tests_file)
            if a.group not in groups or a.smoke not in groups:
                usage_error(f"no group {a.group if a.group not in groups else a.smoke} in "
                            f"{a.tests_file}")
            runs = load_run(a.run, a.group, a.tests_file)
        if not runs:
            usage_error(f"{a.run}: no coverage counts: run scripts/regress.py run GROUP "
                        "--coverage, or scripts/conformance.py with the plan's covers, first "
                        "(docs/coverage.md)")
        table, problems = close(entries, runs)
        if not a.conformance:
            names = [t["name"] for t in groups[a.group]]
            for e in entries:
                for t in e["tests"]:
                    if not any(n == t or n.startswith(t + "-") for n in names):
                        problems.append(f"plan entry {e['id']}: test {t} is not in group "
                                        f"{a.group}")
        kit_rows = None
        if a.conformance and a.kit_bins:
            kit_rows = reach_check.mark(table, reach_check.load_kit_bins(a.kit_bins))
        if a.conformance and a.reach:
            if kit_rows is None:
                usage_error("--reach needs --kit-bins (which bins the golden reach counts)")
            problems += reach_check.cross_check(reach_check.load_reach(a.reach), kit_rows,
                                                test_bins(table, runs))
    except (coverage_plan.PlanError, regressions.RegressionError, reach_check.ReachError) as e:
        usage_error(str(e))
    except (OSError, ValueError, KeyError) as e:
        usage_error(f"{a.run}: unreadable run: {e}")
    rows = sorted(table.values(), key=lambda r: (bool(r["hits"] or r["why"]), r["set"],
                                                 coverage_plan.natural_key(r["bin"])))
    seconds = {n: s for n, _, s, _ in runs}
    hits = test_bins(table, runs)
    ranking = rank(hits, seconds)
    smoke = None if a.conformance else smoke_choice(groups, a.smoke, hits, seconds, runs)
    hit = sum(1 for r in rows if r["hits"])
    reasoned = sum(1 for r in rows if r["why"])
    summary = {
        "group": "the conformance suite" if a.conformance else a.group, "tests": len(runs),
        "sets": sorted({r for _, r, _, _ in runs}),
        "bins": len(rows), "hit": hit, "reasoned": reasoned, "closed": hit + reasoned,
        "holes": len(rows) - hit - reasoned,
        "closed_pct": 100.0 * (hit + reasoned) / max(len(rows), 1), "problems": problems,
        "entries": [{"id": e["id"], "about": e.get("about", ""), "tests": e["tests"],
                     "bins": sum(1 for r in rows if r["entry"] == e["id"]),
                     "hit": sum(1 for r in rows if r["entry"] == e["id"] and r["hits"]),
                     "reasoned": sum(1 for r in rows if r["entry"] == e["id"] and r["why"])}
                    for e in entries],
        "ranking": [{"test": t, "new_bins": n, "cumulative": c, "seconds": s}
                    for t, n, c, s in ranking],
        "smoke": smoke,
    }
    if kit_rows is not None:
        # A kit-reachable bin the plan itself calls unreachable (with its reason) and that no
        # test hit leaves the reach's count, as it leaves the closure's.
        planned = [r for r in kit_rows if r["hits"] or not r["why"]]
        got = sum(1 for r in planned if r["hits"])
        summary["kit"] = {"reachable": len(planned), "hit": got,
                          "pct": 100.0 * got / max(len(planned), 1),
                          "plan_unreachable": len(kit_rows) - len(planned),
                          "out_of_reach": len(table) - len(kit_rows),
                          "cross_checked": bool(a.reach)}
    name = "reach" if a.conformance else "closure"
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, name + ".json"), "w") as f:
        json.dump({"summary": summary, "bins": rows}, f, indent=1)
    with open(os.path.join(out, "holes.txt"), "w") as f:
        for r in rows:
            if not r["hits"] and not r["why"]:
                f.write(f"{r['set']} {r['bin']}\n")
    write_html(os.path.join(out, name + ".html"), summary, rows, ranking, smoke, a.conformance)
    print(f"coverage: plan {summary['closed']} of {summary['bins']} bins closed "
          f"({summary['closed_pct']:.2f} %): {hit} hit, {reasoned} unreachable with a reason, "
          f"{summary['holes']} holes; {len(runs)} tests, sets {', '.join(summary['sets'])}")
    for p in problems:
        print(f"coverage: {p}")
    if smoke:
        print(f"coverage: smoke {len(smoke['before'])} tests, {smoke['before_bins']} bins in "
              f"{smoke['budget']:.1f} s; chosen {len(smoke['after'])} tests, "
              f"{smoke['after_bins']} bins in {smoke['after_seconds']:.1f} s: "
              f"{' '.join(smoke['after'])}")
    print(f"coverage: report {os.path.join(out, name + '.html')}; holes in "
          f"{os.path.join(out, 'holes.txt')}")
    if a.conformance and kit_rows is not None:
        k = summary["kit"]
        got, pct = k["hit"], k["pct"]
        print(f"coverage: conformance reach on the kit-reachable bins: {got} of {k['reachable']} "
              f"({pct:.2f} %); {k['plan_unreachable']} more the plan calls unreachable; "
              f"{k['out_of_reach']} bins out of the kit's reach, each with its reason "
              f"({a.kit_bins})")
        for r in kit_rows:
            if not r["hits"] and not r["why"]:
                print(f"coverage: not reached: {r['bin']}")
        if pct < a.min_reach:
            print(f"coverage: the reach {pct:.2f} % is below --min-reach {a.min_reach}")
            return 1
    if a.conformance:
        return 1 if problems else 0
    return 0 if summary["holes"] == 0 and not problems else 1


if __name__ == "__main__":
    sys.exit(main())
