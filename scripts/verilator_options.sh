#!/usr/bin/env bash
# Measures the RTL simulation speed under several Verilator option sets (docs/bench.md,
# "Verilator options"): each set gets a build tree of its own (build-vopt/NAME), its
# zblend_bench_rtl runs BM_RtlHazard, and the table goes to out/bench/verilator_options.csv.
# The winner is the default of ZBLEND_VERILATOR_OPT / _THREADS / _OPT_FAST in cmake/rtl.cmake.
# Usage: scripts/verilator_options.sh [-j JOBS] [-r REPETITIONS]
set -euo pipefail

jobs=$(nproc)
reps=5
while getopts "j:r:h" opt; do
  case $opt in
    j) jobs=$OPTARG ;;
    r) reps=$OPTARG ;;
    *) sed -n '2,7p' "$0" | sed 's/^# \{0,1\}//'; [[ $opt == h ]] && exit 0 || exit 2 ;;
  esac
done

root=$(cd "$(dirname "$0")/.." && pwd)
out=$root/out/bench
mkdir -p "$out"
csv=$out/verilator_options.csv

# name | ZBLEND_VERILATOR_OPT | ZBLEND_VERILATOR_THREADS | ZBLEND_VERILATOR_OPT_FAST
sets=(
  "O0|-O0|1|"
  "O3|-O3|1|"
  "O3-xfast|-O3;--x-assign;fast;--x-initial;fast|1|"
  "O3-xfast-threads2|-O3;--x-assign;fast;--x-initial;fast|2|"
  "O3-xfast-cxxO2|-O3;--x-assign;fast;--x-initial;fast|1|-O2"
)

rows="name,verilator_options,threads,opt_fast,fragments_per_s,build_s"
for s in "${sets[@]}"; do
  IFS='|' read -r name vopt threads fast <<<"$s"
  dir=$root/build-vopt/$name
  echo "verilator_options: $name: building ($dir)" >&2
  t0=$(date +%s)
  cmake -S "$root" -B "$dir" -DCMAKE_BUILD_TYPE=Release "-DZBLEND_VERILATOR_OPT=$vopt" \
    "-DZBLEND_VERILATOR_THREADS=$threads" "-DZBLEND_VERILATOR_OPT_FAST=$fast" >/dev/null
  cmake --build "$dir" -j "$jobs" --target zblend_bench_rtl >/dev/null
  build_s=$(( $(date +%s) - t0 ))
  echo "verilator_options: $name: running BM_RtlHazard x$reps" >&2
  rate=$("$dir/zblend_bench_rtl" --benchmark_filter=BM_RtlHazard --benchmark_repetitions="$reps" \
           --benchmark_report_aggregates_only=true --benchmark_format=json |
         /usr/bin/python3 -c 'import json,sys
print(round([b for b in json.load(sys.stdin)["benchmarks"] if b.get("aggregate_name")=="median"][0]["items_per_second"]))')
  rows+=$'\n'"$name,\"${vopt//;/ }\",$threads,$fast,$rate,$build_s"
done
printf '%s\n' "$rows" >"$csv.tmp" && mv "$csv.tmp" "$csv"
column -s, -t <"$csv"
echo "verilator_options: $csv" >&2
