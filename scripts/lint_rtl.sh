#!/usr/bin/env bash
# Verilator lint (-Wall) of zb_rop with the waivers of rtl/lint_waivers.vlt.
# Usage: lint_rtl.sh [OPTIONS...]     one parameter set, e.g. -GDEPTH_BITS=16 -GCOV_SAMPLES=4
#        lint_rtl.sh --all            every set of rtl/lint_sets.txt
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
# The package first: its types are used by every module after it.
rtl=("$root/rtl/zb_pkg.sv")
for f in "$root"/rtl/*.sv; do [[ $f == */zb_pkg.sv ]] || rtl+=("$f"); done
lint() { verilator --lint-only -Wall "$root/rtl/lint_waivers.vlt" "${rtl[@]}" --top-module zb_rop "$@"; }
if [[ ${1:-} == --all ]]; then
  while IFS= read -r line; do
    [[ $line =~ ^([a-z0-9_-]+):\ *(.*)$ ]] || continue
    name=${BASH_REMATCH[1]}
    read -r -a opts <<<"${BASH_REMATCH[2]}"
    lint "${opts[@]}"
    echo "lint: $name clean"
  done <"$root/rtl/lint_sets.txt"
else
  lint "$@"
fi
