#!/usr/bin/env bash
# A mutant that the lock-step monitor catches reports its first wrong write (docs/mutation.md):
# mutant 412 of the netlist (Yosys's sample, seed 1) ties bit 4 of the peel word in zb_depth's
# peel compare (z > peel, X2) to 0, so some fragments in front of the peel plane pass the peel
# test and blend (in this run the first is an accumulate pass's: it writes the accumulation).
# The run must stop at the X11 write it spoils, naming the fragment, the cycle, both values and
# the pixel's history, with an FST that replays it; and the unmutated netlist (mutant 0) must
# pass the same run.
set -u
source "$(dirname "$0")/../lib.sh"
mutant_args "$@"

expect_mutant 412 '^mutate -mode const0 -module zb_rop -cell $flatten\\u_depth.$gt$rtl/zb_depth.sv:[0-9]*$[0-9]* -port B -portbit 4 -wire u_depth.x2_peel_q ' \
  "the peel-compare mutant"
args=(--suite random --seed 1 --fragments 300000)
"$tb" --mutant 0 "${args[@]}" -q --mismatch-fst "" >"$tmp/out.txt" 2>&1 ||
  fail "the unmutated netlist (mutant 0) fails: it is not zb_rop"
echo "ok: mutant 0 passes"
lockstep mutant-412 X11 --mutant 412 "${args[@]}"
grep -qE '^  X11: rtl wrote (colour rgba\([0-9,]+\)|no colour, accumulation acc\([0-9,]+\) reveal [0-9]+); golden no colour$' "$tmp/out.txt" ||
  fail "mutant-412: the X11 line does not show the write the peel test should have stopped"
grep -qE 'peel_test=1' "$tmp/out.txt" || fail "mutant-412: the pass shown does not test the peel plane"
