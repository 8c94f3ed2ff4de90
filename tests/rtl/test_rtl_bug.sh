#!/usr/bin/env bash
# The checkers can fail. zblend_tb_bug runs the RTL with deliberate defects, one per run:
#   blend   (default) the alpha blend flips bit 0 of red when the source alpha is odd;
#   window  a fragment entering the issue window in the cycle another to its pixel is picked
#           misses it, and may issue one cycle after it instead of Span cycles (a hazard).
# Each must be caught by the suites' comparison, with a report naming a pixel and both values
# and an FST waveform around it; the window defect also by the RTL's own assertions.
set -u
tb=${1:?usage: test_rtl_bug.sh PATH/TO/zblend_tb_bug}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; echo "--- output:"; cat "$tmp/out.txt"; exit 1; }

# caught NAME ARGS...: the run fails with a full mismatch report.
caught() {
  local name=$1; shift
  rm -f "$tmp/mismatch.fst"
  "$tb" "$@" --mismatch-fst "$tmp/mismatch.fst" >"$tmp/out.txt" 2>&1
  local rc=$?
  [[ $rc -eq 1 ]] || fail "$name: the defective RTL gave exit $rc, want 1"
  grep -qE 'pixel \([0-9]+,[0-9]+\) rtl=rgba\([0-9,]+\) z=0x[0-9a-f]+ cov=[0-9]+ golden=rgba' \
    "$tmp/out.txt" || fail "$name: no 'pixel (x,y) rtl=... golden=...' line"
  grep -q 'accepted at cycle' "$tmp/out.txt" || fail "$name: no fragments listed for the pixel"
  grep -q 'replay reproduced the mismatch' "$tmp/out.txt" ||
    fail "$name: the waveform replay did not reproduce it"
  grep -qE '^0 passed, [1-9] failed' "$tmp/out.txt" || fail "$name: no '0 passed, N failed' summary"
  [[ -s "$tmp/mismatch.fst" ]] || fail "$name: no FST written at $tmp/mismatch.fst"
  head -c 1 "$tmp/mismatch.fst" | od -An -tx1 | grep -q '00' || fail "$name: mismatch.fst is not an FST"
  echo "ok: $name caught: $(grep -m1 '^pixel' "$tmp/out.txt")"
}

caught blend --suite random --seed 1 --fragments 300000
caught window --defect window --no-assertions --suite hazard,random --seed 1 -q

# With its assertions on, the RTL stops itself at the window defect (the hit bits are exact).
# (An inner shell, so the abort's message goes to the log.)
bash -c '"$0" "$@"; exit $?' "$tb" --defect window --suite hazard --seed 1 -q >"$tmp/out.txt" 2>&1
rc=$?
[[ $rc -ne 0 ]] || fail "window: the RTL with assertions passed"
grep -q 'u_window.*HitExact.*failed' "$tmp/out.txt" || fail "window: no HitExact assertion failure"
echo "ok: window stopped by $(grep -o 'u_window[^:]*HitExact' "$tmp/out.txt" | head -1)"
