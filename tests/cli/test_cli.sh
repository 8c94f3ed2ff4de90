#!/usr/bin/env bash
# The zblend command as a user meets it: help, listings, a render, and bad input that must
# give one line on stderr, exit code 2 and no output file.
set -u
zblend=${1:?usage: test_cli.sh PATH/TO/zblend PATH/TO/zblend_tb}
tb=${2:?usage: test_cli.sh PATH/TO/zblend PATH/TO/zblend_tb}
source "$(dirname "$0")/../lib.sh"
# The zblend command's errors.
expect_zblend_error() {
  local name=$1 pattern=$2; shift 2
  expect_error "$name" "$pattern" "$zblend" "$@"
}

mkdir -p "$tmp/out" "$tmp/ro"
chmod 555 "$tmp/ro"

# Help and listings.
for sub in "" render trace methods scenes plan pixel; do
  if "$zblend" $sub --help >"$tmp/help" 2>&1 && grep -q "Usage" "$tmp/help"; then ok; else fail "help $sub"; fi
done
if "$zblend" methods | grep -q "three-pass"; then ok; else fail "methods lists three-pass"; fi
if "$zblend" methods | grep -q "reference"; then ok; else fail "methods lists reference"; fi
for s in cad quads sphere-torus; do
  if "$zblend" scenes | grep -q "^$s "; then ok; else fail "scenes lists $s"; fi
done
if [[ $("$zblend" plan --method three-pass | grep -cE "^[0-9]+ +transparent") == 2 ]]; then ok; else fail "plan three-pass"; fi

# A render: a PNG of the asked size, and stats.
if "$zblend" render -q --scene quads --method three-pass --width 64 --height 48 \
     --out "$tmp/out/q.png" --stats "$tmp/out/q.json"; then
  sig=$(head -c 8 "$tmp/out/q.png" | od -An -tx1 | tr -d ' \n')
  size=$(od -An -tu1 -j16 -N8 "$tmp/out/q.png" | awk '{print $3*256+$4 "x" $7*256+$8}')
  [[ $sig == 89504e470d0a1a0a ]] && ok || fail "PNG signature $sig"
  [[ $size == 64x48 ]] && ok || fail "PNG size $size"
  grep -q '"fragments_in"' "$tmp/out/q.json" && ok || fail "stats json"
  rm -f "$tmp/out/q.png" "$tmp/out/q.json"
else
  fail "render quads"
