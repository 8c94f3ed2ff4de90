#!/usr/bin/env bash
# The CI-sized formal set (scripts/formal.sh --ci) passes: every job proven, bounded or reached,
# in summary.csv and report.md, with each job's log.
set -u
root=${1:?usage: test_formal_ci.sh PROJECT_ROOT OUT_DIR}
out=${2:?usage: test_formal_ci.sh PROJECT_ROOT OUT_DIR}
fail() { echo "FAIL: $*" >&2; exit 1; }

"$root/scripts/formal.sh" --ci --out "$out" || fail "scripts/formal.sh --ci exited $? ($out/report.md)"
[[ -f $out/summary.csv && -f $out/report.md ]] || fail "no summary.csv or report.md in $out"
rows=$(tail -n +2 "$out/summary.csv")
[[ -n $rows ]] || fail "summary.csv lists no job: nothing was checked"
bad=$(awk -F, 'NR > 1 && $4 != "proven" && $4 != "bounded" && $4 != "reached"' "$out/summary.csv")
[[ -z $bad ]] || fail "jobs not passed: $bad"
for group in mul8 premul blend resolve skid stream raw covers; do
  grep -q "^$group" "$out/summary.csv" || fail "group $group missing from the CI set"
done
echo "ok: $(wc -l <<<"$rows") formal jobs passed ($out/summary.csv)"
