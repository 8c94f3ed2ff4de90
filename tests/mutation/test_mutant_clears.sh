#!/usr/bin/env bash
# The fast-clear epoch and the tile counters' saturation, each caught by one suite only.
# Mutant 1004 inverts a bit of the depth plane's compare of a write-back's epoch with the
# plane's, so the last write-back of a store spends the wrong epoch when the next run's fast
# clear meets it; mutant 417 ties the depth plane's W1 flag to 0, so a store writes no fresh
# word back and the next fast clear finds words of the old epoch. Only the clears suite (a
# store straight into a clear, clears with no store between, a probe of every pixel) sees
# them; the tiles suite, whose re-read puts cycles between store and clear, must not. Mutant
# 68 inverts a bit of the tile store count's saturation compare, so the count stops at 767:
# only the tiles suite, whose load-back takes the count to its saturation, sees it.
set -u
source "$(dirname "$0")/mutant_lib.sh" "$@"

expect_mutant 1004 '-mode inv -module zb_rop -cell $flatten\\u_depth.\\u_depth_plane.$eq$rtl/zb_plane.sv:78' \
  "the write-back epoch-compare mutant"
expect_mutant 417 '-mode const0 -module zb_rop -cell $flatten\\u_depth.\\u_depth_plane.$procdff$[0-9]* -port Q -portbit 0 -wire u_depth.u_depth_plane.wback_q ' \
  "the W1 flag mutant"
expect_mutant 68 '-mode inv -module zb_rop -cell $flatten\\u_tile_counters.$eq$rtl/zb_counters.sv:34' \
  "the store-count saturation mutant"
run() { "$tb" -q --mismatch-fst "" "$@" >"$tmp/out.txt" 2>&1; }

run --mutant 0 --suite clears --seed 1 || fail "mutant 0 fails the clears suite"
for m in 1004 417; do
  run --mutant "$m" --suite tiles --seed 1 ||
    fail "mutant $m fails the tiles suite: then this test no longer shows the clears suite alone"
  run --mutant "$m" --suite clears --seed 1
  rc=$?
  [[ $rc -eq 1 ]] || fail "mutant $m in the clears suite: exit $rc, want 1"
  grep -qE '^(LOCKSTEP )?MISMATCH in frame [0-9]+ pass [0-9]+ "clears-(probe|silent)": ' "$tmp/out.txt" ||
    fail "mutant $m: no mismatch report in a clears-probe or clears-silent pass"
  echo "ok: mutant $m: $(grep -m1 'MISMATCH' "$tmp/out.txt")"
done

run --mutant 68 --suite clears --seed 1 ||
  fail "mutant 68 fails the clears suite: then this test no longer shows the tiles suite alone"
run --mutant 68 --suite tiles --seed 1
rc=$?
[[ $rc -eq 1 ]] || fail "mutant 68 in the tiles suite: exit $rc, want 1"
grep -q 'store count 767 at load-back beat 0 after its store was read again: saturated at 1023, it must hold there' "$tmp/out.txt" ||
  fail "mutant 68: no 'store count 767 ... must hold there' line"
echo "ok: mutant 68: $(grep -o 'store count .*' "$tmp/out.txt" | head -1)"
