#!/usr/bin/env python3
"""Runs the README's commands as a user would copy them, so that an example that stops working
fails CI (also docs/verification.md's, which the README points to).

Every command of every ```sh block of the file, in order, in a scratch directory where build/
is the build tree and scripts/ the project's: each must exit 0, and each output it names
(--out, --out-dir, --stats, an export's directory) must exist and not be empty; a `conformance
check`'s DUT directory must be one an earlier command writes (the DUT's own run stands in as
the suite's expected planes). Not run here,
each for its reason (REASONS below): `make run` and `make test` (.ci/run runs both, this test
is inside the second) and the other make targets (hours of both cores; `make -n` checks the
target exists), and commands whose arguments are the reader's own files (a DUT's sources, a
hosts file, a Slurm partition: their subcommand's --help must work instead).
Usage: test_readme.py FILE.md BUILD_DIR SOURCE_DIR"""
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

# The reader's own files: what a command may name that this machine cannot have.
PLACEHOLDERS = ("my_rop.sv", "my_adapter.sv", "my_rop.profile.json", "--sshloginfile", "--partition=")


def commands(readme: str):
    """(line number, command) for each command of each ```sh block, continuations joined."""
    out, block, pending, start = [], False, "", 0
    for n, line in enumerate(readme.splitlines(), 1):
        if line.startswith("```"):
            block = line.strip() == "```sh" and not block
            continue
        if not block:
            continue
        code = re.sub(r"(^|\s)#.*$", "", line).rstrip()
        if not pending:
            start = n
        if code.endswith("\\"):
            pending += code[:-1] + " "
            continue
        text = (pending + code).strip()
        pending = ""
        if text:
            out.append((start, text))
    return out


def outputs(argv):
    """The paths a command says it writes."""
    paths = [argv[i + 1] for i, a in enumerate(argv[:-1]) if a in ("--out", "--out-dir", "--stats")]
    if argv[1:3] == ["conformance", "export"]:
        paths.append(argv[3])
    return paths


def dut_from_golden(suite: Path, dut: Path):
    """A DUT's output for `conformance check`: the suite's own expected planes as got files."""
    for test in sorted(p for p in suite.iterdir() if p.is_dir()):
        (dut / test.name).mkdir(parents=True, exist_ok=True)
        for expect in test.glob("expect.*.hex"):
            shutil.copy(expect, dut / test.name / expect.name.replace("expect.", "got.", 1))


def main() -> int:
    if len(sys.argv) != 4:
        print(__doc__.splitlines()[-1], file=sys.stderr)
        return 2
    readme, build, source = Path(sys.argv[1]), Path(sys.argv[2]).resolve(), Path(sys.argv[3]).resolve()
    cmds = commands(readme.read_text())
    if len(cmds) < 5:
        print(f"FAIL: {readme}: {len(cmds)} commands in its ```sh blocks; expected the command block")
        return 1
    failures = ran = 0
    promised = set()  # what the commands so far say they write (run or not)
    with tempfile.TemporaryDirectory() as tmp:
        work = Path(tmp)
        (work / "build").symlink_to(build)
        (work / "scripts").symlink_to(source / "scripts")
        for line, text in cmds:
            argv = shlex.split(text)
            where = f"README.md:{line}: {text}"
            if argv[1:3] == ["conformance", "check"] and len(argv) > 4 and argv[4] not in promised:
                print(f"FAIL: {where}: nothing before it writes {argv[4]} (a DUT's run must)")
                failures += 1
                continue
            promised.update(outputs(argv))
            if argv[0] == "make":
                target = argv[1] if len(argv) > 1 else ""
                r = subprocess.run(["make", "-n", "-C", str(source), *argv[1:]],
                                   stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
                if r.returncode != 0:
                    print(f"FAIL: {where}: no such make target ({r.stderr.strip()[:200]})")
                    failures += 1
                else:
                    print(f"make   {where} (target exists; .ci/run or its own run executes it)")
                continue
            if any(p in text for p in PLACEHOLDERS):
                sub = [a for a in argv[:3] if not a.startswith("-")]
                r = subprocess.run(sub + ["--help"], cwd=work, stdout=subprocess.DEVNULL,
                                   stderr=subprocess.PIPE, text=True)
                if r.returncode != 0:
                    print(f"FAIL: {where}: '{' '.join(sub)} --help' exited {r.returncode}: "
                          f"{r.stderr.strip()[:200]}")
                    failures += 1
                else:
                    print(f"help   {where} (the reader's own files; its --help works)")
                continue
            if argv[1:3] == ["conformance", "check"]:
                dut_from_golden(work / argv[3], work / argv[4])
            r = subprocess.run(argv, cwd=work, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                               text=True, env=dict(os.environ, PYTHONDONTWRITEBYTECODE="1"))
            ran += 1
            bad = []
            if r.returncode != 0:
                bad.append(f"exit {r.returncode}")
            for p in outputs(argv):
                q = work / p
                if not q.exists() or (q.is_file() and q.stat().st_size == 0) or \
                        (q.is_dir() and not any(q.iterdir())):
                    bad.append(f"{p} missing or empty")
            if not outputs(argv) and not r.stdout.strip():
                bad.append("printed nothing")
            if bad:
                print(r.stdout[-3000:])
                print(f"FAIL: {where}: {', '.join(bad)}")
                failures += 1
            else:
                print(f"ran    {where}")
    print(f"readme: {ran} commands run, {len(cmds) - ran} checked otherwise, {failures} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
