#!/usr/bin/env bash
# The SystemC co-simulation can fail: zblend_systemc built against the RTL with
# +define+ZB_INJECT_BLEND_BUG (alpha blend, odd source alpha: red bit 0 flipped) must report the
# first differing pixel with both values and exit 1 on a trace with odd alphas, which the good
# build runs with 0 mismatches. The built-in scenes' alphas are even, hence the scene file.
set -u
zblend=${1:?usage: test_systemc_bug.sh PATH/TO/zblend PATH/TO/zblend_systemc PATH/TO/zblend_systemc_bug}
good=${2:?usage: test_systemc_bug.sh PATH/TO/zblend PATH/TO/zblend_systemc PATH/TO/zblend_systemc_bug}
bug=${3:?usage: test_systemc_bug.sh PATH/TO/zblend PATH/TO/zblend_systemc PATH/TO/zblend_systemc_bug}
source "$(dirname "$0")/../lib.sh"

odd_alpha_scene "$tmp"
"$zblend" trace --scene "$tmp/odd.obj" --method unsorted -W 64 -H 48 --out "$tmp/t.zbt" \
  >"$tmp/out.txt" 2>&1 || fail "zblend trace"

"$good" --trace "$tmp/t.zbt" >"$tmp/out.txt" 2>&1 || fail "the good RTL failed"
"$bug" --trace "$tmp/t.zbt" >"$tmp/out.txt" 2>&1
rc=$?
[[ $rc -eq 1 ]] || fail "the bug-injected RTL gave exit $rc, want 1"
grep -qE 'FAILED: .*t\.zbt: [1-9][0-9]* mismatches; first: pass [0-9]+ \(.*\): pixel \([0-9]+,[0-9]+\): golden rgba [0-9,]+ .*; rtl rgba [0-9,]+' \
  "$tmp/out.txt" || fail "no 'first: pass .. pixel (x,y): golden rgba .. rtl rgba ..' report"
grep -m1 'FAILED' "$tmp/out.txt"
echo "ok: bug caught"
