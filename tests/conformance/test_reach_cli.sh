#!/usr/bin/env bash
# zblend conformance reach: the suite's reach printed per entry, its totals at 100 % of the
# goals and of the kit-reachable plan bins but the five the plan calls unreachable (layers_insert
# position 4 on a pixel not full, a merge's saturation), at zb_rop's tile and at 16 x 16, the JSON
# per test, the ranking; bad input exit 2, one line, nothing written.
set -u
zblend=${1:?usage: test_reach_cli.sh PATH/TO/zblend}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
bad() { echo "FAIL: $*"; fail=1; }

for tile in 64x64 16x16; do
  "$zblend" conformance reach --tile $tile >"$tmp/r.txt" || bad "reach --tile $tile exited $?"
  grep -q "^reach of 224 tests at tile $tile, window 8, gap 0 %" "$tmp/r.txt" || bad "$tile: no heading"
  grep -qE "^pass_state +3456 +3456$" "$tmp/r.txt" || bad "$tile: not every pass state"
  grep -qE "^goal.state_relation +10368 +10368$" "$tmp/r.txt" || bad "$tile: not every state and relation"
  grep -qE "^suite goals: 11142 of 11142 " "$tmp/r.txt" || bad "$tile: goals: $(grep goals "$tmp/r.txt")"
done
# At gap 0 a Gap distance comes only from a load or a pass between: 16 x 16 tiles make them all.
# All but pass_resident.boundary, which only the resident schedule (below) reaches, and the five.
grep -q "^plan bins a DUT reaches through the kit: 3571 of 3577 " "$tmp/r.txt" || bad "16x16: plan bins"
"$zblend" conformance reach --gap 20 --schedule resident --json "$tmp/r.json" --rank --holes >"$tmp/g.txt" ||
  bad "reach --gap 20 exited $?"
grep -q "^plan bins a DUT reaches through the kit: 3572 of 3577 " "$tmp/g.txt" || bad "gap 20: plan bins"
grep -q "^  states-alpha " "$tmp/g.txt" || bad "no ranking"
python3 - "$tmp/r.json" <<'PY' || bad "the JSON"
import json, sys
j = json.load(open(sys.argv[1]))
assert j["gap"] == 20 and j["resident"] and len(j["plan_bins"]) == 3577, (j["gap"], len(j["plan_bins"]))
assert len(j["tests"]) == 224 and j["tests"]["cad-opaque"]["frame_ops.state_write"] >= 1
assert all(b in j["plan_bins"] + j["goal_bins"] for t in j["tests"].values() for b in t), "an unlisted bin"
PY
one_line() {  # want, command...
  local want=$1
  shift
  "$@" >"$tmp/out" 2>"$tmp/err"
  local rc=$?
  [[ $rc == 2 ]] || bad "exit $rc, want 2: $*"
  grep -q -- "$want" "$tmp/err" || bad "no '$want' in: $(cat "$tmp/err")"
  [[ $(wc -l <"$tmp/err") == 1 ]] || bad "more than one line: $*"
}
one_line "--tile: '0x16' is not WxH" "$zblend" conformance reach --tile 0x16
one_line "--tile: '16' is not WxH" "$zblend" conformance reach --tile 16
one_line "--gap: 99 is outside 0 to 95" "$zblend" conformance reach --gap 99
one_line "--window: 0 is outside 1 to 64" "$zblend" conformance reach --window 0
mkdir "$tmp/dir.json"
one_line "--json" "$zblend" conformance reach --json "$tmp/dir.json"
one_line "--schedule" "$zblend" conformance reach --schedule tiles
[[ $fail -eq 0 ]] && echo "reach: every reachable bin at 64x64 and 16x16, the JSON, the ranking, bad input"
exit $fail
