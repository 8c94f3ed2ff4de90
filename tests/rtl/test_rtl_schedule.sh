#!/usr/bin/env bash
# The tile schedule (docs/rtl.md "Schedules"): the passes between two host frame operations run
# on the resident tile, one load and one store a tile. Its frames are the pass schedule's bit for
# bit with fewer tile cycles; the suites pass under it; lock-step still stops a defect at its
# first wrong write, naming the fragment's pass in the group and replaying the tile's whole group
# in the waveform; end-of-group comparison alone still catches it; a bad --schedule is refused.
set -u
tb=${1:?usage: test_rtl_schedule.sh PATH/TO/zblend_tb PATH/TO/zblend_tb_bug PATH/TO/zblend}
bug=${2:?usage: test_rtl_schedule.sh PATH/TO/zblend_tb PATH/TO/zblend_tb_bug PATH/TO/zblend}
zblend=${3:?usage: test_rtl_schedule.sh PATH/TO/zblend_tb PATH/TO/zblend_tb_bug PATH/TO/zblend}
source "$(dirname "$0")/../lib.sh"

# Every method on cad, golden and RTL in lock-step, under each schedule.
for s in pass tile; do
  "$zblend" render --scene cad --method all --backend both --schedule "$s" --width 160 \
    --height 120 --out-dir "$tmp/$s" -q >"$tmp/out.txt" 2>&1 || fail "render --schedule $s failed"
done
for f in "$tmp"/pass/*.png; do
  cmp -s "$f" "$tmp/tile/$(basename "$f")" || fail "$(basename "$f"): the schedules' frames differ"
done
# summary.csv: rtl_stream_cycles (17) the same, rtl_tile_cycles (18) fewer for three-pass.
col() { awk -F, -v m="$2" -v c="$3" '$1 == m { print $c }' "$tmp/$1/summary.csv"; }
[[ $(col pass three-pass 17) == "$(col tile three-pass 17)" ]] || fail "three-pass: streaming cycles differ"
[[ $(col tile three-pass 18) -lt $(col pass three-pass 18) ]] ||
  fail "three-pass: the tile schedule took $(col tile three-pass 18) tile cycles, the pass one $(col pass three-pass 18)"
echo "ok: cad, every method: the same frames; three-pass tile cycles $(col pass three-pass 18) -> $(col tile three-pass 18)"

"$tb" --schedule tile --suite random,tiles,clears,accum,states --seed 3 -q >"$tmp/out.txt" 2>&1 ||
  fail "the suites fail under the tile schedule"
echo "ok: random, tiles, clears, accum and states pass under the tile schedule"

# The blend defect (zblend_tb_bug's default) inside a group: random's frames run several passes
# between frame operations.
tb=$bug
lockstep blend-tile X11 --schedule tile --suite random --seed 1 --fragments 300000
grep -qE '^    #[0-9]+ \(pass [0-9]+\) z=' "$tmp/out.txt" || fail "blend-tile: the history does not name each fragment's pass"
end_of_pass blend-tile --schedule tile --suite random --seed 1 --fragments 300000

expect_schedule_error() {
  local err rc
  err=$("$@" 2>&1 >/dev/null); rc=$?
  [[ $rc -eq 2 ]] || fail "$1 --schedule diagonal: exit $rc, want 2"
  grep -q "schedule 'diagonal' (choose from" <<<"$err" || fail "$1: '$err' does not name the choices"
}
expect_schedule_error "$zblend" render --scene cad --backend rtl --schedule diagonal --out "$tmp/x.png"
expect_schedule_error "$tb" --schedule diagonal --suite random
[[ ! -e $tmp/x.png ]] || fail "render --schedule diagonal left x.png"
echo "ok: --schedule diagonal refused by zblend render and zblend_tb"

# The tile operations' own defects (zblend_tb_bug): the copy of depth to peel flips a bit, the
# store's resolve wraps instead of saturating, its resolve of the accumulation truncates. The
# tile schedule's store check catches each; the pass schedule never runs them (its frame
# operations stay on the host). random has no accumulate pass: accum's frames resolve wboit.
for d in copy resolve resolve-wboit; do
  suite=$([[ $d == resolve-wboit ]] && echo accum || echo random)
  "$bug" --schedule tile --defect "$d" --suite "$suite" --seed 2 --iterations 1 -q \
    --mismatch-fst "$tmp/m.fst" >"$tmp/out.txt" 2>&1
  rc=$?
  [[ $rc -eq 1 ]] || fail "defect $d: exit $rc under the tile schedule, want 1"
  want=$([[ $d == copy ]] && echo peel || echo colour)
  grep -qE "^  tile store beat [0-9]+ lane [0-9]+: $want rtl .* golden " "$tmp/out.txt" ||
    fail "defect $d: no 'tile store beat B lane L: $want rtl ... golden ...' line"
  "$bug" --schedule pass --defect "$d" --suite "$suite" --seed 2 --iterations 1 -q >"$tmp/out.txt" 2>&1 ||
    fail "defect $d: the pass schedule, which never copies or resolves on the tile, failed"
  echo "ok: defect $d caught at the store under the tile schedule"
done
