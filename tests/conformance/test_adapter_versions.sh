#!/usr/bin/env bash
# The adapter interface's versions (docs/conformance.md "Adapter versions"), without a simulator:
# a profile naming no adapter_version has it read off the adapter's ports (the version-6 adapter
# of tests/conformance/adapter_v6, conformance/ref's of version 7); under version 6 the layers
# tests are NOT SUPPORTED with the reason, even when the profile claims the layers; a profile's
# adapter_version wins over the ports; a bad one is exit 2 and one line.
#   test_adapter_versions.sh SUITE OUT
set -u
root=$(cd "$(dirname "$0")/../.." && pwd)
suite=${1:?usage: test_adapter_versions.sh SUITE OUT} out=${2:?}
fail() { echo "FAIL: $*" >&2; exit 1; }
rm -rf "$out"
mkdir -p "$out"
conf() { python3 "$root/scripts/conformance.py" --suite "$suite" --sim icarus --out "$out/run" "$@"; }
v6=$root/tests/conformance/adapter_v6/profile.json
v7=$root/conformance/ref/profile.json
all="blend.*,layers.*,depth_func.*,depth_write,color_mask,peel_test,accum_plane,depth_bits.*,coverage_samples.*"
nlayers=$(python3 -c 'import json,sys
print(sum("blend.layers" in t["features"] for t in json.load(open(sys.argv[1]))["tests"]))' "$suite/manifest.json")
[[ $nlayers -gt 0 ]] || fail "the suite has no layers tests"

conf --profile "$v6" --features "$all" --list >"$out/v6.txt" 2>&1 || fail "--list on the v6 profile: exit $?"
grep -q "^conformance: adapter interface version 6 (read off zb_ref_adapter.sv's ports; " "$out/v6.txt" ||
  fail "version 6 not read off the v6 adapter: $(head -n 1 "$out/v6.txt")"
n=$(grep -c "^NOT SUPPORTED .*adapter version 6 has no layers port" "$out/v6.txt")
[[ $n == "$nlayers" ]] || fail "$n layers tests NOT SUPPORTED by adapter version 6, want $nlayers"
grep -q "^NOT SUPPORTED" <(grep -v "adapter version 6" "$out/v6.txt") &&
  fail "a test NOT SUPPORTED for another reason under every feature"

conf --profile "$v7" --features "$all" --list >"$out/v7.txt" 2>&1 || fail "--list on the v7 profile: exit $?"
grep -q "^conformance: adapter interface version 7 (read off zb_ref_adapter.sv's ports; " "$out/v7.txt" ||
  fail "version 7 not read off conformance/ref's adapter: $(head -n 1 "$out/v7.txt")"
grep -q "^NOT SUPPORTED" "$out/v7.txt" && fail "a test NOT SUPPORTED under version 7 with every feature"

# A profile's own adapter_version wins over the ports; a bad one is refused.
python3 - "$v7" "$out" <<'PY'
import json, os, sys
p = json.load(open(sys.argv[1]))
base = os.path.dirname(sys.argv[1])
p["sources"] = [os.path.join(base, s) for s in p["sources"]]
for name, v in (("declared6", 6), ("bad", 5), ("badtype", "7")):
    json.dump({**p, "adapter_version": v}, open(os.path.join(sys.argv[2], name + ".json"), "w"))
PY
conf --profile "$out/declared6.json" --features "$all" --list >"$out/d6.txt" 2>&1 || fail "declared 6: exit $?"
grep -q "^conformance: adapter interface version 6 (the profile's adapter_version)" "$out/d6.txt" ||
  fail "the profile's adapter_version 6 not taken: $(head -n 1 "$out/d6.txt")"
for bad in bad badtype; do
  conf --profile "$out/$bad.json" --list >"$out/$bad.txt" 2>&1
  rc=$?
  [[ $rc == 2 ]] || fail "adapter_version in $bad.json: exit $rc, want 2"
  [[ $(wc -l <"$out/$bad.txt") == 1 ]] && grep -q "adapter_version: .* is not one of 6, 7" "$out/$bad.txt" ||
    fail "adapter_version in $bad.json: $(cat "$out/$bad.txt")"
done
echo "ok: adapter versions: 6 and 7 read off the ports, $nlayers layers tests NOT SUPPORTED under 6, the profile's key wins, bad keys refused"
