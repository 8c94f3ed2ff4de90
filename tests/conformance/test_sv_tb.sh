#!/usr/bin/env bash
# The SystemVerilog conformance testbench (conformance/sv) on zb_rop, through
# scripts/conformance.py, on a suite exported by the conformance_export fixture.
#   test_sv_tb.sh pass SIM SUITE OUT ZBLEND TESTS [ARGS...]   every listed test matches
#   test_sv_tb.sh bug  SIM SUITE OUT ZBLEND TEST  [ARGS...]   with the blend defect in the RTL,
#       the run fails and the checker names the first differing pixel of that test
#   test_sv_tb.sh lockstep-bug SIM SUITE OUT ZBLEND TEST LIBS...   the DPI-C lock-step run stops
#       at the first wrong write, naming the fragment, the pixel and both values
#   test_sv_tb.sh resolve-bug SIM SUITE OUT ZBLEND TEST [ARGS...]   the testbench's resolve wboit
#       without its rounding: the checker names a colour pixel, the accumulation plane ok
#   test_sv_tb.sh accum-bug SIM SUITE OUT ZBLEND TEST [ARGS...]   zb_rop's accumulation bypass
#       defect (+zb_bug_accum): the checker names the first differing accum pixel
#   test_sv_tb.sh lockstep-accum-bug SIM SUITE OUT ZBLEND TEST LIBS...   the same defect stops the
#       lock-step run at the first wrong accumulation write
#   test_sv_tb.sh no-accum SIM SUITE OUT ZBLEND TESTS [ARGS...]   the adapter without the
#       accumulation plane: the tests that need it are skipped (not passed), the others match
# ARGS go to conformance.py (e.g. --param TILE_W=32, --lockstep --golden-libs ...). TESTS "@quick"
# is the suite's quick tier (conformance.py --quick; its names from the manifest).
set -u
mode=${1:?usage: test_sv_tb.sh MODE SIM SUITE OUT ZBLEND TESTS [ARGS...] (MODE: see above)}
sim=$2 suite=$3 out=$4 zblend=$5 tests=$6
shift 6
root=$(cd "$(dirname "$0")/../.." && pwd)
fail() { echo "FAIL: $*" >&2; [[ -f $out/log.txt ]] && tail -n 30 "$out/log.txt" >&2; exit 1; }
rm -rf "$out"
mkdir -p "$out"
# The lock-step run stopped at its first wrong write: the MISMATCH line names the cycle, pass,
# fragment, pixel and stage, both sides' values follow (WRITE: "colour write 1 (rgba 0x", ...),
# and the run went no further.
stopped_at_first_wrong_write() {
  local log=$1 write=$2
  grep -q "^zb_conf: MISMATCH at cycle [0-9]*: pass [0-9]* fragment [0-9]*, pixel ([0-9]*, [0-9]*), X11:" "$log" ||
    fail "no MISMATCH line naming the cycle, pass, fragment, pixel and stage in $log"
  grep -q "^zb_conf:   rtl    $write" "$log" || fail "the RTL's value is not reported ($write)"
  grep -q "^zb_conf:   golden $write" "$log" || fail "the golden value is not reported ($write)"
  grep -q "^zb_conf: done:" "$log" && fail "the run went on past the first wrong write"
}
sel=(--tests "$tests")
if [[ $tests == @quick ]]; then
  sel=(--quick)
  tests=$(python3 -c 'import json, sys
print(",".join(t["name"] for t in json.load(open(sys.argv[1]))["tests"] if t["tier"] == "quick"))' \
    "$suite/manifest.json") || fail "no manifest in $suite"
fi
run() {
  python3 "$root/scripts/conformance.py" --suite "$suite" --sim "$sim" --out "$out" "${sel[@]}" \
    --zblend "$zblend" -j 2 "$@" >"$out/log.txt" 2>&1
}

n=$(tr ',' '\n' <<<"$tests" | grep -c .)
case $mode in
  pass)
    run "$@" || fail "conformance.py exited $? on zb_rop under $sim"
    grep -q "^$n of $n tests pass$" "$out/log.txt" || fail "the checker did not pass all $n tests"
    for t in ${tests//,/ }; do
      grep -q "^zb_conf: done: " "$out/$t/sim.log" || fail "$t: the simulation did not finish"
      if [[ " $* " == *" --lockstep "* ]]; then
        c=$(sed -n 's/^zb_conf: lock-step: \([0-9]*\) retires compared.*/\1/p' "$out/$t/sim.log")
        [[ -n $c && $c -gt 0 ]] || fail "$t: the lock-step scoreboard compared no write"
      fi
    done
    echo "ok: $n tests of the suite match on zb_rop under $sim"
    ;;
  bug)
    run --define ZB_INJECT_BLEND_BUG "$@"
    rc=$?
    [[ $rc == 1 ]] || fail "conformance.py exited $rc on the defective RTL, want 1"
    line=$(grep "^FAIL  $tests: color pixel (" "$out/log.txt") ||
      fail "the checker did not name the first differing colour pixel of $tests"
    echo "ok: the defect caught under $sim: $line"
    ;;
  lockstep-bug)
    run --define ZB_INJECT_BLEND_BUG --lockstep --golden-libs "$@"
    rc=$?
    [[ $rc == 1 ]] || fail "the lock-step run exited $rc on the defective RTL, want 1"
    log=$out/$tests/sim.log
    stopped_at_first_wrong_write "$log" "colour write 1 (rgba 0x"
    c=$(sed -n 's/^zb_conf: MISMATCH at cycle \([0-9]*\):.*/\1/p' "$log")
    # The printed command reproduces it with waves: the FST starts 30 cycles before the wrong
    # write, its save file puts marker A at that cycle.
    again=$(sed -n 's/^conformance: reproduce: //p' "$out/log.txt")
    [[ -n $again ]] || fail "no reproduce command printed"
    (cd "$root" && eval "$again") >"$out/again.txt" 2>&1 && fail "the reproduce command passed"
    grep -q "^zb_conf: MISMATCH at cycle $c:" "$log" || fail "the reproduce command did not fail at cycle $c"
    fst=$out/$tests/waves.fst
    [[ -s $fst && -s ${fst%.fst}.gtkw ]] || fail "no waves.fst and waves.gtkw in $out/$tests"
    first=$(fst2vcd "$fst" 2>/dev/null | grep -m1 '^#[0-9]')
    [[ $first == "#$(( (c - 30) * 10000 ))" ]] || fail "the FST starts at $first, want #$(( (c - 30) * 10000 ))"
    grep -q "^\*[-0-9.]* $(( c * 10000 )) " "${fst%.fst}.gtkw" || fail "marker A is not at cycle $c"
    grep -q "^\[markername\] Afirst wrong write$" "${fst%.fst}.gtkw" || fail "marker A is not named"
    echo "ok: the lock-step run stopped at the first wrong write: $(grep -m1 MISMATCH "$log"); reproduced with waves"
    ;;
  resolve-bug)
    run --define ZB_CONF_INJECT_RESOLVE_BUG "$@"
    rc=$?
    [[ $rc == 1 ]] || fail "conformance.py exited $rc with the resolve defect, want 1"
    line=$(grep -E "^FAIL  $tests: color pixel \(.*, accum ok\]; why: .* conformance pixel .* $tests --at [0-9]+,[0-9]+$" "$out/log.txt") ||
      fail "the checker did not name a colour pixel of $tests with the accumulation plane ok, and the command for its history"
    echo "ok: the wrong resolve caught under $sim: $line"
    ;;
  accum-bug)
    run --define ZB_INJECT_ACCUM_BUG --plusarg +zb_bug_accum "$@"
    rc=$?
    [[ $rc == 1 ]] || fail "conformance.py exited $rc on the accumulation defect, want 1"
    line=$(grep "^FAIL  $tests: accum pixel (" "$out/log.txt") ||
      fail "the checker did not name the first differing accum pixel of $tests"
    echo "ok: the accumulation defect caught under $sim: $line"
    ;;
  lockstep-accum-bug)
    run --define ZB_INJECT_ACCUM_BUG --plusarg +zb_bug_accum --lockstep --golden-libs "$@"
    rc=$?
    [[ $rc == 1 ]] || fail "the lock-step run exited $rc on the accumulation defect, want 1"
    log=$out/$tests/sim.log
    stopped_at_first_wrong_write "$log" "accumulation write 1 (acc 0x"
    echo "ok: the lock-step run stopped at the first wrong accumulation write: $(grep -m1 MISMATCH "$log")"
    ;;
  no-accum)
    run --define ZB_CONF_NO_ACCUM "$@" || fail "conformance.py exited $? without the accumulation plane"
    skips=0
    for t in ${tests//,/ }; do
      if grep -q "^skip  $t: needs the accumulation plane" "$out/log.txt"; then
        skips=$((skips + 1))
        [[ -e $out/$t/got.color.hex ]] && fail "$t: skipped, yet it wrote signatures"
      else
        grep -q "^pass  $t$" "$out/log.txt" || fail "$t: neither passed nor skipped"
        [[ -e $out/$t/got.accum.hex ]] && fail "$t: a got.accum.hex from a DUT without the plane"
      fi
    done
    [[ $skips -gt 0 ]] || fail "no test was skipped"
    grep -qx "$((n - skips)) of $((n - skips)) tests pass, $skips skipped (they need the accumulation plane)" "$out/log.txt" ||
      fail "the summary does not count $skips skipped apart from the passes"
    echo "ok: without the accumulation plane under $sim: $((n - skips)) pass, $skips skipped"
    ;;
  *) echo "usage: test_sv_tb.sh pass|bug|lockstep-bug|resolve-bug|accum-bug|lockstep-accum-bug|no-accum ..." >&2; exit 2 ;;
esac
