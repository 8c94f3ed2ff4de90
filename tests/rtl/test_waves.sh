#!/usr/bin/env bash
# Waves ready to read (docs/testbench.md "Waves"). The blend defect of zblend_tb_bug stops the
# lock-step run at its first wrong write; the report names the mismatch window's FST and its
# GTKWave save file, and ends with one command that reproduces the failure with waves. Checked:
#   - the save file against its FST (scripts/check_waves.py reads the FST with GTKWave's
#     fst2vcd): every listed signal present, the file starting where the window starts, the
#     marker of the first wrong write where the testbench's mismatch flag and retire probe say,
#     each accept marker on its fragment's accept; and GTKWave itself, under Xvfb, opens it with
#     every signal and the marker;
#   - the reproduce command, run as printed: it fails again and writes the whole run's FST and
#     save file, whose marker lies at the report's rising edge;
#   - the checker itself fails on a save file whose marker is one cycle late.
# Usage: test_waves.sh PATH/TO/zblend_tb_bug
set -u
tb=$(realpath "${1:?usage: test_waves.sh PATH/TO/zblend_tb_bug}")
root=$(cd "$(dirname "$0")/../.." && pwd)
check=(python3 "$root/scripts/check_waves.py")
source "$(dirname "$0")/../lib.sh"
cd "$tmp"

"$tb" --suite random --seed 1 --fragments 300000 -q --mismatch-fst "$tmp/w/bug.fst" >out.txt 2>&1
[[ $? -eq 1 ]] || fail "the blend defect did not fail the run"
grep -q "^  save file: $tmp/w/bug.gtkw (gtkwave $tmp/w/bug.gtkw): signals by stage, markers at the first wrong write and the pixel's accepts" out.txt ||
  fail "the report names no save file"
[[ $(grep -v '^suite \|passed, .* failed$' out.txt | tail -1) == "reproduce with waves: "* ]] ||
  fail "the failure's report does not end with the reproduce command"
"${check[@]}" "$tmp/w/bug.gtkw" --window --gtkwave >check.txt 2>&1 || { cat check.txt; fail "the save file does not match its FST"; }
echo "ok: $(cat check.txt)"

# The reproduce command as printed, from this directory: the same failure, the whole run's waves.
cmd=$(sed -n 's/^reproduce with waves: //p' out.txt)
[[ $cmd == "$tb "*" --waves out/waves/random-1.fst" ]] || fail "reproduce command: '$cmd'"
eval "$cmd" >again.txt 2>&1
[[ $? -eq 1 ]] || fail "the reproduce command passed: $cmd"
edge=$(sed -n 's/^LOCKSTEP MISMATCH.*its rising edge at \([0-9]*\) ns)$/\1/p' out.txt)
[[ $(sed -n 's/^LOCKSTEP MISMATCH.*its rising edge at \([0-9]*\) ns)$/\1/p' again.txt) == "$edge" ]] ||
  fail "the reproduce command failed elsewhere"
"${check[@]}" out/waves/random-1.gtkw >check.txt 2>&1 || { cat check.txt; fail "the reproduced run's save file does not match its FST"; }
grep -q "^\*[-0-9.]* $((edge * 1000)) $((edge * 1000)) " out/waves/random-1.gtkw ||
  fail "the reproduced run's marker is not at the report's rising edge (${edge} ns)"
echo "ok: reproduce command: the same wrong write at ${edge} ns; $(cat check.txt)"

# The checker fails on a defect: marker A one cycle late.
sed "s/^\*\([^ ]*\) \([0-9]*\) \([0-9]*\)/*\1 \2 $((edge * 1000 + 10000))/" "$tmp/w/bug.gtkw" >late.gtkw
"${check[@]}" late.gtkw >check.txt 2>&1 && fail "check_waves.py accepts a marker one cycle late"
grep -q "marker A (first wrong write #[0-9]*) at $((edge * 1000 + 10000)): tb.mismatch is not 1" check.txt ||
  { cat check.txt; fail "check_waves.py does not say what is wrong with the late marker"; }
echo "ok: check_waves.py refuses a marker one cycle late"
