#!/usr/bin/env bash
# Bad input that never hurts (docs/scenes.md, "Bad input"): broken scene files, missing files and
# directories, non-finite and huge coordinates, frame sizes, --camera, corrupt traces. An error
# is one line on stderr, exit code 2 and no file left; what is allowed (degenerate triangles,
# far-away geometry) renders.
set -u
zblend=$(realpath "${1:?usage: test_bad_input.sh PATH/TO/zblend PATH/TO/zblend_tb}")
tb=$(realpath "${2:?usage: test_bad_input.sh PATH/TO/zblend PATH/TO/zblend_tb}")
source "$(dirname "$0")/../lib.sh"

# scene_error NAME PATTERN FILE [ARGS...]: the same error from `zblend render` and `zblend trace`.
scene_error() {
  local name=$1 pattern=$2 file=$3; shift 3
  expect_error "render: $name" "$pattern" "$zblend" render --scene "$file" "$@" --out "$tmp/out/a.png"
  expect_error "trace: $name" "$pattern" "$zblend" trace --scene "$file" "$@" --out "$tmp/out/a.zbt"
}

# fragments FILE.json: the frame's fragment count from --stats.
fragments() { grep -m1 '"fragments":' "$1" | tr -dc '0-9'; }

mkdir -p "$tmp/out" "$tmp/in"
cd "$tmp/in" || exit 2
tri='v 0 0 0\nv 1 0 0\nv 0 1 0\n'

# ---- OBJ and MTL -------------------------------------------------------------------------------
printf 'v 0 0 0\nv 1 abc 0\n' >word.obj
scene_error "obj not a number" "word.obj: line 2: 'v': 'abc' is not a number" word.obj
printf 'v 0 0 0\nv 1 0 0\nv 0 1\n' >short.obj
scene_error "obj truncated vertex" "short.obj: line 3: 'v' needs 3 numbers, has 2" short.obj
printf "${tri}f 1 2\n" >face.obj
scene_error "obj truncated face" "face.obj: line 4: a face needs 3 vertices, has 2" face.obj
printf "${tri}f 1 2 -4\n" >index.obj
scene_error "obj index" "index.obj: line 4: vertex index -4 out of range \(1 to 3\)" index.obj
printf "mtllib m.mtl\n${tri}usemtl a\nf 1 2 3\n" >uses.obj
scene_error "missing mtl" "uses.obj: line 1: material library 'm.mtl' not found" uses.obj
printf 'newmtl a\nd abc\n' >m.mtl
scene_error "mtl bad d" "m.mtl: line 2: 'd': 'abc' is not a number" uses.obj
printf 'newmtl a\nKd 1 1.5 0\n' >m.mtl
scene_error "mtl bad Kd" "m.mtl: line 2: 'Kd': 1.5 is outside 0 to 1" uses.obj
printf 'newmtl a\nKd 1 1\n' >m.mtl
scene_error "mtl truncated Kd" "m.mtl: line 2: 'Kd' needs 3 numbers, has 2" uses.obj
rm m.mtl && mkdir m.mtl
scene_error "mtl is a directory" "uses.obj: line 1: material library 'm.mtl' not found" uses.obj
printf 'v 0 0 0\nv 1 0 0\nv nan 1 0\nf 1 2 3\n' >nan.obj
scene_error "obj nan" "nan.obj: line 3: 'v': nan is not finite" nan.obj
printf 'v 0 0 0\nv -inf 0 0\nv 0 1 0\nf 1 2 3\n' >inf.obj
scene_error "obj inf" "inf.obj: line 2: 'v': -inf is not finite" inf.obj
printf 'v 0 0 0\nv 1e39 0 0\nv 0 1 0\nf 1 2 3\n' >overflow.obj
scene_error "obj beyond float" "overflow.obj: line 2: 'v': 1e39 is not finite" overflow.obj
printf "$tri" >points.obj
scene_error "obj without faces" "scene 'points.obj': no triangles" points.obj

# ---- glTF and GLB ------------------------------------------------------------------------------
# Four positions (48 bytes) and six unsigned short indices (12 bytes); NaN in the second vertex.
buffer() { printf '\0\0\0\0\0\0\0\0\0\0\0\0'; printf "$1"; printf '\0\0\0\0\0\0\0\0'
           printf '\0\0\0\0\0\0\x80\x3f\0\0\0\0\0\0\x80\x3f\0\0\x80\x3f\0\0\0\0'
           printf '\0\0\1\0\2\0\1\0\3\0\2\0'; }
