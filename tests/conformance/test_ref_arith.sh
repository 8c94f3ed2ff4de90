#!/usr/bin/env bash
# Declared arithmetic (docs/datapath.md "Declared arithmetic") on conformance/ref's zb_ref_rop:
#   test_ref_arith.sh pass SIM SUITE OUT ZBLEND DEFINE NAME [ARGS...]
#       the DUT built with DEFINE (its own arithmetic) and declared NAME: every supported test
#       passes, none fails
#   test_ref_arith.sh cts SIM SUITE OUT ZBLEND DEFINES - [ARGS...]
#       the DUT built with DEFINES (comma-separated) asking for the CTS verdict (--arithmetic cts):
#       no test fails, some pass by the threshold only (cts_pass, counted apart from pass)
#   test_ref_arith.sh cts-fails SIM SUITE OUT ZBLEND DEFINES - [ARGS...]
#       the same with a defect beyond the threshold among DEFINES: exit 1, a colour pixel fails
#   test_ref_arith.sh wrong SIM SUITE OUT ZBLEND DEFINE NAME [ARGS...]
#       the DUT built with DEFINE (arithmetic NAME) but declared zblend's: exit 1, and the tests
#       that fail are exactly those in which the two arithmetics make some pass's planes
#       differently, found without the DUT: the suite's own expect files (zblend's final planes)
#       and the golden model's digests after each pass (`zblend conformance digests`) checked as
#       got files under --arithmetic NAME. Neither set is empty, and some supported test passes.
set -u
root=$(cd "$(dirname "$0")/../.." && pwd)
mode=${1:?usage: test_ref_arith.sh pass|wrong SIM SUITE OUT ZBLEND DEFINE NAME [ARGS...]}
sim=${2:?} suite=${3:?} out=${4:?} zblend=${5:?} define=${6:?} name=${7:?}
shift 7
fail() { echo "FAIL: $*" >&2; [[ -f $out/log.txt ]] && tail -n 20 "$out/log.txt" >&2; exit 1; }
rm -rf "$out"
mkdir -p "$out"
declared=$name
[[ $mode == wrong ]] && declared=zblend
[[ $mode == cts* ]] && declared=cts
defines=()
for d in ${define//,/ }; do defines+=(--define "$d"); done
python3 "$root/scripts/conformance.py" --suite "$suite" --sim "$sim" --out "$out/run" \
  --profile "$root/conformance/ref/profile.json" "${defines[@]}" --arithmetic "$declared" \
  --zblend "$zblend" -j 2 "$@" >"$out/log.txt" 2>&1
rc=$?
verdicts() {  # the tests of a verdict in results.json, sorted, one a line
  python3 -c 'import json,sys
print("\n".join(sorted(t["name"] for t in json.load(open(sys.argv[1]))["tests"] if t["verdict"] == sys.argv[2])))' \
    "$out/run/results.json" "$1"
}
[[ -f $out/run/results.json ]] || fail "no results.json (exit $rc)"
npass=$(verdicts pass | grep -c .)
case $mode in
  pass)
    [[ $rc == 0 ]] || fail "$define declared $name: exit $rc"
    [[ -z $(verdicts fail) && $npass -gt 0 ]] || fail "$define declared $name: $npass pass, failing: $(verdicts fail | tr '\n' ' ')"
    python3 -c 'import json,sys; assert json.load(open(sys.argv[1]))["arithmetic"] == sys.argv[2]' \
      "$out/run/results.json" "$name" || fail "results.json does not record arithmetic $name"
    echo "ok: zb_ref_rop with $define declared $name under $sim: $npass pass, 0 fail"
    ;;
  cts)
    ncts=$(verdicts cts_pass | grep -c .)
    [[ $rc == 0 && -z $(verdicts fail) ]] || fail "$define under the CTS verdict: exit $rc, failing: $(verdicts fail | tr '\n' ' ')"
    [[ $ncts -gt 0 ]] || fail "$define under the CTS verdict: no test passed by the threshold only"
    grep -q "^conformance: $npass pass, $ncts pass by the CTS threshold only (not exact), 0 fail" "$out/log.txt" ||
      fail "the summary does not count the CTS passes apart: $(grep '^conformance: .* pass, ' "$out/log.txt")"
    for t in $(verdicts cts_pass); do
      grep -q "^cts   $t: [0-9]* colour pixels\? within the CTS blend threshold" "$out/log.txt" ||
        fail "$t: no cts line from the checker"
    done
    echo "ok: zb_ref_rop with $define under the CTS verdict ($sim): $npass exact, $ncts by the threshold only, 0 fail"
    ;;
  cts-fails)
    [[ $rc == 1 ]] || fail "$define under the CTS verdict: exit $rc, want 1"
    grep -q "^FAIL  .*: color pixel (" "$out/log.txt" || fail "no colour pixel beyond the threshold named"
    echo "ok: $define fails under the CTS verdict ($sim): $(grep -m1 '^FAIL' "$out/log.txt" | cut -c1-120)"
    ;;
  wrong)
    [[ $rc == 1 ]] || fail "$define declared zblend: exit $rc, want 1"
    verdicts fail >"$out/failed.txt"
    # The same tests' expect files (zblend's planes) as got files, checked in the DUT's arithmetic.
    ran=$(python3 -c 'import json,sys
print(",".join(t["name"] for t in json.load(open(sys.argv[1]))["tests"] if t["verdict"] in ("pass", "fail")))' \
      "$out/run/results.json")
    for t in ${ran//,/ }; do
      mkdir -p "$out/zblend/$t"
      for f in "$suite/$t"/expect.*.hex; do cp "$f" "$out/zblend/$t/got.${f##*/expect.}"; done
      "$zblend" conformance digests "$suite" "$t" >"$out/zblend/$t/got.passes.hex" ||
        fail "zblend conformance digests $t"
    done
    "$zblend" conformance check "$suite" "$out/zblend" --tests "$ran" --arithmetic "$name" \
      >"$out/differ.log" 2>&1
    sed -n 's/^FAIL  \([^:]*\):.*/\1/p' "$out/differ.log" | sort >"$out/differ.txt"
    [[ -s $out/differ.txt ]] || fail "no supported test tells $name from zblend's arithmetic"
    [[ $npass -gt 0 ]] || fail "no test passed: the wrong declaration should fail only where the arithmetics differ"
    diff "$out/failed.txt" "$out/differ.txt" >"$out/sets.diff" ||
      fail "the failing tests are not those where $name and zblend differ: $(cat "$out/sets.diff")"
    # The pixel history in the DUT's rule ends where the DUT ended: the first failing colour pixel.
    line=$(grep -m1 "^FAIL  .*: color pixel (" "$out/log.txt") || fail "no failing colour pixel"
    read -r t x y got < <(sed -E 's/^FAIL  ([^:]*): color pixel \(([0-9]+), ([0-9]+)\): expected [0-9a-f]+, got ([0-9a-f]+).*/\1 \2 \3 \4/' <<<"$line")
    "$zblend" conformance pixel "$suite" "$t" --at "$x,$y" --arithmetic "$name" >"$out/history.txt" 2>&1 ||
      fail "conformance pixel $t --at $x,$y --arithmetic $name: exit $?"
    final=$(sed -nE 's/^final  colour \(([0-9]+),([0-9]+),([0-9]+),([0-9]+)\).*/\1 \2 \3 \4/p' "$out/history.txt")
    read -r r g b a <<<"$final"
    [[ -n $final && $(printf '%02x%02x%02x%02x' "$a" "$b" "$g" "$r") == "$got" ]] ||
      fail "$t ($x, $y): the history in $name ends at ($final), the DUT wrote $got"
    grep -q "^    roundings: R $name(" "$out/history.txt" || fail "the history shows no $name roundings"
    echo "ok: zb_ref_rop with $define declared zblend under $sim: the $(grep -c . "$out/failed.txt") tests where the arithmetics differ fail, $npass pass; $t ($x, $y) replayed in $name ends at the DUT's $got"
    ;;
  *) echo "usage: test_ref_arith.sh pass|wrong ..." >&2; exit 2 ;;
esac
