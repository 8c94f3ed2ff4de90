#!/usr/bin/env bash
# The conformance kit alone (make kit, make kit-install; docs/conformance.md "The kit"): builds
# a tree configured with ZBLEND_KIT_ONLY (no Verilator, nothing Verilated), fails if anything
# Verilated was built all the same, then either installs the kit under a prefix or lays it out
# under OUT and archives it with the suite:
#   OUT/zblend-conformance-kit-VERSION.tar.gz    bin/ lib/ include/ share/zblend-conformance/
#   OUT/zblend-conformance-suite-vN.tar.gz       the suite exported by that kit, SHA256SUMS inside
# VERSION is `git describe --always --dirty` (the commit, -dirty for uncommitted changes); N is
# the suite's version (its manifest's, conformance/suite.h kSuiteVersion). The staged kit is
# checked before it is archived: its Python module finds its library by the kit's layout and
# replays three tests of the suite equal to their expect files.
# Usage: kit.sh [-j N] [-d BUILD_DIR] [--out DIR | --install PREFIX]
set -euo pipefail

jobs=$(nproc)
dir=build-kit
out=out/kit
prefix=""
while [[ $# -gt 0 ]]; do
  case $1 in
    -j) jobs=$2; shift 2 ;;
    -d) dir=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --install) prefix=$2; shift 2 ;;
    *) echo "kit: error: unknown argument '$1' (usage: kit.sh [-j N] [-d BUILD_DIR] [--out DIR | --install PREFIX])" >&2; exit 2 ;;
  esac
done
cd "$(dirname "$0")/.."
SECONDS=0

if [[ -f $dir/CMakeCache.txt ]] && ! grep -q '^ZBLEND_KIT_ONLY:BOOL=ON' "$dir/CMakeCache.txt"; then
  echo "kit: error: $dir is a build tree without ZBLEND_KIT_ONLY (the kit's tree is its own; give another -d or remove $dir)" >&2
  exit 2
fi
[[ -f $dir/CMakeCache.txt ]] || cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=Release -DZBLEND_KIT_ONLY=ON >/dev/null
cmake --build "$dir" -j "$jobs"
echo "kit: $dir configured and built in $SECONDS s"

# Nothing Verilated: no Verilator found, no generated model, no Verilator runtime in a product.
verilated() {
  grep -E '^verilator_DIR:[A-Z]+=/' "$dir/CMakeCache.txt" | sed "s|^|$dir/CMakeCache.txt: |" || true
  find "$dir" \( -name 'V*__Syms.h' -o -name 'verilated*' -o -name '*.vpp' -o -name 'V*.mk' \) -print
  find "$dir" -maxdepth 3 -type f \( -name '*.a' -o -name '*.so' -o -perm -u+x \) ! -name '*.sh' -print |
    while read -r f; do
      if nm -C "$f" 2>/dev/null | grep -q 'Verilated'; then echo "$f: Verilator's runtime"; fi
    done
}
found=$(verilated | sort -u)
if [[ -n $found ]]; then
  echo "kit: error: the kit's tree $dir built or found Verilated code, which it must not" \
       "(ZBLEND_KIT_ONLY in CMakeLists.txt configures nothing Verilated):" >&2
  echo "$found" | sed 's/^/kit:   /' >&2
  exit 1
fi
echo "kit: $dir holds nothing Verilated"

version=$(git describe --always --dirty 2>/dev/null || echo unknown)
python=python3
python3 -c 'import numpy' 2>/dev/null || python=/usr/bin/python3

if [[ -n $prefix ]]; then
  cmake --install "$dir" --prefix "$prefix" >/dev/null
  echo "kit $version" >"$prefix/share/zblend-conformance/VERSION"
  echo "kit: installed $version in $prefix: bin/zblend-conformance, lib/libzbgolden.so, include/, share/zblend-conformance/"
  exit 0
fi

name=zblend-conformance-kit-$version
rm -rf "$out"
mkdir -p "$out"
cmake --install "$dir" --prefix "$out/$name" >/dev/null
"$out/$name/bin/zblend-conformance" export "$out/suite" >/dev/null
suite_version=$("$python" -c 'import json, sys; print(json.load(open(sys.argv[1]))["version"])' "$out/suite/manifest.json")
printf 'kit %s\ncommit %s\nsuite %s\n' "$version" "$(git rev-parse HEAD 2>/dev/null || echo unknown)" \
  "$suite_version" >"$out/$name/share/zblend-conformance/VERSION"
suite=zblend-conformance-suite-v$suite_version
mv "$out/suite" "$out/$suite"
cp LICENSE "$out/$suite/LICENSE"  # the suite is zblend's work too: Apache-2.0
(cd "$out/$suite" && find . -type f ! -name SHA256SUMS -printf '%P\n' | LC_ALL=C sort | xargs sha256sum >SHA256SUMS)

# The staged kit as a team would use it: the module finds lib/ by the layout, no ZBGOLDEN_LIB.
env -u ZBGOLDEN_LIB "$python" "$out/$name/share/zblend-conformance/python/zbgolden.py" "$out/$suite" \
  cad-three-pass glass-torus-wboit hazard | sed 's/^/kit: /'

# Reproducible archives: sorted, owner 0, the commit's time, gzip without a name or time.
mtime=@$(git log -1 --format=%ct 2>/dev/null || date +%s)
for d in "$name" "$suite"; do
  tar --sort=name --owner=0 --group=0 --numeric-owner --mtime="$mtime" -C "$out" -cf - "$d" | gzip -n -9 >"$out/$d.tar.gz"
done
for d in "$name" "$suite"; do
  printf 'kit: %s.tar.gz: %s files, %s\n' "$out/$d" "$(tar -tzf "$out/$d.tar.gz" | grep -vc '/$')" \
    "$(du -h "$out/$d.tar.gz" | cut -f1)"
done
echo "kit: $version in $SECONDS s; the exporter and checker: $out/$name/bin/zblend-conformance"
