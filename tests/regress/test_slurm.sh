#!/usr/bin/env bash
# The regression runner through Slurm: a single-node Slurm on this machine (scripts/slurm_local.sh,
# localhost only), the smoke group as an sbatch array job, the results gathered into JUnit XML and
# the HTML summary; then every daemon the test started is stopped, and checked gone.
# Usage: test_slurm.sh BUILD
set -u
build=$(realpath "${1:?usage: test_slurm.sh BUILD}")
root=$(cd "$(dirname "$0")/../.." && pwd)
tmp=$(mktemp -d)
dir=$tmp/slurm
stopped=0
cleanup() {
  [[ $stopped -eq 1 ]] || "$root/scripts/slurm_local.sh" stop "$dir" >/dev/null 2>&1
  rm -rf "$tmp"
}
trap cleanup EXIT
fail() { echo "FAIL: $*"; [[ -f $tmp/log.txt ]] && { echo "--- output:"; tail -30 "$tmp/log.txt"; }; exit 1; }
cd "$root"

conf=$("$root/scripts/slurm_local.sh" start "$dir") || fail "the local Slurm did not start: $conf"
export "${conf?}"
echo "ok: Slurm up: $(sinfo -h -o '%P %D %t %N')"
n=$(python3 scripts/regress.py list smoke | wc -l)
python3 scripts/regress.py slurm smoke --submit --build "$build" --out "$tmp/out" >"$tmp/log.txt" 2>&1 ||
  fail "the smoke group through Slurm failed"
python3 - "$tmp/out" "$n" <<'PY' || fail "the gathered results are not the smoke group's"
import json, os, sys, xml.etree.ElementTree as ET
out, n = sys.argv[1], int(sys.argv[2])
cases = ET.parse(os.path.join(out, "junit.xml")).getroot().findall(".//testcase")
assert len(cases) == n and not any(c.find("failure") is not None for c in cases), len(cases)
s = json.load(open(os.path.join(out, "summary.json")))
assert s["tests"] == n and s["passed"] == n, s
outs = os.listdir(os.path.join(out, "slurm"))
assert len(outs) == n, f"{len(outs)} array task logs, want {n}"
for r in s["results"]:
    assert r["seconds"] > 0 and r["host"], r
PY
grep -q "sbatch job [0-9]* ended (exit 0)" "$tmp/log.txt" || fail "no sbatch job in the log"
echo "ok: smoke through Slurm: $n array tasks, all passed, JUnit and HTML gathered"

"$root/scripts/slurm_local.sh" stop "$dir" || fail "a daemon survived the stop"
stopped=1
left=$(pgrep -f "$dir" || true)
[[ -z $left ]] || fail "processes of the test's Slurm still running: $left"
echo "ok: munged, slurmctld and slurmd stopped"
