#!/usr/bin/env bash
# zblend pixel --backend rtl --waves (docs/history.md "Beside the RTL"): the save file's markers
# at the pixel's accepts and X4 and X11 writes are where the FST shows them (check_waves.py,
# GTKWave under Xvfb), and the check refuses a write marker moved one cycle.
set -u
zblend=$(realpath "${1:?usage: test_pixel_waves.sh PATH/TO/zblend}")
root=$(cd "$(dirname "$0")/../.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
cd "$tmp" || exit 2

"$zblend" pixel -q --scene cad -W 64 -H 48 -m depth-peel-2 --at "30,20" --backend rtl \
  --waves px.fst >px.txt 2>px.err || fail "zblend pixel --waves: $(cat px.err)"
[[ -s px.fst && -s px.gtkw ]] || fail "no FST or save file: $(ls)"
grep -q "(gtkwave px.gtkw)" px.err || fail "stderr does not name the save file: $(cat px.err)"
markers=$(grep -c '^\[markername\]' px.gtkw)
[[ $markers -ge 6 ]] || fail "$markers markers, want an accept and two writes for two fragments at least"
python3 "$root/scripts/check_waves.py" px.gtkw --gtkwave >check.txt 2>&1 || { cat check.txt; fail "check_waves.py"; }
echo "ok: $(cat check.txt)"

# Marker B (the first X4 write) one cycle late: refused, saying why.
b=$(sed -n 's/^\*[^ ]* [0-9-]* [0-9-]* \([0-9]*\) .*/\1/p' px.gtkw)
[[ -n $b ]] || fail "no marker B in the save file's marker line"
sed "s/^\(\*[^ ]* [0-9-]* [0-9-]*\) $b /\1 $((b + 10000)) /" px.gtkw >late.gtkw
python3 "$root/scripts/check_waves.py" late.gtkw >late.txt 2>&1 && fail "check_waves.py accepts an X4 marker one cycle late"
grep -q "marker B (pass [0-9]* fragment [0-9]* (#[0-9]*) X4) at $((b + 10000)): no X4 retire of fragment" late.txt ||
  { cat late.txt; fail "check_waves.py does not say what is wrong with the late X4 marker"; }
echo "ok: check_waves.py refuses an X4 marker one cycle late"

# Two pixels: a save file each (GTKWave names 26 markers), each checked against the same FST.
"$zblend" pixel -q --scene cad -W 64 -H 48 -m depth-peel-2 --at "30,20;31,20" --backend rtl \
  --waves two.fst >two.txt 2>two.err || fail "zblend pixel --waves, two pixels: $(cat two.err)"
for xy in 30-20 31-20; do
  [[ -s two-$xy.gtkw ]] || fail "no save file two-$xy.gtkw: $(ls)"
  grep -q "(gtkwave two-$xy.gtkw)" two.err || fail "stderr does not name two-$xy.gtkw: $(cat two.err)"
  grep -q "^\[\*\] zblend: pixel (${xy/-/, })" two-$xy.gtkw || fail "two-$xy.gtkw is not titled with its pixel"
  python3 "$root/scripts/check_waves.py" two-$xy.gtkw >two-$xy.txt 2>&1 ||
    { cat two-$xy.txt; fail "check_waves.py on two-$xy.gtkw"; }
done
cmp -s two-30-20.gtkw two-31-20.gtkw && fail "the two pixels' save files are the same"
echo "ok: a save file a pixel, each checked"

# Every fragment marked, in the text's numbering: depth-peel-4's pixel has more accepts and
# writes than GTKWave's 26 markers, so they go on in F-2.gtkw, F-3.gtkw...; each page checked
# against the FST, and together they mark each fragment of the text once as accepted, with the
# stream number (#S) the text gives it.
"$zblend" pixel -q --scene cad -W 64 -H 48 -m depth-peel-4 --at "32,24" --backend rtl \
  --waves dp.fst >dp.txt 2>dp.err || fail "zblend pixel --waves, depth-peel-4: $(cat dp.err)"
pages=(dp.gtkw dp-[0-9]*.gtkw)
[[ ${#pages[@]} -ge 3 ]] || fail "depth-peel-4: ${#pages[@]} save files, want 3 or more: $(ls)"
grep -q "(gtkwave dp.gtkw)" dp.err && grep -q "dp-2.gtkw" dp.err || fail "stderr does not name the pages: $(cat dp.err)"
for p in "${pages[@]}"; do
  python3 "$root/scripts/check_waves.py" "$p" >check.txt 2>&1 || { cat check.txt; fail "check_waves.py on $p"; }
done
python3 - dp.txt "${pages[@]}" <<'PY' || fail "the markers do not number the text's fragments"
import re, sys
text = open(sys.argv[1]).read()
want, p = {}, None
for ln in text.splitlines():
    m = re.match(r"pass (\d+) '", ln)
    if m:
        p = int(m.group(1))
    m = re.match(r"  fragment (\d+) of the pass", ln)
    if m:
        f = (p, int(m.group(1)))
    m = re.match(r"    rtl: #(\d+) accepted", ln)
    if m:
        want[f] = int(m.group(1))
got = {}
for page in sys.argv[2:]:
    for ln in open(page):
        m = re.match(r"\[markername\] [A-Z]pass (\d+) fragment (\d+) \(#(\d+)\) accepted$", ln)
        if m:
            f = (int(m.group(1)), int(m.group(2)))
            assert f not in got, f"{f} marked twice"
            got[f] = int(m.group(3))
assert len(want) > 26, len(want)
assert got == want, (sorted(set(want) ^ set(got))[:5])
print(f"ok: {len(got)} fragments marked over {len(sys.argv) - 2} save files")
PY
