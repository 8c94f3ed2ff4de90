#!/usr/bin/env bash
# The regression runner's GNU parallel path through ssh: two test hosts on this machine
# (scripts/ssh_hosts.sh: network namespaces, each with its own sshd; the file system is shared),
# the quick group through them. The joblog must put every job on one of the two hosts and none on
# this machine, each host must have run some and its sshd logged them in, and the gathered JUnit
# XML and summary must be the group's. Then the path must catch failures: a failing test (a mutant)
# and a host whose sshd is gone, each a FAIL and exit 1. Last, the hosts are stopped and checked
# gone; a trap stops them on any failure, and a run killed outright is cleaned by the next.
# Usage: test_ssh.sh BUILD [WORK]   (zblend_tb and zblend_tb_mut built in BUILD; each run's hosts
# and output in WORK/run.PID, default WORK BUILD/regress/ssh, removed when it passes). Needs root.
set -euo pipefail
build=$(realpath "${1:?usage: test_ssh.sh BUILD [WORK]}")
work=$(realpath -m "${2:-$build/regress/ssh}")
root=$(cd "$(dirname "$0")/../.." && pwd)
hosts_sh=$root/scripts/ssh_hosts.sh
run=$work/run.$$
dir=$run/hosts
regress=(python3 "$root/scripts/regress.py")
stopped=0
cleanup() {
  [[ $stopped -eq 1 ]] || "$hosts_sh" stop "$dir" >/dev/null 2>&1 || true
}
trap cleanup EXIT
trap 'exit 130' INT
trap 'exit 143' TERM
fail() {
  echo "FAIL: $*"
  [[ -f $run/log.txt ]] && { echo "--- output (all of it in $run):"; tail -30 "$run/log.txt"; }
  exit 1
}
# listening NS ADDR: what listens on ADDR's port 22 inside the namespace NS.
listening() { nsenter --net="/run/netns/$1" ss -Hltn "src $2:22"; }
# check_run OUT N HOSTS_DIR ADDR...: prints the jobs per host; exits 1 saying what is wrong.
check_run() {
  python3 - "$@" <<'PY'
import collections, json, os, re, sys, xml.etree.ElementTree as ET
out, n, hosts_dir, addrs = sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[4:]
cases = ET.parse(os.path.join(out, "junit.xml")).getroot().findall(".//testcase")
assert len(cases) == n and not any(c.find("failure") is not None for c in cases), len(cases)
s = json.load(open(os.path.join(out, "summary.json")))
assert s["tests"] == n and s["passed"] == n, s
assert "100.0 % passed" in open(os.path.join(out, "summary.html")).read()
# The joblog: Seq, Host, Starttime, JobRuntime, Send, Receive, Exitval, Signal, Command.
rows = [ln.split("\t") for ln in open(os.path.join(out, "joblog")).read().splitlines()[1:]]
assert len(rows) == n, f"{len(rows)} jobs in the joblog, want {n}"
per_host = collections.Counter()
for r in rows:
    m = re.fullmatch(r"ssh -F \S+/ssh_config root@(\S+)", r[1])
    assert m and m.group(1) in addrs, f"job {r[0]} ran on '{r[1]}', not on a test host"
    assert r[6] == "0" and r[7] == "0", f"job {r[0]}: exit {r[6]}, signal {r[7]}"
    per_host[m.group(1)] += 1
assert all(per_host[a] >= 1 for a in addrs), f"jobs per host: {dict(per_host)}"
# Each host's sshd logged in every job it ran (and start's own check).
for i, a in enumerate(addrs, 1):
    log = open(os.path.join(hosts_dir, f"sshd-{i}.log")).read()
    logins = len(re.findall(r"Accepted publickey for root from ", log))
    assert logins >= per_host[a] + 1, f"{a}: {logins} logins for {per_host[a]} jobs"
print(", ".join(f"{per_host[a]} on {a}" for a in addrs))
PY
}

cd "$root"

# A run killed outright (kill -9, a CTest time-out) leaves its sshds, namespaces and output: stop
# and remove them, unless that run is still going.
for old in "$work"/run.*; do
  [[ -d $old ]] || continue
  grep -qs test_ssh.sh "/proc/${old##*.}/cmdline" && continue
  "$hosts_sh" stop "$old/hosts" >/dev/null 2>&1 || fail "the hosts of an earlier run in $old do not stop"
  rm -rf "$old"
