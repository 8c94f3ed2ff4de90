#!/usr/bin/env bash
# The SystemC co-simulation can fail: zblend_systemc built against the RTL with
# +define+ZB_INJECT_BLEND_BUG (alpha blend, odd source alpha: red bit 0 flipped) must report the
# first differing pixel with both values and exit 1 on a trace with odd alphas, which the good
# build runs with 0 mismatches. The built-in scenes' alphas are even, hence the scene file.
set -u
zblend=${1:?usage: test_systemc_bug.sh PATH/TO/zblend PATH/TO/zblend_systemc PATH/TO/zblend_systemc_bug}
good=${2:?usage: test_systemc_bug.sh PATH/TO/zblend PATH/TO/zblend_systemc PATH/TO/zblend_systemc_bug}
bug=${3:?usage: test_systemc_bug.sh PATH/TO/zblend PATH/TO/zblend_systemc PATH/TO/zblend_systemc_bug}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; echo "--- output:"; cat "$tmp/out.txt"; exit 1; }

# Two overlapping transparent triangles, alphas 77 and 179 (d 0.3, 0.7).
printf 'mtllib m.mtl\nv -1 -1 0\nv 1 -1 0\nv 0 1 0\nv -1 1 -0.5\nv 1 1 -0.5\nv 0 -1 -0.5\n' >"$tmp/odd.obj"
printf 'usemtl a\nf 1 2 3\nusemtl b\nf 4 6 5\n' >>"$tmp/odd.obj"
printf 'newmtl a\nKd 0.9 0.2 0.1\nd 0.3\nnewmtl b\nKd 0.1 0.3 0.9\nd 0.7\n' >"$tmp/m.mtl"
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
