#!/usr/bin/env bash
# scripts/conformance.py as an outside team meets it, on Icarus (instant builds):
#  - a corrupt suite (a truncated stream.hex), an earlier suite version, a misspelt feature, a
#    profile key it does not know, a --tests glob naming nothing: exit 2, one line, no run;
#  - selection by glob and by feature, --list, NOT SUPPORTED counted apart, results.json and
#    junit.xml (read with Python's parsers);
#  - a DUT breaking the adapter's rules (tests/conformance/duts): a store pixel outside a store, an
#    unknown frag_ready_o, a hang: each a failure naming the port and rule or the watchdog, with
#    a reproduce command; a simulation past --timeout killed, its output kept.
#   test_kit_cli.sh SUITE OUT ZBLEND
set -u
suite=${1:?usage: test_kit_cli.sh SUITE OUT ZBLEND} out=$2 zblend=$3
root=$(cd "$(dirname "$0")/../.." && pwd)
duts=$root/tests/conformance/duts
fail() { echo "FAIL: $*" >&2; exit 1; }
rm -rf "$out"
mkdir -p "$out"
conf() { python3 "$root/scripts/conformance.py" --sim icarus --zblend "$zblend" -j 2 "$@"; }

# Bad input: exit 2 and one line naming the problem, before any build.
bad_input() {  # WANT-IN-MESSAGE ARGS...
  local want=$1
  shift
  conf "$@" >"$out/bad.txt" 2>&1
  local rc=$?
  [[ $rc == 2 ]] || fail "exit $rc, want 2, for: $*"
  grep -q "$want" "$out/bad.txt" || fail "no '$want' in: $(cat "$out/bad.txt")"
  [[ $(wc -l <"$out/bad.txt") == 1 ]] || fail "more than one line for: $*"
  [[ -e $out/run/build ]] && fail "a build started for bad input: $*"
  return 0
}
cp -r "$suite" "$out/suite"
s=$out/suite
truncate -s -40 "$s/hazard/stream.hex"
bad_input "corrupt suite: .*hazard/stream.hex: SHA-256" --suite "$s" --out "$out/run"
cp "$suite/hazard/stream.hex" "$s/hazard/stream.hex"
sed -i 's/"version": 8/"version": 7/' "$s/manifest.json"
bad_input "suite version 7 is refused: at 16 and 32 bits it has none of the tests" --suite "$s" --out "$out/run"
sed -i 's/"version": 7/"version": 5/' "$s/manifest.json"
bad_input "suite version 5 is refused: it has no tiers and none of the tests generated" --suite "$s" --out "$out/run"
sed -i 's/"version": 5/"version": 4/' "$s/manifest.json"
bad_input "suite version 4 is refused: it has no per-test features" --suite "$s" --out "$out/run"
echo '{"features": ["*"], "sources": ["x.sv"], "resident_tile": "yes"}' >"$out/resident.json"
touch "$out/x.sv"
bad_input "resident_tile: 'yes' is not true or false" --suite "$suite" --out "$out/run" --profile "$out/resident.json"
echo '{"features": ["*"], "sources": ["x.sv"]}' >"$out/flat.json"
bad_input "schedule resident: the profile .* does not say" --suite "$suite" --out "$out/run" --profile "$out/flat.json" --schedule resident
bad_input "feature 'blend.alfa' .* names no feature" --suite "$suite" --out "$out/run" --features blend.alfa
echo '{"features": ["*"], "source": []}' >"$out/typo.json"
bad_input "unknown key 'source'" --suite "$suite" --out "$out/run" --profile "$out/typo.json"
bad_input "'cad-nothing\*' names no test" --suite "$suite" --out "$out/run" --tests 'cad-nothing*'

