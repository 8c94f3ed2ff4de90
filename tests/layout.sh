#!/usr/bin/env bash
# The layout's rules (docs/layout.md), checked on the tree:
#  1. a golden-model header under an area's internal/ is included only inside cmodel/;
#  2. outside its own folder, a cmodel header is included by area ("raster/raster.h");
#  3. the golden model includes nothing of the folders built on it;
#  4. app/ is zblend's own: cli/ (below every program) and the other programs (tb/, systemc/,
#     oracle/, bench/) include none of its headers.
set -u
root=${1:?usage: layout.sh SOURCE_DIR}
cd "$root" || exit 2
fail=0
report() { echo "layout: $*" >&2; fail=1; }

while IFS= read -r hit; do
  report "$hit: an internal header of the golden model, included outside cmodel/"
done < <(grep -rn --include='*.cpp' --include='*.h' -E '#include "[a-z_]+/internal/' \
           app lab tb rtlmodel systemc oracle bench fuzz conformance tests 2>/dev/null)

# Every cmodel header's name, and the area it lives in.
declare -A area
while IFS= read -r h; do
  rel=${h#cmodel/}
  [[ $rel == */internal/* ]] && continue
  area[$(basename "$rel")]=${rel%/*}
done < <(find cmodel -name '*.h')
while IFS= read -r line; do
  file=${line%%:*}
  name=$(sed -E 's/.*#include "([^"]+)".*/\1/' <<<"$line")
  [[ $name == */* ]] && continue
  [[ -n ${area[$name]:-} ]] || continue
  dir=$(dirname "$file")
  [[ $dir == "cmodel/${area[$name]}" ]] && continue
  [[ -f $dir/$name ]] && continue  # a header of the including folder with the same name
  report "$file: #include \"$name\": write \"${area[$name]}/$name\""
done < <(grep -rn --include='*.cpp' --include='*.h' -E '#include "[^"/]+"' . | grep -v '^./build' | sed 's|^\./||')

while IFS= read -r hit; do
  report "$hit: the golden model includes a folder built on it"
done < <(grep -rn --include='*.cpp' --include='*.h' \
           -E '#include "(rtl_|lab|sizing|cosim|suites|commands|zb_|cli\.h|output_paths|scene_options)' cmodel)

# Every app header's name: included by its name alone ("commands.h") or by a path to app/.
declare -A app_header
while IFS= read -r h; do
  app_header[$(basename "$h")]=1
done < <(find app -name '*.h' 2>/dev/null)
while IFS= read -r line; do
  file=${line%%:*}
  name=$(sed -E 's/.*#include "([^"]+)".*/\1/' <<<"$line")
  base=${name##*/}
  if [[ $name != app/* && $name != */app/* ]]; then
    [[ $name == */* || -z ${app_header[$base]:-} ]] && continue  # not app's
    [[ -f $(dirname "$file")/$base ]] && continue  # the including folder's, of the same name
  fi
  report "$file: #include \"$name\": app/ is zblend's own; what programs share is in cli/"
done < <(grep -rn --include='*.cpp' --include='*.h' -E '#include "[^"]+"' \
           cli tb systemc oracle bench 2>/dev/null)

[[ $fail -eq 0 ]] && echo "layout: clean"
exit $fail
