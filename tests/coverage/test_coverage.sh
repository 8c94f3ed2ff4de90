#!/usr/bin/env bash
# The coverage plan on the RTL (docs/coverage.md): a bin hit with its stimulus goes unhit
# without it; the report refuses bad plans (exit 2), and fails (exit 1) on a cover no entry
# names and on a reason a test contradicts.
# Usage: test_coverage.sh BUILD
set -uo pipefail
source "$(dirname "$0")/../lib.sh"
build=$(cd "$1" && pwd)
root=$(cd "$(dirname "$0")/../.." && pwd)
here=$root/tests/coverage
plan=$root/tb/cov/coverage_plan.json
mkdir -p "$tmp/out"

regress() {  # GROUP: the group of groups.json through the runner, its coverage kept
  python3 "$root/scripts/regress.py" run "$1" --file "$here/groups.json" --coverage \
    --build "$build" --out "$tmp/$1" -j 1 >"$tmp/out.txt" 2>&1 || fail "regress $1"
}
report() {  # GROUP [ARGS...]: the closure report of the group's run; its exit status in $rc
  local g=$1; shift
  python3 "$root/scripts/coverage_report.py" "$tmp/$g" --group "$g" --smoke "$g" \
    --tests-file "$here/groups.json" "$@" >"$tmp/out.txt" 2>&1
  rc=$?
}
bin_hits() {  # RUN BIN: the bin's hits on the default set
  python3 -c "import json,sys
rows = json.load(open(sys.argv[1]))['bins']
print(next(r['hits'] for r in rows if r['set'] == 'default' and r['bin'] == sys.argv[2]))" \
    "$tmp/$1/closure.json" "$2"
}

# 1. With back-pressure a slot waits under stall_i; without it, never: the bin goes unhit.
stalled='window_slot[slot=0,event=WaitsStalled]'
regress stalls
report stalls
[[ $rc -eq 1 ]] || fail "a run of one test closes the plan? exit $rc"
[[ $(bin_hits stalls "$stalled") -gt 0 ]] || fail "$stalled unhit with back-pressure"
grep -q "^default window_slot\[slot=0,event=Waits\]" "$tmp/stalls/holes.txt" &&
  fail "the window suite left slot 0 without a waiting fragment"
grep -q '"first": "bp"' "$tmp/stalls/closure.json" || fail "no bin names its first test"
ok
regress calm
report calm
[[ $(bin_hits calm "$stalled") -eq 0 ]] || fail "$stalled hit without back-pressure"
grep -qF "default $stalled" "$tmp/calm/holes.txt" || fail "$stalled not listed as a hole"
ok

# 2. Bad plans: exit 2, one line, what and where.
bad() {  # NAME PATTERN PYTHON-EDIT: the plan edited, refused
  python3 -c "import json,sys
p = json.load(open(sys.argv[1])); E = {e['id']: e for e in p['entries']}; $3
json.dump(p, open(sys.argv[2], 'w'))" "$plan" "$tmp/plan.json" || fail "$1: the edit failed"
  expect_error "$1" "$2" python3 "$root/scripts/coverage_report.py" "$tmp/stalls" \
    --group stalls --smoke stalls --tests-file "$here/groups.json" --plan "$tmp/plan.json" \
    --out "$tmp/out/r"
}
echo '{"entries": [' >"$tmp/broken.json"
expect_error not-json "broken.json:2:1: not JSON" python3 "$root/scripts/coverage_report.py" \
  "$tmp/stalls" --group stalls --smoke stalls --tests-file "$here/groups.json" \
  --plan "$tmp/broken.json" --out "$tmp/out/r"
bad unknown-key "entries\[0\] \(pass_state\): unknown key\(s\) color" "E['pass_state']['color'] = 1"
bad dims "2 capture\(s\).*5 'dims'" "E['pass_state']['cover'] = 'u_cov.g_depth[*].g_dw[*].X'"
bad no-cover "plan entry frag_depth: no cover u_cov.FragDepthLow" \
  "E['frag_depth']['bins']['zero'] = 'u_cov.FragDepthLow'"
bad bad-regex "unreachable\[0\]: bad regular expression" \
  "E['frag_depth']['unreachable'] = [{'bins': '(', 'why': 'x'}]"
bad value "index 5 beyond the 5 values of dimension blend" \
  "E['pass_state']['dims'][2]['values'] = E['pass_state']['dims'][2]['values'][:5]"

# 3. A cover no entry names, and a reason a bin's hits contradict: exit 1, named.
python3 -c "import json,sys
p = json.load(open(sys.argv[1])); p['entries'] = [e for e in p['entries'] if e['id'] != 'frame_ops']
json.dump(p, open(sys.argv[2], 'w'))" "$plan" "$tmp/plan.json"
report stalls --plan "$tmp/plan.json"
[[ $rc -eq 1 ]] && grep -q "cover u_cov.StateWrite (set default) is in no plan entry" "$tmp/out.txt" ||
  fail "an unplanned cover passed (exit $rc)"
ok
python3 -c "import json,sys
p = json.load(open(sys.argv[1]))
e = next(e for e in p['entries'] if e['id'] == 'frame_ops')
e['unreachable'] = [{'bins': r'frame_ops\.state_write', 'why': 'never written'}]
json.dump(p, open(sys.argv[2], 'w'))" "$plan" "$tmp/plan.json"
report stalls --plan "$tmp/plan.json"
[[ $rc -eq 1 ]] && grep -q "frame_ops.state_write (set default) is written unreachable but bp hits it" \
  "$tmp/out.txt" || fail "a contradicted reason passed (exit $rc)"
ok
echo "coverage_plan: $pass passed"
