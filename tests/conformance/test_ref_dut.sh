#!/usr/bin/env bash
# The conformance kit on conformance/ref's zb_ref_rop (a DUT unlike zb_rop: one fragment at a
# time, a subset profile, random stalls on every port, the store answering in its first cycle),
# through scripts/conformance.py with its profile, on a suite exported by the conformance_export
# fixture. Verdicts are read from OUT/results.json.
#   test_ref_dut.sh lint
#       Verilator -Wall lint and Icarus elaboration of both variants (zb_ref_rop, with and without
#       ZB_REF_FULL, and zb_ref_pipe) and their adapters, clean, with no defect, with every defect
#       of conformance/ref/defects.json at once and with each alone
#   test_ref_dut.sh pass SIM SUITE OUT ZBLEND TESTS NPASS NNOT [ARGS...]
#       exit 0; NPASS tests pass, NNOT are NOT SUPPORTED (not run), none fails or times out
#   test_ref_dut.sh stalls SIM SUITE OUT ZBLEND TESTS NPASS NNOT SEED RATE GAP TEST
#       the same with the DUT's stalls at +zb_ref_seed=SEED +zb_ref_stall=RATE and GAP % of
#       cycles with no fragment offered; then TEST run again at the defaults gives the same
#       planes in fewer cycles (the stalls changed, the result did not)
#   test_ref_dut.sh bug SIM SUITE OUT ZBLEND TESTS BAD
#       ZB_REF_INJECT_BLEND_BUG: exit 1; BAD (it alpha-blends) fails on a colour pixel, the
#       other TESTS (replace only) pass
#   test_ref_dut.sh hang SIM SUITE OUT ZBLEND TEST
#       ZB_REF_INJECT_HANG: the testbench's watchdog fails TEST (not the timeout), naming
#       frag_ready_o; the printed reproduce command hangs and fails the same way
# TESTS: a --tests value ("" for the whole suite); ARGS go to conformance.py.
set -u
root=$(cd "$(dirname "$0")/../.." && pwd)
ref=$root/conformance/ref
profile=$ref/profile.json
mode=${1:?usage: test_ref_dut.sh lint | MODE SIM SUITE OUT ZBLEND TESTS ... (see above)}
fail() { echo "FAIL: $*" >&2; [[ -f ${out:-}/log.txt ]] && tail -n 30 "$out/log.txt" >&2; exit 1; }

if [[ $mode == lint ]]; then
  # The build's configurations and the corners: 8 and 32 bits, one sample, a tile of 15 pixels.
  sets=("" "-GDEPTH_BITS=16 -GCOV_SAMPLES=4" "-GDEPTH_BITS=32 -GTILE_W=32 -GTILE_H=8"
        "-GDEPTH_BITS=8 -GCOV_SAMPLES=1 -GTILE_W=3 -GTILE_H=5")
  # The defect catalogue's defines of one variant (conformance/ref/defects.json).
  defects() {
    python3 -c 'import json,sys
print(" ".join(d["define"] for d in json.load(open(sys.argv[1])) if d["variant"] == sys.argv[2]))' \
      "$ref/defects.json" "$1"
  }
  ref_defects=$(defects ref) pipe_defects=$(defects pipe)
  [[ -n $ref_defects && -n $pipe_defects ]] || fail "no defects of a variant in $ref/defects.json"
  # Per variant: its sources, then its define sets, one a line: none, the full datapath, the kit's
  # own defects, every defect at once, and each defect alone.
  inject="ZB_REF_INJECT_BLEND_BUG ZB_REF_INJECT_HANG"
  ref_sets=$(printf '%s\n' "" "ZB_REF_FULL" "$inject" "$inject $ref_defects" \
    ZB_REF_ARITH_SUM_ROUND255 "ZB_REF_FULL ZB_REF_ARITH_SUM_CEIL256" ZB_REF_ARITH_SUM_FLOOR256 \
    "ZB_REF_FULL $inject $ref_defects"; for d in $ref_defects; do echo "ZB_REF_FULL $d"; done)
  pipe_sets=$(printf '%s\n' "ZB_REF_PIPE" "ZB_REF_PIPE $pipe_defects"; for d in $pipe_defects; do echo "ZB_REF_PIPE $d"; done)
  n=0
  for variant in ref pipe; do
    if [[ $variant == ref ]]; then
      srcs=("$ref/zb_ref_rop.sv" "$ref/zb_ref_adapter.sv") defsets=$ref_sets
    else
      srcs=("$ref/zb_ref_pipe.sv" "$ref/zb_ref_adapter.sv") defsets=$pipe_sets
    fi
    while IFS= read -r defs; do
      for set in "${sets[@]}"; do
        vdefs=() idefs=() iparams=()
        for d in $defs; do vdefs+=("+define+$d"); idefs+=("-D$d"); done
        for p in $set; do iparams+=("-Pzb_conf_adapter.${p#-G}"); done
        # shellcheck disable=SC2086  # $set: one option a word
        verilator --lint-only -Wall --top-module zb_conf_adapter $set "${vdefs[@]}" "${srcs[@]}" ||
          fail "verilator lint $variant [$set] [$defs]"
        msg=$(iverilog -g2012 -Wall -o /dev/null -s zb_conf_adapter "${iparams[@]}" "${idefs[@]}" \
          "${srcs[@]}" 2>&1) || fail "iverilog $variant [$set] [$defs]: $msg"
        [[ -z $msg ]] || fail "iverilog warns $variant [$set] [$defs]: $msg"
        n=$((n + 1))
      done
    done <<<"$defsets"
  done
  echo "ok: zb_ref_rop (subset and ZB_REF_FULL) and zb_ref_pipe with their adapters lint clean (Verilator -Wall) and elaborate silently (Icarus): ${#sets[@]} parameter sets, with no defect, every defect at once and each alone ($n builds each)"
  exit 0
