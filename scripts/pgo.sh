#!/usr/bin/env bash
# The speed build's model with gcc profile-guided optimisation (make pgo; docs/bench.md "PGO"):
# in one build tree (a profile names its objects by path), the model instrumented
# (ZBLEND_PGO=generate), a training render of the built-in scene `cad` with every method on the
# RTL, then the model compiled again with that profile (ZBLEND_PGO=use). Builds zblend and
# zblend_bench_rtl there; the profile is replaced on every run. The result renders cad against
# the golden model in lock-step before it is used.
# Usage: scripts/pgo.sh [-j JOBS] [-d DIR]   (DIR: build-pgo)
set -euo pipefail

jobs=$(nproc)
root=$(cd "$(dirname "$0")/.." && pwd)
dir=$root/build-pgo
while getopts "j:d:h" opt; do
  case $opt in
    j) jobs=$OPTARG ;;
    d) dir=$(realpath -m "$OPTARG") ;;
    *) sed -n '2,8p' "$0" | sed 's/^# \{0,1\}//'; [[ $opt == h ]] && exit 0 || exit 2 ;;
  esac
done
profile=$dir/pgo
targets=(zblend zblend_bench_rtl)

echo "pgo: 1/3 the instrumented model ($dir)" >&2
rm -rf "$profile"
cmake -S "$root" -B "$dir" -DCMAKE_BUILD_TYPE=Release -DZBLEND_PGO=generate \
  "-DZBLEND_PGO_DIR=$profile" >/dev/null
cmake --build "$dir" -j "$jobs" --target "${targets[@]}" >/dev/null

echo "pgo: 2/3 training: zblend render --scene cad --backend rtl -m all" >&2
train=$dir/pgo-train
rm -rf "$train"
# One model thread: the counters are the same whatever the threads, and this keeps them exact.
"$dir/zblend" render --scene cad --backend rtl -m all --threads 1 -q --out-dir "$train"
ls "$profile" | grep -q '\.gcda$' ||
  { echo "pgo: error: the training run left no profile in $profile" >&2; exit 1; }

echo "pgo: 3/3 the model compiled with the profile" >&2
cmake -S "$root" -B "$dir" -DZBLEND_PGO=use >/dev/null
cmake --build "$dir" -j "$jobs" --target "${targets[@]}" >/dev/null
# The optimised model against the golden model, every write at its cycle: it must still be exact.
"$dir/zblend" render --scene cad --backend both -m three-pass,wboit,depth-peel-2 -q \
  --out-dir "$dir/pgo-check"
echo "pgo: $dir/zblend and $dir/zblend_bench_rtl" >&2
