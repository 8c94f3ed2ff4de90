#!/usr/bin/env bash
# The fast-clear epoch and the tile counters, each caught by one suite only.
# Mutant 327 ties to 0 bit 9 of one memory's read register in the second depth bank (the
# depth words of every eighth lane read there lose that bit): only the clears suite's silent
# passes show it, in the counts of their depth tests; the tiles suite must not. Mutant 14
# inverts bit 54 of the accumulation plane's bank 7 read: only the tiles suite's accumulate
# pass reads that plane. Mutant 62 holds at 1 a bit of a tile count's saturation compare, so the
# count stops at 895, where the clears suite never looks: only the tiles suite's load-back,
# which takes the counts to their saturation and checks them at every beat, names it.
set -u
source "$(dirname "$0")/../lib.sh"
mutant_args "$@"

expect_mutant 327 '-mode const0 -module zb_rop -cell $flatten\\u_depth.\\g_renamed.g_bank.1..u_plane.\\g_bank.4..u_mem.$procdff$[0-9]* -port Q -portbit 9 ' \
  "the second depth bank's read-register mutant"
expect_mutant 14 '-mode inv -module zb_rop -cell u_accum.u_accum_plane.g_bank.7..u_mem.mem_q -port RD_DATA -portbit 54 ' \
  "the accumulation plane's read mutant"
expect_mutant 62 '-mode const1 -module zb_rop -cell $flatten\\u_tile_counters.$eq$rtl/zb_counters.sv:34$[0-9]* -port A -portbit 7 ' \
  "the tile count's saturation-compare mutant"
run() { "$tb" -q --mismatch-fst "" "$@" >"$tmp/out.txt" 2>&1; }

run --mutant 0 --suite clears --seed 1 || fail "mutant 0 fails the clears suite"
run --mutant 0 --suite tiles --seed 1 || fail "mutant 0 fails the tiles suite"

run --mutant 327 --suite tiles --seed 1 ||
  fail "mutant 327 fails the tiles suite: then this test no longer shows the clears suite alone"
run --mutant 327 --suite clears --seed 1
rc=$?
[[ $rc -eq 1 ]] || fail "mutant 327 in the clears suite: exit $rc, want 1"
grep -qE '^MISMATCH in frame [0-9]+ pass [0-9]+ "clears-two-silent[a-z-]*": counters differ' "$tmp/out.txt" ||
  fail "mutant 327: no 'counters differ' report in a clears-two-silent pass"
echo "ok: mutant 327: $(grep -m1 'MISMATCH' "$tmp/out.txt")"

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

tiles_catches 14 'LOCKSTEP MISMATCH in frame [0-9]+ pass [0-9]+ "tiles-accumulate": the first wrong write' \
  'LOCKSTEP MISMATCH ... "tiles-accumulate": the first wrong write'
for m in 62; do
  tiles_catches "$m" 'counted [0-9]+ store and [0-9]+ load beats after its store was read again and loaded back; two tiles of beats saturate at [0-9]+: want [0-9]+ and [0-9]+ at load-back beat [0-9]+' \
    "counted N store and N load beats after its store was read again ... want N and N at load-back beat N"
done
