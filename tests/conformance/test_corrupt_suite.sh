#!/usr/bin/env bash
# A corrupt suite is refused alike by every program that reads one: scripts/conformance.py,
# `conformance pixel` and `conformance check` of zblend and of the kit's zblend-conformance each
# exit 2 with conformance.py's one line (after the program's name), print nothing on stdout and
# write nothing. The corruption: one fragment's alpha changed in a stream.hex (still a valid
# stream, which pixel would otherwise explain though the DUT never ran it); then an expect file
# missing.
#   test_corrupt_suite.sh ZBLEND ZBLEND_CONFORMANCE
set -u
zblend=$(realpath "${1:?usage: test_corrupt_suite.sh ZBLEND ZBLEND_CONFORMANCE}")
kit=$(realpath "${2:?usage: test_corrupt_suite.sh ZBLEND ZBLEND_CONFORMANCE}")
root=$(cd "$(dirname "$0")/../.." && pwd)
source "$root/tests/lib.sh"
s=$tmp/suite
mkdir "$tmp/out" "$tmp/dut"
"$zblend" conformance export --quick "$s" >/dev/null || fail "export --quick"

# The runner's line, its program's name taken off; then each command's, the same.
same_refusal() {  # WHAT
  local err rc want
  err=$(python3 "$root/scripts/conformance.py" --suite "$s" --sim icarus --out "$tmp/out/run" \
    --zblend "$zblend" 2>&1 >/dev/null); rc=$?
  [[ $rc -eq 2 && $(wc -l <<<"$err") -eq 1 && $err == "conformance.py: error: corrupt suite: "* ]] ||
    fail "$1: conformance.py: exit $rc: $err"
  want=${err#conformance.py: error: }
  for cmd in "$zblend conformance pixel $s cad-coverage-aa --at 3,3 --json $tmp/out/p.json" \
             "$kit pixel $s cad-coverage-aa --at 3,3" \
             "$zblend conformance check $s $tmp/dut" "$kit check $s $tmp/dut --tests hazard"; do
    expect_error "$1: $cmd" "" $cmd
    err=$($cmd 2>&1 >"$tmp/stdout")
    [[ $err == "$(basename "${cmd%% *}"): error: $want" ]] ||
      fail "$1: $cmd: '$err', want conformance.py's '$want'"
    [[ -s $tmp/stdout ]] && fail "$1: $cmd printed: $(head -3 "$tmp/stdout")"
  done
  echo "ok: $1: every program refuses it with: $want"
}

# Fragment line 4 (a FRAG word: [95:64] rgba, its top byte the alpha, digits 9 and 10).
f=$s/cad-coverage-aa/stream.hex
[[ $(sed -n 4p "$f") == 03* ]] || fail "line 4 of $f is not a fragment: $(sed -n 4p "$f")"
alpha=$(sed -n 4p "$f" | cut -c9-10)
sed -i "4s/^\(.\{8\}\)../\1$(printf %02x $(( (16#$alpha + 1) % 256 )))/" "$f"
[[ $(sed -n 4p "$f" | cut -c9-10) != "$alpha" ]] || fail "the alpha did not change"
"$zblend" conformance pixel "$s" hazard --at 1,1 >/dev/null 2>&1 &&
  fail "pixel of another test runs on a suite with a changed stream"
same_refusal "one fragment's alpha changed in cad-coverage-aa/stream.hex"

"$zblend" conformance export --quick "$s" >/dev/null || fail "export --quick again"
rm "$s/hazard/expect.peel.hex"
same_refusal "hazard/expect.peel.hex missing"
