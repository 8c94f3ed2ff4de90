#!/usr/bin/env bash
# test_readme.py fails on a README whose example no longer works: a command that exits non-zero
# and leaves the file it names unwritten, a make target that is gone; a command continued over
# two lines runs whole; a conformance check of a DUT directory no step writes.
# Usage: test_readme_catches.sh BUILD_DIR SOURCE_DIR
set -uo pipefail
build=$1
source=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fence='```'
cat >"$tmp/README.md" <<MD
# a README gone stale

${fence}sh
make no-such-target                     # a target since removed
build/zblend scenes
build/zblend methods
build/zblend render --scene no-such-scene --method opaque --out a.png
build/zblend render --scene cad --method opaque --out b.png \\
    --stats b.json
build/zblend plan --method three-pass
build/zblend conformance check out/suite out/dut   # no step above runs a DUT into out/dut
${fence}
MD
log=$(python3 "$source/tests/cli/test_readme.py" "$tmp/README.md" "$build" "$source" 2>&1)
rc=$?
fail=0
expect() {
  grep -q -- "$1" <<<"$log" || { echo "FAIL: the report lacks: $1"; fail=1; }
}
[[ $rc -eq 1 ]] || { echo "FAIL: exit $rc, expected 1"; fail=1; }
expect "FAIL: README.md:4: make no-such-target: no such make target"
expect "FAIL: README.md:7: build/zblend render --scene no-such-scene .*: exit 2, a.png missing or empty"
expect "ran    README.md:8: build/zblend render --scene cad"
expect "FAIL: README.md:11: build/zblend conformance check out/suite out/dut: nothing before it writes out/dut"
expect "readme: 5 commands run, 2 checked otherwise, 3 failed"
[[ $fail -eq 0 ]] || { printf '%s\n' "$log"; exit 1; }
echo "ok: a failing command, its missing output, a removed make target and a DUT run never made are caught"
