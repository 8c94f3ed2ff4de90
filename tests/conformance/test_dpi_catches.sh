#!/usr/bin/env bash
# tb_golden_dpi must fail on a wrong value: with +zb_expect_wrong it expects red 109 where the
# golden model's alpha blend gives 108 (tb_golden_dpi.sv), so it must exit 1 naming both sides.
set -u
test=${1:?usage: test_dpi_catches.sh PATH/TO/zblend_dpi_test}
out=$("$test" +zb_expect_wrong 2>&1); rc=$?
if [[ $rc -ne 1 ]]; then
  echo "dpi_catches: exit $rc with a wrong expected value, want 1: $out"
  exit 1
fi
if ! grep -q 'FAIL alpha: colour: golden=8039426c expected=8039426d' <<<"$out"; then
  echo "dpi_catches: no report naming both values in: $out"
  exit 1
fi
echo "dpi_catches: a wrong expected value fails the test, naming both sides"
