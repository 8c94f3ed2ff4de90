#!/usr/bin/env bash
# Timing under back-pressure: the issue schedule of the accepts the RTL made (rtl_timing.h).
# Mutant 744 takes zb_input's I as free only when the window takes its fragment, not when I is
# empty (its "I empty" term tied off): a fragment accepted while the window is full and I empty waits in S a cycle longer.
# Every write stays right, and I is empty with the window full only after a valid gap, so only
# the timing check under back-pressure sees it: the run must stop naming the late fragment,
# pass with --no-timing-check, and the unmutated netlist must pass with the check.
set -u
source "$(dirname "$0")/../lib.sh"
mutant_args "$@"

expect_mutant 744 '-mode const1 -module zb_rop -cell $flatten\\u_input.$not$rtl/zb_input.sv:54' \
  "the I-free mutant"
args=(--suite random --seed 1000 --fragments 50000 --backpressure 0.3 -q --mismatch-fst "")
"$tb" --mutant 0 "${args[@]}" >"$tmp/out.txt" 2>&1 || fail "mutant 0 fails under back-pressure"
"$tb" --mutant 744 --no-timing-check "${args[@]}" >"$tmp/out.txt" 2>&1 ||
  fail "mutant 744 fails without the timing check: then this test no longer shows the check alone"
"$tb" --mutant 744 "${args[@]}" >"$tmp/out.txt" 2>&1
rc=$?
[[ $rc -eq 1 ]] || fail "mutant 744 under back-pressure: exit $rc, want 1"
grep -qE 'rtl: fragment #[0-9]+ \(position [0-9]+ of tile \([0-9]+,[0-9]+\).s stream\) reached X4 [0-9]+ cycles after its issue in the schedule' "$tmp/out.txt" ||
  fail "no 'fragment #N ... reached X4 N cycles after its issue in the schedule' line"
echo "ok: $(grep -o 'fragment #[0-9]* .*the tile.s first [0-9]*' "$tmp/out.txt")"
