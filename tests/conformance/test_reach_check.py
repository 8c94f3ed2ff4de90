#!/usr/bin/env python3
"""scripts/reach_check.py: the golden reach held to zb_rop's covers. Passes on agreement, and
names each kind of disagreement: a bin hit on one side only (both ways), the two bin lists
differing (both ways); a same-pixel distance compared whatever came between."""
import os
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
import reach_check  # noqa: E402

BINS = ["frag_depth.zero", "frag_depth.max", "same_pixel[distance=1,between=Calm]",
        "same_pixel[distance=1,between=Gap]", "window_slot[slot=0,event=Taken]"]
failures = passes = 0


def check(cond, what):
    global failures, passes
    if cond:
        passes += 1
    else:
        failures += 1
        print(f"FAIL: {what}")


def table():
    return {("default", b): {"bin": b, "hits": 1, "why": None} for b in BINS}


with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
    f.write('{"unreachable": [{"bins": "window_slot\\\\[.*", "why": "the window is the DUT\'s"}]}')
kit = reach_check.load_kit_bins(f.name)
os.unlink(f.name)
t = table()
rows = reach_check.mark(t, kit)
check(len(rows) == 4 and t[("default", BINS[4])]["kit_why"] == "the window is the DUT's",
      "kit_bins marks the window's bin out of reach, the four others in")
reach = {"plan_bins": BINS[:4], "tests": {"t": {BINS[0]: 2, BINS[2]: 1}}}
rtl = {"t": {("default", BINS[0]), ("default", BINS[3]), ("default", BINS[4])}}
# Golden Calm and zb_rop Gap at distance 1: the same distance, agreement.
check(reach_check.cross_check(reach, rows, rtl) == [], "agreement passes")
p = reach_check.cross_check(reach, rows, {"t": {("default", BINS[3])}})
check(len(p) == 1 and "frag_depth.zero: golden hit, zb_rop not hit" in p[0], f"golden-only bin: {p}")
p = reach_check.cross_check(reach, rows, {"t": rtl["t"] | {("default", BINS[1])}})
check(len(p) == 1 and "frag_depth.max: golden not hit, zb_rop hit" in p[0], f"zb_rop-only bin: {p}")
p = reach_check.cross_check(reach, rows, {"t": {("default", BINS[0])}})
check(len(p) == 1 and "same_pixel[distance=1]: golden hit" in p[0], f"a distance on one side: {p}")
p = reach_check.cross_check(dict(reach, plan_bins=BINS[:3]), rows, rtl)
check(any("same_pixel[distance=1,between=Gap] is kit-reachable" in x for x in p), f"list short: {p}")
p = reach_check.cross_check(dict(reach, plan_bins=BINS), rows, rtl)
check(any("window_slot[slot=0,event=Taken] is counted by the golden reach" in x for x in p),
      f"list long: {p}")
p = reach_check.cross_check(reach, rows, {"u": set()})
check(any("test u ran on zb_rop but the golden reach has no entry" in x for x in p), f"test: {p}")
try:
    reach_check.load_kit_bins("/nonexistent.json")
    check(False, "a missing kit_bins file raises")
except reach_check.ReachError as e:
    check("/nonexistent.json" in str(e), f"the error names the file: {e}")
print(f"{passes} passed, {failures} failed")
sys.exit(1 if failures else 0)
