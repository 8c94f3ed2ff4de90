#!/usr/bin/env bash
# The fast-clear epoch and the tile counters, each caught by one suite only.
# Mutant 703 inverts the depth plane's compare of a write-back's epoch with the plane's, so the
# last write-back of a store spends the wrong epoch when the next run's fast clear meets it;
# mutant 458 ties the colour plane's W1 flag to 0, so a store writes no fresh word back and the
# next fast clear finds words of the old epoch. Only the clears suite (a store straight into a
# clear, clears with no store between, a probe of every pixel) sees them; the tiles suite, whose
# re-read puts cycles between store and clear, must not. Mutant 1 flips a bit of the tile
# counters' next value under a condition the clears suite never meets: only the tiles suite,
# whose counts the driver checks per tile and at every beat of the load-back, sees it. Mutant
# 845 inverts the load count's "at all ones" flop: the tiles suite's load-back, which takes the
# counts to their saturation, names it.
# Mutant 435 flips a load-count bit at the flop's output, so its hold path rewrites it and the
# count is wrong at some cycles only: the load-back's check at every beat names it. Mutant 1014
# keeps the depth plane's all-fresh flag through loads: only the clears suite's last iteration
# (one tile loaded, the next fast-cleared, twice with no store between) shows it, in the counts.
set -u
source "$(dirname "$0")/../lib.sh"
mutant_args "$@"

expect_mutant 703 '-mode inv -module zb_rop -cell $flatten\\u_depth.\\u_depth_plane.$eq$rtl/zb_plane.sv:78' \
  "the write-back epoch-compare mutant"
expect_mutant 458 '-mode const0 -module zb_rop -cell $flatten\\u_color.\\u_color_plane.$procdff$[0-9]* -port Q -portbit 0 -wire u_color.u_color_plane.wback_q ' \
  "the W1 flag mutant"
expect_mutant 1 '-mode cnot0 -module zb_rop -cell $flatten\\u_tile_counters.$procmux' \
  "the tile-count mutant"
expect_mutant 845 '-mode inv -module zb_rop -cell $flatten\\u_tile_counters.$procdff$[0-9]* -port Q -portbit 0 -wire u_tile_counters.g_cnt\[0\].sat_q ' \
  "the load-count saturation mutant"
expect_mutant 435 '-mode cnot1 -module zb_rop -cell $flatten\\u_tile_counters.$procdff$[0-9]* -port Q -portbit 5 -ctrlbit 2 -wire cnt_tile_loads_o ' \
  "the load count's hold-path mutant"
expect_mutant 1014 '-mode const0 -module zb_rop -cell $flatten\\u_depth.\\u_depth_plane.$logic_or$rtl/zb_plane.sv:86' \
  "the depth plane's all-fresh flag mutant"
run() { "$tb" -q --mismatch-fst "" "$@" >"$tmp/out.txt" 2>&1; }

run --mutant 0 --suite clears --seed 1 || fail "mutant 0 fails the clears suite"
for m in 703 458; do
  run --mutant "$m" --suite tiles --seed 1 ||
    fail "mutant $m fails the tiles suite: then this test no longer shows the clears suite alone"
  run --mutant "$m" --suite clears --seed 1
  rc=$?
  [[ $rc -eq 1 ]] || fail "mutant $m in the clears suite: exit $rc, want 1"
  grep -qE '^(LOCKSTEP )?MISMATCH in frame [0-9]+ pass [0-9]+ "clears-(store|probe|silent)": ' "$tmp/out.txt" ||
    fail "mutant $m: no mismatch report in a clears pass"
  echo "ok: mutant $m: $(grep -m1 'MISMATCH' "$tmp/out.txt")"
done

# tiles_catches M PATTERN WHAT: mutant M fails the tiles suite with a line matching PATTERN.
tiles_catches() {
  run --mutant "$1" --suite tiles --seed 1
  local rc=$?
  [[ $rc -eq 1 ]] || fail "mutant $1 in the tiles suite: exit $rc, want 1"
  grep -qE -- "$2" "$tmp/out.txt" || fail "mutant $1: no '$3' line"
  echo "ok: mutant $1: $(grep -m1 -oE -- "$2" "$tmp/out.txt")"
}

run --mutant 1 --suite clears --seed 1 ||
  fail "mutant 1 fails the clears suite: then this test no longer shows the tiles suite alone"
tiles_catches 1 'rtl: tile \([0-9]+,[0-9]+\) counted [0-9]+ (load and [0-9]+ store beats, the driver moved [0-9]+ and [0-9]+|store and [0-9]+ load beats after its store was read again)' \
  "tile (x,y) counted N load and N store beats, the driver moved ..., or ... after its store was read again"
tiles_catches 845 'counted [0-9]+ store and [0-9]+ load beats after its store was read again and loaded back; two tiles of beats saturate at [0-9]+' \
  "counted N store and N load beats after its store was read again ... saturate at N"
tiles_catches 435 'two tiles of beats saturate at [0-9]+: want [0-9]+ and [0-9]+ at load-back beat [0-9]+' \
  "... want N and N at load-back beat N"

run --mutant 1014 --suite tiles --seed 1 ||
  fail "mutant 1014 fails the tiles suite: then this test no longer shows the clears suite alone"
run --mutant 1014 --suite clears --seed 1
rc=$?
[[ $rc -eq 1 ]] || fail "mutant 1014 in the clears suite: exit $rc, want 1"
grep -qE '^MISMATCH in frame [0-9]+ pass [0-9]+ "clears-two-silent": counters differ' "$tmp/out.txt" ||
  fail "mutant 1014: no 'counters differ' report in a clears-two-silent pass"
echo "ok: mutant 1014: $(grep -m1 'MISMATCH' "$tmp/out.txt")"