# --list: globs and a feature select; the profile splits supported from NOT SUPPORTED.
conf --suite "$suite" --out "$out/run" --list --tests 'cad-*,random' --feature blend.alpha \
  --features 'blend.replace,blend.alpha,depth_func.*,depth_write,color_mask,depth_bits.*,coverage_samples.*' \
  >"$out/list.txt" || fail "--list exited $?"
grep -q "^supported *cad-three-pass " "$out/list.txt" || fail "--list: cad-three-pass not supported"
grep -q "^NOT SUPPORTED *cad-facing-additive *needs blend.additive$" "$out/list.txt" ||
  fail "--list: cad-facing-additive not NOT SUPPORTED for blend.additive"
grep -q "^NOT SUPPORTED *random *needs .*blend.coverage.*peel_test" "$out/list.txt" ||
  fail "--list: random not NOT SUPPORTED"
grep -q "cad-opaque\|cad-coverage-aa" "$out/list.txt" && fail "--list: a test without an alpha blend listed"
grep -q "^5 of 7 selected tests supported by the profile (--features) and the adapter (version 7)$" "$out/list.txt" ||
  fail "--list: the count line: $(tail -1 "$out/list.txt")"

# A suite archive is unpacked, checked and listed alike.
tar czf "$out/suite.tar.gz" -C "$(dirname "$suite")" "$(basename "$suite")"
conf --suite "$out/suite.tar.gz" --out "$out/arc" --list --tests 'cad-*,random' --feature blend.alpha \
  --features 'blend.replace,blend.alpha,depth_func.*,depth_write,color_mask,depth_bits.*,coverage_samples.*' \
  >"$out/list-arc.txt" || fail "--list of the archive exited $?"
cmp -s "$out/list.txt" "$out/list-arc.txt" || fail "the archive lists differently: $(diff "$out/list.txt" "$out/list-arc.txt")"

# A run: two tests pass on zb_rop, one NOT SUPPORTED; results as data.
conf --suite "$suite" --out "$out/run" --tests 'cad-three-pass,cad-opaque,cad-coverage-aa' \
  --features 'blend.replace,blend.alpha,depth_func.*,depth_write,color_mask,depth_bits.*,coverage_samples.*' \
  --param TILE_W=32 --param TILE_H=32 >"$out/run.txt" 2>&1 || fail "the run exited $?: $(tail -5 "$out/run.txt")"
grep -q "^conformance: 2 pass, 0 fail, 1 not supported, 0 timeout, of 3 tests" "$out/run.txt" ||
  fail "the summary line: $(grep 'pass,' "$out/run.txt")"
python3 - "$out/run" <<'PY' || fail "results.json or junit.xml"
import json, sys, xml.etree.ElementTree as ET
d = sys.argv[1]
r = json.load(open(f"{d}/results.json"))
v = {t["name"]: t["verdict"] for t in r["tests"]}
assert v == {"cad-opaque": "pass", "cad-three-pass": "pass", "cad-coverage-aa": "not_supported"}, v
assert r["counts"] == {"pass": 2, "cts_pass": 0, "fail": 0, "not_supported": 1, "timeout": 0, "not_run": 0}, r["counts"]
assert r["suite_version"] == 8 and r["timing"] == "tight" and r["schedule"] == "resident"
s = ET.parse(f"{d}/junit.xml").getroot().find("testsuite")
assert (s.get("tests"), s.get("failures"), s.get("skipped")) == ("3", "0", "1"), s.attrib
sk = [c.get("name") for c in s.iter("testcase") if c.find("skipped") is not None]
assert sk == ["cad-coverage-aa"], sk
assert "blend.coverage" in s.find("testcase[@name='cad-coverage-aa']/skipped").get("message")
PY
[[ -e $out/run/cad-coverage-aa/sim.log ]] && fail "a NOT SUPPORTED test was run"

