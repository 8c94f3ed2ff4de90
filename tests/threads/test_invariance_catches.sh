#!/usr/bin/env bash
# check_invariance.py fails on a zblend whose counters or images change with the thread count,
# naming the file and the place, and passes one whose host time and memory alone change.
# Usage: test_invariance_catches.sh zblend work_dir
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
zblend=$1
work=$2
fails=0
run() {  # change: what fake_zblend.py changes at --threads 3
  FAKE_CHANGE=$1 python3 "$here/check_invariance.py" --zblend "$here/fake_zblend.py" \
    --out "$work/$1" --threads 1,3 -- "$zblend" render --scene quads --method opaque,three-pass \
    --width 160 --height 120 --backend both --out-dir '{out}' --stats '{out}/stats.json'
}
expect_fail() {  # change, pattern the report must hold
  local log
  log=$(run "$1" 2>&1)
  if [[ $? -ne 1 ]] || ! grep -q -- "$2" <<<"$log"; then
    printf '%s\n' "$log"
    echo "FAIL: a run whose $1 changes with the thread count must fail, reporting '$2'"
    fails=$((fails + 1))
  fi
}
expect_fail counter "FAIL: summary.csv: --threads 1 and --threads 3 differ at line 2"
expect_fail png "FAIL: opaque-error.png: --threads 1 and --threads 3 differ at byte"  # the first PNG: an error map
if ! log=$(run host 2>&1); then
  printf '%s\n' "$log"
  echo "FAIL: host time and memory alone changed, and the checker failed"
  fails=$((fails + 1))
fi
[[ $fails -eq 0 ]] && echo "ok: counter and image changes caught, host time and memory let pass"
exit $((fails > 0))
