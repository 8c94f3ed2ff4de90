#!/usr/bin/env bash
# The defect catalogue of conformance/ref (defects.json, README.md "Defect catalogue"): each
# defect is a define on one of the two reference DUTs, the kind of mistake an RTL engineer makes
# writing a ROP from docs/datapath.md. This runs each through scripts/conformance.py with its
# variant's profile and its define, and requires the suite to catch it.
#   test_ref_defects.sh SUITE OUT ZBLEND [conformance.py args...] [-- NAME...]
#       every named defect (all when none is named), each into OUT/<name>; caught when
#       conformance.py exits 1 with at least one test `fail` or `timeout` in
#       OUT/<name>/results.json. One line a defect, `caught NAME by TEST (N of M tests failed)` or
#       `MISSED NAME ...`, then `N passed, M failed` (passed = caught); exit 1 if any is missed,
#       2 on bad input. --sim verilator unless the args name a simulator.
#   test_ref_defects.sh list
#       the catalogue: name, variant, category, define, and what exposes it
# Environment: CONFORMANCE_PY, the conformance.py to run (default: this repository's);
# REF_PROFILES, the folder of the variants' profiles (default: conformance/ref).
set -u
root=$(cd "$(dirname "$0")/../.." && pwd)
catalogue=$root/conformance/ref/defects.json
conformance_py=${CONFORMANCE_PY:-$root/scripts/conformance.py}
profiles=${REF_PROFILES:-$root/conformance/ref}
usage() {
  echo "usage: test_ref_defects.sh SUITE OUT ZBLEND [conformance.py args...] [-- NAME...] | list" >&2
  exit 2
}

# One field of a defect, or the names of them all.
field() {
  python3 -c 'import json,sys
for d in json.load(open(sys.argv[1])):
    if d["name"] == sys.argv[2]: print(d[sys.argv[3]])' "$catalogue" "$1" "$2"
}
all_names() { python3 -c 'import json,sys; print(" ".join(d["name"] for d in json.load(open(sys.argv[1]))))' "$catalogue"; }

if [[ ${1:-} == list ]]; then
  python3 -c 'import json,sys
ds = json.load(open(sys.argv[1]))
for d in ds:
    print("%-24s %-5s %-14s %s" % (d["name"], d["variant"], d["category"], d["define"]))
    print("%-24s shows when: %s" % ("", d["shows_when"]))
print("%d defects" % len(ds))' "$catalogue"
  exit 0
fi

[[ $# -ge 3 ]] || usage
suite=$1 out=$2 zblend=$3
shift 3
args=() names=()
while [[ $# -gt 0 ]]; do
  if [[ $1 == -- ]]; then
    shift
    names=("$@")
    break
  fi
  args+=("$1")
  shift
done
[[ " ${args[*]} " == *" --sim "* || " ${args[*]} " == *" --sim="* ]] || args+=(--sim verilator)
if [[ ${#names[@]} -eq 0 ]]; then
  read -r -a names <<<"$(all_names)"
fi
for n in "${names[@]}"; do
  [[ -n $(field "$n" define) ]] || { echo "test_ref_defects: no defect '$n' in $catalogue" >&2; exit 2; }
done
mkdir -p "$out" || exit 2

# The first failing test and the counts, from results.json: "TEST N M", or nothing.
verdicts() {
  python3 -c 'import json,sys
r = json.load(open(sys.argv[1]))
bad = [t["name"] for t in r["tests"] if t["verdict"] in ("fail", "timeout")]
ran = [t for t in r["tests"] if t["verdict"] in ("pass", "fail", "timeout")]
print((bad[0] if bad else "-"), len(bad), len(ran))' "$1" 2>/dev/null
}

passed=0 failed=0
for n in "${names[@]}"; do
  define=$(field "$n" define) profile=$profiles/$(field "$n" profile)
  dir=$out/$n
  rm -rf "$dir"
  mkdir -p "$dir"
  t0=$SECONDS
  python3 "$conformance_py" --suite "$suite" --out "$dir" --profile "$profile" --define "$define" \
    --zblend "$zblend" "${args[@]}" >"$dir/log.txt" 2>&1
  rc=$?
  secs=$((SECONDS - t0))
  read -r first nbad nran <<<"$(verdicts "$dir/results.json")"
  if [[ $rc == 1 && -n ${nbad:-} && $nbad -gt 0 ]]; then
    echo "caught $n by $first ($nbad of $nran tests failed; ${secs} s)"
    passed=$((passed + 1))
  elif [[ -n ${nran:-} ]]; then
    echo "MISSED $n (0 of $nran tests failed; conformance.py exited $rc; ${secs} s)"
    failed=$((failed + 1))
  else
    echo "MISSED $n (conformance.py exited $rc, no results: $(tail -n 1 "$dir/log.txt"))"
    failed=$((failed + 1))
  fi
done
echo "$passed passed, $failed failed"
[[ $failed == 0 ]]