fi

sim=${2:?} suite=${3:?} out=${4:?} zblend=${5:?} tests=$6
shift 6
rm -rf "$out"
mkdir -p "$out"
run() {
  local sel=()
  [[ -n $tests ]] && sel=(--tests "$tests")
  python3 "$root/scripts/conformance.py" --suite "$suite" --sim "$sim" --out "$out" \
    --profile "$profile" "${sel[@]}" --zblend "$zblend" -j 2 "$@" >"$out/log.txt" 2>&1
}
# results.json's count of a verdict; its verdict and message of a test.
count() { python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["counts"][sys.argv[2]])' "$out/results.json" "$1"; }
verdict() {
  python3 -c 'import json,sys
t = [t for t in json.load(open(sys.argv[1]))["tests"] if t["name"] == sys.argv[2]]
print(t[0]["verdict"] + " " + t[0]["message"] if t else "absent")' "$out/results.json" "$1"
}
names() {  # the tests of one verdict, a line each
  python3 -c 'import json,sys
for t in json.load(open(sys.argv[1]))["tests"]:
    if t["verdict"] == sys.argv[2]: print(t["name"])' "$out/results.json" "$1"
}
cycles() { sed -n 's/^zb_conf: done: .*, \([0-9]*\) cycles$/\1/p' "$1"; }
# Every supported test passed, every other one was not run, and the counts are the expected ones.
expect_counts() {
  local npass=$1 nnot=$2 t
  [[ -f $out/results.json ]] || fail "no results.json"
  [[ $(count pass) == "$npass" ]] || fail "$(count pass) tests pass, want $npass"
  [[ $(count not_supported) == "$nnot" ]] || fail "$(count not_supported) NOT SUPPORTED, want $nnot"
  [[ $(count fail) == 0 && $(count timeout) == 0 ]] || fail "$(count fail) failed, $(count timeout) timed out"
  for t in $(names pass); do
    grep -q "^zb_conf: done: " "$out/$t/sim.log" || fail "$t: passed without finishing its simulation"
  done
  for t in $(names not_supported); do
    [[ -e $out/$t/sim.log ]] && fail "$t: NOT SUPPORTED, yet it was simulated"
  done
  grep -q "^conformance: $npass pass, 0 fail, $nnot not supported, 0 timeout" "$out/log.txt" ||
    fail "the summary line does not say $npass pass, $nnot not supported"
}