# Broken DUTs: a named failure, verdict fail, a reproduce command.
broken() {  # DEFINE WANT-IN-SIM-LOG (a grep pattern) WANT-IN-RESULT (a string)
  local o=$out/broken-$1
  conf --suite "$suite" --out "$o" --profile "$duts/broken.profile.json" --tests cad-opaque \
    --define "$1" --watchdog 300 >"$o.txt" 2>&1
  local rc=$?
  [[ $rc == 1 ]] || fail "$1: exit $rc, want 1"
  grep -q "$2" "$o/cad-opaque/sim.log" || fail "$1: no '$2' in its sim.log: $(tail -3 "$o/cad-opaque/sim.log")"
  grep -q "^conformance: reproduce: python3 .* --tests cad-opaque --waves$" "$o.txt" ||
    fail "$1: no reproduce command"
  python3 -c "import json,sys; t=json.load(open(sys.argv[1]))['tests'][0]; assert t['verdict']=='fail' and sys.argv[2] in t['message'], t" \
    "$o/results.json" "$3" || fail "$1: results.json"
}
broken BROKEN_ST_VALID "zb_conf: PROTOCOL: cycle [0-9]*: st_valid_o: high with no store under way" \
  "st_valid_o: high with no store under way"
broken BROKEN_X "zb_conf: PROTOCOL: cycle [0-9]*: frag_ready_o: is X or Z" "frag_ready_o: is X or Z"
broken BROKEN_HANG "zb_conf: WATCHDOG: 300 cycles without progress at cycle [0-9]*, pass 0, tile (0, 0), fragment 0 of the pass: waiting for frag_ready_o (frag_valid_i=1 frag_ready_o=0" \
  "WATCHDOG: 300 cycles without progress"

# --first-fail: one test at a time in suite order, the run stops at the first that fails, the rest
# reported not_run (results.json and junit.xml's skipped).
o=$out/first-fail
conf --suite "$suite" --out "$o" --profile "$duts/broken.profile.json" \
  --tests 'cad-opaque,cad-three-pass,cad-hidden-line' --define BROKEN_X --first-fail >"$o.txt" 2>&1
[[ $? == 1 ]] || fail "--first-fail: exit, want 1"
python3 - "$o" <<'PY' || fail "--first-fail: results"
import json, sys, xml.etree.ElementTree as ET
r = json.load(open(f"{sys.argv[1]}/results.json"))
v = [t["verdict"] for t in r["tests"]]
assert v == ["fail", "not_run", "not_run"], v
assert ET.parse(f"{sys.argv[1]}/junit.xml").getroot().find("testsuite").get("skipped") == "2"
PY
[[ -e $o/cad-three-pass/sim.log ]] && fail "--first-fail: a test after the failure ran"
grep -q "2 not run (--first-fail)" "$o.txt" || fail "--first-fail: the summary does not count the tests not run"

# --timeout: the hang with the watchdog out of reach is killed, its output kept.
o=$out/timeout
conf --suite "$suite" --out "$o" --profile "$duts/broken.profile.json" --tests cad-opaque \
  --define BROKEN_HANG --watchdog 2000000000 --timeout 3 >"$o.txt" 2>&1
[[ $? == 1 ]] || fail "--timeout: exit, want 1"
grep -q "^conformance: \[1/1\] TIMEOUT cad-opaque" "$o.txt" || fail "--timeout: no TIMEOUT line"
grep -q "^zb_conf: planes: color depth coverage peel$" "$o/cad-opaque/sim.log" ||
  fail "--timeout: the simulator's output was not kept"
grep -q "^conformance: killed after 3.0 s (--timeout)" "$o/cad-opaque/sim.log" || fail "--timeout: sim.log does not say it was killed"
python3 -c "import json,sys; assert json.load(open(sys.argv[1]))['counts']['timeout'] == 1" "$o/results.json" ||
  fail "--timeout: results.json"
echo "ok: bad suites and profiles refused; selection, NOT SUPPORTED, results.json, junit.xml; protocol, X, watchdog and timeout caught; --first-fail stops at the first failure"
