#!/usr/bin/env bash
# The fast-clear epoch and the tile counters, each caught by one suite only.
# Mutant 679 keeps the second depth bank's all-fresh flag through loads and pipeline writes
# (that term tied to 0), so a tile loaded and the next fast-cleared twice with no store between
# counts wrongly: only the clears suite's silent passes show it, in the counts; the tiles suite
# must not. Mutant 18 keeps the accumulation plane's write-back running (W2 held at 1), so the
# plane's words are rewritten as its clear value after every read: only the tiles suite's
# accumulate pass writes that plane. Mutants 462 and 508 corrupt the tile counters (a count's
# saturation flag held at 0, a bit of a count's next value inverted) where the clears suite never
# looks: only the tiles suite's load-back, which takes the counts to their saturation and checks
# them at every beat, names them.
set -u
source "$(dirname "$0")/../lib.sh"
mutant_args "$@"

expect_mutant 679 '-mode const0 -module zb_rop -cell $flatten\\u_depth.\\g_renamed.g_bank.1..u_plane.$logic_or$rtl/zb_plane.sv:96' \
  "the second depth bank's all-fresh flag mutant"
expect_mutant 18 '-mode const1 -module zb_rop -cell $flatten\\u_accum.\\u_accum_plane.$procdff$[0-9]* -port Q -portbit 0 -wire u_accum.u_accum_plane.wb2_q ' \
  "the accumulation plane's write-back mutant"
expect_mutant 462 '-mode const0 -module zb_rop -cell $flatten\\u_tile_counters.$procdff$[0-9]* -port Q .* -wire u_tile_counters.g_cnt.1..sat_q ' \
  "the tile count's saturation mutant"
expect_mutant 508 '-mode inv -module zb_rop -cell $flatten\\u_tile_counters.$procmux$[0-9]* -port B -portbit 3 ' \
  "the tile count's next-value mutant"
run() { "$tb" -q --mismatch-fst "" "$@" >"$tmp/out.txt" 2>&1; }

run --mutant 0 --suite clears --seed 1 || fail "mutant 0 fails the clears suite"
run --mutant 0 --suite tiles --seed 1 || fail "mutant 0 fails the tiles suite"

run --mutant 679 --suite tiles --seed 1 ||
  fail "mutant 679 fails the tiles suite: then this test no longer shows the clears suite alone"
run --mutant 679 --suite clears --seed 1
rc=$?
[[ $rc -eq 1 ]] || fail "mutant 679 in the clears suite: exit $rc, want 1"
grep -qE '^MISMATCH in frame [0-9]+ pass [0-9]+ "clears-two-silent[a-z-]*": counters differ' "$tmp/out.txt" ||
  fail "mutant 679: no 'counters differ' report in a clears-two-silent pass"
echo "ok: mutant 679: $(grep -m1 'MISMATCH' "$tmp/out.txt")"

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

tiles_catches 18 'LOCKSTEP MISMATCH in frame [0-9]+ pass [0-9]+ "tiles-accumulate": the first wrong write' \
  'LOCKSTEP MISMATCH ... "tiles-accumulate": the first wrong write'
for m in 462 508; do
  tiles_catches "$m" 'counted [0-9]+ store and [0-9]+ load beats after its store was read again and loaded back; two tiles of beats saturate at [0-9]+: want [0-9]+ and [0-9]+ at load-back beat [0-9]+' \
    "counted N store and N load beats after its store was read again ... want N and N at load-back beat N"
done
