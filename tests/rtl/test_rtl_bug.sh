#!/usr/bin/env bash
# The checker can fail: zblend_tb built against the RTL with +define+ZB_INJECT_BLEND_BUG (the
# alpha blend flips bit 0 of red when the source alpha is odd) must be caught by the random
# suite, with a report naming a pixel and both values, and an FST waveform around it.
set -u
tb=${1:?usage: test_rtl_bug.sh PATH/TO/zblend_tb_bug}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; echo "--- output:"; cat "$tmp/out.txt"; exit 1; }

"$tb" --suite random --seed 1 --fragments 300000 --mismatch-fst "$tmp/mismatch.fst" \
  >"$tmp/out.txt" 2>&1
rc=$?
[[ $rc -ne 0 ]] || fail "the bug-injected RTL passed (exit 0)"
grep -qE 'pixel \([0-9]+,[0-9]+\) rtl=rgba\([0-9,]+\) z=0x[0-9a-f]+ cov=[0-9]+ golden=rgba' "$tmp/out.txt" \
  || fail "no 'pixel (x,y) rtl=... golden=...' line"
grep -q 'accepted at cycle' "$tmp/out.txt" || fail "no fragments listed for the pixel"
grep -q 'replay reproduced the mismatch' "$tmp/out.txt" || fail "the waveform replay did not reproduce it"
grep -q '0 passed, 1 failed' "$tmp/out.txt" || fail "no '0 passed, 1 failed' summary"
[[ -s "$tmp/mismatch.fst" ]] || fail "no FST written at $tmp/mismatch.fst"
head -c 1 "$tmp/mismatch.fst" | od -An -tx1 | grep -q '00' || fail "mismatch.fst is not an FST file"
grep -m1 '^pixel' "$tmp/out.txt"
echo "ok: bug caught, FST $(stat -c %s "$tmp/mismatch.fst") bytes"
