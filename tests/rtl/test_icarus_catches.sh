#!/usr/bin/env bash
# The Icarus elaboration check (scripts/lint_rtl.sh --icarus) fails on RTL Icarus 11 cannot
# read: a copy of rtl/ with one parameter typed `int unsigned` (what Icarus rejects) must fail,
# and the copy as it is must pass.
set -u
root=${1:?usage: test_icarus_catches.sh PROJECT_ROOT}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
mkdir -p "$tmp/scripts"
cp -r "$root/rtl" "$tmp/"
cp "$root/scripts/lint_rtl.sh" "$tmp/scripts/"
bash "$tmp/scripts/lint_rtl.sh" --icarus >"$tmp/log" 2>&1 || fail "the unchanged copy fails: $(cat "$tmp/log")"
sed -i 's/parameter int COV_SAMPLES = 16/parameter int unsigned COV_SAMPLES = 16/' "$tmp/rtl/zb_blend.sv"
grep -q 'parameter int unsigned COV_SAMPLES' "$tmp/rtl/zb_blend.sv" || fail "the defect was not injected"
bash "$tmp/scripts/lint_rtl.sh" --icarus >"$tmp/log" 2>&1 && fail "an int unsigned parameter passed"
grep -q 'zb_blend.sv' "$tmp/log" || fail "the failure does not name the file: $(cat "$tmp/log")"
echo "ok: Icarus's check fails on an int unsigned parameter: $(head -1 "$tmp/log")"
