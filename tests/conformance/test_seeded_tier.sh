#!/usr/bin/env bash
# The seeded random tier (zblend conformance export --seed N) run on a DUT: the second DUT's
# subset under Icarus, with random timing from the same seed. Its three random-core streams
# (one per depth width) pass; the three that need more than replace and alpha are NOT SUPPORTED.
set -u
zblend=${1:?usage: test_seeded_tier.sh PATH/TO/zblend SEED}
seed=${2:?usage: test_seeded_tier.sh PATH/TO/zblend SEED}
root=$(cd "$(dirname "$0")/../.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; [[ -f $tmp/log.txt ]] && tail -n 20 "$tmp/log.txt"; exit 1; }
"$zblend" conformance export --seed "$seed" "$tmp/suite" >/dev/null || fail "export --seed $seed"
python3 "$root/scripts/conformance.py" --suite "$tmp/suite" --sim icarus --out "$tmp/run" \
  --profile "$root/conformance/ref/profile.json" --timing random --seed "$seed" -j 2 \
  --zblend "$zblend" >"$tmp/log.txt" 2>&1 || fail "conformance.py exited $?"
grep -q "^conformance: 3 pass, 0 fail, 3 not supported, 0 timeout, of 6 tests" "$tmp/log.txt" ||
  fail "counts: $(grep 'pass,' "$tmp/log.txt")"
for t in random-core-s$seed random-core-d16-s$seed random-core-d32-s$seed; do
  grep -q "^pass  $t$" "$tmp/log.txt" || fail "$t did not pass"
done
echo "ok: seed $seed's random tier: 3 pass, 3 NOT SUPPORTED on the second DUT's subset, random timing"
echo "3 passed, 0 failed"
