#!/usr/bin/env bash
# layout.sh must fail on a tree that breaks each of its rules, and pass on the clean one.
set -u
here=$(cd "$(dirname "$0")" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/cmodel/raster/internal" "$tmp/cli" "$tmp/tb/rtlmodel" "$tmp/conformance" \
         "$tmp/app/lab" "$tmp/app/oracle" "$tmp/docs"
echo '#pragma once' >"$tmp/cmodel/raster/internal/edge.h"
echo '#pragma once' >"$tmp/cmodel/raster/raster.h"
echo '#pragma once' >"$tmp/cli/cli.h"
echo '#pragma once' >"$tmp/tb/cosim.h"
echo '#pragma once' >"$tmp/tb/rtlmodel/rtl_rop.h"
echo '#pragma once' >"$tmp/conformance/suite.h"
echo '#pragma once' >"$tmp/app/commands.h"
echo '#pragma once' >"$tmp/app/lab/lab.h"
echo '#pragma once' >"$tmp/app/oracle/gl_render.h"
table() {
  printf '# Architecture\n\n## The top level\n\n| folder | why |\n|---|---|\n'
  for d in "$@"; do printf '| `%s/` | a reason |\n' "$d"; done
  printf '\n## Next\n'
}
table cmodel cli tb conformance app docs >"$tmp/docs/architecture.md"
# Downward includes of every kind, which the clean tree must take.
printf '#include "rtl_rop.h"\n#include "cli.h"\n#include "raster/raster.h"\n' >"$tmp/tb/main.cpp"
printf '#include "cosim.h"\n#include "suite.h"\n#include "lab.h"\n' >"$tmp/app/main.cpp"
status=0
check() {  # NAME FILE CONTENT PATTERN
  printf '%s\n' "$3" >"$tmp/$2"
  out=$("$here/layout.sh" "$tmp" 2>&1) && { echo "layout_catches: $1: passed, should fail"; status=1; }
  grep -qF "$4" <<<"$out" || { echo "layout_catches: $1: no '$4' in: $out"; status=1; }
  rm -f "$tmp/$2"
}
check internal app/a.cpp '#include "raster/internal/edge.h"' 'an internal header'
check unqualified app/a.cpp '#include "raster.h"' 'write "raster/raster.h"'
check cmodel-up cmodel/raster/r.cpp '#include "rtl_rop.h"' 'cmodel/ sits below tb/'
check cli-up cli/cli.cpp '#include "../app/commands.h"' 'cli/ sits below app/'
check tb-up tb/main.cpp '#include "commands.h"' \
  'tb/main.cpp: #include "commands.h" (app/commands.h): tb/ sits below app/'
check tb-to-kit tb/a.cpp '#include "suite.h"' 'tb/ sits below conformance/'
check kit-to-lab conformance/a.cpp '#include "lab.h"' 'conformance/ sits below app/'
check driver-up tb/rtlmodel/a.cpp '#include "cosim.h"' 'tb/rtlmodel/ (the driver) sits below'
check oracle-to-app app/oracle/main.cpp '#include "app/commands.h"' "nothing of app/'s root"
check lab-to-oracle app/lab/a.cpp '#include "gl_render.h"' "nothing of app/'s root"
mkdir "$tmp/extra"
check top-level docs/unused.md '' 'extra/: a top-level folder without its row'
rmdir "$tmp/extra"
table cmodel cli tb conformance app docs gone >"$tmp/docs/architecture.md"
check stale-row docs/unused.md '' 'names gone/, which is not in the tree'
table cmodel cli tb conformance app docs >"$tmp/docs/architecture.md"
"$here/layout.sh" "$tmp" >/dev/null || { echo "layout_catches: the clean tree fails"; status=1; }
[[ $status -eq 0 ]] && echo "layout_catches: every rule caught"
exit $status
