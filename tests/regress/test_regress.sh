#!/usr/bin/env bash
# The regression runner (scripts/regress.py) on the quick group: local processes and GNU
# parallel pass and write JUnit XML and the HTML summary; a defective RTL (mutant 38, caught by
# the clears suite's lock-step monitor) fails the run, its test is run again with waves, and the
# summary's replay command reproduces the failure; parallel --resume-failed runs only what failed;
# a malformed regression file is refused with exit 2 and where it is wrong.
# Usage: test_regress.sh BUILD   (zblend_tb and zblend_tb_mut built there)
set -u
build=$(realpath "${1:?usage: test_regress.sh BUILD}")
root=$(cd "$(dirname "$0")/../.." && pwd)
regress=(python3 "$root/scripts/regress.py")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; [[ -f $tmp/log.txt ]] && { echo "--- output:"; tail -30 "$tmp/log.txt"; }; exit 1; }
cd "$root"

# junit FILE TESTS FAILURES: the XML parses and counts that.
junit() {
  python3 - "$@" <<'PY' || fail "JUnit $1: want $2 test cases, $3 failures"
import sys, xml.etree.ElementTree as ET
root = ET.parse(sys.argv[1]).getroot()
cases = root.findall(".//testcase")
failed = [c for c in cases if c.find("failure") is not None]
assert len(cases) == int(sys.argv[2]) and len(failed) == int(sys.argv[3]), (len(cases), len(failed))
assert root.get("tests") == sys.argv[2] and root.get("failures") == sys.argv[3]
PY
}
n=$("${regress[@]}" list quick | wc -l)
[[ $n -ge 3 ]] || fail "quick lists $n tests"

"${regress[@]}" run quick -j 2 --build "$build" --out "$tmp/ok" >"$tmp/log.txt" 2>&1 || fail "quick group fails"
junit "$tmp/ok/junit.xml" "$n" 0
grep -q "100.0 % passed" "$tmp/ok/summary.html" || fail "summary.html has no 100 % pass rate"
grep -q "about [0-9]* s left" "$tmp/log.txt" || fail "no progress with the time left"
echo "ok: run: $n tests, JUnit and HTML"

# A defective RTL (mutant 38: lane 6 of the colour plane never writes back, so a read leaves
# its fresh words stale where the store should have rewritten them): the clears suite fails at a wrong write, its
# waves are written, the replay reproduces it. One seed: the one waves slot would go to
# whichever failure came first.
cat >"$tmp/reg1.json" <<'J'
{"groups": {"g": [
  {"name": "clears", "suite": "clears", "seeds": [1]},
  {"name": "window", "args": ["--suite", "window", "--seed", "1"]}]}}
J
"${regress[@]}" run g -j 2 --file "$tmp/reg1.json" --tb "$build/zblend_tb_mut" --tb-args "--mutant 38" \
  --out "$tmp/bad" --waves 1 >"$tmp/log.txt" 2>&1
