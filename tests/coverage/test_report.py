#!/usr/bin/env python3
"""The closure report's parts on made-up counts (docs/coverage.md): a coverage file's cover
points, the ranking of tests by the bins they add, and the smoke set chosen in a budget."""
import os
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                "scripts"))
import coverage_plan  # noqa: E402
import coverage_report  # noqa: E402

failures = 0


def check(what, got, want):
    global failures
    if got != want:
        print(f"FAIL: {what}: got {got!r}, want {want!r}")
        failures += 1


# A coverage file: user points only, generate indices as Verilator writes them, per instance.
with tempfile.TemporaryDirectory() as d:
    dat = os.path.join(d, "t.dat")
    with open(dat, "w") as f:
        f.write("# SystemC::Coverage-3\n")
        for h, page, n in (("zb_rop.zb_rop.u_cov.g_slot__BRA__3__KET__.SlotWaits", "v_user/x", 7),
                           ("zb_rop.zb_rop.u_cov.FragDepthZero", "v_user/x", 0),
                           ("zb_rop.zb_rop.u_depth", "v_line/zb_depth", 99)):
            f.write(f"C '\001f\002a.sv\001l\00210\001page\002{page}\001h\002{h}' {n}\n")
    check("read_dat", coverage_plan.read_dat(dat),
          {"u_cov.g_slot[3].SlotWaits": 7, "u_cov.FragDepthZero": 0})

# Dimensions name the bins; a dimension numbered from 1.
entry = {"id": "d", "cover": "u_cov.g_dist[*].SamePixel*",
         "dims": [{"name": "distance", "from": 1}, {"name": "between", "values": ["Calm", "Gap"]}]}
check("bins", coverage_plan.bins(entry, {"u_cov.g_dist[0].SamePixelGap", "u_cov.g_dist[10].SamePixelCalm",
                                         "u_cov.g_dist[2].SamePixelCalm"}),
      [("d[distance=1,between=Gap]", "u_cov.g_dist[0].SamePixelGap"),
       ("d[distance=3,between=Calm]", "u_cov.g_dist[2].SamePixelCalm"),
       ("d[distance=11,between=Calm]", "u_cov.g_dist[10].SamePixelCalm")])

# Ranking: the test adding the most bins first; a test adding none is left out.
hits = {"a": {1, 2}, "b": {1, 2, 3, 4}, "c": {5}, "d": {1}}
secs = {"a": 1.0, "b": 10.0, "c": 2.0, "d": 0.5}
check("rank", coverage_report.rank(hits, secs), [("b", 4, 4, 10.0), ("c", 1, 5, 2.0)])

# Smoke in a budget of 4 s: b does not fit; a, c and d fit, and d adds nothing a does not.
chosen, got, spent = coverage_report.choose_smoke(hits, secs, ["a", "b", "c", "d"], 4.0)
check("smoke chosen", sorted(chosen), ["a", "c"])
check("smoke bins", got, {1, 2, 5})
check("smoke seconds", spent, 3.0)
# A budget that fits all: the smallest set reaching them all.
chosen, got, _ = coverage_report.choose_smoke(hits, secs, ["a", "b", "c", "d"], 100.0)
check("smoke, any budget", (sorted(chosen), got), (["b", "c"], {1, 2, 3, 4, 5}))

# The budget left is filled with the previous smoke's tests, in order, as they fit.
chosen, got, spent = coverage_report.choose_smoke(hits, secs, ["a", "b", "c", "d"], 4.0,
                                                  keep=["b", "d"])
check("smoke, filled", (chosen, spent), (["a", "c", "d"], 3.5))

# An entry of one set only, in a run of two: the other set lacks its covers (as LAYERS 0 lacks
# the layers unit's), which is no error; in its own set a missing cover still is.
only = {"id": "u", "cover": "u_unit.Hit", "sets": ["default"], "unreachable": []}
both = {"id": "b", "cover": "u_cov.Both", "sets": ["default", "small"], "unreachable": []}
runs = [("t1", "default", 1.0, {"u_unit.Hit": 2, "u_cov.Both": 1}),
        ("t2", "small", 1.0, {"u_cov.Both": 3})]
table, problems = coverage_report.close([only, both], runs)
check("a set without an entry's covers", (sorted(table), problems),
      ([("default", "b[]"), ("default", "u[]"), ("small", "b[]")], []))
try:
    coverage_report.close([only, both], [("t1", "default", 1.0, {"u_cov.Both": 1})])
    check("a missing cover in the entry's own set", "no error", "PlanError")
except coverage_plan.PlanError:
    pass

print("coverage_report_unit: " + ("FAILED" if failures else "all passed"))
sys.exit(1 if failures else 0)
