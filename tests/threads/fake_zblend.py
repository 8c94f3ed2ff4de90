#!/usr/bin/env python3
"""A zblend whose output depends on the thread count, for check_invariance.py to catch.

Runs the real zblend (first argument), then, with --threads 3, changes what FAKE_CHANGE names
in the run's --out-dir: "counter" adds 1 to the first row's rtl_cycles in summary.csv, "png"
flips the last byte of the first PNG, "host" only changes host_ms and peak_rss_bytes (which the
checker must let pass)."""
import csv
import json
import os
import subprocess
import sys
from pathlib import Path

real, args = sys.argv[1], sys.argv[2:]
rc = subprocess.call([real] + args)
if rc or args[args.index("--threads") + 1] != "3":
    sys.exit(rc)
out = Path(args[args.index("--out-dir") + 1])
change = os.environ.get("FAKE_CHANGE", "counter")
summary = out / "summary.csv"
rows = list(csv.DictReader(summary.open()))
if change in ("counter", "host"):
    col = "rtl_cycles" if change == "counter" else "host_ms"
    rows[0][col] = str(float(rows[0][col]) + 1) if change == "host" else str(int(rows[0][col]) + 1)
    with summary.open("w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]), lineterminator="\n")
        w.writeheader()
        w.writerows(rows)
if change == "host":
    stats = out / "stats.json"
    d = json.loads(stats.read_text())
    d["memory"]["peak_rss_bytes"] += 4096
    d["methods"][0]["host_ms"] += 1.0
    stats.write_text(json.dumps(d))
if change == "png":
    png = sorted(out.glob("*.png"))[0]
    data = bytearray(png.read_bytes())
    data[-1] ^= 1
    png.write_bytes(bytes(data))
