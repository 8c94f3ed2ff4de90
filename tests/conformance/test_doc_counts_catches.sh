#!/usr/bin/env bash
# test_doc_counts.py fails on a docs/conformance.md gone stale: a name dropped from the quick
# tier's list, a tier's count, the goal count and the reach sample behind the tools, a check
# command reading an OUT nothing documented writes. The copy unchanged passes.
#   test_doc_counts_catches.sh ZBLEND SOURCE_DIR
set -u
zblend=${1:?usage: test_doc_counts_catches.sh ZBLEND SOURCE_DIR} source=${2:?usage: test_doc_counts_catches.sh ZBLEND SOURCE_DIR}
source "$source/tests/lib.sh"
doc=$tmp/conformance.md
checker() { python3 "$source/tests/conformance/test_doc_counts.py" "$zblend" "$doc" >"$tmp/out.txt" 2>&1; }

cp "$source/docs/conformance.md" "$doc"
checker || fail "the doc as it is: exit $?"
sed -i 's/`glass-torus-back-front`, `values-accumulate`/`values-accumulate`/' "$doc"
sed -i 's/^\(| quick |.*| \)33 |/\132 |/' "$doc"
sed -i 's/("goal\.\*", 11,142)/("goal.*", 11,062)/; s/^suite goals: 11142 of 11142/suite goals: 11062 of 11062/' "$doc"
sed -i 's|^\(build/zblend conformance check out/conformance/suite\) out/conformance/verilator --tests|\1 out/dut --tests|' "$doc"
cmp -s "$doc" "$source/docs/conformance.md" && fail "the stale edits changed nothing"
checker; rc=$?
[[ $rc -eq 1 ]] || fail "the stale doc: exit $rc, want 1"
for want in "the quick tier's list lacks \`glass-torus-back-front\`" \
            "the Tiers table: quick 32 tests, the tool lists 33" \
            "the goals are 11,062; the tool counts 11142" \
            "the sample of 'build/zblend conformance reach --tile 16x16' shows 'suite goals: 11062 of 11062" \
            "check reads out/dut, which no documented run of conformance.py on out/conformance/suite"; do
  grep -qF -- "$want" "$tmp/out.txt" || fail "the report lacks: $want"
done
[[ $(grep -c '^FAIL' "$tmp/out.txt") -eq 5 ]] || fail "not 5 FAIL lines"
echo "ok: a dropped quick-tier name, stale counts and a check of an unwritten OUT are caught"
