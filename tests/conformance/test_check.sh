#!/usr/bin/env bash
# zblend conformance check: passes when the got files are the expect files; fails, naming the
# test, plane, pixel and both values, and the command that shows the pixel's history, when one
# word of one got file changes; names a missing got
# file; --tests checks a slice; a damaged suite (a file against the manifest's SHA-256, the expect
# files against the signature) or an unknown test is exit 2.
set -u
zblend=$(realpath "${1:?usage: test_check.sh PATH/TO/zblend SUITE}")
suite=$(realpath "${2:?usage: test_check.sh PATH/TO/zblend SUITE}")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
bad() { echo "FAIL: $*"; fail=1; }

# The expect files as a DUT's got files.
out=$tmp/out
tests=0
for d in "$suite"/*/; do
  name=$(basename "$d")
  mkdir -p "$out/$name"
  for p in color depth coverage peel accum; do cp "$d/expect.$p.hex" "$out/$name/got.$p.hex"; done
  tests=$((tests + 1))
done

"$zblend" conformance check "$suite" "$out" >"$tmp/pass.log" 2>&1; rc=$?
[[ $rc -eq 0 ]] || bad "check of the expect files: exit $rc: $(grep -v '^pass' "$tmp/pass.log" | head -3)"
[[ $(grep -c '^pass  ' "$tmp/pass.log") -eq $tests ]] || bad "not one pass line per test ($tests)"
grep -q "^$tests of $tests tests pass$" "$tmp/pass.log" || bad "no summary: $(tail -1 "$tmp/pass.log")"

# A DUT's $writememh may differ in case and leading zeros, with // comments: still a pass.
g=$out/random/got.color.hex
{ echo "// written by a DUT"; tr 'a-f' 'A-F' <"$g" | sed 's/^0*\(.\)/\1/'; } >"$tmp/g" && cp "$tmp/g" "$g"
"$zblend" conformance check "$suite" "$out" --tests random >/dev/null 2>&1 ||
  bad "upper case, no leading zeros and a comment fail the check"
cp "$suite/random/expect.color.hex" "$g"

# One word of one got file changed: the 100th depth word of cad-three-pass, pixel (99 % 32,
# 99 / 32) = (3, 3) of its 32x24 frame.
g=$out/cad-three-pass/got.depth.hex
want=$(sed -n 100p "$g")
sed -i '100s/.*/00abcdef/' "$g"
"$zblend" conformance check "$suite" "$out" >"$tmp/fail.log" 2>"$tmp/fail.err"; rc=$?
[[ $rc -eq 1 ]] || bad "one changed word: exit $rc, want 1"
line="FAIL  cad-three-pass: depth pixel (3, 3): expected $want, got 00abcdef [color ok, depth 1 pixel differs, coverage ok, peel ok, accum ok]; why: $zblend conformance pixel $suite cad-three-pass --at 3,3"
grep -qxF "$line" "$tmp/fail.log" || bad "no line '$line' in: $(grep FAIL "$tmp/fail.log")"
# The command the line ends with prints the pixel's history, from the suite alone; its final
# depth is the expected word.
why=$(grep -m1 '^FAIL' "$tmp/fail.log" | sed 's/.*; why: //')
$why >"$tmp/why.txt" 2>&1 && grep -q "^pixel (3, 3), 32x24 frame" "$tmp/why.txt" || bad "'$why': $(head -3 "$tmp/why.txt")"
$why --json - | python3 -c 'import json, sys; d = json.load(sys.stdin)
assert d["pixels"][0]["final"]["depth"] == int(sys.argv[1], 16), d["pixels"][0]["final"]' "$want" ||
  bad "'$why --json -': its final depth is not the expected $want"
[[ $(grep -c '^FAIL' "$tmp/fail.log") -eq 1 ]] || bad "more than one test failed: $(grep FAIL "$tmp/fail.log")"
grep -qx "zblend: FAILED: 1 of $tests tests failed" "$tmp/fail.err" || bad "stderr: $(cat "$tmp/fail.err")"

