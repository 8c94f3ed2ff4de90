#!/usr/bin/env bash
# The fast-clear epoch and the tile counters. Mutant 794 holds bit 0 of the second depth bank's
# epoch at 0, so its fast clears step the two-bit generation by two or not at all: a silent pass
# (no write) after a fast clear then reads words as current, and only the pass counters show it:
# the clears suite's two silent passes must report the counters differing (on this sample the
# tiles suite also catches it). Mutant 1154 holds the accumulation plane's all-fresh flag at 1,
# so its fast clear never steps the epoch: only the tiles suite's accumulate pass writes that
# plane. Mutants 1058 and 778 corrupt the tile counters (a bit of the load count's flop, a bit
# of the store count's) where the clears suite never looks: only the tiles suite's load-back,
# which takes the counts to their saturation and checks them at every beat, names them.
set -u
source "$(dirname "$0")/../lib.sh"
mutant_args "$@"

expect_mutant 794 '-mode const0 -module zb_rop -cell $flatten\\u_depth.\\g_renamed.g_bank.1..u_plane.$procdff$[0-9]* -port Q -portbit 0 -wire u_depth.g_renamed.g_bank.1..u_plane.epoch_q ' \
  "the second depth bank's epoch mutant"
expect_mutant 1154 '-mode const1 -module zb_rop -cell $flatten\\u_accum.\\u_accum_plane.$procmux$[0-9]* -port Y -portbit 0 -wire u_accum.u_accum_plane.all_fresh_d ' \
  "the accumulation plane's all-fresh mutant"
expect_mutant 1058 '-mode inv -module zb_rop -cell $flatten\\u_tile_counters.$procdff$[0-9]* -port Q .* -wire cnt_tile_loads_o ' \
  "the load count's flop mutant"
expect_mutant 778 '-mode inv -module zb_rop -cell $flatten\\u_tile_counters.$procdff$[0-9]* -port Q .* -wire cnt_tile_stores_o ' \
  "the store count's flop mutant"
run() { "$tb" -q --mismatch-fst "" "$@" >"$tmp/out.txt" 2>&1; }

run --mutant 0 --suite clears --seed 1 || fail "mutant 0 fails the clears suite"
run --mutant 0 --suite tiles --seed 1 || fail "mutant 0 fails the tiles suite"

run --mutant 794 --suite clears --seed 1
rc=$?
[[ $rc -eq 1 ]] || fail "mutant 794 in the clears suite: exit $rc, want 1"
grep -qE '^MISMATCH in frame [0-9]+ pass [0-9]+ "clears-two-silent[a-z-]*": counters differ' "$tmp/out.txt" ||
  fail "mutant 794: no 'counters differ' report in a clears-two-silent pass"
echo "ok: mutant 794: $(grep -m1 'MISMATCH' "$tmp/out.txt")"

# tiles_catches M PATTERN WHAT: mutant M passes the clears suite and fails the tiles suite with
# a line matching PATTERN.
tiles_catches() {
  run --mutant "$1" --suite clears --seed 1 ||
    fail "mutant $1 fails the clears suite: then this test no longer shows the tiles suite alone"
  run --mutant "$1" --suite tiles --seed 1
  local rc=$?
  [[ $rc -eq 1 ]] || fail "mutant $1 in the tiles suite: exit $rc, want 1"
  grep -qE -- "$2" "$tmp/out.txt" || fail "mutant $1: no '$3' line"
  echo "ok: mutant $1: $(grep -m1 -oE -- "$2" "$tmp/out.txt")"
}

tiles_catches 1154 'LOCKSTEP MISMATCH in frame [0-9]+ pass [0-9]+ "tiles-accumulate": the first wrong write' \
  'LOCKSTEP MISMATCH ... "tiles-accumulate": the first wrong write'
for m in 1058 778; do
  tiles_catches "$m" 'counted [0-9]+ store and [0-9]+ load beats after its store was read again and loaded back; two tiles of beats saturate at [0-9]+: want [0-9]+ and [0-9]+ at load-back beat [0-9]+' \
    "counted N store and N load beats after its store was read again ... want N and N at load-back beat N"
done
