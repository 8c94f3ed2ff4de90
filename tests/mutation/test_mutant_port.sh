#!/usr/bin/env bash
# The port contract (docs/rtl.md "Port timing"): frag_ready_o is low in any cycle with stall_i,
# tile_req_i or tile_clear_i. The driver offers no fragment in those cycles, so only the
# driver's own check sees a port that would take one: mutant 719 inverts zb_input's hold_i
# (`stall_i | tile_req_i | tile_clear_i`: ready only while held); the run must stop at the first such cycle, naming it, and
# the unmutated netlist must pass the same runs.
set -u
source "$(dirname "$0")/../lib.sh"
mutant_args "$@"

expect_mutant 719 '-mode inv .* -wire u_input.hold_i -wirebit 0 ' "the hold_i mutant"
for args in "--suite tiles --seed 1" "--suite random --seed 2 --fragments 20000 --backpressure 0.3"; do
  # shellcheck disable=SC2086
  "$tb" --mutant 0 $args -q --mismatch-fst "" >"$tmp/out.txt" 2>&1 || fail "mutant 0 fails $args"
  # shellcheck disable=SC2086
  "$tb" --mutant 719 $args -q --mismatch-fst "" >"$tmp/out.txt" 2>&1
  rc=$?
  [[ $rc -eq 1 ]] || fail "mutant 719 $args: exit $rc, want 1"
  grep -qE 'rtl: tile \([0-9]+,[0-9]+\) frag_ready_o high at cycle [0-9]+ with tile_clear_i' "$tmp/out.txt" ||
    fail "mutant 719 $args: no 'frag_ready_o high at cycle N with tile_clear_i' line"
  echo "ok: $args: $(grep -o 'frag_ready_o high at cycle [0-9]* with [a-z_]*' "$tmp/out.txt" | head -1)"
done
