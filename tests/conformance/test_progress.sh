#!/usr/bin/env bash
# scripts/conformance.py's progress lines tell the truth: a test whose simulation finished but
# whose planes the checker then fails is never reported `ok` (or `pass`) on its progress line.
# The DUT: the second DUT with a defect of its catalogue (notequal and gequal swapped), which two
# of three quick tests catch; run in parallel, and one at a time with --first-fail.
#   test_progress.sh SUITE OUT ZBLEND
set -u
suite=$(realpath "${1:?usage: test_progress.sh SUITE OUT ZBLEND}") out=$2 zblend=$(realpath "$3")
root=$(cd "$(dirname "$0")/../.." && pwd)
source "$root/tests/lib.sh"
rm -rf "$out"
mkdir -p "$out"

for mode in "-j 2" "-j 1 --first-fail"; do
  o=$out/run-${mode// /}
  # shellcheck disable=SC2086  # the mode's words are options
  python3 "$root/scripts/conformance.py" --suite "$suite" --sim icarus --out "$o" $mode \
    --profile "$root/conformance/ref/profile_full.json" --define ZB_REF_DEFECT_FUNC_SWAP_NE_GE \
    --tests cad-coverage-aa,states-alpha,depth-bits --zblend "$zblend" >"$o.txt" 2>&1
  rc=$?
  cp "$o.txt" "$tmp/out.txt"
  [[ $rc -eq 1 ]] || fail "$mode: exit $rc, want 1 (the defect caught)"
  # Each test's verdict and the word of its progress line: "NAME VERDICT WORD".
  python3 - "$o/results.json" "$o.txt" >"$tmp/words" <<'PY' || fail "$mode: results.json"
import json, re, sys
verdicts = {t["name"]: t["verdict"] for t in json.load(open(sys.argv[1]))["tests"]}
for ln in open(sys.argv[2]):
    m = re.match(r"conformance: \[\d+/\d+\] (\S+) (\S+) ", ln)
    if m:
        print(m.group(2), verdicts[m.group(2)], m.group(1))
PY
  grep -q " fail " "$tmp/words" || fail "$mode: no failing test had a progress line"
  while read -r name verdict word; do
    [[ $verdict == fail && ($word == ok || $word == pass) ]] &&
      fail "$mode: the progress line says '$word' for $name, which failed"
  done <"$tmp/words"
  # Nor for a passing test: the line comes before the check.
  grep -q " ok$" "$tmp/words" && fail "$mode: a progress line says 'ok' before the check"
  echo "ok: $mode: progress lines $(tr '\n' ';' <"$tmp/words")"
done
