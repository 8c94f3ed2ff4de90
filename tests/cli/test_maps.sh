#!/usr/bin/env bash
# zblend render's error maps and worst pixel as a user reads them (docs/cli.md "Error maps"):
# exact pixels apart from the smallest error, the scale chosen by --error-scale, the worst pixel
# in the table, summary.csv and --stats, and that pixel's own history agreeing.
set -u
zblend=${1:?usage: test_maps.sh PATH/TO/zblend}
source "$(dirname "$0")/../lib.sh"
py=/usr/bin/python3  # Debian's, with python3-pil (the test group installs it with matplotlib)
mkdir -p "$tmp/out"
render() {  # DIR ARGS...: cad, three methods and the reference, 160x120
  local dir=$1; shift
  "$zblend" render --scene cad -m depth-peel-4,opaque,coverage-aa,reference -W 160 -H 120 \
    --out-dir "$tmp/$dir" --stats "$tmp/$dir/stats.json" "$@" >"$tmp/$dir.txt" 2>"$tmp/$dir.err" ||
    fail "render $dir: $(cat "$tmp/$dir.err")"
}
render auto
render own --error-scale per-method
render one --error-scale 1
render huge --error-scale 1000
grep -q "error maps: .*0 to 50 dE2000 for every method" "$tmp/auto.err" && ok || fail "auto: the shared scale is not said: $(cat "$tmp/auto.err")"
grep -q "error maps: .*each map on its own scale" "$tmp/own.err" && ok || fail "per-method: not said"

# Exact pixels: where a method's image equals the reference's, its map shows the exact colour,
# and nowhere else (the images compared here, not the model's numbers). Then the scales: the
# same errors brighter on a smaller scale.
$py - "$tmp" <<'PY' && ok || fail "maps: exact pixels or scales"
import sys
from PIL import Image
t = sys.argv[1]
EXACT = (24, 64, 72)
def img(d, name):
    return Image.open(f"{t}/{d}/{name}").convert("RGB")
ref = img("auto", "reference.png")
w, h = ref.size
def light(d, m):  # the mean brightness of a map's frame where the method errs
    mp, im = img(d, f"{m}-error.png"), img("auto", f"{m}.png")
    s = n = 0
    for y in range(h):
        for x in range(w):
            if im.getpixel((x, y)) != ref.getpixel((x, y)):
                s += sum(mp.getpixel((x, y)))
                n += 1
    return s / max(n, 1)
for m in ("depth-peel-4", "opaque"):
    mp, im = img("auto", f"{m}-error.png"), img("auto", f"{m}.png")
    assert mp.size[1] == h + 44, mp.size
    for y in range(h):
        for x in range(w):
            same = im.getpixel((x, y)) == ref.getpixel((x, y))
            ringed = mp.getpixel((x, y)) == (0, 255, 255)  # the worst pixel's ring
            assert ringed or (mp.getpixel((x, y)) == EXACT) == same, (m, x, y)
    a, o, one, huge = light("auto", m), light("own", m), light("one", m), light("huge", m)
    assert huge < a <= one and a <= o, (m, huge, a, o, one)
# depth-peel-4 errs by about 1 dE at most: on the run's shared scale (50) it is near black, on
# its own it shows.
assert light("own", "depth-peel-4") > 2 * light("auto", "depth-peel-4")
PY

# The worst pixel: in the table, summary.csv and --stats alike; its history gives its dE.
read -r wx wy de <<<"$($py - "$tmp/auto" <<'PY'
import csv, json, sys
d = sys.argv[1]
rows = {r["method"]: r for r in csv.DictReader(open(f"{d}/summary.csv"))}
stats = {m["method"]: m for m in json.load(open(f"{d}/stats.json"))["methods"]}
r, s = rows["opaque"], stats["opaque"]["error"]["worst_pixel"]
assert (int(r["worst_x"]), int(r["worst_y"])) == (s["x"], s["y"]), (r, s)
assert abs(float(r["delta_e_max"]) - s["delta_e"]) < 1e-3
assert rows["reference"]["worst_x"] == "" and stats["reference"]["error"]["worst_pixel"] is None
print(s["x"], s["y"], s["delta_e"])
PY
)"
[[ -n $wx ]] && ok || fail "worst pixel: summary.csv and --stats disagree"
grep -qE "^opaque .* [0-9.]+ \($wx,$wy\)$" "$tmp/auto.txt" && ok || fail "the table does not show ($wx,$wy): $(grep ^opaque "$tmp/auto.txt")"
"$zblend" pixel -q --scene cad -m opaque -W 160 -H 120 --at "$wx,$wy" >"$tmp/px.txt" || fail "pixel at the worst"
got=$(sed -n 's/.*CIEDE2000 against it \([0-9.]*\).*/\1/p' "$tmp/px.txt")
$py -c "import sys; assert abs($got - $de) < 0.006, ($got, $de)" && ok || fail "pixel ($wx, $wy): dE $got, the table's $de"

# Bad scales, and a scale with no map to draw.
expect_error "error scale word" "^zblend: error: --error-scale: 'big' is not auto, per-method or a number" \
  "$zblend" render --scene quads -W 32 -H 24 --out-dir "$tmp/out/x" --error-scale big
expect_error "error scale zero" "^zblend: error: --error-scale: '0' is not auto" \
  "$zblend" render --scene quads -W 32 -H 24 --out-dir "$tmp/out/x" --error-scale 0
expect_error "error scale no maps" "^zblend: error: --error-scale: no error maps are written" \
  "$zblend" render --scene quads -W 32 -H 24 --out "$tmp/out/x.png" --error-scale 5
echo "$pass passed"
