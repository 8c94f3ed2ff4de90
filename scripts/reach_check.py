"""The conformance suite's reach, the golden model's against zb_rop's (coverage_report.py
--conformance --kit-bins --reach; docs/conformance.md "What the suite reaches").

kit_bins.json names the plan bins a DUT cannot reach through the kit, each with why; the others
are kit-reachable, and `zblend conformance reach --json` counts those on the golden model, test
by test. Here both are held to zb_rop's bound covers on the same tests: the golden reach's bin
list must be exactly the kit-reachable bins, and per test a bin the golden model says is hit
must be hit by zb_rop's cover, and the other way round. The same-pixel bins are compared by
distance alone: the distance is the stream's and the schedule's (the order fragments are taken
in), but what came between at zb_rop's window (a gap, or the DUT refusing on its own) depends on
its skid register and window, which the port does not show; so per distance, a hit in any of
Calm, Gap and Full on one side asks for one on the other.
"""
import json
import re


class ReachError(Exception):
    pass


def load_kit_bins(path):
    """[(compiled regex, why)] of the kit-unreachable bins."""
    try:
        with open(path) as f:
            j = json.load(f)
        return [(re.compile(u["bins"]), u["why"]) for u in j["unreachable"]]
    except (OSError, ValueError, KeyError, TypeError, re.error) as e:
        raise ReachError(f"{path}: {e} (a JSON object with \"unreachable\": [{{\"bins\": REGEX, "
                         "\"why\": TEXT}}])") from e


def kit_reason(kit, name):
    return next((why for rx, why in kit if rx.fullmatch(name)), None)


def mark(table, kit):
    """Marks each row kit-reachable or not ("kit_why"); returns the kit-reachable rows."""
    out = []
    for row in table.values():
        row["kit_why"] = kit_reason(kit, row["bin"])
        if row["kit_why"] is None:
            out.append(row)
        elif not row["why"] and not row["hits"]:
            row["why"] = "out of the kit's reach: " + row["kit_why"]
    return out


def load_reach(path):
    try:
        with open(path) as f:
            j = json.load(f)
        j["plan_bins"], j["tests"]  # noqa: B018
        return j
    except (OSError, ValueError, KeyError) as e:
        raise ReachError(f"{path}: {e} (write it with `zblend conformance reach --json FILE`)") from e


SAME_PIXEL = re.compile(r"same_pixel\[distance=(\d+),between=\w+\]")


def compared(b):
    """The name a bin is compared under: a same-pixel distance without what came between."""
    m = SAME_PIXEL.fullmatch(b)
    return f"same_pixel[distance={m.group(1)}]" if m else b


def cross_check(reach, reachable_rows, hits, limit=20):
    """Problems: the bin lists differ, or a test where the golden model and zb_rop disagree on a
    bin. `hits` is {test: set of (set, bin)} from zb_rop's covers."""
    problems = []
    ours = {r["bin"] for r in reachable_rows}
    golden = set(reach["plan_bins"])
    for b in sorted(golden - ours)[:limit]:
        problems.append(f"reach: {b} is counted by the golden reach but kit_bins.json calls it "
                        "unreachable (or the plan has no such bin)")
    for b in sorted(ours - golden)[:limit]:
        problems.append(f"reach: {b} is kit-reachable by kit_bins.json but the golden reach does "
                        "not count it (conformance/reach.cpp)")
    disagree = []
    for test, rtl in hits.items():
        g = reach["tests"].get(test)
        if g is None:
            problems.append(f"reach: test {test} ran on zb_rop but the golden reach has no entry "
                            "(the same suite and options?)")
            continue
        rtl_hit = {compared(b) for _, b in rtl}
        golden_hit = {compared(b) for b, n in g.items() if n > 0 and b in golden}
        for b in sorted({compared(b) for b in golden & ours}):
            gh, rh = b in golden_hit, b in rtl_hit
            if gh != rh:
                disagree.append(f"reach: {test}: {b}: golden {'hit' if gh else 'not hit'}, "
                                f"zb_rop {'hit' if rh else 'not hit'}")
    problems += disagree[:limit]
    if len(disagree) > limit:
        problems.append(f"reach: {len(disagree) - limit} more disagreements")
    return problems