buffer '\0\0\x80\x3f' >t.bin
buffer '\0\0\xc0\x7f' >nan.bin
# gltf URI BYTES INDEX_COUNT: one mesh, indexed, with the buffer file URI.
gltf() {
  printf '{"asset": {"version": "2.0"}, "nodes": [{"mesh": 0}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
  "buffers": [{"uri": "%s", "byteLength": %s}],
  "bufferViews": [{"buffer": 0, "byteLength": 48}, {"buffer": 0, "byteOffset": 48, "byteLength": 12}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3"},
                {"bufferView": 1, "componentType": 5123, "count": %s, "type": "SCALAR"}]}' "$1" "$2" "$3"
}
gltf t.bin 60 6 >good.gltf
if "$zblend" render -q --scene good.gltf --width 16 --height 12 --out "$tmp/out/g.png"; then ok; else fail "good.gltf renders"; fi
rm -f "$tmp/out/g.png"
gltf t.bin 60 6 | head -c 150 >cut.gltf
scene_error "gltf truncated JSON" "cut.gltf: JSON: malformed: parse error at line [0-9]+, column [0-9]+" cut.gltf
printf '{"asset": {"version": "2.0"}, "nodes": [{"mesh": 0},]}' >comma.gltf
scene_error "gltf bad JSON" "comma.gltf: JSON: malformed: " comma.gltf
printf '{"asset": {"version": "2.0"}, "nodes": "all"}' >type1.gltf
scene_error "gltf wrong type" 'type1.gltf: nodes: expected an array, not string "all"' type1.gltf
gltf t.bin 60 6 | sed 's/"mesh": 0/"mesh": "zero"/' >type2.gltf
scene_error "gltf wrong type of index" 'type2.gltf: nodes\[0\].mesh: expected an index .*, not string "zero"' type2.gltf
gltf t.bin 60 6 | sed 's/"componentType": 5123/"componentType": -1/' >type3.gltf
scene_error "gltf negative enum" 'type3.gltf: accessors\[1\].componentType: expected an index .*, not number -1' type3.gltf
gltf t.bin 60 9 >long.gltf
scene_error "gltf accessor out of bounds" "long.gltf: accessors\[1\]: 9 elements run past the end of bufferView 1" long.gltf
gltf t.bin 60 6 | sed 's/"byteOffset": 48, "byteLength": 12/"byteOffset": 56, "byteLength": 12/' >view.gltf
scene_error "gltf view out of bounds" "view.gltf: bufferViews\[1\]: bytes 56 to 68 lie outside buffer 0 \(60 bytes\)" view.gltf
gltf missing.bin 60 6 >nobin.gltf
scene_error "gltf missing buffer" "nobin.gltf: buffers\[0\]: file 'missing.bin' not found" nobin.gltf
gltf t.bin 64 6 >size.gltf
scene_error "gltf buffer size" "size.gltf: buffers\[0\]: file 't.bin' has 60 bytes, byteLength says 64" size.gltf
gltf nan.bin 60 6 >nan.gltf
scene_error "gltf nan" "nan.gltf: accessors\[0\]: element 1 is not finite" nan.gltf
printf '{"asset": {"version": "2.0"}, "nodes": [{"name": "empty"}], "scenes": [{"nodes": [0]}]}' >nomesh.gltf
scene_error "gltf without meshes" "scene 'nomesh.gltf': no triangles" nomesh.gltf
printf '{"asset": {"version": "1.0"}, "scene": "defaultScene"}' >v1.gltf
scene_error "gltf 1.0" 'v1.gltf: asset.version: string "1.0" is not supported' v1.gltf
# glb JSON BIN: a GLB file; the JSON padded to 4 bytes.
glb() {
  local json=$1 bin=$2 n
  while (( ${#json} % 4 )); do json+=' '; done
  u32() { printf "\\x$(printf %02x $(($1 & 255)))\\x$(printf %02x $(($1 >> 8 & 255)))\\x$(printf %02x $(($1 >> 16 & 255)))\\x$(printf %02x $(($1 >> 24 & 255)))"; }
  n=$(stat -c %s "$bin")
  printf glTF; u32 2; u32 $((12 + 8 + ${#json} + 8 + n))
  u32 ${#json}; printf JSON; printf '%s' "$json"
  u32 "$n"; printf 'BIN\0'; cat "$bin"
}
glb "$(gltf t.bin 60 6 | sed 's/"uri": "t.bin", //' | tr -d '\n')" t.bin >good.glb
if "$zblend" render -q --scene good.glb --width 16 --height 12 --out "$tmp/out/g.png"; then ok; else fail "good.glb renders"; fi
rm -f "$tmp/out/g.png"
{ printf 'glTX'; tail -c +5 good.glb; } >magic.glb
scene_error "glb bad magic" "magic.glb: byte 0: not a GLB file \(magic is not 'glTF'\)" magic.glb
head -c 100 good.glb >cut.glb
scene_error "glb truncated" "cut.glb: byte 8: GLB length [0-9]+ but the file has 100 bytes \(truncated\?\)" cut.glb
# The header's length fixed up to the cut file: the JSON chunk itself runs past the end.
size=$(stat -c %s cut.glb)
{ printf 'glTF\2\0\0\0'; printf "\\x$(printf %02x "$size")\\0\\0\\0"; tail -c +13 cut.glb; } >chunk.glb
scene_error "glb truncated chunk" "chunk.glb: byte 12: chunk 0 of [0-9]+ bytes runs past the end of the file" chunk.glb
printf 'glTF' >tiny.glb
scene_error "glb header" "tiny.glb: byte 0: GLB header needs 12 bytes, file has 4" tiny.glb

# ---- files that are not there or not files -----------------------------------------------------
scene_error "missing file" "nope/x.obj: open: no such file" nope/x.obj
mkdir -p dir.obj plain
scene_error "directory named .obj" "dir.obj: open: is a directory, not a scene file" dir.obj
scene_error "directory" "plain: open: is a directory, not a scene file" plain
scene_error "directory with slash" "plain/: open: is a directory, not a scene file" plain/
printf 'ply\n' >model.ply
scene_error "unknown file type" "model.ply: name: unsupported file type '.ply'" model.ply

# ---- degenerate triangles draw nothing -----------------------------------------------------------
# Red on the white background, so that the images show the triangle.
cam=(--camera eye=0.3,0.3,3,at=0.3,0.3,0,fov=40 --width 32 --height 24)
printf 'newmtl red\nKd 1 0 0\n' >red.mtl
printf "mtllib red.mtl\nusemtl red\n${tri}f 1 2 3\n" >one.obj
printf "mtllib red.mtl\nusemtl red\n${tri}v 2 0 0\nv 0.5 0.5 0\nf 1 1 1\nf 1 2 3\nf 1 2 4\nf 2 3 5\nf 3 3 1\n" >degenerate.obj
if "$zblend" render -q --scene one.obj "${cam[@]}" --out "$tmp/one.png" --stats "$tmp/one.json" &&
   "$zblend" render -q --scene degenerate.obj "${cam[@]}" --out "$tmp/degenerate.png" --stats "$tmp/degenerate.json"; then
  cmp -s "$tmp/one.png" "$tmp/degenerate.png" && ok || fail "degenerate triangles change the image"
  [[ $(fragments "$tmp/one.json") -gt 0 && $(fragments "$tmp/one.json") == $(fragments "$tmp/degenerate.json") ]] &&
    ok || fail "degenerate triangles: fragments $(fragments "$tmp/one.json") vs $(fragments "$tmp/degenerate.json")"
else
  fail "render with degenerate triangles"
fi
printf "${tri}v 2 0 0\nf 1 1 1\nf 1 2 4\n" >flat.obj
if "$zblend" render -q --scene flat.obj --width 16 --height 12 --out "$tmp/flat.png" --stats "$tmp/flat.json"; then
  [[ $(fragments "$tmp/flat.json") == 0 ]] && ok || fail "only degenerate triangles: $(fragments "$tmp/flat.json") fragments"
else
  fail "only degenerate triangles: no background image"
fi
if "$zblend" trace --scene flat.obj --width 16 --height 12 --out "$tmp/flat.zbt" >/dev/null; then ok; else fail "trace of degenerate triangles"; fi

# ---- far outside the view ----------------------------------------------------------------------
# A triangle through the view, spanning +-S, seen face-on from 5 away, fills the image (clipped
# vertices are set exactly on their planes: docs/raster.md, step 4). With cameras that see
# nothing, and at spans whose clip coordinates overflow float, the frame only has to render.
big() { printf "v -$1 -$1 0\nv $1 -$1 0\nv 0 $1 0\nf 1 2 3\n"; }
for s in 1e3 1e8 1e20 1e30; do
  big "$s" >"span$s.obj"
  if "$zblend" render -q --scene "span$s.obj" --camera eye=0,0,5,at=0,0,0,fov=60 --width 16 --height 12 \
       --out "$tmp/span.png" --stats "$tmp/span.json"; then
    [[ $(fragments "$tmp/span.json") == 192 ]] && ok || fail "span $s: $(fragments "$tmp/span.json") of 192 pixels"
  else
    fail "span $s with --camera"
  fi
done
for s in 1e20 1e30 1e38 3.4e38; do
  big "$s" >"span$s.obj"
  printf 'v 1e30 1e30 1e30\nv 1e30 -1e30 1e30\nv 0 0 -1e30\nf 4 5 6\n' >>"span$s.obj"
  for camera in eye=0,0,5,at=0,0,0,fov=60 eye=1e30,0,5,at=0,0,0,fov=10,up=0,0,1 ""; do
    if "$zblend" render -q --scene "span$s.obj" ${camera:+--camera "$camera"} --method all --width 16 \
         --height 12 --out-dir "$tmp/far" &&
       "$zblend" trace --scene "span$s.obj" ${camera:+--camera "$camera"} --width 16 --height 12 \
         --out "$tmp/far.zbt" >/dev/null; then ok; else fail "span $s, camera '$camera'"; fi
  done
done

# ---- frame size and --camera -------------------------------------------------------------------
for sub in render trace; do
  ext=png; [[ $sub == trace ]] && ext=zbt
  expect_error "$sub zero height" "--height: 0 is out of range \(1 to 8192\)" "$zblend" $sub --height 0 --out "$tmp/out/a.$ext"
  expect_error "$sub negative width" "--width: -5 is out of range \(1 to 8192\)" "$zblend" $sub --width=-5 --out "$tmp/out/a.$ext"
  expect_error "$sub width 8193" "--width: 8193 is out of range \(1 to 8192\)" "$zblend" $sub --width 8193 --out "$tmp/out/a.$ext"
  expect_error "$sub height 8193" "--height: 8193 is out of range \(1 to 8192\)" "$zblend" $sub --height 8193 --out "$tmp/out/a.$ext"
  expect_error "$sub zero up" "--camera: field 'up' is the zero vector" \
    "$zblend" $sub --camera eye=0,0,5,at=0,0,0,fov=40,up=0,0,0 --out "$tmp/out/a.$ext"
  expect_error "$sub parallel up" "--camera: 'up' is parallel to the view direction" \
    "$zblend" $sub --camera eye=0,0,5,at=0,0,0,fov=40,up=0,0,3 --out "$tmp/out/a.$ext"
  expect_error "$sub camera behind" "--camera: the whole scene lies behind the eye" \
    "$zblend" $sub --scene one.obj --camera eye=0,0,5,at=0,0,9,fov=40 --out "$tmp/out/a.$ext"
done
if "$zblend" render -q --scene quads --width 8192 --height 2 --out "$tmp/wide.png"; then ok; else fail "8192 wide"; fi
# up=-y turns the image of the (asymmetric) triangle upside down.
if "$zblend" render -q --scene one.obj --camera eye=0.3,0.3,3,at=0.3,0.3,0,fov=40,up=0,-1,0 --width 32 \
     --height 24 --out "$tmp/flipped.png" && ! cmp -s "$tmp/one.png" "$tmp/flipped.png"; then ok; else fail "up=0,-1,0"; fi

# ---- corrupt traces to the testbench -----------------------------------------------------------
"$zblend" trace --scene quads --method three-pass --width 8 --height 6 --out "$tmp/good.zbt" >/dev/null
if "$tb" --replay "$tmp/good.zbt" >/dev/null; then ok; else fail "replay of a good trace"; fi
{ printf 'ZBTRACX'; tail -c +8 "$tmp/good.zbt"; } >magic.zbt
expect_error "replay bad magic" "trace 'magic.zbt': byte 0: not a zblend trace \(bad magic\)" "$tb" --replay magic.zbt
head -c 33 "$tmp/good.zbt" >cut.zbt
expect_error "replay truncated header" "trace 'cut.zbt': byte 33: truncated, expected the clear colour" "$tb" --replay cut.zbt
head -c -10 "$tmp/good.zbt" >cut2.zbt
expect_error "replay truncated pass" "trace 'cut2.zbt': byte [0-9]+: pass 3: [0-9]+ fragments announced, [0-9]+ bytes left" \
  "$tb" --replay cut2.zbt
{ head -c 12 "$tmp/good.zbt"; printf '\0\0\0\0'; tail -c +17 "$tmp/good.zbt"; } >width.zbt
expect_error "replay zero width" "trace 'width.zbt': byte 12: frame 0x6 is out of range" "$tb" --replay width.zbt
{ cat "$tmp/good.zbt"; printf 'x'; } >long.zbt
expect_error "replay trailing bytes" "trace 'long.zbt': byte [0-9]+: 1 bytes after the last pass" "$tb" --replay long.zbt
: >empty.zbt
expect_error "replay empty" "trace 'empty.zbt': byte 0: truncated" "$tb" --replay empty.zbt
expect_error "replay directory" "trace 'plain': is a directory" "$tb" --replay plain
expect_error "replay missing" "trace 'nope.zbt': cannot open: No such file" "$tb" --replay nope.zbt

echo "$pass passed"
