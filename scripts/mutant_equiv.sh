#!/usr/bin/env bash
# Is a surviving mutant equivalent to zb_rop? (make mutate, docs/mutation.md)
# Yosys's equivalence flow on zb_rop (gold) and the mutant (gate), alike but for the one mutated
# cell: equiv_make pairs their signals by name, equiv_struct pairs the outputs of alike cells
# (auto-named ones too: -icells) and merges them, equiv_simple proves each pair on its input
# cone over 4 cycles, equiv_induct the rest together by induction, both starting from the same
# state. Sound, not complete: "proven" means the mutant's outputs, and every signal left paired,
# equal zb_rop's in every cycle; "not proven" names the signals that were not shown equal (the
# mutant may still be equivalent).
# Exit: 0 proven equivalent; 1 not proven; 2 usage; 3 Yosys failed or ran out of time.
set -uo pipefail

usage() {
  echo "usage: scripts/mutant_equiv.sh [--time-limit S] DESIGN.il N | DESIGN.il \"MUTATION\"" >&2
  echo "  DESIGN.il  zb_rop unmutated (build/tb/mutation/design.il); N: line N of mutations.txt beside it" >&2
}
limit=900
if [[ ${1:-} == --time-limit ]]; then limit=${2:?}; shift 2; fi
[[ $# -eq 2 && -f $1 ]] || { usage; exit 2; }
design=$1 mutation=$2
if [[ $mutation =~ ^[0-9]+$ ]]; then
  list=$(dirname "$design")/mutations.txt
  mutation=$(sed -n "${2}p" "$list" 2>/dev/null)
  [[ -n $mutation ]] || { echo "mutant_equiv.sh: $list has no mutant $2" >&2; exit 2; }
fi
[[ $mutation == "mutate "*"-module zb_rop "* ]] ||
  { echo "mutant_equiv.sh: not a zb_rop mutation: $mutation" >&2; exit 2; }
# The flow models each flop as one step and async resets as sync (async2sync): a mutant of a clock
# or an async reset would be "proven" wrongly, so it gets no proof.
if [[ $mutation =~ -port\ [A-Z_]*(CLK|ARST)\  ]]; then
  echo "no proof: a mutant of a clock or async reset (the flow models neither)"; exit 3
fi
mutation=${mutation/-module zb_rop /-module gate }
command -v yosys >/dev/null || { echo "mutant_equiv.sh: yosys not found (scripts/setup.sh)" >&2; exit 3; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# zb_rop's outputs (the flattened design has no other module): never left out of the pairing.
grep -oE '^ *wire .*output [0-9]+ \\\S+' "$design" | awk '{print $NF}' | sort -u > "$work/ports"
: > "$work/blacklist"
# Round 1 pairs every signal by name. An internal signal the mutant changes but its ports never
# see (a bit nothing reads, say) is then "not proven"; the next round leaves those signals
# unpaired, so the gate keeps its own values there and only the rest must be equal. Sound: a
# proof still covers every output and every paired signal in every cycle.
# A pair left unproven only where zb_rop's value is x (a don't-care the RTL wrote, such as a
# write address in cycles that write nothing) is proven again with x modelled (-undef): the
# mutant then only picks a value for the don't-care.
# Last, when leaving signals unpaired changes nothing and a pair equiv_struct made is left:
# without equiv_struct, whose merging of alike cells can pair their inputs where only the
# outputs agree (a mux whose select the mutant ties, on an x arm), and with x modelled. Slower
# (minutes), so only then.
rounds=6
undef=""
struct="equiv_struct -icells;"
for round in $(seq $rounds); do
  left=$((limit - SECONDS))
  [[ $left -gt 0 ]] || { echo "mutant_equiv.sh: time limit ($limit s) before round $round"; exit 3; }
  timeout "$left" yosys -q -l "$work/log" -p "read_rtlil $design; rename zb_rop gold;
    copy gold gate; $mutation; async2sync; equiv_make -blacklist $work/blacklist gold gate equiv;
    hierarchy -top equiv; $struct equiv_simple $undef -seq 4; equiv_induct $undef -seq 4;
    equiv_status" >/dev/null 2>&1
  rc=$?
  if [[ $rc -eq 124 ]]; then echo "mutant_equiv.sh: time limit ($limit s) in round $round"; exit 3; fi
  if grep -q "Equivalence successfully proven" "$work/log"; then
    n=$(wc -l < "$work/blacklist")
    how=${undef:+, x modelled}
    [[ -n $struct ]] || how+=", cells unmerged"
    if [[ $n -gt 0 ]]; then echo "proven equivalent ($n internal signals unpaired$how)"
    else echo "proven equivalent${how:+ (${how#, })}"; fi
    exit 0
  fi
  grep -qE "Found a total of [0-9]+ unproven" "$work/log" ||
    { echo "mutant_equiv.sh: yosys failed (exit $rc)"; exit 3; }
  # The unproven signals, by gold's name (not constants, which equiv_struct may pair).
  grep -oE 'Unproven \$equiv \S+ \S+' "$work/log" | awk '{print $4}' | grep -v "^[0-9]*'" |
    sed 's/_gold$//' | sort -u > "$work/unproven"
  at_port=$(comm -12 "$work/unproven" "$work/ports" | head -3 | tr '\n' ' ')
  if [[ -n $at_port ]]; then echo "not proven: differs at output ${at_port% }"; exit 1; fi
  if [[ ! -s $work/unproven ]]; then
    if [[ -z $undef ]] && grep -qE 'Unproven \$equiv \S+ [0-9]+.x+ ' "$work/log"; then
      undef=-undef
      continue
    fi
    echo "not proven: only constants left unproven"; exit 1
  fi
  # Leaving them unpaired changed nothing (equiv_struct pairs alike cells' outputs again).
  if [[ -f $work/unproven.last ]] && cmp -s "$work/unproven" "$work/unproven.last"; then
    [[ -n $struct ]] && grep -q 'Unproven \$equiv \$auto\$equiv_struct' "$work/log" || break
    struct="" undef=-undef
    continue
  fi
  cp "$work/unproven" "$work/unproven.last"
  cat "$work/unproven" >> "$work/blacklist"
done
echo "not proven: internal signals after round $round: $(head -3 "$work/unproven" | tr '\n' ' ')"
exit 1
