#!/usr/bin/env bash
# Yosys's mutants of zb_rop in one netlist (docs/mutation.md). The build calls it; so can you.
#  1. zb_rop at the given widths, flattened (prep -flatten: its submodules' cells included),
#     `mutate -list N -seed S` samples N mutations evenly over cells, wires and source lines (a
#     few more listed, memories' read enables left out: see below).
#  2. Each is applied with `mutate -ctrl mutsel W i`: live only when mutsel == i (0: none), so
#     one netlist, Verilated once, holds all N; the wrapper tb/mutation/zb_rop_mutant.sv sets mutsel
#     from the plusarg +zb_mutant=i.
# Writes OUT/mutations.txt (line i: mutant i, Yosys's own description), OUT/mutants.v,
# OUT/design.il (zb_rop unmutated, for scripts/mutant_equiv.sh) and OUT/hier.il (the same, not
# flattened, for scripts/mutant_equiv_local.py).
set -euo pipefail

usage() {
  cat <<'USAGE'
usage: scripts/mutants.sh --out DIR [--count N] [--seed S] [--src REGEX] [-G NAME=VALUE ...]
  --out DIR        output directory (mutations.txt, mutants.v, yosys logs)
  --count N        mutants, 1 to 2047 (default 1200)
  --seed S         Yosys's sampling seed (default 1)
  --src REGEX      only mutations with a source line in a file matching REGEX (an extended
                   regular expression over Yosys's -src paths, e.g. 'rtl/zb_layers[a-z_]*\.sv'):
                   eight times the count are listed over the whole design, those kept sampled
  -G NAME=VALUE    a zb_rop parameter (as Verilator's -G), repeatable
USAGE
}

root=$(cd "$(dirname "$0")/.." && pwd)
out="" count=1200 seed=1 params="" src=""
while [[ $# -gt 0 ]]; do
  case $1 in
    --out) out=${2:?}; shift 2 ;;
    --count) count=${2:?}; shift 2 ;;
    --seed) seed=${2:?}; shift 2 ;;
    --src) src=${2:?}; shift 2 ;;
    -G) params+=" -set ${2%%=*} ${2#*=}"; shift 2 ;;
    -G*) p=${1#-G}; params+=" -set ${p%%=*} ${p#*=}"; shift ;;
    -h|--help) usage; exit 0 ;;
    *) echo "mutants.sh: unknown option '$1'" >&2; usage >&2; exit 2 ;;
  esac
done
[[ -n $out ]] || { echo "mutants.sh: --out DIR is required" >&2; usage >&2; exit 2; }
[[ $count =~ ^[0-9]+$ && $count -ge 1 && $count -le 2047 ]] ||
  { echo "mutants.sh: --count $count: choose 1 to 2047 (mutsel is 11 bits)" >&2; exit 2; }
[[ $seed =~ ^[0-9]+$ ]] || { echo "mutants.sh: --seed $seed is not a number" >&2; exit 2; }
command -v yosys >/dev/null || { echo "mutants.sh: yosys not found (scripts/setup.sh)" >&2; exit 1; }

mkdir -p "$out"
tmp=$(mktemp -d "$out/.mutants.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
cd "$root"
rtl="rtl/zb_pkg.sv $(ls rtl/*.sv | grep -v '/zb_pkg.sv$' | tr '\n' ' ')"  # the package first

# Source paths relative to the repository, so the list is the same from any build tree.
yosys -q -l "$tmp/list.log" -p "read_verilog -sv $rtl; ${params:+chparam$params zb_rop;}
  hierarchy -top zb_rop; rename -top zb_rop; prep -top zb_rop -flatten;
  write_rtlil $tmp/design.il; mutate -list $((${src:+8 * }count + 32)) -seed $seed -o $tmp/listed.txt" >/dev/null 2>&1 ||
  { echo "mutants.sh: yosys failed listing mutations (log: $tmp/list.log)" >&2; cp "$tmp/list.log" "$out/"; exit 1; }
# A memory's read enable is left out: Yosys 0.23's Verilog backend asserts (kernel/mem.cc:459)
# on a read port whose enable a mutation drives.
# A few more are listed and as many dropped evenly over the list (it runs in netlist order).
grep -v -- ' -port RD_EN ' "$tmp/listed.txt" | { if [[ -n $src ]]; then grep -E -- "-src ($src):" || true; else cat; fi; } > "$tmp/kept.txt"
[[ $(wc -l < "$tmp/kept.txt") -ge $count ]] ||
  { echo "mutants.sh: only $(wc -l < "$tmp/kept.txt") mutations listed${src:+ in sources matching '$src'}, fewer than $count" >&2; exit 1; }
awk -v n="$(wc -l < "$tmp/kept.txt")" -v c="$count" \
  'int(NR * c / n) > int((NR - 1) * c / n)' "$tmp/kept.txt" > "$tmp/mutations.txt"
[[ $(wc -l < "$tmp/mutations.txt") -eq $count ]] ||
  { echo "mutants.sh: yosys listed $(wc -l < "$tmp/mutations.txt") mutations, not $count" >&2; exit 1; }

{
  echo "read_rtlil $tmp/design.il"
  awk '{ $1 = ""; print "mutate -ctrl mutsel 11 " NR $0 }' "$tmp/mutations.txt"
  echo "opt_clean; splitnets -driver; rename zb_rop zb_rop_mutants; write_verilog -noattr $tmp/mutants.v"
} > "$tmp/apply.ys"
yosys -q -l "$tmp/apply.log" "$tmp/apply.ys" >/dev/null 2>&1 ||
  { echo "mutants.sh: yosys failed applying mutations (log: $tmp/apply.log)" >&2; cp "$tmp/apply.log" "$out/"; exit 1; }

# zb_rop at the same widths but not flattened: scripts/mutant_equiv_local.py proves a mutant on
# the module that holds its cell.
yosys -q -l "$tmp/hier.log" -p "read_verilog -sv $rtl; ${params:+chparam$params zb_rop;}
  hierarchy -top zb_rop; rename -top zb_rop; prep -top zb_rop; write_rtlil $tmp/hier.il" >/dev/null 2>&1 ||
  { echo "mutants.sh: yosys failed elaborating the hierarchy (log: $tmp/hier.log)" >&2; cp "$tmp/hier.log" "$out/"; exit 1; }

mv "$tmp/mutations.txt" "$tmp/mutants.v" "$tmp/design.il" "$tmp/hier.il" "$out/"
echo "mutants.sh: $count mutants of zb_rop (seed $seed${src:+, in $src}) in $out/mutants.v"
