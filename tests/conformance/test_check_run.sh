#!/usr/bin/env bash
# `zblend conformance check SUITE OUT` after a run of scripts/conformance.py checks the tests that
# run simulated (OUT/results.json), not the whole suite: a --quick run of the second DUT's subset
# profile (9 of the 30 quick tests supported) checks clean, and a test it ran whose got file is
# gone is still reported missing; the DUT lacks the accumulation plane, which the run recorded
# and check heeds. `check --quick` checks the quick tier alone, as the runner's
# --quick runs it; a stray or empty results.json is exit 2, one line.
#   test_check_run.sh SUITE OUT ZBLEND
set -u
suite=$(realpath "${1:?usage: test_check_run.sh SUITE OUT ZBLEND}") out=$2 zblend=$(realpath "$3")
root=$(cd "$(dirname "$0")/../.." && pwd)
source "$root/tests/lib.sh"
rm -rf "$out"
mkdir -p "$out" "$tmp/out"
run=$out/run
python3 "$root/scripts/conformance.py" --suite "$suite" --sim icarus --out "$run" --quick -j 2 \
  --profile "$root/conformance/ref/profile.json" --zblend "$zblend" >"$out/run.txt" 2>&1 ||
  fail "the --quick run exited $?: $(tail -3 "$out/run.txt")"
ran=$(python3 -c 'import json, sys
print(sum(t["verdict"] == "pass" for t in json.load(open(sys.argv[1]))["tests"]))' "$run/results.json")
[[ $ran -gt 0 ]] || fail "the run passed no test"

"$zblend" conformance check "$suite" "$run" >"$tmp/out.txt" 2>&1 ||
  fail "check of the --quick run's OUT: exit $?"
grep -q missing "$tmp/out.txt" && fail "check reports tests the run never ran as missing"
[[ $(grep -c '^pass  ' "$tmp/out.txt") -eq $ran ]] || fail "not $ran pass lines"
grep -qx "$ran of $ran tests pass (the tests the run simulated, without the accumulation plane, $run/results.json)" "$tmp/out.txt" ||
  fail "the count line does not say the run chose the tests"
echo "ok: the --quick run's OUT checks clean: $(tail -1 "$tmp/out.txt")"

# A test the run chose, its got file gone: still missing, a failure.
t=$(grep -m1 '^pass  ' "$tmp/out.txt" | cut -c7-)
rm "$run/$t/got.depth.hex"
"$zblend" conformance check "$suite" "$run" >"$tmp/out.txt" 2>&1; rc=$?
[[ $rc -eq 1 ]] && grep -qF "FAIL  $t: missing $run/$t/got.depth.hex" "$tmp/out.txt" ||
  fail "a missing got file of a test the run ran: exit $rc"
echo "ok: $t's missing got.depth.hex is reported"

# --quick: the expect files of the quick tier as got files, no results.json.
q=$tmp/quick
mkdir "$q"
for t in $(python3 -c 'import json, sys
print(" ".join(t["name"] for t in json.load(open(sys.argv[1]))["tests"] if t["tier"] == "quick"))' \
  "$suite/manifest.json"); do
  mkdir "$q/$t"
  for p in color depth coverage peel accum; do cp "$suite/$t/expect.$p.hex" "$q/$t/got.$p.hex"; done
done
n=$(ls "$q" | wc -l)
"$zblend" conformance check "$suite" "$q" --quick >"$tmp/out.txt" 2>&1 && grep -qx "$n of $n tests pass" "$tmp/out.txt" ||
  fail "check --quick on the quick tier's files: $(tail -1 "$tmp/out.txt")"
"$zblend" conformance check "$suite" "$q" >"$tmp/out.txt" 2>&1 && fail "the full tier passes without its files"
"$zblend" conformance check "$suite" "$q" --quick --tests tiles,hazard >"$tmp/out.txt" 2>&1 &&
  grep -qx "2 of 2 tests pass" "$tmp/out.txt" || fail "--quick --tests: $(tail -1 "$tmp/out.txt")"
rm -f "$tmp/out.txt"
echo "ok: check --quick checks the quick tier ($n tests)"

# Bad input: exit 2, one line.
expect_error "--quick, a test of the full tier" "--tests: 'cad-three-pass' is not a test of .*'s quick tier" \
  "$zblend" conformance check "$suite" "$q" --quick --tests cad-three-pass
echo '{"tests": [{"name": "nope", "verdict": "pass"}]}' >"$q/results.json"
expect_error "results.json naming no test" "$q/results.json: 'nope' is not a test of" \
  "$zblend" conformance check "$suite" "$q"
echo '{"tests": [{"name": "tiles", "verdict": "not_supported"}]}' >"$q/results.json"
expect_error "results.json with no simulated test" "results.json says the run simulated no test" \
  "$zblend" conformance check "$suite" "$q"
echo 'not json' >"$q/results.json"
expect_error "results.json not JSON" "results.json: .*parse error" "$zblend" conformance check "$suite" "$q"
echo "ok: bad selections refused ($pass)"
