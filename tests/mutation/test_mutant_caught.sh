#!/usr/bin/env bash
# A mutant that the lock-step monitor catches reports its first wrong write (docs/mutation.md):
# mutant 1 of the netlist (Yosys's sample, seed 1) ties bit 6 of a coverage bank's read address
# to 1, so a fragment reads another pixel's coverage. The run must stop at the X4 write it
# spoils, naming the fragment, the cycle, both values and the pixel's history, with an FST that
# replays it; and the unmutated netlist (mutant 0) must pass the same run.
set -u
source "$(dirname "$0")/mutant_lib.sh" "$@"

expect_mutant 1 '^mutate -mode const1 -module zb_rop -cell u_depth.u_cov_plane.g_bank\[3\].u_mem.mem_q -port RD_ADDR -portbit 6 ' \
  "the coverage read-address mutant"
args=(--suite random --seed 1 --fragments 300000)
"$tb" --mutant 0 "${args[@]}" -q --mismatch-fst "" >"$tmp/out.txt" 2>&1 ||
  fail "the unmutated netlist (mutant 0) fails: it is not zb_rop"
echo "ok: mutant 0 passes"
lockstep mutant-1 X4 --mutant 1 "${args[@]}"
grep -qE '^  X4: rtl wrote depth 0x[0-9a-f]+, coverage 0; golden depth 0x[0-9a-f]+, coverage 14$' "$tmp/out.txt" ||
  fail "mutant-1: the X4 line does not show the wrong coverage"
