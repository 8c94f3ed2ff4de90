# Shared by the command-line test scripts: counters and the bad-input contract.
# The caller sets $tmp (with $tmp/out) before calling expect_error.
pass=0 fail=0

ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAIL: $*"; }

# expect_error NAME PATTERN PROGRAM ARGS...: exit 2, one stderr line matching PATTERN, no file
# left in $tmp/out.
expect_error() {
  local name=$1 pattern=$2; shift 2
  local before after err rc
  before=$(ls -A "$tmp/out" | sort)
  err=$("$@" 2>&1 >/dev/null); rc=$?
  after=$(ls -A "$tmp/out" | sort)
  if [[ $rc -ne 2 ]]; then bad "$name: exit $rc, want 2 ($err)"; return; fi
  if [[ $(printf '%s\n' "$err" | wc -l) -ne 1 ]]; then bad "$name: not one line: $err"; return; fi
  if ! grep -qE -- "$pattern" <<<"$err"; then bad "$name: '$err' lacks /$pattern/"; return; fi
  if [[ "$before" != "$after" ]]; then bad "$name: left files: $after"; return; fi
  ok
}
