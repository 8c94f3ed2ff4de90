# The checks a defective RTL's run must pass (test_rtl_bug.sh, tests/mutation/): sourced with
# $tb set to the testbench program. It makes $tmp and removes it at exit.
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; [[ -f $tmp/out.txt ]] && { echo "--- output:"; cat "$tmp/out.txt"; }; exit 1; }

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

