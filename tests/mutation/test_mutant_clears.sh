#!/usr/bin/env bash
# The fast-clear epoch and the tile counters' hold, each caught by one check only.
# Mutants 512 and 566 let the depth plane's last write-back of a store keep or spend the wrong
# epoch when the next run's fast clear meets it: only the clears suite (a store straight into a
# clear, clears with no store between, a probe of every pixel) sees them; the tiles suite, whose
# re-read puts cycles between store and clear, must not. Mutant 846 makes the store count's bit 3
# follow bit 4 in its hold path, so a saturated count alternates 1023/1015 by cycle: only the
# tiles suite's per-cycle check during the load-back sees it.
set -u
source "$(dirname "$0")/mutant_lib.sh" "$@"

expect_mutant 512 '-mode inv -module zb_rop -cell $flatten\\u_depth.\\u_depth_plane.$not$rtl/zb_plane.sv:138' \
  "the write-back generation mutant"
expect_mutant 566 '-mode inv -module zb_rop -cell $flatten\\u_depth.\\u_depth_plane.$eq$rtl/zb_plane.sv:78' \
  "the write-back epoch-compare mutant"
expect_mutant 846 '-mode cnot1 -module zb_rop -cell $flatten\\u_tile_counters.$procdff$3055 -port Q -portbit 3 -ctrlbit 4' \
  "the store-count hold mutant"
run() { "$tb" -q --mismatch-fst "" "$@" >"$tmp/out.txt" 2>&1; }

run --mutant 0 --suite clears --seed 1 || fail "mutant 0 fails the clears suite"
for m in 512 566; do
  run --mutant "$m" --suite tiles --seed 1 ||
    fail "mutant $m fails the tiles suite: then this test no longer shows the clears suite alone"
  run --mutant "$m" --suite clears --seed 1
  rc=$?
  [[ $rc -eq 1 ]] || fail "mutant $m in the clears suite: exit $rc, want 1"
  grep -q 'LOCKSTEP MISMATCH in frame [0-9]* pass [0-9]* "clears-probe": the first wrong write, at cycle' "$tmp/out.txt" ||
    fail "mutant $m: no lock-step report of a wrong write in a clears-probe pass"
  echo "ok: mutant $m: $(grep -m1 'LOCKSTEP MISMATCH' "$tmp/out.txt")"
done

run --mutant 846 --suite clears --seed 1 ||
  fail "mutant 846 fails the clears suite: then this test no longer shows the hold check alone"
run --mutant 846 --suite tiles --seed 1
rc=$?
[[ $rc -eq 1 ]] || fail "mutant 846 in the tiles suite: exit $rc, want 1"
grep -q 'store count 1015 at load-back beat 0 after its store was read again: saturated at 1023, it must hold there' "$tmp/out.txt" ||
  fail "mutant 846: no 'store count 1015 ... must hold there' line"
echo "ok: mutant 846: $(grep -o 'store count .*' "$tmp/out.txt" | head -1)"