done
mkdir -p "$run"
"$hosts_sh" start "$dir" 2 >"$run/log.txt" 2>&1 || fail "the test hosts did not start"
mapfile -t addrs < <(awk '{print $4}' "$dir/hosts")
mapfile -t namespaces < <(awk '{print $2}' "$dir/hosts")
[[ ${#addrs[@]} -eq 2 ]] || fail "want 2 hosts, have: ${addrs[*]}"
# Each sshd listens in its namespace only: nothing here answers on the hosts' addresses.
for i in 0 1; do
  [[ -n $(listening "${namespaces[i]}" "${addrs[i]}") ]] ||
    fail "no sshd listening in ${namespaces[i]} on ${addrs[i]}"
  [[ -z $(ss -Hltn "src ${addrs[i]}") ]] || fail "something listens on ${addrs[i]} outside its namespace"
done
echo "ok: 2 test hosts up: ${addrs[*]}"

# The quick group through both hosts, one job at a time on each.
n=$("${regress[@]}" list quick | wc -l)
"${regress[@]}" parallel quick -j 1 --build "$build" --sshloginfile "$dir/sshloginfile" \
  --out "$run/out-ok" >"$run/log.txt" 2>&1 || fail "the quick group through ssh failed"
check_run "$run/out-ok" "$n" "$dir" "${addrs[@]}" >"$run/check.txt" 2>&1 ||
  fail "the run through ssh: $(tail -1 "$run/check.txt")"
echo "ok: quick through ssh: $n jobs ($(cat "$run/check.txt")), all passed, JUnit and HTML gathered"

# A failing test through ssh: the mutant the clears suite's lock-step monitor catches.
cat >"$run/g.json" <<'J'
{"groups": {"g": [
  {"name": "clears", "suite": "clears", "seeds": [1]},
  {"name": "window", "args": ["--suite", "window", "--seed", "1"]}]}}
J
rc=0
"${regress[@]}" parallel g -j 1 --file "$run/g.json" --build "$build" --tb "$build/zblend_tb_mut" \
  --tb-args "--mutant 38" --sshloginfile "$dir/sshloginfile" --out "$run/out-bad" \
  >"$run/log.txt" 2>&1 || rc=$?
[[ $rc -eq 1 ]] || fail "a failing test through ssh: exit $rc, want 1"
if ! grep -q '^regress: g: 1/2 passed, 1 FAILED' "$run/log.txt" ||
  ! grep -q '^regress: FAIL clears: LOCKSTEP MISMATCH' "$run/log.txt"; then
  fail "no FAIL line for the mutant's lock-step mismatch"
fi
grep -q 'failures="1"' "$run/out-bad/junit.xml" || fail "JUnit: want 1 failure"
echo "ok: a failing test through ssh: exit 1, reported with its mismatch"

# A host whose sshd is gone: its job dies in ssh (exit 255), leaves no result, and is reported.
dead=${addrs[1]}
kill "$(cat "$dir/sshd-2.pid")" || fail "no sshd to stop on $dead"
for _ in $(seq 50); do
  [[ -n $(listening "${namespaces[1]}" "$dead") ]] || break
  sleep 0.1
done
[[ -z $(listening "${namespaces[1]}" "$dead") ]] || fail "the sshd on $dead does not stop"
grep " root@$dead\$" "$dir/sshloginfile" >"$run/dead.slf"
rc=0
"${regress[@]}" parallel g -j 1 --file "$run/g.json" --build "$build" \
  --sshloginfile "$run/dead.slf" --out "$run/out-dead" >"$run/log.txt" 2>&1 || rc=$?
[[ $rc -eq 1 ]] || fail "a host down: exit $rc, want 1"
grep -q '^regress: g: 0/2 passed, 2 FAILED' "$run/log.txt" || fail "a host down: want 2 failures"
grep -q "^regress: FAIL window: no result: its job on root@$dead exited 255" "$run/log.txt" ||
  fail "a host down: the failure does not name the host and ssh's exit"
echo "ok: a host down: exit 1, its jobs reported with the host"

# Stop: no sshd, namespace or veth of the test may be left.
"$hosts_sh" stop "$dir" >"$run/log.txt" 2>&1 || fail "the test hosts did not stop"
stopped=1
left=$(pgrep -af -- "$dir/" || true)
[[ -z $left ]] || fail "processes of the test hosts still running: $left"
for ns in "${namespaces[@]}"; do
  [[ ! -e /run/netns/$ns ]] || fail "namespace $ns is left"
done
for a in "${addrs[@]}"; do
  [[ -z $(ip -4 -o addr show to "${a%.*}.1/32") ]] || fail "the veth of $a is left"
done
echo "ok: sshds, namespaces and veths gone"
rm -rf "$run"
