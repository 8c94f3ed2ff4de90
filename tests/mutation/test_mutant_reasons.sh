#!/usr/bin/env bash
# Written reasons (tb/mutation/reasons.json, scripts/mutant_reasons.py): every reason covers at
# least one mutant of the netlist; a malformed file is refused with exit 2; and a reason that
# claims a killable mutant (mutant 412, which the first test kills: mutation_caught's) fails the
# run with exit 1, naming the reason, the mutant and the test.
set -u
build=${1:?usage: test_mutant_reasons.sh BUILD_DIR}
root=$(cd "$(dirname "$0")/../.." && pwd)
source "$(dirname "$0")/../lib.sh"

python3 -c "
import sys; sys.path.insert(0, '$root/scripts')
from mutant_reasons import Reasons
r = Reasons('$root/tb/mutation/reasons.json')
r.count([l.strip() for l in open('$build/tb/mutation/mutations.txt') if l.strip()])
print('stale:', r.stale())
sys.exit(1 if r.stale() else 0)" >"$tmp/out.txt" 2>&1 || fail "tb/mutation/reasons.json has reasons that match no mutant"
echo "ok: every reason in tb/mutation/reasons.json matches a mutant of the netlist"

printf '{"reasons": [{"id": "x", "kind": "equivalent", "match": ["a"]}]}\n' >"$tmp/bad.json"
python3 "$root/scripts/mutate.py" --build "$build" --reasons "$tmp/bad.json" --out "$tmp/o" >"$tmp/out.txt" 2>&1
rc=$?
[[ $rc -eq 2 ]] || fail "a reason without 'why': exit $rc, want 2"
grep -q "reasons\[0\]: 'why' is missing" "$tmp/out.txt" || fail "the error does not name the missing field"
echo "ok: a malformed reasons file is refused: $(tail -1 "$tmp/out.txt")"

python3 - "$build/tb/mutation/mutations.txt" "$tmp/wrong.json" <<'PY'
import json, re, sys
first = open(sys.argv[1]).read().splitlines()[411].strip()
json.dump({"reasons": [{"id": "claims-mutant-412", "kind": "unobservable",
                        "match": ["^" + re.escape(first) + "$"], "why": "wrong on purpose"}]},
          open(sys.argv[2], "w"))
PY
python3 "$root/scripts/mutate.py" --build "$build" --reasons "$tmp/wrong.json" --mutants 412 \
  --group quick --no-equiv --no-full -j 1 --out "$tmp/run" >"$tmp/out.txt" 2>&1
rc=$?
[[ $rc -eq 1 ]] || fail "a reason contradicted by a kill: exit $rc, want 1"
grep -qE 'written reasons that a test contradicts .*claims-mutant-412 \(mutant 412, killed by rtl_[a-z_]+\)' "$tmp/out.txt" ||
  fail "no 'written reasons that a test contradicts ... claims-mutant-412 (mutant 412, killed by ...)' line"
grep -q '^\*\*Wrong reasons\*\*' "$tmp/run/report.md" || fail "report.md does not list the wrong reason"
echo "ok: a reason a test contradicts fails the run: $(grep -o 'claims-mutant-412 (.*)' "$tmp/out.txt")"
