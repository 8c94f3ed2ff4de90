#!/usr/bin/env bash
# The fast-clear epoch and the tile counters, each caught by one suite only.
# Mutant 939 keeps the depth plane's all-fresh flag through loads (the load's term tied to 0), so
# a tile loaded and the next fast-cleared twice with no store between counts wrongly: only the
# clears suite's last iteration shows it, in the counts; the tiles suite must not. Mutant 308 holds the
# accumulation plane's W1 flag at 1, so a write-back meets a stale word: only the tiles suite's
# accumulate pass writes that plane. Mutants 17, 581 and 1106 corrupt the tile counters (a bit
# of the next value under a condition, a bit of the increment, the saturation's "not at all
# ones" input tied off) where the clears suite never looks: only the tiles suite's load-back,
# which takes the counts to their saturation and checks them at every beat, names them.
set -u
source "$(dirname "$0")/../lib.sh"
mutant_args "$@"

expect_mutant 939 '-mode const0 -module zb_rop -cell $flatten\\u_depth.\\u_depth_plane.$logic_or$rtl/zb_plane.sv:86' \
  "the depth plane's all-fresh flag mutant"
expect_mutant 308 '-mode const1 -module zb_rop -cell $flatten\\u_accum.\\u_accum_plane.$procdff$[0-9]* -port Q -portbit 0 -wire u_accum.u_accum_plane.wback_q ' \
  "the accumulation plane's W1 flag mutant"
expect_mutant 17 '-mode cnot1 -module zb_rop -cell $flatten\\u_tile_counters.$procmux' \
  "the tile count's next-value mutant"
expect_mutant 581 '-mode cnot1 -module zb_rop -cell $flatten\\u_tile_counters.$add$rtl/zb_counters.sv:33' \
  "the tile count's increment mutant"
expect_mutant 1106 '-mode const0 -module zb_rop -cell $flatten\\u_tile_counters.$logic_not$rtl/zb_counters.sv:32' \
  "the tile count's saturation mutant"
run() { "$tb" -q --mismatch-fst "" "$@" >"$tmp/out.txt" 2>&1; }

run --mutant 0 --suite clears --seed 1 || fail "mutant 0 fails the clears suite"
run --mutant 0 --suite tiles --seed 1 || fail "mutant 0 fails the tiles suite"

run --mutant 939 --suite tiles --seed 1 ||
  fail "mutant 939 fails the tiles suite: then this test no longer shows the clears suite alone"
run --mutant 939 --suite clears --seed 1
rc=$?
[[ $rc -eq 1 ]] || fail "mutant 939 in the clears suite: exit $rc, want 1"
grep -qE '^MISMATCH in frame [0-9]+ pass [0-9]+ "clears-two-silent": counters differ' "$tmp/out.txt" ||
  fail "mutant 939: no 'counters differ' report in a clears-two-silent pass"
echo "ok: mutant 939: $(grep -m1 'MISMATCH' "$tmp/out.txt")"

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

tiles_catches 308 'LOCKSTEP MISMATCH in frame [0-9]+ pass [0-9]+ "tiles-accumulate": the first wrong write' \
  'LOCKSTEP MISMATCH ... "tiles-accumulate": the first wrong write'
for m in 17 581 1106; do
  tiles_catches "$m" 'counted [0-9]+ store and [0-9]+ load beats after its store was read again and loaded back; two tiles of beats saturate at [0-9]+: want [0-9]+ and [0-9]+ at load-back beat [0-9]+' \
    "counted N store and N load beats after its store was read again ... want N and N at load-back beat N"
done