# One accumulation word of a wboit test changed (its lowest digit): the accum plane is named,
# with both 18-digit words, pixel 200 = (8, 6).
g=$out/glass-torus-wboit/got.accum.hex
want=$(sed -n 201p "$g")
changed=${want:0:17}$(printf %x $(( (16#${want:17:1} + 1) % 16 )))
sed -i "201s/.*/$changed/" "$g"
"$zblend" conformance check "$suite" "$out" --tests glass-torus-wboit >"$tmp/acc.log" 2>/dev/null; rc=$?
line="FAIL  glass-torus-wboit: accum pixel (8, 6): expected $want, got $changed [color ok, depth ok, coverage ok, peel ok, accum 1 pixel differs]; why: $zblend conformance pixel $suite glass-torus-wboit --at 8,6"
[[ $rc -eq 1 ]] && grep -qxF "$line" "$tmp/acc.log" || bad "changed accumulation word: exit $rc: $(cat "$tmp/acc.log"), want '$line'"
# A DUT without the accumulation plane (--no-accum): the wboit tests are skipped, not passed,
# and no got.accum.hex is read.
rm "$out/random/got.accum.hex"
"$zblend" conformance check "$suite" "$out" --no-accum --tests random,glass-torus-wboit >"$tmp/skip.log" 2>&1; rc=$?
[[ $rc -eq 0 && $(cat "$tmp/skip.log") == "pass  random
skip  glass-torus-wboit: needs the accumulation plane (a resolve wboit), which the DUT does not have
1 of 1 tests pass, 1 skipped (they need the accumulation plane)" ]] || bad "--no-accum: exit $rc: $(cat "$tmp/skip.log")"
"$zblend" conformance check "$suite" "$out" --tests random >/dev/null 2>&1 && bad "a missing got.accum.hex passes"
cp "$suite/random/expect.accum.hex" "$out/random/got.accum.hex"
cp "$suite/glass-torus-wboit/expect.accum.hex" "$g"

# A slice: only the named tests are checked, in the suite's order.
"$zblend" conformance check "$suite" "$out" --tests random,cad-three-pass >"$tmp/slice.log" 2>/dev/null; rc=$?
[[ $rc -eq 1 && $(cut -d: -f1 "$tmp/slice.log") == $'FAIL  cad-three-pass\npass  random\n1 of 2 tests pass' ]] ||
  bad "--tests slice: exit $rc: $(cat "$tmp/slice.log")"
"$zblend" conformance check "$suite" "$out" --tests random >/dev/null 2>&1 || bad "--tests random fails"

# A missing got file fails its test, naming the file.
rm "$out/hazard/got.peel.hex"
"$zblend" conformance check "$suite" "$out" --tests hazard >"$tmp/missing.log" 2>/dev/null; rc=$?
[[ $rc -eq 1 ]] && grep -qF "FAIL  hazard: missing $out/hazard/got.peel.hex" "$tmp/missing.log" ||
  bad "missing got file: exit $rc: $(cat "$tmp/missing.log")"
# A short got file fails its test, saying so.
head -5 "$suite/hazard/expect.peel.hex" >"$out/hazard/got.peel.hex"
"$zblend" conformance check "$suite" "$out" --tests hazard 2>/dev/null | grep -q "got.peel.hex: 5 words, expected 4096 (64x64)" ||
  bad "a short got file is not named"

# Bad input: exit 2, one line on stderr.
expect2() {  # NAME PATTERN ARGS...
  local name=$1 pattern=$2; shift 2
  local err rc
  err=$("$zblend" conformance check "$@" 2>&1 >/dev/null); rc=$?
  [[ $rc -eq 2 && $(wc -l <<<"$err") -eq 1 ]] && grep -qE -- "$pattern" <<<"$err" ||
    bad "$name: exit $rc, stderr: $err"
}
expect2 "unknown test" "--tests: 'nope' is not a test of" "$suite" "$out" --tests nope
expect2 "empty test name" "--tests: 'random,' has an empty name" "$suite" "$out" --tests random,
expect2 "no OUT" "OUT: '$tmp/none' is not a directory" "$suite" "$tmp/none"
expect2 "no suite" "SUITE $tmp/manifest.json: cannot read" "$tmp" "$out"
cp -r "$suite" "$tmp/damaged"
sed -i '1s/.*/00000000/' "$tmp/damaged/random/expect.color.hex"
expect2 "a changed expect file" "^zblend: error: corrupt suite: $tmp/damaged/random/expect.color.hex: SHA-256 [0-9a-f]{16}\.\.\., the manifest says" \
  "$tmp/damaged" "$out" --tests random
# Its hash in "files" made to agree: the signature still holds the expect files.
python3 - "$tmp/damaged" <<'PY'
import hashlib, json, sys
path = f"{sys.argv[1]}/manifest.json"
m = json.load(open(path))
t = next(t for t in m["tests"] if t["name"] == "random")
t["files"]["expect.color.hex"] = hashlib.sha256(
    open(f"{sys.argv[1]}/random/expect.color.hex", "rb").read()).hexdigest()
json.dump(m, open(path, "w"))
PY
expect2 "a changed expect file, its hash too" "the expect files of test 'random' do not match its signature_sha256" \
  "$tmp/damaged" "$out" --tests random
version=$(python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["version"])' "$suite/manifest.json")
echo "{\"suite\": \"zblend-conformance\", \"version\": $((version + 1)), \"tests\": []}" >"$tmp/damaged/manifest.json"
expect2 "a later version" "version $((version + 1)) is not supported" "$tmp/damaged" "$out"
echo "{\"suite\": \"zblend-conformance\", \"version\": $version, \"configs\": [], \"tests\": [{\"name\": \"../x\"}]}" >"$tmp/damaged/manifest.json"
expect2 "a test without its fields" "manifest.json: .*key 'width' not found|is not a directory name" "$tmp/damaged" "$out"
echo 'not json' >"$tmp/damaged/manifest.json"
expect2 "not JSON" "manifest.json: .*parse error" "$tmp/damaged" "$out"

[[ $fail -eq 0 ]] && echo "check: $tests tests pass on the expect files; a changed word, a missing and a short file fail; bad suites are exit 2"
exit $fail
