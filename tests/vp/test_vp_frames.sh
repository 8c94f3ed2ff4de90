#!/usr/bin/env bash
# zblend_vp's frames against zblend render's, and against themselves under every platform option:
# the PNG files must be the same bytes (both programs write the colour plane with one encoder).
# usage: test_vp_frames.sh ZBLEND_VP ZBLEND WORKDIR [WIDTH HEIGHT]   (96x72; make vp: 640x480)
set -euo pipefail
vp=$1 zblend=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
size=(--width "${4:-96}" --height "${5:-72}")
fail() { echo "FAIL: $*" >&2; exit 1; }

# 1. Every method, both insides, against zblend render's frame (the golden model, one thread).
"$vp" --scene cad "${size[@]}" --method all --inside both --out-dir "$work/base" -q ||
  fail "zblend_vp --method all --inside both"
n=0
for png in "$work"/base/vp-*-golden.png; do
  m=${png#"$work/base/vp-"}; m=${m%-golden.png}
  "$zblend" render --scene cad "${size[@]}" --method "$m" --threads 1 --out "$work/render-$m.png" >/dev/null 2>&1 ||
    fail "zblend render --method $m"
  for inside in golden rtl; do
    cmp -s "$work/render-$m.png" "$work/base/vp-$m-$inside.png" ||
      fail "$m, $inside inside: zblend_vp's frame differs from zblend render's"
  done
  n=$((n + 1))
done
[[ $n -ge 14 ]] || fail "only $n methods ran"

# 2. The same frames programmed register by register, without DMI, with a quantum of one cycle
#    and of a whole frame.
for opts in "--programming registers" "--no-dmi" "--quantum 1" "--quantum frame"; do
  dir=$work/${opts// /_}
  # shellcheck disable=SC2086
  "$vp" --scene cad "${size[@]}" --method all --inside both --out-dir "$dir" -q $opts ||
    fail "zblend_vp $opts"
  for png in "$work"/base/*.png; do
    cmp -s "$png" "$dir/$(basename "$png")" || fail "$opts: $(basename "$png") differs"
  done
done
echo "zblend_vp: $n methods on both insides match zblend render at ${size[1]}x${size[3]}; registers, no DMI, quantum 1 and frame the same"
