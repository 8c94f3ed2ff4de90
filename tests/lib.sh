# The test scripts' one library: `source "$(dirname "$0")/../lib.sh"` (from tests/AREA/).
# One way to fail: `fail WHAT`, which ends the test at once.
#
#   $tmp            a scratch directory, made here and removed at exit
#   fail WHAT...    the test fails: "FAIL: WHAT", then $tmp/out.txt (the output being checked)
#                   when there is one; exit 1
#   ok              counts a passed check in $pass (for a closing line such as "$pass passed")
#   expect_error    the bad-input contract: exit 2, one line on stderr, no file left
#   run, lockstep, end_of_pass   a defective RTL's run of $tb, and how it must be caught
#   mutant_args, expect_mutant   a single-mutant test's arguments, and its mutant's identity
tmp=$(mktemp -d)
trap 'chmod -R u+w "$tmp" 2>/dev/null; rm -rf "$tmp"' EXIT
pass=0

fail() { echo "FAIL: $*"; [[ -f $tmp/out.txt ]] && { echo "--- output:"; cat "$tmp/out.txt"; }; exit 1; }
ok() { pass=$((pass + 1)); }

# ---- Bad input (tests/cli, tests/conformance) ------------------------------------------------

# expect_error NAME PATTERN PROGRAM ARGS...: exit 2, one stderr line matching PATTERN, no file
# left in $tmp/out (the caller makes it).
expect_error() {
  local name=$1 pattern=$2; shift 2
  local before after err rc
  before=$(ls -A "$tmp/out" | sort)
  err=$("$@" 2>&1 >/dev/null); rc=$?
  after=$(ls -A "$tmp/out" | sort)
  [[ $rc -eq 2 ]] || fail "$name: exit $rc, want 2 ($err)"
  [[ $(printf '%s\n' "$err" | wc -l) -eq 1 ]] || fail "$name: not one line: $err"
  grep -qE -- "$pattern" <<<"$err" || fail "$name: '$err' lacks /$pattern/"
  [[ "$before" == "$after" ]] || fail "$name: left files: $after"
  ok
}

# ---- A defective RTL's run (tests/rtl, tests/mutation): $tb is the testbench -----------------

# run NAME ARGS...: the run fails (exit 1) and writes an FST.
run() {
  local name=$1; shift
  rm -f "$tmp/mismatch.fst"
  "$tb" "$@" --mismatch-fst "$tmp/mismatch.fst" -q >"$tmp/out.txt" 2>&1
  local rc=$?
  [[ $rc -eq 1 ]] || fail "$name: the defective RTL gave exit $rc, want 1"
  [[ -s "$tmp/mismatch.fst" ]] || fail "$name: no FST written at $tmp/mismatch.fst"
  head -c 1 "$tmp/mismatch.fst" | od -An -tx1 | grep -q '00' || fail "$name: mismatch.fst is not an FST"
  grep -q 'replay reproduced the RTL.s pixel' "$tmp/out.txt" ||
    fail "$name: the waveform replay did not reproduce the RTL's pixel"
}

# lockstep NAME STAGE ARGS...: stopped at the first wrong write of STAGE (X4 or X11).
lockstep() {
  local name=$1 stage=$2; shift 2
  run "$name" "$@"
  grep -qE '^LOCKSTEP MISMATCH in frame [0-9]+ pass [0-9]+.*: the first wrong write, at cycle [0-9]+ \(its rising edge at [0-9]+ ns\)' \
    "$tmp/out.txt" || fail "$name: no 'LOCKSTEP MISMATCH ... at cycle N' line"
  grep -qE '^  fragment #[0-9]+ \(primitive [0-9]+\) at pixel \([0-9]+,[0-9]+\), accepted at cycle [0-9]+' \
    "$tmp/out.txt" || fail "$name: the fragment is not named"
  grep -qE "^  $stage: rtl wrote .*; golden " "$tmp/out.txt" || fail "$name: no '$stage: rtl wrote ...; golden ...' line"
  grep -qE '^      golden: .*' "$tmp/out.txt" && grep -qE '^      rtl: +X4 at cycle [0-9]+' "$tmp/out.txt" ||
    fail "$name: no pixel history with both sides"
  echo "ok: $name stopped at: $(grep -m1 "^  $stage: " "$tmp/out.txt")"
}

# end_of_pass NAME ARGS...: caught by the frame comparison alone.
end_of_pass() {
  local name=$1; shift
  run "$name" --no-lockstep "$@"
  grep -qE '^MISMATCH in .*pixels differ' "$tmp/out.txt" || fail "$name: no 'MISMATCH ... pixels differ' line"
  grep -qE 'pixel \([0-9]+,[0-9]+\) rtl=rgba\([0-9,]+\) z=0x[0-9a-f]+ cov=[0-9]+ golden=rgba' \
    "$tmp/out.txt" || fail "$name: no 'pixel (x,y) rtl=... golden=...' line"
  grep -q 'accepted at cycle' "$tmp/out.txt" || fail "$name: no fragments listed for the pixel"
  echo "ok: $name caught at the end of its pass: $(grep -m1 '^pixel' "$tmp/out.txt")"
}

# ---- Single-mutant tests (tests/mutation/test_mutant_*.sh) -----------------------------------

# mutant_args "$@": the test's arguments, PATH/TO/zblend_tb_mut PATH/TO/mutations.txt, as $tb
# and $mutations.
mutant_args() {
  tb=${1:?usage: $(basename "$0") PATH/TO/zblend_tb_mut PATH/TO/mutations.txt}
  mutations=${2:?usage: $(basename "$0") PATH/TO/zblend_tb_mut PATH/TO/mutations.txt}
}

# expect_mutant N PATTERN WHAT: line N of the netlist's list matches PATTERN (grep's basic
# syntax), or the sample moved (a change to the RTL renumbers it) and the test fails saying what
# it expected and where that mutant is now, if it still is in the sample.
expect_mutant() {
  sed -n "$1p" "$mutations" | grep -q -- "$2" && return
  local now
  now=$(grep -n -m1 -- "$2" "$mutations" | cut -d: -f1)
  [[ -n $now ]] && now="(it is mutant $now now)" || now="(no mutant of the sample is: pick another)"
  fail "mutant $1 is not $3 this test expects: $(sed -n "$1p" "$mutations") $now"
}

# ---- Scenes ------------------------------------------------------------------------------------

# odd_alpha_scene DIR: DIR/odd.obj (with DIR/m.mtl), two overlapping transparent triangles of
# alphas 77 and 179 (d 0.3, 0.7): odd alphas, which the built-in scenes lack, for the injected
# blend defect (odd source alpha).
odd_alpha_scene() {
  printf 'mtllib m.mtl\nv -1 -1 0\nv 1 -1 0\nv 0 1 0\nv -1 1 -0.5\nv 1 1 -0.5\nv 0 -1 -0.5\n' >"$1/odd.obj"
  printf 'usemtl a\nf 1 2 3\nusemtl b\nf 4 6 5\n' >>"$1/odd.obj"
  printf 'newmtl a\nKd 0.9 0.2 0.1\nd 0.3\nnewmtl b\nKd 0.1 0.3 0.9\nd 0.7\n' >"$1/m.mtl"
}
