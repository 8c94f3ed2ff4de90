#!/usr/bin/env bash
# layout.sh must fail on a tree that breaks each of its rules.
set -u
here=$(cd "$(dirname "$0")" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/cmodel/raster/internal" "$tmp/app" "$tmp/cli" "$tmp/tb" "$tmp/oracle"
echo '#pragma once' >"$tmp/cmodel/raster/internal/edge.h"
echo '#pragma once' >"$tmp/cmodel/raster/raster.h"
echo '#pragma once' >"$tmp/app/commands.h"
status=0
check() {  # NAME FILE CONTENT PATTERN
  printf '%s\n' "$3" >"$tmp/$2"
  out=$("$here/layout.sh" "$tmp" 2>&1) && { echo "layout_catches: $1: passed, should fail"; status=1; }
  grep -q "$4" <<<"$out" || { echo "layout_catches: $1: no '$4' in: $out"; status=1; }
  rm -f "$tmp/$2"
}
check internal app/a.cpp '#include "raster/internal/edge.h"' 'an internal header'
check unqualified app/a.cpp '#include "raster.h"' 'write "raster/raster.h"'
check upward cmodel/raster/r.cpp '#include "rtl_rop.h"' 'includes a folder built on it'
check app-from-tb tb/main.cpp '#include "commands.h"' \
  "tb/main.cpp: #include \"commands.h\": app/ is zblend's own"
check app-from-cli cli/cli.cpp '#include "../app/commands.h"' "app/ is zblend's own"
check app-from-oracle oracle/main.cpp '#include "app/commands.h"' "app/ is zblend's own"
"$here/layout.sh" "$tmp" >/dev/null || { echo "layout_catches: the clean tree fails"; status=1; }
[[ $status -eq 0 ]] && echo "layout_catches: every rule caught"
exit $status
