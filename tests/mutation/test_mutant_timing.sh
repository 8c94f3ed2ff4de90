#!/usr/bin/env bash
# Timing under back-pressure: the issue schedule of the accepts the RTL made (rtl_timing.h).
# Mutant 684 makes the window's M-hit term for a fragment taken in (`pick_q & eq_k`: K holds a
# fragment to its pixel) see slot 7 in K always (pick_q bit 7 held at 1): a fragment taken in to
# slot 7's pixel then waits as if K had it, reaching X4 later than the schedule. Every write stays right,
# so only the timing check sees it: under back-pressure the run must stop naming the late
# fragment, pass with --no-timing-check, and the unmutated netlist must pass with the check.
set -u
source "$(dirname "$0")/../lib.sh"
mutant_args "$@"

expect_mutant 684 '-mode const1 -module zb_rop -cell $flatten\\u_window.$and$rtl/zb_issue_window.sv:130$[0-9]* -port A -portbit 7 ' \
  "the window's M-hit mutant"
args=(--suite random --seed 1000 --fragments 50000 --backpressure 0.3 -q --mismatch-fst "")
"$tb" --mutant 0 "${args[@]}" >"$tmp/out.txt" 2>&1 || fail "mutant 0 fails under back-pressure"
"$tb" --mutant 684 --no-timing-check "${args[@]}" >"$tmp/out.txt" 2>&1 ||
  fail "mutant 684 fails without the timing check: then this test no longer shows the check alone"
"$tb" --mutant 684 "${args[@]}" >"$tmp/out.txt" 2>&1
rc=$?
[[ $rc -eq 1 ]] || fail "mutant 684 under back-pressure: exit $rc, want 1"
grep -qE 'rtl: fragment #[0-9]+ \(position [0-9]+ of tile \([0-9]+,[0-9]+\).s stream\) reached X4 [0-9]+ cycles after its issue in the schedule' "$tmp/out.txt" ||
  fail "no 'fragment #N ... reached X4 N cycles after its issue in the schedule' line"
echo "ok: $(grep -o 'fragment #[0-9]* .*the tile.s first [0-9]*' "$tmp/out.txt")"
