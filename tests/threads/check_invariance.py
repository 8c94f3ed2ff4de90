#!/usr/bin/env python3
"""Thread-count invariance: the same command with each thread count must write the same files.

Runs zblend once per thread count into a directory of its own and compares every file written
with the first run's, byte for byte, except host quantities: the host_ms column of a CSV file and
the *_ms, peak_rss_bytes keys of a JSON file (host time and memory, which no thread count fixes).
Exit 0 when all agree, 1 with the first difference of each file, 2 on bad usage.

  check_invariance.py --zblend Z --out DIR --threads 1,2,3,8 -- render --scene cad ... {out}
  check_invariance.py ... --flag -j -- lab --scenes cad,quads ... --out-dir {out}

{out} in the command is each run's directory; the thread count is given as --threads N (or as
the option --flag names)."""
import argparse
import csv
import io
import json
import shutil
import subprocess
import sys
from pathlib import Path

HOST_COLUMNS = {"host_ms"}
HOST_KEYS = {"peak_rss_bytes"}


def scrub_json(value):
    if isinstance(value, dict):
        return {k: scrub_json(v) for k, v in value.items()
                if not (k.endswith("_ms") or k in HOST_KEYS)}
    if isinstance(value, list):
        return [scrub_json(v) for v in value]
    return value


def normalized(path: Path) -> bytes:
    data = path.read_bytes()
    if path.suffix == ".csv":
        rows = list(csv.reader(io.StringIO(data.decode())))
        if rows:
            keep = [i for i, name in enumerate(rows[0]) if name not in HOST_COLUMNS]
            out = io.StringIO()
            csv.writer(out, lineterminator="\n").writerows([[r[i] for i in keep if i < len(r)]
                                                            for r in rows])
            return out.getvalue().encode()
    if path.suffix == ".json":
        return json.dumps(scrub_json(json.loads(data)), sort_keys=True, indent=1).encode()
    return data


def first_difference(a: bytes, b: bytes) -> str:
    la, lb = a.decode(errors="replace").splitlines(), b.decode(errors="replace").splitlines()
    for n, (x, y) in enumerate(zip(la, lb), 1):
        if x != y:
            return f"line {n}:\n      {x[:160]}\n    ≠ {y[:160]}"
    if len(la) != len(lb):
        return f"{len(la)} lines against {len(lb)}"
    for n, (x, y) in enumerate(zip(a, b)):
        if x != y:
            return f"byte {n}: 0x{x:02x} against 0x{y:02x}"
    return f"{len(a)} bytes against {len(b)}"


def files(root: Path) -> dict:
    return {p.relative_to(root).as_posix(): p for p in sorted(root.rglob("*")) if p.is_file()}


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--zblend", required=True, help="the zblend program")
    ap.add_argument("--out", required=True, help="work directory (replaced)")
    ap.add_argument("--threads", default="1,2,3,8", help="thread counts, the first the baseline")
    ap.add_argument("--flag", default="--threads", help="the option that takes the count")
    ap.add_argument("--ignore", action="append", default=[],
                    help="a glob of files not compared (each use says why, where it is given)")
    ap.add_argument("command", nargs=argparse.REMAINDER, help="-- then zblend's arguments")
    a = ap.parse_args()
    command = a.command[1:] if a.command[:1] == ["--"] else a.command
    if not command or not any("{out}" in c for c in command):
        ap.error("give zblend's arguments after --, with {out} where its output goes")
    try:
        counts = [int(t) for t in a.threads.split(",")]
    except ValueError:
        ap.error(f"--threads: '{a.threads}' is not a comma-separated list of integers")
    if len(counts) < 2 or min(counts) < 1:
        ap.error("--threads: at least two counts, each 1 or more")

    work = Path(a.out)
    shutil.rmtree(work, ignore_errors=True)
    runs = {}
    for t in counts:
        out = work / f"threads-{t}"
        argv = [a.zblend] + [c.replace("{out}", str(out)) for c in command] + [a.flag, str(t)]
        print(f"invariance: {' '.join(argv)}", flush=True)
        r = subprocess.run(argv, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        (work / f"threads-{t}.log").write_text(r.stdout)
        if r.returncode != 0:
            print(r.stdout[-4000:])
            print(f"FAIL: {a.flag} {t} exited {r.returncode}")
            return 1
        runs[t] = {k: v for k, v in files(out).items()
                   if not any(Path(k).match(g) for g in a.ignore)}

    base, failures = counts[0], 0
    for t in counts[1:]:
        if set(runs[t]) != set(runs[base]):
            only = sorted(set(runs[t]) ^ set(runs[base]))
            print(f"FAIL: {a.flag} {t} wrote another set of files than {a.flag} {base}: {only[:8]}")
            failures += 1
        for name in sorted(set(runs[t]) & set(runs[base])):
            x, y = normalized(runs[base][name]), normalized(runs[t][name])
            if x != y:
                print(f"FAIL: {name}: {a.flag} {base} and {a.flag} {t} differ at "
                      f"{first_difference(x, y)}")
                failures += 1
    n = len(runs[base])
    if failures:
        print(f"invariance: {failures} difference(s) over {n} files and {len(counts)} runs")
        return 1
    print(f"invariance: {n} files alike for {a.flag} {', '.join(map(str, counts))} "
          f"(host time and memory aside)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
