#!/usr/bin/env bash
# Runs the libFuzzer targets of a build tree (make fuzz, make fuzz-ci; docs/fuzzing.md).
# usage: fuzz.sh BUILD SECONDS OUT CRASHES [TARGET...]
# Each target runs SECONDS, JOBS at a time (default: the cores), from the seeds in
# tests/fuzz/corpus/TARGET/ (read only) and OUT/TARGET/, where new inputs and OUT/TARGET.log go. A
# crash, leak, timeout or broken invariant is saved to CRASHES/ and fails the run with the
# command that reproduces it.
# FUZZ_RUNS="obj=N gltf=N ..." gives a target a fixed number of runs from seed FUZZ_SEED
# (default 1) in place of SECONDS: the same work on a fast or a loaded machine.
set -u
build=${1:?usage: fuzz.sh BUILD SECONDS OUT CRASHES [TARGET...]}
seconds=${2:?seconds per target}
out=${3:?output directory}
crashes=${4:?crash directory}
shift 4
targets=("$@")
[[ ${#targets[@]} -gt 0 ]] || targets=(obj gltf trace raster)
jobs=${JOBS:-$(nproc)}
root=$(cd "$(dirname "$0")/.." && pwd)

mkdir -p "$out" "$crashes"
budget() {  # the libFuzzer options that bound target $1's run
  local entry
  for entry in ${FUZZ_RUNS:-}; do
    [[ ${entry%%=*} == "$1" ]] && { echo "-runs=${entry#*=} -seed=${FUZZ_SEED:-1}"; return; }
  done
  echo "-max_total_time=$seconds"
}
run() {
  local t=$1 dict=()
  [[ -f "$root/tests/fuzz/$t.dict" ]] && dict=("-dict=$root/tests/fuzz/$t.dict")
  mkdir -p "$out/$t"
  # shellcheck disable=SC2046  # budget() gives separate options
  "$build/fuzz_$t" "${dict[@]}" $(budget "$t") -timeout=10 -rss_limit_mb=2048 \
    -print_final_stats=1 -artifact_prefix="$crashes/$t-" "$out/$t" "$root/tests/fuzz/corpus/$t" \
    >"$out/$t.log" 2>&1
  echo $? >"$out/$t.rc"
}

for t in "${targets[@]}"; do
  [[ -x "$build/fuzz_$t" ]] || { echo "fuzz: error: no $build/fuzz_$t (build it: make fuzz-build)" >&2; exit 2; }
done
running=0
for t in "${targets[@]}"; do
  rm -f "$out/$t.rc"
  run "$t" &
  running=$((running + 1))
  if [[ $running -ge $jobs ]]; then wait -n; running=$((running - 1)); fi
done
wait

failed=0
for t in "${targets[@]}"; do
  rc=$(cat "$out/$t.rc" 2>/dev/null || echo 1)
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$out/$t.log")
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$out/$t.log")
  found=$(ls "$out/$t" | wc -l)
  if [[ $rc -eq 0 ]]; then
    printf 'fuzz: %-6s %10s runs  %7s/s  %5s inputs in %s/%s  no crash\n' "$t" "${runs:-?}" "${rate:-?}" \
      "$found" "$out" "$t"
  else
    failed=1
    artifact=$(sed -n 's/.*Test unit written to \(.*\)$/\1/p' "$out/$t.log" | tail -1)
    echo "fuzz: $t FAILED (exit $rc); from $out/$t.log:"
    # From the sanitizer's or libFuzzer's report on, without the progress lines.
    awk '/ERROR|runtime error|invariant broken|terminate called|deadly signal|Timeout|out-of-memory|leak/ { on = 1 }
         on && !/^(#[0-9]+|\tNEW_|INFO:)/' "$out/$t.log" | head -60 | sed 's/^/  /'
    if [[ -n $artifact ]]; then
      echo "fuzz: the input: $artifact"
      echo "fuzz: reproduce: $build/fuzz_$t $artifact"
    fi
  fi
done
exit $failed
