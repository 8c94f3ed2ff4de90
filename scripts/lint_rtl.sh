#!/usr/bin/env bash
# Verilator lint (-Wall) of zb_rop with the waivers of rtl/lint_waivers.vlt, and its elaboration
# under Icarus Verilog (the second simulator, docs/rtl.md "Simulators").
# Usage: lint_rtl.sh [OPTIONS...]          one parameter set, e.g. -GDEPTH_BITS=16 -GCOV_SAMPLES=4
#        lint_rtl.sh --sim [OPTIONS...]    the same set with the simulation views (rtl/sim/) in
#                                          place of their synthesis views, as Verilator builds it
#        lint_rtl.sh --cov [OPTIONS...]    the same set as the coverage build reads it: the
#                                          simulation views and the coverage plan's bind module
#        lint_rtl.sh --icarus [OPTIONS...] the same set elaborated by iverilog -g2012, -Wall
#        lint_rtl.sh --conformance         the conformance testbench (conformance/sv), plain and
#                                          with its DPI-C lock-step scoreboard
#        lint_rtl.sh --all                 every set of rtl/lint_sets.txt on both, then the
#                                          conformance testbench
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
# The package first: its types are used by every module after it.
rtl=("$root/rtl/zb_pkg.sv")
for f in "$root"/rtl/*.sv; do [[ $f == */zb_pkg.sv ]] || rtl+=("$f"); done
sv=$root/conformance/sv

# The simulation views (docs/rtl.md "Two builds, two views"): rtl/sim/X.sv in place of rtl/X.sv.
sim=()
for f in "${rtl[@]}"; do
  v=$root/rtl/sim/$(basename "$f")
  [[ -f $v ]] && sim+=("$v") || sim+=("$f")
done

lint() { verilator --lint-only -Wall "$root/rtl/lint_waivers.vlt" "${rtl[@]}" --top-module zb_rop "$@"; }
lint_sim() { verilator --lint-only -Wall "$root/rtl/lint_waivers.vlt" "${sim[@]}" --top-module zb_rop "$@"; }
lint_cov() { lint_sim "$root/tb/cov/zb_rop_cov.sv" "$root/tb/cov/zb_rop_cov_bind.sv" "$@"; }

# Verilator's -GNAME=V and +define+X as iverilog's -Pzb_rop.NAME=V and -DX. Icarus warns only
# of what docs/rtl.md "Simulators" explains (constant selects in always_* processes, unique
# case): any other warning fails.
icarus() {
  local args=() o out
  for o in "$@"; do
    case $o in
      -G*) args+=("-Pzb_rop.${o#-G}") ;;
      +define+*) args+=("-D${o#+define+}") ;;
      *) echo "lint_rtl.sh: --icarus: cannot translate '$o' for iverilog" >&2; exit 2 ;;
    esac
  done
  out=$(iverilog -g2012 -Wall -o /dev/null -s zb_rop "${args[@]}" "${rtl[@]}" 2>&1) ||
    { printf '%s\n' "$out" >&2; exit 1; }
  out=$(grep -v -e 'constant selects in always_\* processes are not currently supported' \
                -e 'qualities are ignored' <<<"$out" || true)
  [[ -z $out ]] || { printf '%s\n' "$out" >&2; echo "lint_rtl.sh: iverilog warns" >&2; exit 1; }
}

conformance() {
  local common=(--lint-only -Wall --timing --top-module zb_conf_tb "$root/rtl/lint_waivers.vlt"
                "$sv/zb_conf.vlt")
  verilator "${common[@]}" "${rtl[@]}" "$sv/zb_conf_adapter.sv" "$sv/zb_conf_tb.sv"
  verilator "${common[@]}" "$sv/zb_golden_pkg.vlt" +define+ZB_CONF_LOCKSTEP "${rtl[@]}" \
    "$sv/zb_golden_pkg.sv" "$sv/zb_conf_scoreboard.sv" "$sv/zb_conf_adapter.sv" "$sv/zb_conf_tb.sv"
}

case ${1:-} in
  --all)
    while IFS= read -r line; do
      [[ $line =~ ^([a-z0-9_-]+):\ *(.*)$ ]] || continue
      name=${BASH_REMATCH[1]}
      read -r -a opts <<<"${BASH_REMATCH[2]}"
      lint "${opts[@]}"
      lint_sim "${opts[@]}"
      lint_cov "${opts[@]}"
      icarus "${opts[@]}"
      echo "lint: $name clean (Verilator -Wall, both views, the coverage bind; Icarus elaborates)"
    done <"$root/rtl/lint_sets.txt"
    conformance
    echo "lint: the conformance testbench clean"
    ;;
  --icarus) shift; icarus "$@" ;;
  --sim) shift; lint_sim "$@" ;;
  --cov) shift; lint_cov "$@" ;;
  --conformance) conformance ;;
  *) lint "$@" ;;
esac