fi
if "$zblend" render -q --scene cad --method all --width 80 --height 60 --out-dir "$tmp/run"; then
  methods=$(( $("$zblend" methods | wc -l) - 1 ))  # one image per method (header line off)
  # An image per method, and an error map per method but the reference.
  [[ $(ls "$tmp/run"/*.png | grep -vc -- -error.png) -eq $methods &&
     $(ls "$tmp/run"/*-error.png | wc -l) -eq $((methods - 1)) ]] && ok || fail "out-dir images: $(ls "$tmp/run")"
  [[ $(head -1 "$tmp/run/summary.csv") == method,passes,fragments,* ]] && ok || fail "summary header"
  grep -q '^reference,.*,0.0000,inf,0,' "$tmp/run/summary.csv" && ok || fail "reference row has no error"
else
  fail "render all"
fi

# Both backends, compared bit for bit, with back-pressure.
if "$zblend" render -q --scene sphere-torus --method all --width 48 --height 36 --backend both \
     --backpressure 0.25 --out-dir "$tmp/both"; then
  # mismatches, then the line-error columns (empty: three-pass draws no edges), then the worst pixel
  grep -qE '^three-pass,3,.*,[0-9]+,[0-9]+,0,,,,[0-9]+,[0-9]+$' "$tmp/both/summary.csv" && ok || fail "both: mismatches column"
  grep -qE '^hidden-line,2,.*,0,[0-9]+,[0-9.]+,[0-9.]+,[0-9]+,[0-9]+$' "$tmp/both/summary.csv" && ok || fail "both: line error columns"
else
  fail "render --backend both"
fi

# A real scene file from Debian's assimp-testmodels on both backends, and a file trace.
regr01=/usr/share/assimp/models/OBJ/regr01.obj
if "$zblend" render -q --scene "$regr01" --method all --width 40 --height 30 --backend both \
     --out-dir "$tmp/regr01"; then
  grep -qE '^three-pass,3,.*,0,,,,[0-9]*,[0-9]*$' "$tmp/regr01/summary.csv" && ok || fail "regr01 both: mismatches"
  grep -qE '^wboit,2,.*,0,,,,[0-9]*,[0-9]*$' "$tmp/regr01/summary.csv" && ok || fail "regr01 both: wboit mismatches"
else
  fail "render regr01.obj --backend both"
fi
if "$zblend" render -q --scene "$regr01" --method three-pass --width 40 --height 30 --backend rtl \
     --camera eye=-1200,-1400,700,at=620,380,120,fov=45 --out "$tmp/out/r.png"; then ok; else fail "render regr01 rtl --camera"; fi
rm -f "$tmp/out/r.png"

# The lab and a sweep, tiny: a CSV row per method, the reference row at zero error.
if "$zblend" lab -q --scenes quads --methods opaque,reference -W 32 -H 24 --no-rtl --no-charts \
     --out-dir "$tmp/lab"; then
  [[ $(grep -c '^quads,' "$tmp/lab/lab.csv") -eq 2 ]] && ok || fail "lab: rows $(cat "$tmp/lab/lab.csv")"
  grep -qE '^quads,[^,]*,reference,.*,0\.0000,inf,0,' "$tmp/lab/lab.csv" && ok || fail "lab: reference row"
else
  fail "lab"
fi
if "$zblend" sweep depth -q --no-charts -W 32 -H 24 --out-dir "$tmp/sweep" &&
   [[ -s "$tmp/sweep/depth.csv" && ! -e "$tmp/sweep/depth.png" ]]; then ok; else fail "sweep depth"; fi

# A trace file.
if "$zblend" trace --scene quads --method unsorted --width 32 --height 24 --out "$tmp/out/q.zbt" >/dev/null &&
   [[ $(head -c 7 "$tmp/out/q.zbt") == ZBTRACE ]]; then ok; else fail "trace write"; fi
rm -f "$tmp/out/q.zbt"

# Bad input.
expect_zblend_error "unknown scene" "unknown scene 'nope'.*cad" render --scene nope --out "$tmp/out/a.png"
expect_zblend_error "unknown method" "unknown method 'nope'.*three-pass" render --method nope --out "$tmp/out/a.png"
expect_zblend_error "zero width" "--width: 0 is out of range" render --width 0 --out "$tmp/out/a.png"
expect_zblend_error "huge height" "--height: 100000 is out of range" render --height 100000 --out "$tmp/out/a.png"
expect_zblend_error "depth bits" "--depth-bits" render --depth-bits 40 --out "$tmp/out/a.png"
expect_zblend_error "not a number" "width" render --width abc --out "$tmp/out/a.png"
expect_zblend_error "no output" "--out" render --scene cad
expect_zblend_error "not png" "must end in .png" render --out "$tmp/out/a.jpg"
expect_zblend_error "several methods one file" "--out-dir" render --method opaque,three-pass --out "$tmp/out/a.png"
expect_zblend_error "unknown subcommand" "" frobnicate
expect_zblend_error "unknown backend" "unknown backend 'gpu'.*golden, rtl, both" render --backend gpu --out "$tmp/out/a.png"
expect_zblend_error "rtl depth bits" "--depth-bits: the RTL model is built with 24" render --backend rtl --depth-bits 16 --out "$tmp/out/a.png"
expect_zblend_error "waves need rtl" "--waves: needs --backend rtl" render --waves "$tmp/out/w.fst" --out "$tmp/out/a.png"
expect_zblend_error "backpressure range" "--backpressure: 1.5 is out of range" render --backend rtl --backpressure 1.5 --out "$tmp/out/a.png"
expect_zblend_error "lab scene" "--scenes: .*'nope'" lab --scenes nope --out-dir "$tmp/out/lab"
expect_zblend_error "lab method" "'foo'" lab --methods foo --out-dir "$tmp/out/lab"
expect_zblend_error "lab jobs" "-j" lab -j 0 --out-dir "$tmp/out/lab"
expect_zblend_error "sweep name" "unknown sweep 'bogus'" sweep bogus --out-dir "$tmp/out/sw"
expect_zblend_error "plan of reference" "no pass plan" plan --method reference
expect_zblend_error "trace of reference" "no pass plan" trace --method reference --out "$tmp/out/t.zbt"
expect_zblend_error "trace extension" "must end in .zbt" trace --out "$tmp/out/t.bin"
# --no-error: the golden model alone, the same image, no error in the stats, memory reported.
if "$zblend" render -q --scene cad --method three-pass --width 96 --height 72 --out "$tmp/a.png" &&
   "$zblend" render -q --scene cad --method three-pass --width 96 --height 72 --no-error \
     --out "$tmp/b.png" --stats "$tmp/b.json"; then
  cmp -s "$tmp/a.png" "$tmp/b.png" && ok || fail "--no-error changes the image"
  grep -q '"error": null' "$tmp/b.json" && ok || fail "--no-error: error in stats"
  grep -q '"frame_bytes": 89856' "$tmp/b.json" && ok || fail "memory.frame_bytes (96 x 72 x 13)"
  grep -qE '"peak_rss_bytes": [1-9][0-9]+' "$tmp/b.json" && ok || fail "memory.peak_rss_bytes"
else
  fail "render --no-error"
fi
expect_zblend_error "no-error with reference" "--no-error: the reference method" render \
  --method three-pass,reference --no-error --out-dir "$tmp/out/d"
expect_zblend_error "threads" "--threads" render --threads 0 --out "$tmp/out/a.png"
expect_zblend_error "trace size" "--width: 9000 is out of range" trace --width 9000 --out "$tmp/out/t.zbt"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n' >"$tmp/bad.obj"
expect_zblend_error "obj index" "bad.obj: line 4: vertex index 9 out of range" render --scene "$tmp/bad.obj" --out "$tmp/out/a.png"
printf '{"asset": {"version": "2.0"}, "nodes": [' >"$tmp/trunc.gltf"
expect_zblend_error "truncated gltf" "trunc.gltf: JSON: malformed" trace --scene "$tmp/trunc.gltf" --out "$tmp/out/t.zbt"
expect_zblend_error "missing scene file" "no/such.obj: open: no such file" render --scene "$tmp/no/such.obj" --out "$tmp/out/a.png"
expect_zblend_error "camera field" "--camera: field 'fov'" render --camera eye=0,0,5,at=0,0,0,fov=x --out "$tmp/out/a.png"
if [[ $(id -u) -ne 0 ]]; then
  expect_zblend_error "unwritable" "not writable" render --out "$tmp/ro/a.png"
else
  expect_zblend_error "unwritable" "cannot write" render -q --width 8 --height 8 --out /proc/zblend-test.png
fi

# ---- output paths (docs/cli.md): missing directories made, files on the way refused ----------
: >"$tmp/afile"
mkdir -p "$tmp/dir.png" "$tmp/dir.fst"
small=(-q --width 8 --height 6)
if "$zblend" render "${small[@]}" --out "$tmp/new1/a/x.png" && [[ -s "$tmp/new1/a/x.png" ]]; then ok; else fail "--out: parent directories made"; fi
if "$zblend" render "${small[@]}" --backend rtl --out "$tmp/new2/x.png" --waves "$tmp/new2/w/w.fst" &&
   [[ -s "$tmp/new2/w/w.fst" ]]; then ok; else fail "--waves: parent directories made"; fi
if "$zblend" render "${small[@]}" --out-dir "$tmp/new3/b/c" && [[ -s "$tmp/new3/b/c/summary.csv" ]]; then ok; else fail "--out-dir: made"; fi
if "$zblend" plan --scene quads --max-error 255 -W 16 -H 12 --json "$tmp/new4/p.json" >/dev/null 2>&1 &&
   [[ -s "$tmp/new4/p.json" ]]; then ok; else fail "--json: parent directories made"; fi
expect_zblend_error "out-dir is a file" "^zblend: error: --out-dir: /etc/passwd is a file, not a directory$" render --out-dir /etc/passwd
expect_zblend_error "out-dir under a file" "--out-dir: $tmp/afile is a file, not a directory" render --out-dir "$tmp/afile/sub"
expect_zblend_error "out under a file" "--out: $tmp/afile is a file, not a directory" render --out "$tmp/afile/x.png"
expect_zblend_error "out is a directory" "--out: $tmp/dir.png is a directory, not a .png file" render --out "$tmp/dir.png"
expect_zblend_error "stats under a file" "--stats: $tmp/afile is a file" render --out "$tmp/out/a.png" --stats "$tmp/afile/s.json"
expect_zblend_error "stats extension" "--stats: .* must end in .json" render --out "$tmp/out/a.png" --stats "$tmp/out/s.txt"
expect_zblend_error "waves under a file" "--waves: $tmp/afile is a file" render --backend rtl --out "$tmp/out/a.png" --waves "$tmp/afile/w.fst"
expect_zblend_error "waves extension" "--waves: .* must end in .fst" render --backend rtl --out "$tmp/out/a.png" --waves "$tmp/out/w.vcd"
expect_zblend_error "plan json under a file" "--json: $tmp/afile is a file" plan --scene quads -e 5 --json "$tmp/afile/p.json"
expect_zblend_error "trace under a file" "--out: $tmp/afile is a file" trace --out "$tmp/afile/t.zbt"
expect_zblend_error "lab out-dir is a file" "--out-dir: $tmp/afile is a file" lab --out-dir "$tmp/afile"
expect_zblend_error "sweep out-dir under a file" "--out-dir: $tmp/afile is a file" sweep depth --out-dir "$tmp/afile/s"
# The testbench: the same rule, checked before any suite runs.
tiny=(--suite random --iterations 1 --fragments 6000)
expect_error "tb trace extension" "^zblend_tb: error: --waves: '.*x.vcd' must end in .fst$" "$tb" "${tiny[@]}" --waves "$tmp/out/x.vcd"
expect_error "tb trace under a file" "--waves: $tmp/afile is a file, not a directory" "$tb" "${tiny[@]}" --waves "$tmp/afile/x.fst"
expect_error "tb trace is a directory" "--waves: $tmp/dir.fst is a directory" "$tb" "${tiny[@]}" --waves "$tmp/dir.fst"
expect_error "tb mismatch-fst under a file" "--mismatch-fst: $tmp/afile is a file" "$tb" "${tiny[@]}" --mismatch-fst "$tmp/afile/dir/x.fst"
if "$tb" -q "${tiny[@]}" --waves "$tmp/new5/sub/x.fst" >/dev/null && [[ -s "$tmp/new5/sub/x.fst" ]]; then ok; else fail "tb --waves: parent directories made"; fi

# ---- options that would do nothing are refused ----------------------------------------------
expect_zblend_error "backpressure on golden" "--backpressure: needs --backend rtl or both" render --backpressure 0.3 --out "$tmp/out/a.png"
expect_zblend_error "seed on golden" "--seed: needs --backend rtl or both" render --seed 5 --out "$tmp/out/a.png"
expect_zblend_error "schedule on golden" "--schedule: needs --backend rtl or both" render --schedule pass --out "$tmp/out/a.png"
expect_zblend_error "no-lockstep on rtl" "--no-lockstep: needs --backend both" render --backend rtl --no-lockstep --out "$tmp/out/a.png"
expect_zblend_error "negative seed" "--seed: -1 is out of range" render --backend rtl --seed -1 --out "$tmp/out/a.png"
expect_zblend_error "threads above the maximum" "--threads: 1000 is out of range \(1 to 256\)" render --threads 1000 --out "$tmp/out/a.png"
expect_zblend_error "threads with waves" "--waves: one waveform needs one RTL model; --threads 2" render --backend rtl --threads 2 --waves "$tmp/out/w.fst" --out "$tmp/out/a.png"
[[ ! -e "$tmp/out/w.fst" && ! -e "$tmp/out/a.png" ]] && ok || fail "threads with waves: nothing written"
expect_error "tb iterations 0" "--iterations: 0 is out of range" "$tb" --suite random --iterations 0
expect_error "tb fragments 0" "--fragments: 0 is out of range" "$tb" --suite random --iterations 1 --fragments 0

# ---- error maps: by default under --out-dir, on request beside --out ----------------------------
if "$zblend" render -q --scene quads --method three-pass,hidden-line,reference -W 64 -H 48 --out-dir "$tmp/out/em" &&
   [[ -s $tmp/out/em/three-pass-error.png && -s $tmp/out/em/hidden-line-error.png && ! -e $tmp/out/em/reference-error.png ]]
then ok; else fail "render --out-dir: error maps: $(ls "$tmp/out/em" 2>&1)"; fi
"$zblend" render -q --scene quads --method three-pass -W 64 -H 48 --out-dir "$tmp/out/nem" --no-error-map &&
  ! ls "$tmp/out/nem" | grep -q -- -error.png && ok || fail "--no-error-map: $(ls "$tmp/out/nem")"
"$zblend" render -q --scene quads --method wboit -W 64 -H 48 --out "$tmp/out/w.png" --error-map &&
  [[ -s $tmp/out/w-error.png ]] && ok || fail "--error-map beside --out: $(ls "$tmp/out")"
python3 - "$tmp/out/w-error.png" <<'PY' && ok || fail "the error map is not the frame above a legend"
import struct, sys
w, h = struct.unpack(">II", open(sys.argv[1], "rb").read()[16:24])
assert w == 240 and h == 48 + 44, (w, h)  # at least the legend's width; a 44-pixel strip below
PY
rm -f "$tmp/out/w.png" "$tmp/out/w-error.png"
expect_zblend_error "error map and no error" "--error-map, --no-error: a map is the error" render --error-map --no-error --out "$tmp/out/a.png"
expect_zblend_error "error map both ways" "--error-map, --no-error-map: give one of them" render --error-map --no-error-map --out-dir "$tmp/out/x"
expect_zblend_error "no error map without out-dir" "--no-error-map: needs --out-dir" render --no-error-map --out "$tmp/out/a.png"

# ---- commands mistyped or missing: the nearest name, or the list ----------------------------
expect_zblend_error "command typo" "^zblend: error: unknown command 'rendr'; did you mean 'render'\?$" rendr --scene cad
expect_zblend_error "subcommand typo" "^zblend conformance: error: unknown command 'exprot'; did you mean 'export'\?$" conformance exprot x
expect_zblend_error "no command" "^zblend: error: a command is required: render, trace, .*conformance \(see 'zblend --help'\)$"
expect_zblend_error "no subcommand" "^zblend conformance: error: a command is required: export, check" conformance
expect_zblend_error "command unlike any" "^zblend: error: unknown command 'xyzzy' \(choose from render, " xyzzy

# ---- plan: --method and --scene ------------------------------------------------------------
expect_zblend_error "plan method and scene" "^zblend: error: --method, --scene: give one of them" plan --method three-pass --scene cad
# The hidden-line offset: both bounds, not with --max-error, within 0 to 100 percent.
offset_json="$tmp/offset-plan.json"
if "$zblend" plan --scene parts --max-hidden-drawn 5 --max-visible-missing 5 -W 80 -H 60 --json "$offset_json" 2>/dev/null |
   grep -q "^choice: " && grep -q '"found": true' "$offset_json" && grep -q '"choice_is_default"' "$offset_json"; then ok; else fail "plan offset: no choice"; fi
expect_zblend_error "plan offset one bound" "--max-visible-missing: needed with the other bound" plan --scene cad --max-hidden-drawn 1
expect_zblend_error "plan offset and error" "--max-error, --max-hidden-drawn: give one of them" plan --scene cad --max-error 3 --max-hidden-drawn 1 --max-visible-missing 1
expect_zblend_error "plan offset range" "--max-hidden-drawn: 101 is out of range \(0 to 100" plan --scene cad --max-hidden-drawn 101 --max-visible-missing 1
# The wboit planes: a choice and its JSON within the bound, exit 1 beyond every format, alone.
wboit_json="$tmp/wboit-plan.json"
if "$zblend" plan --scene cad --max-delta-e 1 -W 80 -H 60 --json "$wboit_json" 2>/dev/null |
   grep -q "^choice: ACC_BITS" && grep -q '"found": true' "$wboit_json"; then ok; else fail "plan wboit: no choice"; fi
if "$zblend" plan --scene layers-4-a90 --max-delta-e 0.5 -W 80 -H 60 >/dev/null 2>&1; then
  fail "plan wboit: a bound no format meets passed"; else ok; fi
expect_zblend_error "plan wboit and error" "--max-delta-e: give it alone" plan --scene cad --max-delta-e 1 --max-error 3
expect_zblend_error "plan wboit range" "--max-delta-e: 101 is out of range" plan --scene cad --max-delta-e 101

# ---- pixel: a pixel's history, its JSON, and bad --at -------------------------------------------
if "$zblend" pixel -q --scene quads --method depth-peel-2 -W 64 -H 48 --at "32,24;0,0" \
     --json "$tmp/out/px.json" >"$tmp/px.txt" &&
   [[ $(grep -c "^pixel (" "$tmp/px.txt") == 2 ]] && grep -q "^pass 0 'peel-1-opaque-depth'" "$tmp/px.txt" &&
   grep -q "^final  colour" "$tmp/px.txt" && grep -q '"zblend_pixel_history": 1' "$tmp/out/px.json"; then ok
else fail "pixel: text and JSON: $(head -5 "$tmp/px.txt")"; fi
if "$zblend" pixel -q --scene quads -W 64 -H 48 --at 32,24 --json - |
   python3 -c 'import json,sys; d=json.load(sys.stdin); assert d["pixels"][0]["x"] == 32'; then ok
else fail "pixel --json -: not one JSON document"; fi
# A trace's pixel: the trace's own frame and passes, the same final value as the scene's.
"$zblend" trace --scene quads --method depth-peel-2 -W 64 -H 48 --out "$tmp/px.zbt" >/dev/null 2>&1
if "$zblend" pixel --trace "$tmp/px.zbt" --at 32,24 --json - >"$tmp/pxt.json" &&
   python3 - "$tmp/out/px.json" "$tmp/pxt.json" <<'PY'; then ok; else fail "pixel --trace: not the scene's history"; fi
import json, sys
scene, trace = (json.load(open(p)) for p in sys.argv[1:])
assert not trace["from_scene"] and scene["from_scene"]
a, b = scene["pixels"][0], trace["pixels"][0]
assert (a["x"], a["y"]) == (b["x"], b["y"]) == (32, 24)
assert a["final"] == b["final"] and len(a["events"]) == len(b["events"]), (a["final"], b["final"])
PY
expect_zblend_error "pixel trace and scene" "^zblend: error: --trace, --scene: a trace holds its frame" pixel --trace "$tmp/px.zbt" --scene cad --at 1,1
expect_zblend_error "pixel trace outside" "^zblend: error: --at: pixel \(64, 0\) is outside the 64x48 frame" pixel --trace "$tmp/px.zbt" --at 64,0
printf 'not a trace' >"$tmp/bad.zbt"
expect_zblend_error "pixel bad trace" "^zblend: error: .*bad.zbt" pixel --trace "$tmp/bad.zbt" --at 1,1
# Beside the RTL: each fragment's retire, the final planes the same.
if "$zblend" pixel -q --scene quads --method three-pass -W 64 -H 48 --at 32,24 --backend both >"$tmp/pxr.txt" &&
   [[ $(grep -c "^  fragment " "$tmp/pxr.txt") -gt 0 &&
      $(grep -c "^    rtl: #[0-9]* accepted at cycle [0-9]*; X4 at cycle [0-9]*; X11 at cycle [0-9]*$" "$tmp/pxr.txt") == $(grep -c "^  fragment " "$tmp/pxr.txt") ]] &&
   grep -q "^rtl    the same on every plane$" "$tmp/pxr.txt"; then ok
else fail "pixel --backend rtl: $(head -12 "$tmp/pxr.txt")"; fi
expect_zblend_error "pixel schedule on golden" "^zblend: error: --schedule: needs --backend rtl or both" pixel --at 1,1 --schedule pass
expect_zblend_error "pixel waves on golden" "^zblend: error: --waves: needs --backend rtl or both" pixel --at 1,1 --waves "$tmp/out/p.fst"
expect_zblend_error "pixel rtl depth" "^zblend: error: --backend rtl: the RTL model is built with 24-bit depth, not 16" pixel --at 1,1 --backend rtl --depth-bits 16
expect_zblend_error "pixel backend" "^zblend: error: --backend: unknown backend 'fpga'" pixel --at 1,1 --backend fpga
expect_zblend_error "pixel outside" "^zblend: error: --at: pixel \(64, 0\) is outside the 64x48 frame" pixel -W 64 -H 48 --at 64,0 --json "$tmp/out/bad.json"
expect_zblend_error "pixel not x,y" "^zblend: error: --at: '3' is not X,Y" pixel --at "1,2;3" --json "$tmp/out/bad.json"
expect_zblend_error "pixel twice" "^zblend: error: --at: pixel \(1, 2\) given twice" pixel --at "1,2;1,2"
expect_zblend_error "pixel method" "^zblend: error: --method: unknown method 'nope'" pixel --at 1,2 --method nope
expect_zblend_error "pixel no --at" "^zblend: error: --at is required" pixel --scene quads

# ---- unknown options name the closest one, in every subcommand and zblend_tb ------------------
expect_zblend_error "render typo" "^zblend render: error: unknown option '--scnee'; did you mean '--scene'\?$" render --scnee cad
expect_zblend_error "trace typo" "^zblend trace: error: unknown option '--metod'; did you mean '--method'\?$" trace --metod opaque
expect_zblend_error "plan typo" "^zblend plan: error: unknown option '--max-eror'; did you mean '--max-error'\?$" plan --max-eror 3
expect_zblend_error "lab typo" "^zblend lab: error: unknown option '--scens'; did you mean '--scenes'\?$" lab --scens quads
expect_zblend_error "sweep typo" "^zblend sweep: error: unknown option '--step'; did you mean '--steps'\?$" sweep depth --step 3
expect_zblend_error "methods typo" "^zblend methods: error: unknown option '--hepl'; did you mean '--help'\?$" methods --hepl
expect_zblend_error "scenes typo" "^zblend scenes: error: unknown option '--hlep'; did you mean '--help'\?$" scenes --hlep
expect_zblend_error "typo with =" "unknown option '--out_dir'; did you mean '--out-dir'\?$" render --out_dir="$tmp/out/d"
expect_zblend_error "nothing close" "^zblend render: error: unknown option '--frobnicate' \(see 'zblend render --help'\)$" render --frobnicate
expect_error "tb typo" "^zblend_tb: error: unknown option '--iteratoins'; did you mean '--iterations'\?$" "$tb" --iteratoins 3

# ---- lab --help: the RTL flag's default shown once, plainly -------------------------------------
"$zblend" lab --help >"$tmp/help" 2>&1
if ! grep -q '{false}' "$tmp/help" && [[ $(grep -c 'the default' "$tmp/help") -eq 1 ]] &&
   grep -qE '^ +--no-rtl +Golden model only' "$tmp/help"; then ok; else fail "lab --help: $(grep rtl "$tmp/help")"; fi
expect_zblend_error "lab rtl and no-rtl" "--rtl, --no-rtl: give one of them" lab --rtl --no-rtl --out-dir "$tmp/out/lab"

# ---- warnings: nothing drawn, textures ignored; --background; silent under -q --------------------
models=/usr/share/assimp/models
"$zblend" render --scene "$models/OBJ/concave_polygon.obj" -W 64 -H 48 --out "$tmp/cp.png" 2>"$tmp/err" >/dev/null
rc=$?
[[ $rc -eq 0 ]] && grep -qx "zblend render: warning: nothing drawn: 0 fragments reach the frame; try --camera" "$tmp/err" &&
  ok || fail "nothing drawn: exit $rc, $(cat "$tmp/err")"
"$zblend" render -q --scene "$models/OBJ/concave_polygon.obj" -W 64 -H 48 --out "$tmp/cp.png" 2>"$tmp/err"
[[ $? -eq 0 && ! -s "$tmp/err" ]] && ok || fail "nothing drawn under -q: $(cat "$tmp/err")"
"$zblend" render --scene "$models/OBJ/spider.obj" -W 32 -H 24 --out "$tmp/spider.png" 2>"$tmp/err" >/dev/null
[[ $(grep -cx "zblend render: warning: material 'Skin': texture ignored, its base colour is used" "$tmp/err") -eq 1 &&
   $(grep -c "warning: material" "$tmp/err") -eq $(grep "warning: material" "$tmp/err" | sort -u | wc -l) ]] &&
  ok || fail "OBJ texture warnings: $(cat "$tmp/err")"
[[ $(head -1 "$tmp/err") == *"spider.obj: 1368 triangles in the scene, "* ]] && ok || fail "warnings after the first line: $(head -1 "$tmp/err")"
boxgltf=$models/glTF2/BoxTextured-glTF/BoxTextured.gltf
if [[ -f $boxgltf ]]; then
  "$zblend" trace --scene "$boxgltf" -W 16 -H 12 --out "$tmp/box.zbt" 2>"$tmp/err" >/dev/null
  grep -qx "zblend trace: warning: material 'Texture': texture ignored, its base colour is used" "$tmp/err" &&
    ok || fail "glTF texture warning: $(cat "$tmp/err")"
  "$zblend" render -q --scene "$boxgltf" -W 16 -H 12 --out "$tmp/box.png" 2>"$tmp/err"
  [[ ! -s "$tmp/err" ]] && ok || fail "texture warning under -q: $(cat "$tmp/err")"
fi
# box.obj: the white default material on the white background; --background shows it.
box=(--scene "$models/OBJ/box.obj" -W 32 -H 24)
if "$zblend" render -q "${box[@]}" --out "$tmp/box-white.png" &&
   "$zblend" render -q "${box[@]}" --background 0,0,0 --out "$tmp/box-black.png" &&
   "$zblend" render -q "${box[@]}" --background 0,0,0,255 --out "$tmp/box-black4.png"; then
  ! cmp -s "$tmp/box-white.png" "$tmp/box-black.png" && cmp -s "$tmp/box-black.png" "$tmp/box-black4.png" &&
    ok || fail "--background: images"
else
  fail "render --background"
fi
if "$zblend" trace "${box[@]}" --background 10,20,30 --out "$tmp/bg.zbt" >/dev/null &&
   "$zblend" trace "${box[@]}" --out "$tmp/nobg.zbt" >/dev/null && ! cmp -s "$tmp/bg.zbt" "$tmp/nobg.zbt"; then ok; else fail "trace --background"; fi
for v in 1,2 256,0,0 0,0,0,0,0 a,b,c 1,,2 -1,0,0; do
  expect_zblend_error "background $v" "^zblend: error: --background: '$v' is not R,G,B or R,G,B,A, each 0 to 255$" render --background "$v" --out "$tmp/out/a.png"
done

# ---- render's first line: the scene's triangles and those after clipping ----------------------
if "$zblend" render --scene "$regr01" --width 40 --height 30 --out "$tmp/r.png" --stats "$tmp/r.json" 2>"$tmp/err" >/dev/null; then
  head -1 "$tmp/err" | grep -qE "regr01.obj: 2710 triangles in the scene, [0-9]+ after clipping, [0-9]+ fragments at 40x30 " &&
    ok || fail "render header: $(head -1 "$tmp/err")"
  grep -q '"triangles": 2710,' "$tmp/r.json" && grep -qE '"triangles_drawn": [0-9]+,' "$tmp/r.json" &&
    ok || fail "stats triangles: $(grep triangles "$tmp/r.json")"
else
  fail "render regr01 --stats"
fi

# ---- zblend_tb: progress on stderr, none under -q ---------------------------------------------
"$tb" "${tiny[@]}" >/dev/null 2>"$tmp/err"
grep -qx "zblend_tb: suite random: started" "$tmp/err" && ok || fail "tb progress: $(cat "$tmp/err")"
"$tb" -q "${tiny[@]}" >/dev/null 2>"$tmp/err"
[[ $? -eq 0 && ! -s "$tmp/err" ]] && ok || fail "tb -q: $(cat "$tmp/err")"

echo "$pass passed"
