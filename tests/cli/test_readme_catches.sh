#!/usr/bin/env bash
# test_readme.py fails on a README whose example no longer works: a command that exits non-zero
# and leaves the file it names unwritten, a make target that is gone; a command continued over
# two lines runs whole.
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
expect "readme: 5 commands run, 1 checked otherwise, 2 failed"
[[ $fail -eq 0 ]] || { printf '%s\n' "$log"; exit 1; }
echo "ok: a failing command, its missing output and a removed make target are caught"
