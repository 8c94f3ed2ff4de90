#!/usr/bin/env bash
# A mutant that the lock-step monitor catches reports its first wrong write (docs/mutation.md):
# mutant 195 of the netlist (Yosys's sample, seed 1) flips bit 14 of the peel word in zb_depth's
# peel compare (z > peel, X2) when bit 22 is clear, so some fragments behind the peel plane fail
# the peel test.
# The run must stop at the X4 write it spoils, naming the fragment, the cycle, both values and
# the pixel's history, with an FST that replays it; and the unmutated netlist (mutant 0) must
# pass the same run.
set -u
source "$(dirname "$0")/../lib.sh"
mutant_args "$@"

expect_mutant 195 '^mutate -mode cnot0 -module zb_rop -cell $flatten\\u_depth.$gt$rtl/zb_depth.sv:[0-9]*$[0-9]* -port B -portbit 14 -ctrlbit 22 ' \
  "the peel-compare mutant"
args=(--suite random --seed 1 --fragments 300000)
"$tb" --mutant 0 "${args[@]}" -q --mismatch-fst "" >"$tmp/out.txt" 2>&1 ||
  fail "the unmutated netlist (mutant 0) fails: it is not zb_rop"
echo "ok: mutant 0 passes"
lockstep mutant-195 X4 --mutant 195 "${args[@]}"
grep -qE '^  X4: rtl wrote no depth, no coverage; golden depth 0x[0-9a-f]+, no coverage$' "$tmp/out.txt" ||
  fail "mutant-195: the X4 line does not show the depth write the peel test should have let through"
