#!/usr/bin/env bash
# zblend conformance export: byte-for-byte reproducible (two exports, diff -r), each test's
# signature_sha256 as sha256sum computes it over its five expect files, each file's own hash, each
# test's features as its stream's PASS words say (decoded here apart), each stream's count line
# and manifest counts as the files hold them, --quick a subset of the full suite, file for file,
# whose reach is the full suite's (`conformance reach`), each test's tier, the seeded random tier
# (the same bytes for a seed, other streams for another), and an export over an earlier suite
# replacing it with nothing left beside it.
set -u
zblend=$(realpath "${1:?usage: test_export.sh PATH/TO/zblend}")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
bad() { echo "FAIL: $*"; fail=1; }

"$zblend" conformance export "$tmp/a" >"$tmp/a.log" || bad "export a: $(cat "$tmp/a.log")"
"$zblend" conformance export "$tmp/b" >/dev/null || bad "export b"
diff -r "$tmp/a" "$tmp/b" >"$tmp/diff" || bad "two exports differ: $(head -5 "$tmp/diff")"
cat "$tmp/a.log"

# name, frame and counts of every test, from the manifest (python3 reads the JSON only).
python3 - "$tmp/a/manifest.json" >"$tmp/tests" <<'PY' || bad "manifest unreadable"
import hashlib, json, os, sys
m = json.load(open(sys.argv[1]))
assert m["suite"] == "zblend-conformance" and m["version"] == 8
configs = {c["name"] for c in m["configs"]}
BLEND = ["replace", "alpha", "additive", "coverage", "under", "accumulate", "layers"]
FUNC = ["never", "less", "equal", "lequal", "greater", "notequal", "gequal", "always"]


def features(stream):
    """The features a DUT needs for this stream, decoded from its words (docs/conformance.md
    "stream.hex"): a pass counts only with fragments."""
    words = [int(w, 16) for w in stream.split()[1:]]
    f = {f"depth_bits.{words[0] >> 32 & 0xff}", f"coverage_samples.{words[0] >> 40 & 0xff}"}
    for i, w in enumerate(words):
        op = w >> 120
        if op == 5 and w & 0xf == 4:
            f.add("accum_plane")
        if op != 2 or i + 1 >= len(words) or words[i + 1] >> 120 != 3:
            continue
        blend = w >> 5 & 7
        f.add("blend." + BLEND[blend])
        if blend == 5:
            f.add("accum_plane")
        if blend == 6:
            f.add(f"layers.{(w >> 13 & 7) + 1}")
        if w & 1 and blend != 3:
            f.add("depth_func." + FUNC[w >> 1 & 7])
        if w & 1 and w >> 4 & 1:
            f.add("depth_write")
        if w >> 8 & 0xf != 0xf:
            f.add("color_mask")
        if w >> 12 & 1 and blend != 3:
            f.add("peel_test")
    return sorted(f)


suite = os.path.dirname(sys.argv[1])
assert all((c["acc_bits"], c["rev_bits"], c["weight_bits"]) == (16, 8, 4) for c in m["configs"])
for t in m["tests"]:
    assert t["config"] in configs, t["name"]
    # Only a resolve wboit needs the accumulation plane: the wboit scene tests, random-wboit and
    # the generated accumulation tests (which end with one).
    assert t["needs_accum"] == (t.get("method") == "wboit" or t["name"] in (
        "random-wboit", "values-accumulate", "same-pixel-accumulate")), t["name"]
    assert t["tier"] in ("quick", "full"), t["name"]
    assert (t["kind"] == "generated") == ("family" in t), t["name"]
    d = os.path.join(suite, t["name"])
    assert sorted(t["files"]) == sorted(os.listdir(d)), t["name"]
    for name, sha in t["files"].items():
        assert hashlib.sha256(open(os.path.join(d, name), "rb").read()).hexdigest() == sha, (t["name"], name)
    assert t["features"] == features(open(os.path.join(d, "stream.hex")).read()), t["name"]
    print(t["name"], t["width"] * t["height"], t["words"], t["signature_sha256"])
