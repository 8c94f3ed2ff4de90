#!/usr/bin/env bash
# The port stress mode (docs/testbench.md "Port stress"): mutant 1081 holds at 1 the flag
# that lane 1 of the second depth bank's word was fresh at its read (fresh2_q), so a read's
# write-back (W2) rewrites a current word with the bank's clear value, as if it were fresh. The driver's reads and clears never let that show: the driver's
# suites pass it.
# The port suite, whose fast clears and renamed copies meet reads' write-backs in any order,
# must stop at the first read that differs from its plane model, naming the read, the lane,
# both words and the beat's last operations; the unmutated netlist must pass the same run.
set -u
source "$(dirname "$0")/../lib.sh"
mutant_args "$@"

expect_mutant 1081 '-mode const1 .*-wire u_depth.g_renamed.g_bank.1..u_plane.g_bank.1..g_rw.fresh2_q -wirebit 0 ' \
  "the depth bank write-back's epoch mutant"
for args in "--suite tiles --seed 1" "--suite clears --seed 1" "--schedule tile --suite tiles --seed 5 --backpressure 0.3"; do
  # shellcheck disable=SC2086
  "$tb" --mutant 1081 $args -q --mismatch-fst "" >"$tmp/out.txt" 2>&1 ||
    fail "mutant 1081 fails $args: then the port suite is no longer the one that sees it"
done
echo "ok: the driver's suites pass mutant 1081"
"$tb" --mutant 0 --suite port --seed 1 -q --mismatch-fst "" >"$tmp/out.txt" 2>&1 ||
  fail "the unmutated netlist (mutant 0) fails the port suite"
"$tb" --mutant 1081 --suite port --seed 1 -q --mismatch-fst "" >"$tmp/out.txt" 2>&1
rc=$?
[[ $rc -eq 1 ]] || fail "mutant 1081, port suite: exit $rc, want 1"
grep -qE '^port stress: mismatch at op [0-9]+: read of beat [0-9]+.* \(cycle [0-9]+\): (depth|peel) lane [0-9]+: rtl 0x[0-9a-f]+, model 0x[0-9a-f]+$' "$tmp/out.txt" ||
  fail "no 'port stress: mismatch at op N: read of beat B (cycle C): depth|peel lane L: rtl ..., model ...' line"
grep -qE '^    op [0-9]+: (read|load|fast clear)' "$tmp/out.txt" || fail "no history of the beat under the mismatch"
grep -qE '^reproduce with waves: .* --suite port --seed [0-9]+ --iterations 1 --waves ' "$tmp/out.txt" ||
  fail "no reproduce command"
echo "ok: $(grep -m1 '^port stress' "$tmp/out.txt")"
