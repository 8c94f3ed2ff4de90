#!/usr/bin/env bash
# Is a surviving mutant equivalent to zb_rop? (make mutate, docs/mutation.md)
# usage: mutant_equiv.sh DESIGN.il "MUTATION"   (a line of mutations.txt, as `mutate -list` wrote it)
# Yosys's equivalence flow on zb_rop (gold) and the mutant (gate), same names but for the one
# mutated cell: equiv_make pairs their signals, equiv_struct merges the cells whose inputs are
# proven equal (the tile memories among them), equiv_simple proves each pair on its input cone
# over a few cycles, equiv_induct the rest together by induction. Sound, not complete: "proven"
# means the mutant's ports and state equal zb_rop's in every cycle from reset; "not proven" may
# still be equivalent.
# Exit: 0 proven equivalent; 1 not proven; 2 usage; 3 Yosys failed.
set -uo pipefail
[[ $# -eq 2 && -f $1 ]] || { echo "usage: mutant_equiv.sh DESIGN.il \"mutate -mode ... -module zb_rop ...\"" >&2; exit 2; }
design=$1
mutation=${2/-module zb_rop /-module gate }
[[ $mutation == "mutate "*"-module gate "* ]] || { echo "mutant_equiv.sh: not a zb_rop mutation: $2" >&2; exit 2; }
log=$(mktemp)
trap 'rm -f "$log"' EXIT
yosys -q -l "$log" -p "read_rtlil $design; rename zb_rop gold; copy gold gate; $mutation;
  async2sync; equiv_make gold gate equiv; hierarchy -top equiv; equiv_simple -seq 4;
  equiv_struct; equiv_simple -seq 4; equiv_induct -seq 4; equiv_status" >/dev/null 2>&1 || exit 3
if grep -q "Equivalence successfully proven" "$log"; then exit 0; fi
grep -qE "Found [0-9]+ unproven" "$log" && exit 1
exit 3
