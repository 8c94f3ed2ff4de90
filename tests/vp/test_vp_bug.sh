#!/usr/bin/env bash
# zblend_vp's check can fail: zblend_vp_bug's RTL inside is zb_rop Verilated with
# +define+ZB_INJECT_BLEND_BUG (alpha blend, odd source alpha: red bit 0 flipped). On a trace with
# odd alphas it must exit 1 naming the first differing pixel, where zblend_vp runs it clean.
set -u
zblend=${1:?usage: test_vp_bug.sh ZBLEND ZBLEND_VP ZBLEND_VP_BUG}
good=${2:?} bug=${3:?}
source "$(dirname "$0")/../lib.sh"
odd_alpha_scene "$tmp"
"$zblend" trace --scene "$tmp/odd.obj" --method unsorted -W 64 -H 48 --out "$tmp/t.zbt" \
  >"$tmp/out.txt" 2>&1 || fail "zblend trace"
"$good" --trace "$tmp/t.zbt" --inside both >"$tmp/out.txt" 2>&1 || fail "the good RTL failed"
"$bug" --trace "$tmp/t.zbt" --inside both >"$tmp/out.txt" 2>&1
rc=$?
[[ $rc -eq 1 ]] || fail "the bug-injected RTL gave exit $rc, want 1"
grep -qE ' golden +.* match$' "$tmp/out.txt" || fail "the golden inside should still match"
grep -qE ' rtl +.*MISMATCH at pixel \([0-9]+, [0-9]+\): colour [0-9,]+ depth 0x[0-9a-f]+; golden render [0-9,]+' \
  "$tmp/out.txt" || fail "no 'MISMATCH at pixel (x, y): colour .. golden render ..' for the rtl inside"
grep -m1 'MISMATCH' "$tmp/out.txt"
echo "ok: bug caught"
