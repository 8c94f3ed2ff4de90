#!/usr/bin/env bash
# The layout's rules (docs/architecture.md "The house"), checked on the tree:
#  1. every top-level folder has its row in docs/architecture.md's "The top level", and every
#     row there names a folder that exists;
#  2. no include runs from a lower room to a higher one: cmodel/ < cli/ < tb/ < conformance/ <
#     app/ (tests/ may include anything); inside tb/, rtlmodel/ includes nothing else of tb/;
#     inside app/, lab/ and oracle/ include nothing of app/'s root (zblend's own) nor each other;
#  3. a golden-model header under an area's internal/ is included only inside cmodel/;
#  4. outside its own folder, a cmodel header is included by area ("raster/raster.h").
# Prints the rooms' include arrows (who includes whom) when the tree is clean.
set -u
root=${1:?usage: layout.sh SOURCE_DIR}
cd "$root" || exit 2
fail=0
report() { echo "layout: $*" >&2; fail=1; }

# 1. The top level against its table.
declare -A row
while IFS= read -r name; do
  row[$name]=1
done < <(sed -n '/^## The top level/,/^## /p' docs/architecture.md 2>/dev/null |
           sed -nE 's/^\| `([A-Za-z0-9_.-]+)\/` \| *[^ |].*$/\1/p')
while IFS= read -r dir; do
  [[ -n ${row[$dir]:-} ]] ||
    report "$dir/: a top-level folder without its row in docs/architecture.md \"The top level\"" \
           "(say why it is not inside rtl, tb, cmodel, scripts, tests, app or conformance)"
  unset "row[$dir]"
done < <(find . -mindepth 1 -maxdepth 1 -type d ! -name '.*' ! -name build ! -name 'build-*' \
           ! -name out -printf '%f\n' | sort)
for dir in "${!row[@]}"; do
  report "docs/architecture.md \"The top level\" names $dir/, which is not in the tree"
done

# The rooms, lowest first; tests/ is outside the order.
floor() {  # PATH -> the room's floor, or nothing
  case $1 in
    cmodel/*) echo 0 ;; cli/*) echo 1 ;; tb/*) echo 2 ;; conformance/*) echo 3 ;; app/*) echo 4 ;;
  esac
}
room() {  # PATH -> its room: top folder, or tb/rtlmodel, app/lab, app/oracle (sub-rooms)
  case $1 in
    tb/rtlmodel/*) echo tb/rtlmodel ;; app/lab/*) echo app/lab ;; app/oracle/*) echo app/oracle ;;
    *) echo "${1%%/*}" ;;
  esac
}
declare -A header  # a header's name -> its path (names are unique in the tree)
while IFS= read -r h; do
  header[$(basename "$h")]=${h#./}
done < <(find . -name '*.h' ! -path './build*' ! -path './out/*' ! -path './tests/*')
declare -A area  # a cmodel header's name -> its area
while IFS= read -r h; do
  rel=${h#cmodel/}
  [[ $rel == */internal/* ]] && continue
  area[$(basename "$rel")]=${rel%/*}
done < <(find cmodel -name '*.h' 2>/dev/null)

declare -A arrows
while IFS= read -r line; do
  file=${line%%:*}
  [[ $line =~ \#include\ \"([^\"]+)\" ]] || continue
  name=${BASH_REMATCH[1]}
  dir=${file%/*}
  # What the name resolves to: the including folder's own header, a path from the top, a
  # cmodel area's header, or a header found by its name alone (its folder on the include path).
  target=
  if [[ -f $dir/$name ]]; then
    target=$dir/$name
    [[ $name == *..* ]] && target=$(realpath -m --relative-to=. "$target")
  elif [[ $name == */* && -f $name ]]; then
    target=$name
  elif [[ $name == */* && -f cmodel/$name ]]; then
    target=cmodel/$name
  elif [[ $name != */* && -n ${header[$name]:-} ]]; then
    target=${header[$name]}
  fi
  target=${target#./}
  if [[ $name == */internal/* && $file != cmodel/* ]]; then
    report "$file: #include \"$name\": an internal header of the golden model, included outside cmodel/"
  fi
  if [[ $name != */* && -n ${area[$name]:-} && $dir != "cmodel/${area[$name]}" && ! -f $dir/$name ]]; then
    report "$file: #include \"$name\": write \"${area[$name]}/$name\""
  fi
  [[ -n $target ]] || continue  # a library's, or a generated header (Vzb_rop.h)
  from=$(room "$file") to=$(room "$target")
  [[ $from == "$to" ]] && continue
  ff=$(floor "$file") ft=$(floor "$target")
  [[ -n $ff && -n $ft ]] || continue  # tests/ includes anything
  if (( ft > ff )); then
    report "$file: #include \"$name\" ($target): $from/ sits below $to/ and includes nothing of it"
  elif [[ $from == tb/rtlmodel && $to == tb ]]; then
    report "$file: #include \"$name\" ($target): tb/rtlmodel/ (the driver) sits below the rest of tb/"
  elif [[ $from == app/* && $to == app* ]]; then
    report "$file: #include \"$name\" ($target): $from/ includes nothing of app/'s root (zblend's own) nor of the other programs in app/"
  elif [[ ${from%%/*} != "${to%%/*}" ]]; then
    arrows["${from%%/*} -> ${to%%/*}"]=1
  fi
done < <(grep -rn --include='*.cpp' --include='*.h' -E '^\s*#include "[^"]+"' \
           cmodel cli tb conformance app tests 2>/dev/null)

if [[ $fail -eq 0 ]]; then
  echo "layout: clean; the rooms' include arrows:"
  printf '  %s\n' "${!arrows[@]}" | sort
fi
exit $fail
