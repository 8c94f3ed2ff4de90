#!/usr/bin/env bash
# The zblend command as a user meets it: help, listings, a render, and bad input that must
# give one line on stderr, exit code 2 and no output file.
set -u
zblend=${1:?usage: test_cli.sh PATH/TO/zblend}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
. "$(dirname "$0")/cli_lib.sh"
# The zblend command's errors.
expect_zblend_error() {
  local name=$1 pattern=$2; shift 2
  expect_error "$name" "$pattern" "$zblend" "$@"
}

mkdir -p "$tmp/out" "$tmp/ro"
chmod 555 "$tmp/ro"

# Help and listings.
for sub in "" render trace methods scenes plan; do
  if "$zblend" $sub --help >"$tmp/help" 2>&1 && grep -q "Usage" "$tmp/help"; then ok; else bad "help $sub"; fi
done
if "$zblend" methods | grep -q "three-pass"; then ok; else bad "methods lists three-pass"; fi
if "$zblend" methods | grep -q "reference"; then ok; else bad "methods lists reference"; fi
for s in cad quads sphere-torus; do
  if "$zblend" scenes | grep -q "^$s "; then ok; else bad "scenes lists $s"; fi
done
if [[ $("$zblend" plan --method three-pass | grep -cE "^[0-9]+ +transparent") == 2 ]]; then ok; else bad "plan three-pass"; fi

# A render: a PNG of the asked size, and stats.
if "$zblend" render -q --scene quads --method three-pass --width 64 --height 48 \
     --out "$tmp/out/q.png" --stats "$tmp/out/q.json"; then
  sig=$(head -c 8 "$tmp/out/q.png" | od -An -tx1 | tr -d ' \n')
  size=$(od -An -tu1 -j16 -N8 "$tmp/out/q.png" | awk '{print $3*256+$4 "x" $7*256+$8}')
  [[ $sig == 89504e470d0a1a0a ]] && ok || bad "PNG signature $sig"
  [[ $size == 64x48 ]] && ok || bad "PNG size $size"
  grep -q '"fragments_in"' "$tmp/out/q.json" && ok || bad "stats json"
  rm -f "$tmp/out/q.png" "$tmp/out/q.json"
else
  bad "render quads"
fi
if "$zblend" render -q --scene cad --method all --width 80 --height 60 --out-dir "$tmp/run"; then
  methods=$(( $("$zblend" methods | wc -l) - 1 ))  # one image per method (header line off)
  [[ $(ls "$tmp/run"/*.png | wc -l) -eq $methods ]] && ok || bad "out-dir images: $(ls "$tmp/run")"
  [[ $(head -1 "$tmp/run/summary.csv") == method,passes,fragments,* ]] && ok || bad "summary header"
  grep -q '^reference,.*,0.0000,inf,0,' "$tmp/run/summary.csv" && ok || bad "reference row has no error"
else
  bad "render all"
fi

# Both backends, compared bit for bit, with back-pressure.
if "$zblend" render -q --scene sphere-torus --method all --width 48 --height 36 --backend both \
     --backpressure 0.25 --out-dir "$tmp/both"; then
  grep -qE '^three-pass,3,.*,[0-9]+,[0-9]+,0$' "$tmp/both/summary.csv" && ok || bad "both: mismatches column"
else
  bad "render --backend both"
fi

# A real scene file from Debian's assimp-testmodels on both backends, and a file trace.
regr01=/usr/share/assimp/models/OBJ/regr01.obj
if "$zblend" render -q --scene "$regr01" --method all --width 40 --height 30 --backend both \
     --out-dir "$tmp/regr01"; then
  grep -qE '^three-pass,3,.*,0$' "$tmp/regr01/summary.csv" && ok || bad "regr01 both: mismatches"
else
  bad "render regr01.obj --backend both"
fi
if "$zblend" render -q --scene "$regr01" --method three-pass --width 40 --height 30 --backend rtl \
     --camera eye=-1200,-1400,700,at=620,380,120,fov=45 --out "$tmp/out/r.png"; then ok; else bad "render regr01 rtl --camera"; fi
rm -f "$tmp/out/r.png"

# The lab and a sweep, tiny: a CSV row per method, the reference row at zero error.
if "$zblend" lab -q --scenes quads --methods opaque,reference -W 32 -H 24 --no-rtl --no-charts \
     --out-dir "$tmp/lab"; then
  [[ $(grep -c '^quads,' "$tmp/lab/lab.csv") -eq 2 ]] && ok || bad "lab: rows $(cat "$tmp/lab/lab.csv")"
  grep -qE '^quads,[^,]*,reference,.*,0\.0000,inf,0,' "$tmp/lab/lab.csv" && ok || bad "lab: reference row"
else
  bad "lab"
fi
if "$zblend" sweep depth -q --no-charts -W 32 -H 24 --out-dir "$tmp/sweep" &&
   [[ -s "$tmp/sweep/depth.csv" && ! -e "$tmp/sweep/depth.png" ]]; then ok; else bad "sweep depth"; fi

# A trace file.
if "$zblend" trace --scene quads --method unsorted --width 32 --height 24 --out "$tmp/out/q.zbt" >/dev/null &&
   [[ $(head -c 7 "$tmp/out/q.zbt") == ZBTRACE ]]; then ok; else bad "trace write"; fi
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
expect_zblend_error "missing dir" "does not exist" render --out "$tmp/out/no/such/a.png"
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
  cmp -s "$tmp/a.png" "$tmp/b.png" && ok || bad "--no-error changes the image"
  grep -q '"error": null' "$tmp/b.json" && ok || bad "--no-error: error in stats"
  grep -q '"frame_bytes": 89856' "$tmp/b.json" && ok || bad "memory.frame_bytes (96 x 72 x 13)"
  grep -qE '"peak_rss_bytes": [1-9][0-9]+' "$tmp/b.json" && ok || bad "memory.peak_rss_bytes"
else
  bad "render --no-error"
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

echo "$pass passed, $fail failed"
[[ $fail -eq 0 ]]