case $mode in
  pass)
    npass=$1 nnot=$2
    shift 2
    run "$@" || fail "conformance.py exited $? on zb_ref_rop under $sim"
    expect_counts "$npass" "$nnot"
    echo "ok: zb_ref_rop under $sim: $npass pass, $nnot NOT SUPPORTED"
    ;;
  stalls)
    npass=$1 nnot=$2 seed=$3 rate=$4 gap=$5 again=$6
    run --plusarg "+zb_ref_seed=$seed" --plusarg "+zb_ref_stall=$rate" --gap "$gap" --seed "$seed" ||
      fail "conformance.py exited $? with stall seed $seed, rate $rate, gap $gap"
    expect_counts "$npass" "$nnot"
    for t in $(names pass); do
      grep -qx "zb_ref_rop: stall seed $seed, stall rate $rate of 256" "$out/$t/sim.log" ||
        fail "$t: the DUT did not take +zb_ref_seed=$seed +zb_ref_stall=$rate"
    done
    # The same test at the DUT's default stalls and no gaps, by the command its sim.log starts with.
    log=$out/$again/sim.log
    cmd=() base=$out/$again-default
    mkdir -p "$base"
    read -r -a words < <(head -n 1 "$log")
    for w in "${words[@]}"; do
      case $w in
        +zb_ref_seed=*|+zb_ref_stall=*|+gap=*|+seed=*) ;;
        +out=*) cmd+=("+out=$base") ;;
        *) cmd+=("$w") ;;
      esac
    done
    "${cmd[@]}" >"$base/sim.log" 2>&1 || fail "$again at the default stalls: exit $? ($base/sim.log)"
    grep -q "^zb_ref_rop: stall seed 625341585, stall rate 64 of 256$" "$base/sim.log" ||
      fail "$again did not run at the default stalls"
    for p in color depth coverage peel; do
      cmp -s "$out/$again/got.$p.hex" "$base/got.$p.hex" || fail "$again: the $p plane depends on the stalls"
    done
    c1=$(cycles "$log") c0=$(cycles "$base/sim.log")
    [[ -n $c0 && -n $c1 && $c1 -gt $c0 ]] ||
      fail "$again: $c1 cycles at stall rate $rate and gap $gap, $c0 at the defaults: the stalls did not change"
    echo "ok: zb_ref_rop under $sim with stall seed $seed, rate $rate/256, gap $gap %: $npass pass, $nnot NOT SUPPORTED; $again the same planes in $c1 cycles as in $c0 at the defaults"
    ;;
  bug)
    bad=$1
    run --define ZB_REF_INJECT_BLEND_BUG
    rc=$?
    [[ $rc == 1 ]] || fail "conformance.py exited $rc with the blend defect, want 1"
    line=$(grep "^FAIL  $bad: color pixel (" "$out/log.txt") ||
      fail "the checker did not name a colour pixel of $bad"
    [[ $(verdict "$bad") == "fail color pixel ("* ]] || fail "results.json: $bad: $(verdict "$bad")"
    for t in ${tests//,/ }; do
      [[ $t == "$bad" || $(verdict "$t") == "pass " ]] || fail "$t (no alpha blend): $(verdict "$t")"
    done
    echo "ok: the blend defect caught under $sim: $line"
    ;;
  hang)
    t0=$SECONDS
    # The timeout is the backstop: a hang it kills is a "timeout" verdict, which fails here.
    run --define ZB_REF_INJECT_HANG --timeout 50
    rc=$?
    secs=$((SECONDS - t0))
    [[ $rc == 1 ]] || fail "conformance.py exited $rc on the hanging DUT, want 1"
    log=$out/$tests/sim.log
    line=$(grep -m1 "^zb_conf: WATCHDOG: " "$log") || fail "no WATCHDOG line in $log"
    [[ $line == *"waiting for frag_ready_o"*"frag_ready_o=0"* ]] ||
      fail "the WATCHDOG line does not name frag_ready_o low: $line"
    [[ $(verdict "$tests") == "fail zb_conf: WATCHDOG: "* ]] || fail "results.json: $(verdict "$tests")"
    again=$(sed -n 's/^conformance: reproduce: //p' "$out/log.txt")
    [[ -n $again ]] || fail "no 'conformance: reproduce:' line"
    [[ $secs -lt 60 ]] || fail "the hang took $secs s to fail"
    rm -f "$log"
    (cd "$root" && eval "$again") >"$out/again.txt" 2>&1 && fail "the reproduce command passed"
    grep -q "^zb_conf: WATCHDOG: " "$log" || fail "the reproduce command did not hang into the watchdog"
    [[ -s $out/$tests/waves.fst ]] || fail "the reproduce command wrote no waves.fst"
    echo "ok: the hang failed by the watchdog under $sim in $secs s: $line"
    ;;
  *) echo "usage: test_ref_dut.sh lint|pass|stalls|bug|hang ..." >&2; exit 2 ;;
esac
