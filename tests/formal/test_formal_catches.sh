#!/usr/bin/env bash
# The formal checkers can fail: scripts/formal.sh --defect injects each known defect (a wrong
# rounding in the arithmetic specifications, a broken multiplier contract, a skid register that
# drops a fragment, depth forwarding, colour bypass and the issue interlock disabled) and every
# one must end in a failed proof with a counterexample VCD. Also the usage errors (exit 2).
set -u
root=${1:?usage: test_formal_catches.sh PROJECT_ROOT OUT_DIR}
out=${2:?usage: test_formal_catches.sh PROJECT_ROOT OUT_DIR}
fail() { echo "FAIL: $*" >&2; exit 1; }
formal="$root/scripts/formal.sh"

for args in "--bogus" "--out" "--only nothing-like-this" "--timeout x"; do
  # shellcheck disable=SC2086
  "$formal" $args >/dev/null 2>&1
  rc=$?
  [[ $rc == 2 ]] || fail "formal.sh $args exited $rc, want 2"
done
"$formal" --help | grep -q '^usage: scripts/formal.sh' || fail "formal.sh --help prints no usage"

"$formal" --defect --ci --out "$out" || fail "scripts/formal.sh --defect exited $?: a defect was missed ($out/report.md)"
n=$(tail -n +2 "$out/summary.csv" | wc -l)
(( n >= 8 )) || fail "only $n defects ran"
missed=$(awk -F, 'NR > 1 && ($5 != "caught" || $8 == "")' "$out/summary.csv")
[[ -z $missed ]] || fail "defects not caught with a counterexample: $missed"
for row in $(tail -n +2 "$out/summary.csv" | cut -d, -f8); do
  [[ -s $row ]] || fail "counterexample $row is empty"
done
echo "ok: $n defects caught, each with a counterexample ($out/summary.csv)"
