#!/usr/bin/env bash
# The prover on a mutant's own module (scripts/mutant_equiv_local.py) can fail, and finds the
# cell again. A small stand-in for zb_rop: a wrapper holding zb_premul as u_pre, flattened
# (design.il, which the mutations name) and not (hier.il). A mutant of bits nothing reads in
# u_pre is proven on zb_premul alone, and on the wrapper with --up 1; a mutant of its output
# flop, or of a product in the zb_mul8 within it, is not proven; without hier.il the script
# refuses (exit 2).
set -u
root=$(cd "$(dirname "$0")/../.." && pwd)
source "$(dirname "$0")/../lib.sh"
cd "$root"
cat > "$tmp/wrap.sv" <<'SV'
module zb_rop (input logic clk_i, input logic [31:0] rgba_i, input logic [9:0] a3_i,
               output logic [31:0] ms_o);
  zb_premul u_pre (.clk_i(clk_i), .rgba_i(rgba_i), .a3_i(a3_i), .ms_o(ms_o));
endmodule
SV
src="rtl/zb_mul8.sv rtl/zb_premul.sv $tmp/wrap.sv"
mkdir -p "$tmp/n"
yosys -q -p "read_verilog -sv $src; hierarchy -top zb_rop; prep -top zb_rop -flatten;
  write_rtlil $tmp/n/design.il; mutate -list 400 -seed 1 -o $tmp/n/mutations.txt" >"$tmp/out.txt" 2>&1 ||
  fail "yosys could not list the wrapper's mutants"
yosys -q -p "read_verilog -sv $src; hierarchy -top zb_rop; prep -top zb_rop; write_rtlil $tmp/n/hier.il" \
  >"$tmp/out.txt" 2>&1 || fail "yosys could not elaborate the hierarchy"

# check NAME PATTERN WANT_EXIT WANT_OUTPUT [ARGS]: the first listed mutant matching PATTERN.
check() {
  local name=$1 pattern=$2 want=$3 text=$4 n out rc
  n=$(grep -n -E -m1 -- "$pattern" "$tmp/n/mutations.txt" | cut -d: -f1)
  [[ -n $n ]] || fail "$name: no mutant matches '$pattern'"
  out=$(python3 scripts/mutant_equiv_local.py "$tmp/n/design.il" "$n" "${@:5}"); rc=$?
  [[ $rc -eq $want ]] || fail "$name: exit $rc, want $want ($out) for mutant $n"
  [[ $out == *"$text"* ]] || fail "$name: output '$out' lacks '$text'"
  echo "ok: $name: $out"
}
unused='-mode const1 .*-wire u_pre\.g_chan\[[0-3]\]\.unused_u '
check unused-bit "$unused" 0 "proven equivalent on zb_premul alone"
check unused-bit-up "$unused" 0 "proven equivalent on zb_rop alone" --up 1
check output-flop '-mode const0 -module zb_rop -cell .flatten.u_pre\..*-wire ms_o ' 1 "not proven on zb_premul"
check nested-product '-mode const0 .*-wire u_pre\.g_chan\[[0-3]\]\.u_mul\.t_q ' 1 "not proven on zb_mul8"

rm "$tmp/n/hier.il"
python3 scripts/mutant_equiv_local.py "$tmp/n/design.il" 1 >/dev/null 2>&1
[[ $? -eq 2 ]] || fail "without hier.il: want exit 2"
echo "ok: without hier.il: exit 2"
