#!/usr/bin/env bash
# The port stress mode (docs/testbench.md "Port stress"): mutant 734 inverts the epoch that the
# accumulation plane's write-back carries from its read (wb2_epoch_q), so a read's fresh words
# are written back current (or fresh) against the epoch they were read at. The driver's reads
# and clears never let that show: the driver's suites pass it. The port suite, whose fast clears
# meet reads' write-backs in any order, must stop at the first read that differs from its plane
# model, naming the read, the lane, both words and the beat's last operations; the unmutated
# netlist must pass the same run.
set -u
source "$(dirname "$0")/../lib.sh"
mutant_args "$@"

expect_mutant 734 '-mode inv .* -wire u_accum.u_accum_plane.wb2_epoch_q -wirebit 0 ' \
  "the accumulation write-back's epoch mutant"
for args in "--suite tiles --seed 1" "--suite clears --seed 1" "--schedule tile --suite tiles --seed 5 --backpressure 0.3"; do
  # shellcheck disable=SC2086
  "$tb" --mutant 734 $args -q --mismatch-fst "" >"$tmp/out.txt" 2>&1 ||
    fail "mutant 734 fails $args: then the port suite is no longer the one that sees it"
done
echo "ok: the driver's suites pass mutant 734"
"$tb" --mutant 0 --suite port --seed 1 -q --mismatch-fst "" >"$tmp/out.txt" 2>&1 ||
  fail "the unmutated netlist (mutant 0) fails the port suite"
"$tb" --mutant 734 --suite port --seed 1 -q --mismatch-fst "" >"$tmp/out.txt" 2>&1
rc=$?
[[ $rc -eq 1 ]] || fail "mutant 734, port suite: exit $rc, want 1"
grep -qE '^port stress: mismatch at op [0-9]+: read of beat [0-9]+.* \(cycle [0-9]+\): accumulation lane [0-9]+: rtl acc\(.*\) reveal [0-9]+, model acc\(.*\) reveal [0-9]+$' "$tmp/out.txt" ||
  fail "no 'port stress: mismatch at op N: read of beat B (cycle C): accumulation lane L: rtl ..., model ...' line"
grep -qE '^    op [0-9]+: (read|load|fast clear)' "$tmp/out.txt" || fail "no history of the beat under the mismatch"
grep -qE '^reproduce with waves: .* --suite port --seed [0-9]+ --iterations 1 --waves ' "$tmp/out.txt" ||
  fail "no reproduce command"
echo "ok: $(grep -m1 '^port stress' "$tmp/out.txt")"
