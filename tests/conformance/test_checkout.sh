#!/usr/bin/env bash
# An outside ROP run from its own checkout (docs/conformance.md "Outside ROPs"): a profile whose
# sources and include_dirs say $CHECKOUT/... needs --checkout DIR (else exit 2, one line naming
# the ROP, its address and commit); with it the sources resolve there, and the run says the
# checkout's commit, warning when it is not the profile's.
#   test_checkout.sh SUITE OUT
set -u
root=$(cd "$(dirname "$0")/../.." && pwd)
suite=${1:?usage: test_checkout.sh SUITE OUT} out=${2:?}
fail() { echo "FAIL: $*" >&2; exit 1; }
rm -rf "$out"
mkdir -p "$out/rop/rtl/inc" "$out/prof"
git -C "$out/rop" init -q && printf 'module outside_rop; endmodule\n' >"$out/rop/rtl/outside_rop.sv" &&
  git -C "$out/rop" add -A && git -C "$out/rop" -c user.name=t -c user.email=t@t commit -qm rop ||
  fail "cannot make a git checkout"
head=$(git -C "$out/rop" rev-parse HEAD)
profile() {  # COMMIT
  printf '{"dut": "outside_rop", "features": ["blend.replace", "depth_func.*", "depth_bits.*", "coverage_samples.*", "depth_write"],\n "checkout": {"name": "Outside", "url": "https://example.invalid/outside", "commit": "%s"},\n "sources": ["$CHECKOUT/rtl/*.sv", "%s/conformance/ref/zb_ref_adapter.sv"], "include_dirs": ["$CHECKOUT/rtl/inc"]}\n' "$1" "$root" >"$out/prof/p.json"
}
conf() { python3 "$root/scripts/conformance.py" --suite "$suite" --sim icarus --out "$out/run" --profile "$out/prof/p.json" --list "$@"; }
profile "$head"
conf >"$out/none.txt" 2>&1
rc=$?
[[ $rc == 2 && $(wc -l <"$out/none.txt") == 1 ]] || fail "no --checkout: exit $rc, $(cat "$out/none.txt")"
grep -q "its sources are in a checkout of Outside (https://example.invalid/outside at $head): give its folder with --checkout DIR" "$out/none.txt" ||
  fail "no --checkout: $(cat "$out/none.txt")"
conf --checkout "$out/rop" >"$out/ok.txt" 2>&1 || fail "--checkout: exit $? ($(tail -n 2 "$out/ok.txt"))"
grep -q "^conformance: checkout $out/rop at ${head:0:12}$" "$out/ok.txt" || fail "the checkout's commit not said: $(head -n 3 "$out/ok.txt")"
profile 0123456789abcdef0123456789abcdef01234567
conf --checkout "$out/rop" >"$out/other.txt" 2>&1 || fail "another commit: exit $?"
grep -q "^conformance: warning: --checkout $out/rop is at ${head:0:12}; the profile was written for 0123456789ab$" "$out/other.txt" ||
  fail "no warning for another commit: $(head -n 3 "$out/other.txt")"
# A modified file in the checkout: a warning naming it.
echo "// changed" >>"$out/rop/rtl/outside_rop.sv"
conf --checkout "$out/rop" >"$out/dirty.txt" 2>&1 || fail "a modified checkout: exit $?"
grep -q "^conformance: warning: --checkout $out/rop has 1 modified file (rtl/outside_rop.sv): the run is of a modified DUT, not of ${head:0:12}$" "$out/dirty.txt" ||
  fail "no warning for a modified checkout: $(head -n 4 "$out/dirty.txt")"
conf --checkout "$out/nothere" >"$out/bad.txt" 2>&1
[[ $? == 2 ]] && grep -q "^conformance.py: error: --checkout .*nothere: not a folder" "$out/bad.txt" ||
  fail "a missing --checkout: $(cat "$out/bad.txt")"
echo "ok: \$CHECKOUT sources need --checkout, resolve in it, its commit is checked against the profile's, its local changes are warned of"
