#!/usr/bin/env bash
# zblend pixel where users trip (docs/history.md): traces on the RTL under both schedules, the
# outputs' bad paths (one line, exit 2, nothing left), a hidden-line pixel judged by its edges,
# a coverage-aa pixel saying which reference it is compared with, and counts in words.
set -u
zblend=$(realpath "${1:?usage: test_pixel_edges.sh PATH/TO/zblend}")
source "$(dirname "$0")/../lib.sh"
py=/usr/bin/python3  # Debian's, with python3-pil
mkdir -p "$tmp/out"
cd "$tmp" || exit 2

# Traces of one pass and of several, on the RTL beside the golden model, both schedules.
"$zblend" trace --scene quads -W 32 -H 32 -m opaque -o one.zbt >one.txt || fail "trace one"
grep -q "^one.zbt: 1 pass, " one.txt && ok || fail "trace: '$(cat one.txt)', want '1 pass'"
"$zblend" trace --scene cad -W 64 -H 48 -m depth-peel-2 -o peel.zbt >/dev/null || fail "trace peel"
for t in one peel; do
  at="16,16;5,5"; [[ $t == peel ]] && at="32,24;30,20"
  "$zblend" pixel --trace $t.zbt --at "$at" >$t-golden.txt || fail "pixel --trace $t.zbt"
  for b in rtl both; do
    for s in tile pass; do
      "$zblend" pixel --trace $t.zbt --at "$at" --backend $b --schedule $s >$t-$b-$s.txt 2>err.txt ||
        fail "pixel --trace $t.zbt --backend $b --schedule $s: $(cat err.txt)"
      [[ $(grep -c "^rtl    the same on every plane$" $t-$b-$s.txt) == 2 ]] || fail "$t $b $s: not the same on the RTL"
      [[ $(grep -c "^    rtl: #[0-9]* accepted at cycle" $t-$b-$s.txt) == $(grep -c "^  fragment " $t-$b-$s.txt) ]] ||
        fail "$t $b $s: a fragment without its retire"
      diff <(grep "^final" $t-golden.txt) <(grep "^final" $t-$b-$s.txt) >/dev/null || fail "$t $b $s: final values differ"
      ok
    done
  done
done
head -1 one-golden.txt | grep -q "^trace one.zbt (1 pass)$" && ok || fail "title: $(head -1 one-golden.txt)"
head -1 peel-golden.txt | grep -q "^trace peel.zbt (8 passes)$" && ok || fail "title: $(head -1 peel-golden.txt)"

# Outputs that cannot be written: at once, naming the option, nothing left.
mkdir -p out/d/p.gtkw out/e/two-1-1.gtkw
expect_error "waves where no directory can be made" "^zblend: error: --waves: " \
  "$zblend" pixel -q --scene quads -W 32 -H 24 --at 1,1 --backend rtl --waves /proc/x/y.fst
expect_error "json where no directory can be made" "^zblend: error: --json: " \
  "$zblend" pixel -q --scene quads -W 32 -H 24 --at 1,1 --json /proc/x/y.json
expect_error "a directory in the save file's way" "^zblend: error: --waves: .*p.gtkw is a directory" \
  "$zblend" pixel -q --scene quads -W 32 -H 24 --at 1,1 --backend rtl --waves out/d/p.fst
expect_error "a directory in a pixel's save file's way" "^zblend: error: --waves: .*two-1-1.gtkw is a directory" \
  "$zblend" pixel -q --scene quads -W 32 -H 24 --at "1,1;2,2" --backend rtl --waves out/e/two.fst
[[ $(ls out/d) == p.gtkw && $(ls out/e) == two-1-1.gtkw ]] && ok || fail "left behind: $(ls out/d out/e)"

# A hidden-line pixel: judged against the exact line reference, not by a shaded CIEDE2000. A
# pixel in the edge colour of the render (every edge right on cad: the render's table) is a
# visible edge drawn; a corner is no edge.
"$zblend" render -q --scene cad -m hidden-line -W 160 -H 120 --out hl.png || fail "render hidden-line"
edge=$($py -c "
from PIL import Image
im = Image.open('hl.png').convert('RGB')
print(next(f'{x},{y}' for y in range(im.size[1]) for x in range(im.size[0]) if im.getpixel((x, y)) == (0, 0, 0)))")
"$zblend" pixel -q --scene cad -m hidden-line -W 160 -H 120 --at "$edge;0,0" --json hl.json >hl.txt || fail "pixel hidden-line"
grep -q "CIEDE2000 against it" hl.txt && fail "hidden-line: a shaded CIEDE2000 printed"
grep -q "^exact line reference: a visible edge here; drawn in the visible style: right$" hl.txt && ok ||
  fail "hidden-line ($edge): no visible-edge verdict: $(grep -A1 composited hl.txt)"
grep -q "^exact line reference: no edge here" hl.txt && ok || fail "hidden-line (0,0): no verdict"
grep -q '"line_reference": "visible"' hl.json && ok || fail "hidden-line JSON: no line_reference"
# A coverage-aa pixel says its map's reference is another.
"$zblend" pixel -q --scene cad -m coverage-aa -W 160 -H 120 --at 80,60 >aa.txt || fail "pixel coverage-aa"
grep -q "CIEDE2000 against it [0-9.]* (the error map and the lab judge coverage anti-aliasing against the supersampled reference" aa.txt &&
  ok || fail "coverage-aa: $(grep composited aa.txt)"
"$zblend" pixel -q --scene cad -m three-pass -W 160 -H 120 --at 80,60 | grep -q "supersampled" &&
  fail "three-pass speaks of the supersampled reference"
echo "$pass passed"
