#!/usr/bin/env bash
# The build `make bench` measures the RTL's speed against (docs/bench.md "Against a baseline"):
# commit REV's sources (git archive, no checkout of this tree), configured and built in
# DIR/build, zblend and zblend_bench_rtl only. Kept between runs: built once per REV.
# Usage: scripts/bench_baseline.sh REV DIR [-j JOBS]
set -euo pipefail
rev=${1:?usage: bench_baseline.sh REV DIR [-j JOBS]}
dir=${2:?usage: bench_baseline.sh REV DIR [-j JOBS]}
jobs=$(nproc)
[[ ${3:-} == -j && -n ${4:-} ]] && jobs=$4
root=$(cd "$(dirname "$0")/.." && pwd)
sha=$(git -C "$root" rev-parse --verify --quiet "$rev^{commit}") ||
  { echo "bench_baseline: error: '$rev' is not a commit of $root (git log lists them)" >&2; exit 2; }
if [[ -f $dir/rev && $(cat "$dir/rev") == "$sha" && -x $dir/build/zblend && -x $dir/build/zblend_bench_rtl ]]; then
  exit 0
fi
echo "bench_baseline: building ${sha:0:7} in $dir (once)" >&2
rm -rf "$dir"
mkdir -p "$dir/src"
git -C "$root" archive "$sha" | tar -x -C "$dir/src"
cmake -S "$dir/src" -B "$dir/build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$dir/build" -j "$jobs" --target zblend zblend_bench_rtl >/dev/null
echo "$sha" >"$dir/rev"
