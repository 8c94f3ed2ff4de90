#!/usr/bin/env bash
# A mutant that the lock-step monitor catches reports its first wrong write (docs/mutation.md):
# mutant 2 of the netlist (Yosys's sample, seed 1) ties bit 13 of the depth in zb_depth's peel
# compare (z > peel, X2) to 1, so a fragment in front of the peel plane may pass the peel test.
# The run must stop at the X4 write it spoils, naming the fragment, the cycle, both values and
# the pixel's history, with an FST that replays it; and the unmutated netlist (mutant 0) must
# pass the same run.
set -u
source "$(dirname "$0")/mutant_lib.sh" "$@"

expect_mutant 2 '^mutate -mode const1 -module zb_rop -cell $flatten\\u_depth.$gt$rtl/zb_depth.sv:[0-9]*$[0-9]* -port A -portbit 13 ' \
  "the peel-compare mutant"
args=(--suite random --seed 1 --fragments 300000)
"$tb" --mutant 0 "${args[@]}" -q --mismatch-fst "" >"$tmp/out.txt" 2>&1 ||
  fail "the unmutated netlist (mutant 0) fails: it is not zb_rop"
echo "ok: mutant 0 passes"
lockstep mutant-2 X4 --mutant 2 "${args[@]}"
grep -qE '^  X4: rtl wrote depth 0x[0-9a-f]+, no coverage; golden no depth, no coverage$' "$tmp/out.txt" ||
  fail "mutant-2: the X4 line does not show the depth write the peel test should have stopped"
