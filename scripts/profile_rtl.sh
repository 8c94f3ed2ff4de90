#!/usr/bin/env bash
# Where the RTL simulation's time goes, per module (make profile-rtl; docs/bench.md "Where the
# simulation's time goes"). Builds zblend_bench_rtl in build-prof with Verilator's
# --prof-cfuncs (each generated function named after its module and line), records `cad`
# three-pass 640x480 on one model with perf, and sums the samples by module, by Verilator
# region (ico: logic on input ports, every evaluation; nba: at the clock edge) and by host code.
# Writes out/profile/modules.csv and prints the table.
# Usage: scripts/profile_rtl.sh [-j JOBS] [-a 0|1]
#   -a 1: the assertion build (zblend_bench_rtl_assert); 0, the default: the speed build
set -euo pipefail

jobs=$(nproc)
assertions=0
while getopts "j:a:h" opt; do
  case $opt in
    j) jobs=$OPTARG ;;
    a) assertions=$OPTARG ;;
    *) sed -n '2,9p' "$0" | sed 's/^# \{0,1\}//'; [[ $opt == h ]] && exit 0 || exit 2 ;;
  esac
done
[[ $assertions == 0 || $assertions == 1 ]] || { echo "profile_rtl: -a takes 0 or 1" >&2; exit 2; }
command -v perf >/dev/null || { echo "profile_rtl: perf not found (scripts/setup.sh profile)" >&2; exit 1; }

root=$(cd "$(dirname "$0")/.." && pwd)
dir=$root/build-prof
out=$root/out/profile
mkdir -p "$out"
echo "profile_rtl: building zblend_bench_rtl with --prof-cfuncs ($dir)" >&2
cmake -S "$root" -B "$dir" -DCMAKE_BUILD_TYPE=Release \
  "-DZBLEND_VERILATOR_OPT=-O3;--x-assign;fast;--x-initial;fast;--prof-cfuncs" >/dev/null
bench=zblend_bench_rtl
[[ $assertions == 0 ]] || bench=zblend_bench_rtl_assert
cmake --build "$dir" -j "$jobs" --target $bench >/dev/null
filter="BM_CadThreePassRtl/w:640/h:480/models:1"
echo "profile_rtl: perf record of $bench $filter" >&2
perf record -q -o "$out/perf.data" "$dir/$bench" --benchmark_filter="$filter" \
  --benchmark_min_time=2 >/dev/null 2>&1
perf report -q -i "$out/perf.data" --no-children --sort symbol 2>/dev/null |
  /usr/bin/python3 -c '
import collections, re, sys
mods, regions = collections.Counter(), collections.Counter()
for line in sys.stdin:
    m = re.match(r"\s*([\d.]+)%\s+\[.\]\s+(\S+)", line)
    if not m:
        continue
    share, sym = float(m.group(1)), m.group(2)
    prof = re.search(r"PROF__(\w+?)__l\d+", sym)
    if prof:
        mods["rtl " + prof.group(1)] += share
        region = re.search(r"___(ico|nba|act)_", sym)
        regions[region.group(1) if region else "other"] += share
    elif sym.startswith(("Vzb_rop", "Verilated", "VerilatedContext")):
        mods["verilator scheduling"] += share
    else:
        # The benchmark times the golden model after the RTL (rtl_over_golden): not the RTL.
        mods["host (driver, raster, golden timing)"] += share
rows = sorted(mods.items(), key=lambda kv: -kv[1])
with open(sys.argv[1], "w") as f:
    f.write("part,share_percent\n")
    for k, v in rows:
        f.write(f"{k},{v:.2f}\n")
    for k, v in sorted(regions.items()):
        f.write(f"region {k},{v:.2f}\n")
for k, v in rows:
    print(f"{v:6.2f} %  {k}")
print("regions of the design code: " + ", ".join(f"{k} {v:.1f} %" for k, v in sorted(regions.items())))
' "$out/modules.csv"
echo "profile_rtl: $out/modules.csv" >&2