rc=$?
[[ $rc -eq 1 ]] || fail "the mutant's run exited $rc, want 1"
junit "$tmp/bad/junit.xml" 2 1
grep -q '^regress: FAIL clears: LOCKSTEP MISMATCH' "$tmp/log.txt" || fail "no FAIL line naming the lock-step mismatch"
waves=$(python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); print(len(d), *[v["waves"] for v in d.values()])' "$tmp/bad/waves.json")
[[ $waves == "1 waves/clears.fst" ]] || fail "waves.json: '$waves', want one FST"
[[ -s $tmp/bad/${waves#1 } ]] || fail "the FST ${waves#1 } is missing"
grep -q 'FAIL</td>' "$tmp/bad/summary.html" && grep -q 'waves (FST)' "$tmp/bad/summary.html" ||
  fail "summary.html shows no failure with its waves"
replay=$(sed -n 's/^  replay: //p' "$tmp/log.txt" | head -1)
[[ -n $replay ]] || fail "no replay command"
(eval "$replay") >"$tmp/replay.txt" 2>&1 && fail "the replay command passed: $replay"
grep -q 'LOCKSTEP MISMATCH' "$tmp/replay.txt" || fail "the replay command did not reproduce the mismatch: $replay"
echo "ok: a defective RTL fails, with waves and a replay command that reproduces it"

# GNU parallel: the joblog, and --resume-failed runs only the failed jobs (clears fails at both
# seeds). The host list names this machine only (":"), as an --sshloginfile of a team's hosts
# would name theirs.
cat >"$tmp/reg.json" <<'J'
{"groups": {"g": [
  {"name": "clears", "suite": "clears", "seeds": [1, 2]},
  {"name": "window", "args": ["--suite", "window", "--seed", "1"]}]}}
J
echo ":" >"$tmp/hosts"
"${regress[@]}" parallel g -j 2 --file "$tmp/reg.json" --tb "$build/zblend_tb_mut" --tb-args "--mutant 38" \
  --sshloginfile "$tmp/hosts" --out "$tmp/par" >"$tmp/log.txt" 2>&1 && fail "parallel passed on the mutant"
junit "$tmp/par/junit.xml" 3 2
[[ $(grep -c 'regress.py one g' "$tmp/par/joblog") -eq 3 ]] || fail "joblog: want 3 jobs"
"${regress[@]}" parallel g -j 2 --file "$tmp/reg.json" --tb "$build/zblend_tb_mut" --tb-args "--mutant 0" \
  --out "$tmp/par" --resume-failed >"$tmp/log.txt" 2>&1 || fail "resume-failed with the unmutated netlist fails"
junit "$tmp/par/junit.xml" 3 0
[[ $(grep -c 'regress.py one g' "$tmp/par/joblog") -eq 5 ]] || fail "joblog after --resume-failed: want 3 + 2 jobs"
echo "ok: parallel: joblog, --resume-failed ran the 2 failed jobs only"

# Bad input: exit 2, the file and the entry named, nothing written.
echo '{"groups": {"g": [{"name": "x", "suite": "tiles", "seeds": [1], "bp": [0.1]}]}}' >"$tmp/bad.json"
"${regress[@]}" run g --file "$tmp/bad.json" --out "$tmp/none" >"$tmp/log.txt" 2>&1
rc=$?
[[ $rc -eq 2 ]] || fail "a malformed file: exit $rc, want 2"
grep -q "bad.json: groups.g\[0\]: unknown key(s) bp" "$tmp/log.txt" || fail "the error does not say where"
[[ ! -e $tmp/none ]] || fail "a refused run wrote $tmp/none"
# RTL parameter sets: each set's tests on its own build tree; an unknown set and --tb refused.
cat >"$tmp/sets.json" <<'J'
{"rtl_params": {"w4": {"ZBLEND_RTL_WINDOW": 4}},
 "groups": {"g": [{"name": "t", "suite": "tiles", "rtl": ["default", "w4"]}]}}
J
echo '{"rtl_params": {"w4": {}}, "groups": {"bad": [{"name": "t", "suite": "tiles", "rtl": ["w5"]}]}}' >"$tmp/sets5.json"
"${regress[@]}" list g --file "$tmp/sets.json" --build "$tmp/b" >"$tmp/log.txt" 2>&1 || fail "list with parameter sets"
grep -q "^0	t-default	$tmp/b/zblend_tb --suite tiles" "$tmp/log.txt" &&
  grep -q "^1	t-w4	$tmp/b-w4/zblend_tb --suite tiles" "$tmp/log.txt" || fail "parameter sets' trees: $(cat "$tmp/log.txt")"
"${regress[@]}" list bad --file "$tmp/sets5.json" >"$tmp/log.txt" 2>&1
[[ $? -eq 2 ]] && grep -q "no RTL parameter set 'w5'" "$tmp/log.txt" || fail "an unknown parameter set is not refused"
"${regress[@]}" run g --file "$tmp/sets.json" --tb "$build/zblend_tb" --out "$tmp/none" >"$tmp/log.txt" 2>&1
[[ $? -eq 2 ]] && grep -q "each its own" "$tmp/log.txt" || fail "--tb with parameter sets is not refused"
echo "ok: RTL parameter sets: one tree each; unknown set and --tb refused"

"${regress[@]}" run nosuch >"$tmp/log.txt" 2>&1
[[ $? -eq 2 ]] && grep -q "no group 'nosuch'" "$tmp/log.txt" || fail "an unknown group is not refused"
echo "ok: malformed file and unknown group refused (exit 2)"