PY
tests=0
while read -r name pixels words sha; do
  tests=$((tests + 1))
  d="$tmp/a/$name"
  got=$(cat "$d/expect.color.hex" "$d/expect.depth.hex" "$d/expect.coverage.hex" \
            "$d/expect.peel.hex" "$d/expect.accum.hex" | sha256sum | cut -d' ' -f1)
  [[ $got == "$sha" ]] || bad "$name: sha256sum $got, manifest $sha"
  for p in color depth coverage peel accum; do
    n=$(wc -l <"$d/expect.$p.hex")
    [[ $n -eq $pixels ]] || bad "$name: expect.$p.hex has $n lines for $pixels pixels"
  done
  lines=$(wc -l <"$d/stream.hex")
  count=$((16#$(head -1 "$d/stream.hex")))
  [[ $count -eq $words && $lines -eq $((words + 1)) ]] ||
    bad "$name: count line $count, $lines lines, manifest words $words"
  [[ $(sed -n 2p "$d/stream.hex") == 01* && $(tail -1 "$d/stream.hex") == 06* ]] ||
    bad "$name: the stream does not run FRAME to END"
  grep -qvE '^[0-9a-f]{32}$' "$d/stream.hex" && bad "$name: a stream line is not 32 lower-case hex digits"
done <"$tmp/tests"
[[ $tests -gt 100 ]] || bad "only $tests tests in the suite"
# random-wboit resolves between passes too (FRAME_OP, opcode 05, operation 4), random never.
r=$tmp/a/random-wboit/stream.hex
first=$(grep -nE '^05[0-9a-f]{29}4$' "$r" | head -1 | cut -d: -f1)
[[ $(grep -cE '^05[0-9a-f]{29}4$' "$r") -ge 2 && -n $first && $(tail -n +"$first" "$r" | grep -c '^02') -ge 1 ]] ||
  bad "random-wboit: fewer than two resolves, or none before a pass"
grep -qE '^05[0-9a-f]{29}4$' "$tmp/a/random/stream.hex" && bad "random: a resolve wboit in the stream"
echo "export: $tests tests, hashes and counts as the files hold them"

"$zblend" conformance export --quick "$tmp/q" >/dev/null || bad "export --quick"
quick=0
for d in "$tmp/q"/*/; do
  name=$(basename "$d")
  quick=$((quick + 1))
  diff -r "$d" "$tmp/a/$name" >/dev/null || bad "quick test $name differs from the full suite's"
done
[[ $quick -ge 10 && $quick -le 40 ]] || bad "--quick has $quick tests, want 10 to 40"
[[ $quick -eq $(grep -c '"tier": "quick"' "$tmp/a/manifest.json") ]] ||
  bad "--quick's $quick tests are not the manifest's quick tier"
# The quick tier keeps every bin the whole suite reaches, at zb_rop's tile and at 16 x 16.
for tile in 64x64 16x16; do
  full=$("$zblend" conformance reach --tile $tile | grep -E '^(plan bins|suite goals)')
  fast=$("$zblend" conformance reach --tile $tile --quick | grep -E '^(plan bins|suite goals)')
  [[ -n $full && $full == "$fast" ]] || bad "tile $tile: the quick tier reaches [$fast], the suite [$full]"
done

# The seeded random tier: a seed's bytes again for the same seed, other streams for another.
"$zblend" conformance export --seed 7 "$tmp/s7" >/dev/null || bad "export --seed 7"
"$zblend" conformance export --seed 7 "$tmp/s7b" >/dev/null || bad "export --seed 7 again"
"$zblend" conformance export --seed 8 "$tmp/s8" >/dev/null || bad "export --seed 8"
diff -r "$tmp/s7" "$tmp/s7b" >/dev/null || bad "two exports of seed 7 differ"
[[ -f $tmp/s7/random-s7/stream.hex && -f $tmp/s8/random-s8/stream.hex ]] || bad "no random-s7 or random-s8"
cmp -s "$tmp/s7/random-s7/stream.hex" "$tmp/s8/random-s8/stream.hex" && bad "seeds 7 and 8 wrote the same stream"
grep -q '"tier": "random"' "$tmp/s7/manifest.json" || bad "the seeded tests are not tier random"
rm -rf "$tmp/s7" "$tmp/s7b" "$tmp/s8"

# Over an earlier suite: replaced, the same bytes, no temporary sibling left.
echo stale >"$tmp/b/hazard/stale.txt"
"$zblend" conformance export "$tmp/b" >/dev/null || bad "export over an earlier suite"
diff -r "$tmp/a" "$tmp/b" >/dev/null || bad "export over an earlier suite left it different"
leftover=$(ls -A "$tmp" | grep '^\.' || true)
[[ -z $leftover ]] || bad "left beside the suite: $leftover"

[[ $fail -eq 0 ]] && echo "export: reproducible, $quick quick tests equal to the full suite's"
exit $fail
