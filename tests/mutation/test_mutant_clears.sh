#!/usr/bin/env bash
# The fast-clear epoch and the tile counters, each caught by one suite only.
# Mutant 26 holds at 1 bit 19 of one memory's read register in the second depth bank (the
# words of every eighth lane read there gain that bit): only the clears suite's silent
# passes show it, in the counts of their depth tests; the tiles suite must not. Mutant 24
# holds at 1 bit 71 of the accumulation word read at X6 (lane 0's revealage): only the tiles
# suite's accumulate pass reads that plane. Mutant 457 inverts bit 3 of the tile store count,
# where the clears suite never looks: only the tiles suite's load-back, which takes the counts
# to their saturation and checks them at every beat, names it.
set -u
source "$(dirname "$0")/../lib.sh"
mutant_args "$@"

expect_mutant 26 '-mode const1 -module zb_rop -cell $flatten\\u_depth.\\g_renamed.g_bank.1..u_plane.\\g_bank.1..u_mem.$procmux$[0-9]* -port Y -portbit 19 ' \
  "the second depth bank's read-register mutant"
expect_mutant 24 '-mode const1 -module zb_rop -cell $flatten\\u_accum.\\u_accum_plane.$shiftx$[^ ]* -port Y -portbit 71 -wire u_accum.u_forward.x6_rdata_i ' \
  "the accumulation plane's read mutant"
expect_mutant 457 '-mode inv -module zb_rop -cell $flatten\\u_tile_counters.$procdff$[0-9]* -port Q -portbit 3 -wire cnt_tile_stores_o ' \
  "the tile store count's mutant"
run() { "$tb" -q --mismatch-fst "" "$@" >"$tmp/out.txt" 2>&1; }

run --mutant 0 --suite clears --seed 1 || fail "mutant 0 fails the clears suite"
run --mutant 0 --suite tiles --seed 1 || fail "mutant 0 fails the tiles suite"

run --mutant 26 --suite tiles --seed 1 ||
  fail "mutant 26 fails the tiles suite: then this test no longer shows the clears suite alone"
run --mutant 26 --suite clears --seed 1
rc=$?
[[ $rc -eq 1 ]] || fail "mutant 26 in the clears suite: exit $rc, want 1"
grep -qE '^MISMATCH in frame [0-9]+ pass [0-9]+ "clears-two-silent[a-z-]*": counters differ' "$tmp/out.txt" ||
  fail "mutant 26: no 'counters differ' report in a clears-two-silent pass"
echo "ok: mutant 26: $(grep -m1 'MISMATCH' "$tmp/out.txt")"

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

tiles_catches 24 'LOCKSTEP MISMATCH in frame [0-9]+ pass [0-9]+ "tiles-accumulate": the first wrong write' \
  'LOCKSTEP MISMATCH ... "tiles-accumulate": the first wrong write'
for m in 457; do
  tiles_catches "$m" 'counted [0-9]+ store and [0-9]+ load beats after its store was read again and loaded back; two tiles of beats saturate at [0-9]+: want [0-9]+ and [0-9]+ at load-back beat [0-9]+' \
    "counted N store and N load beats after its store was read again ... want N and N at load-back beat N"
done
