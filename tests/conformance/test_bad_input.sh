#!/usr/bin/env bash
# zblend conformance export and check on bad input (docs/cli.md "Errors"): exit 2, one line on
# stderr, and nothing left behind: no suite, no temporary sibling, no parent made.
set -u
zblend=$(realpath "${1:?usage: test_bad_input.sh PATH/TO/zblend}")
source "$(dirname "$0")/../lib.sh"
mkdir -p "$tmp/out"
o=$tmp/out

echo text >"$o/file"
mkdir "$o/mine" && echo keep >"$o/mine/notes.txt"
expect_error "no DIR" "zblend: error: DIR: needed" "$zblend" conformance export
expect_error "--list and DIR" "DIR: --list writes nothing" "$zblend" conformance export --list "$o/s"
expect_error "DIR a file" "DIR: $o/file is a file, not a directory" "$zblend" conformance export "$o/file"
expect_error "DIR under a file" "DIR: $o/file is a file, not a directory" "$zblend" conformance export "$o/file/s"
expect_error "DIR not empty" "$o/mine: is not empty and holds no zblend suite" "$zblend" conformance export "$o/mine"
expect_error "misspelt option" "unknown option '--quik'; did you mean '--quick'" "$zblend" conformance export --quik "$o/s"
expect_error "no subcommand" "conformance" "$zblend" conformance
expect_error "check: no OUT" "OUT is required" "$zblend" conformance check "$o"
expect_error "check: no suite" "SUITE $o/manifest.json: cannot read" "$zblend" conformance check "$o" "$o"
expect_error "check: a bad arithmetic" "--arithmetic: 'sum-ceil' is not an arithmetic" "$zblend" conformance check "$o" "$o" --arithmetic sum-ceil
expect_error "digests: no suite" "SUITE $o/manifest.json: cannot read" "$zblend" conformance digests "$o" cad-opaque
expect_error "digests: a bad arithmetic" "--arithmetic: 'round' is not an arithmetic" "$zblend" conformance digests "$o" cad-opaque --arithmetic round
if [[ $(id -u) -ne 0 ]]; then  # root writes anywhere
  mkdir "$o/locked" && chmod a-w "$o/locked"
  expect_error "DIR not writable" "directory '$o/locked' is not writable" "$zblend" conformance export "$o/locked/s"
  chmod u+w "$o/locked" && rmdir "$o/locked"
fi
[[ $(cat "$o/mine/notes.txt") == keep ]] || fail "a refused export changed a directory"

# A failure while writing (here: the suite's directory made read-only under a non-root user is
# not portable, so a DIR whose parent is replaced by a file mid-way is not tried): the temporary
# sibling is removed on every error path of export_suite; none may be left by the refusals above.
leftover=$(find "$tmp" -name '.*tmp-*' -o -name '.*old-*')
[[ -z $leftover ]] || fail "left behind: $leftover"

echo "bad input: $pass refused"
