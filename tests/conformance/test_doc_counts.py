#!/usr/bin/env python3
"""docs/conformance.md against the tools it describes: the tiers' test counts, the quick tier's
names, the suite's goal count and its parts, the reach sample as the command prints it, and every
`conformance check SUITE OUT` naming a suite a documented export writes and an OUT a documented
run of scripts/conformance.py on that suite writes. One FAIL line per difference; exit 1 on any.

  test_doc_counts.py ZBLEND DOC
"""
import fnmatch
import re
import shlex
import subprocess
import sys


def tool(zblend, *args):
    return subprocess.run([zblend, *args], check=True, capture_output=True, text=True).stdout


def listed(zblend, *args):
    """The test names `export --list ARGS` prints, in its order."""
    return [ln.split()[0] for ln in tool(zblend, "conformance", "export", "--list", *args)
            .splitlines()[1:-1]]


def number(s):
    return int(s.replace(",", ""))


def main(zblend, doc_path):
    doc = open(doc_path).read()
    lines = doc.splitlines()
    fails = []

    def want(ok, what):
        if not ok:
            fails.append(what)

    tiers = {"full": listed(zblend), "quick": listed(zblend, "--quick"),
             "random": listed(zblend, "--seed", "7")}
    for tier, names in tiers.items():
        rows = [ln for ln in lines if re.match(rf"\| {tier} \| ", ln)]
        want(len(rows) == 1, f"the Tiers table has no one row '{tier}'")
        for r in rows:
            got = number(r.split("|")[3].strip())
            want(got == len(names), f"the Tiers table: {tier} {got} tests, the tool lists "
                                    f"{len(names)}")
    for ln in lines:
        m = re.search(r"conformance export (--quick |--seed 7 )?\S+ +# the (?:full|quick|seeded "
                      r"random) tier.*: (\d+) tests", ln)
        if m:
            tier = {"--quick ": "quick", "--seed 7 ": "random"}.get(m.group(1), "full")
            want(number(m.group(2)) == len(tiers[tier]),
                 f"'{ln.strip()}': the tool lists {len(tiers[tier])}")

    # The quick tier's names: the paragraph "The quick tier: `a`, `b*` (...), ...".
    m = re.search(r"^The quick tier: (.*?)\.\n", doc, re.S | re.M)
    want(m is not None, "no paragraph 'The quick tier: ...'")
    if m:
        quick, named = set(tiers["quick"]), set()
        for name in re.findall(r"`([^`]+)`", m.group(1)):
            matched = fnmatch.filter(tiers["quick"], name)
            want(matched, f"the quick tier's list names `{name}`, not in the quick tier")
            named.update(matched)
        for name in tiers["quick"]:
            want(name in named, f"the quick tier's list lacks `{name}`")

    # The goals: their count in the reach section, its parts, every "goals A of B" and the
    # sample of `conformance reach` as it prints.
    goals = number(re.search(r"suite goals: \d+ of (\d+)", tool(zblend, "conformance",
                                                               "reach")).group(1))
    m = re.search(r'the suite\'s own goals \("goal\.\*", ([\d,]+)\):(.*?)\n\n', doc, re.S)
    want(m is not None, "no 'the suite's own goals (\"goal.*\", N)' in the reach section")
    if m:
        want(number(m.group(1)) == goals, f"the goals are {m.group(1)}; the tool counts {goals}")
        parts = [number(p) for p in re.findall(r"\(([\d,]+)\)", m.group(2))]
        want(sum(parts) == goals, f"the goals' parts {parts} add to {sum(parts)}, not {goals}")
    for a, b in re.findall(r"goals ([\d,]+) of ([\d,]+)", doc):
        want(number(b) == goals, f"'goals {a} of {b}': the tool counts {goals}")
    for i, ln in enumerate(lines):
        if ln.startswith("$ build/zblend conformance reach"):
            out = tool(zblend, *shlex.split(ln)[2:]).splitlines()
            for sample in lines[i + 1:]:
                if sample.startswith("```"):
                    break
                want(sample == "..." or sample in out,
                     f"the sample of '{ln[2:]}' shows '{sample}', which it does not print")

    # Every `conformance check SUITE OUT` after the steps that make both.
    exported, ran = set(), set()
    for i, ln in enumerate(lines, 1):
        # A command continued with a backslash is read whole.
        k = i
        while ln.startswith(("build/", "python3 ")) and ln.rstrip().endswith("\\") and k < len(lines):
            ln = ln.rstrip()[:-1] + " " + lines[k].strip()
            k += 1
        words = shlex.split(ln.split("#")[0]) if ln.startswith(("build/", "python3 ")) else []
        if words[1:3] == ["conformance", "export"]:
            exported.add(words[-1])
        elif len(words) > 1 and words[1].endswith("conformance.py") and "--out" in words:
            ran.add((words[words.index("--suite") + 1], words[words.index("--out") + 1]))
        elif words[1:3] == ["conformance", "check"]:
            suite, out = words[3], words[4]
            want(suite in exported, f"line {i}: check reads {suite}, which no documented "
                                    "export before it writes")
            want((suite, out) in ran, f"line {i}: check reads {out}, which no documented run "
                                      f"of conformance.py on {suite} before it writes")
    for f in fails:
        print(f"FAIL: {doc_path}: {f}")
    print(f"doc counts: {len(fails)} differences")
    return 1 if fails else 0


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: test_doc_counts.py ZBLEND DOC")
    sys.exit(main(*sys.argv[1:]))
