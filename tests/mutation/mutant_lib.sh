# The arguments and checks every single-mutant test shares (test_mutant_*.sh): sourced with the
# test's own arguments, PATH/TO/zblend_tb_mut and PATH/TO/mutations.txt; sets $tb and
# $mutations and brings checker_lib.sh (fail, $tmp, the report checks).
tb=${1:?usage: $(basename "$0") PATH/TO/zblend_tb_mut PATH/TO/mutations.txt}
mutations=${2:?usage: $(basename "$0") PATH/TO/zblend_tb_mut PATH/TO/mutations.txt}
source "$(dirname "${BASH_SOURCE[0]}")/../rtl/checker_lib.sh"

# expect_mutant N PATTERN WHAT: line N of the netlist's list matches PATTERN (grep's basic
# syntax), or the sample moved (a change to the RTL renumbers it) and the test fails saying what
# it expected and where that mutant is now, if it still is in the sample.
expect_mutant() {
  sed -n "$1p" "$mutations" | grep -q -- "$2" && return
  local now
  now=$(grep -n -m1 -- "$2" "$mutations" | cut -d: -f1)
  fail "mutant $1 is not $3 this test expects: $(sed -n "$1p" "$mutations")" \
    "${now:+(it is mutant $now now)}${now:-(no mutant of the sample is: pick another)}"
}
