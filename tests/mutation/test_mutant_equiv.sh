#!/usr/bin/env bash
# The equivalence prover (scripts/mutant_equiv.sh) can fail. On zb_premul, small enough for
# seconds, standing in for zb_rop: a mutant of bits nothing reads (its unused_u) is proven
# equivalent only by leaving those signals unpaired; a mutant of an output flop is not proven
# and names the port; a mutant of a clock gets no proof (the flow would "prove" it wrongly). On
# zb_tile_mem, a memory's write address: a don't-care without a write, not with one.
set -u
root=$(cd "$(dirname "$0")/../.." && pwd)
source "$(dirname "$0")/../lib.sh"
cd "$root"
yosys -q -p "read_verilog -sv rtl/zb_mul8.sv rtl/zb_premul.sv; prep -top zb_premul -flatten;
  rename zb_premul zb_rop; write_rtlil $tmp/design.il; mutate -list 300 -seed 1 -o $tmp/mutations.txt" \
  >"$tmp/yosys.txt" 2>&1 || { cat "$tmp/yosys.txt"; fail "yosys could not list zb_premul's mutants"; }

# check NAME PATTERN WANT_EXIT WANT_OUTPUT: the first listed mutant matching PATTERN.
check() {
  local name=$1 pattern=$2 want=$3 text=$4 m out rc
  m=$(grep -E -m1 -- "$pattern" "$tmp/mutations.txt") || fail "$name: no mutant matches '$pattern'"
  out=$(scripts/mutant_equiv.sh "$tmp/design.il" "$m"); rc=$?
  [[ $rc -eq $want ]] || fail "$name: exit $rc, want $want ($out) for: $m"
  [[ $out == *"$text"* ]] || fail "$name: output '$out' lacks '$text'"
  echo "ok: $name: $out"
}
check unused-bit '-mode const1 .*-wire g_chan\[[0-3]\]\.unused_u ' 0 "internal signals unpaired"
check output-flop '-mode const0 .*-wire ms_o ' 1 'differs at output \ms_o'
check clock '-port CLK ' 3 "no proof"

# A memory (zb_tile_mem): its write address is a don't-care in cycles without a write (the RTL's
# x), so a mutant of that x arm is proven; a mutant of the address a write uses is not.
yosys -q -p "read_verilog -sv rtl/zb_tile_mem.sv; chparam -set WIDTH 4 -set WORDS 8 zb_tile_mem;
  prep -top zb_tile_mem -flatten; rename zb_tile_mem zb_rop; write_rtlil $tmp/mem.il;
  mutate -list 200 -seed 1 -o $tmp/mem_mutations.txt" >"$tmp/yosys.txt" 2>&1 ||
  { cat "$tmp/yosys.txt"; fail "yosys could not list zb_tile_mem's mutants"; }
addr_mux=$(grep -m1 -oE -- '-cell \S+ -port B -portbit [0-9]+ .*-wire waddr_i ' "$tmp/mem_mutations.txt" |
  awk '{print $2}')
[[ -n $addr_mux ]] || fail "no mutant of zb_tile_mem's write address mux"
mem_check() {  # NAME MUTATION WANT_EXIT WANT_OUTPUT
  local out rc
  out=$(scripts/mutant_equiv.sh "$tmp/mem.il" "$2"); rc=$?
  [[ $rc -eq $3 && $out == *"$4"* ]] || fail "$1: exit $rc, '$out' (want $3, '$4') for: $2"
  echo "ok: $1: $out"
}
mem_check write-address-idle "mutate -mode const0 -module zb_rop -cell $addr_mux -port A -portbit 1" \
  0 "proven equivalent"
mem_check write-address-used "$(grep -m1 -F -- "-cell $addr_mux -port B -portbit 0 " "$tmp/mem_mutations.txt")" \
  1 "not proven"

scripts/mutant_equiv.sh "$tmp/design.il" 9999 >/dev/null 2>&1
[[ $? -eq 2 ]] || fail "a mutant number past the list: want exit 2"
echo "ok: bad mutant number: exit 2"
