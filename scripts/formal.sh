#!/usr/bin/env bash
# zblend formal proofs (make formal; docs/formal.md): the flow SymbiYosys would generate, written
# out for Debian's yosys 0.23, yosys-smtbmc and z3. Per job:
#   1. yosys: read_verilog -formal -sv -DSYNTHESIS -Itb/formal rtl/zb_pkg.sv rtl/*.sv tb/formal/<harness>.sv
#      (the RTL's concurrent SVA is beyond yosys 0.23's reader: the harnesses restate it); chparam;
#      hierarchy; flatten; the harness's taps (`// formal-tap: <wire> <path>` lines, in the harness
#      or a tb/formal/ header it includes, become `connect -nounset -set`, so a harness reads DUT
#      internals after flattening; a path ending in [*] is a memory's words, connected after
#      memory_map, sat only) and, for a defect run,
#      a forced signal; proc; prep; memory_nordff; async2sync; chformal -assume -early; opt -full
#      (z3 4.8.12 spends minutes on some models' transition function without it); setundef
#      -anyseq; dffunmap; write_smt2 -wires.
#   2. yosys-smtbmc -s z3: induction = base case (BMC, -t D) then the inductive step (-i -t D);
#      bmc = -t D; cover = -c -t D (every cover reached). Counterexamples and cover traces as VCD.
# One solver process at a time. Writes OUT/summary.csv, OUT/report.md, and per job OUT/<job>/
# (yosys.log, the model, each solver log and VCD).
set -euo pipefail

usage() {
  cat <<'USAGE'
usage: scripts/formal.sh [options]
  --ci          the CI-sized set (make test; at most 5 minutes on 2 cores): smaller depths,
                one channel of the arithmetic units
  --defect      instead of the proofs, inject each known defect and require its proof to FAIL
                with a counterexample (the checkers can fail)
  --out DIR     output directory (default out/formal)
  --only NAME   run only the jobs whose name starts with NAME (repeatable)
  --timeout S   solver time limit per call, seconds (default 3600; --ci 300)
  --list        print the jobs of the selected set and exit
  -h, --help    this text
Exit status: 0 every proof passed (or, with --defect, every defect caught); 1 a proof failed,
did not close, timed out or a cover was unreached (or a defect was missed); 2 usage.
USAGE
}

root=$(cd "$(dirname "$0")/.." && pwd)
out=out/formal
ci=0
defect=0
only=()
timeout_s=""
list=0
while [[ $# -gt 0 ]]; do
  case $1 in
    --ci) ci=1; shift ;;
    --defect) defect=1; shift ;;
    --out) [[ $# -ge 2 && -n $2 ]] || { echo "formal.sh: --out needs a directory" >&2; exit 2; }
           out=$2; shift 2 ;;
    --only) [[ $# -ge 2 && -n $2 ]] || { echo "formal.sh: --only needs a job name" >&2; exit 2; }
            only+=("$2"); shift 2 ;;
    --timeout) [[ $# -ge 2 && $2 =~ ^[0-9]+$ ]] || { echo "formal.sh: --timeout needs seconds" >&2; exit 2; }
               timeout_s=$2; shift 2 ;;
    --list) list=1; shift ;;
    -h|--help) usage; exit 0 ;;
    *) echo "formal.sh: unknown option '$1'" >&2; usage >&2; exit 2 ;;
  esac
done
[[ -n $timeout_s ]] || timeout_s=$(( ci ? 300 : 3600 ))

# The jobs: name | method | depth (CI) | depth (full) | in CI | harness | parameters | engine.
# A job in CI runs with its CI depth there; every job runs in the full set with its full depth.
# Parameters: NAME=VALUE for the harness (chparam). Engines: smtbmc (yosys-smtbmc -s z3) or sat
# (yosys's own `sat`, MiniSAT): z3 4.8.12 takes minutes, or hangs, on the transition function
# of zb_input's and zb_rop's models before solving anything (docs/formal.md "Engines").
RopSmall="TILE=2 BEAT=2 DEPTH_BITS=8 COV_SAMPLES=1 CNT_W=2"
jobs=(
  "mul8|induction|2|2|yes|zb_mul8_check||smtbmc"
  "mul_pairs|induction|2|2|no|zb_mul8_check|K_W=4 V_W=9|smtbmc"
  "mul_wide|induction|2|2|no|zb_mul8_check|K_W=12 V_W=4|smtbmc"
  "premul_c0|induction|4|4|yes|zb_premul_check|CHAN=0|smtbmc"
  "premul_c1|induction|4|4|no|zb_premul_check|CHAN=1|smtbmc"
  "premul_c2|induction|4|4|no|zb_premul_check|CHAN=2|smtbmc"
  "premul_c3|induction|4|4|no|zb_premul_check|CHAN=3|smtbmc"
  "blend_c0|induction|4|4|yes|zb_blend_check|CHAN=0|smtbmc"
  "blend_c1|induction|4|4|no|zb_blend_check|CHAN=1|smtbmc"
  "blend_c2|induction|4|4|no|zb_blend_check|CHAN=2|smtbmc"
  "blend_c3|induction|4|4|no|zb_blend_check|CHAN=3|smtbmc"
  "blend_acc|induction|4|4|yes|zb_blend_check|ACC=1 CHAN=0|smtbmc"
  "resolve_c0|induction|1|1|yes|zb_resolve_check|CHAN=0|smtbmc"
  "resolve_c1|induction|1|1|no|zb_resolve_check|CHAN=1|smtbmc"
  "resolve_c2|induction|1|1|no|zb_resolve_check|CHAN=2|smtbmc"
  "resolve_c3|induction|1|1|no|zb_resolve_check|CHAN=3|smtbmc"
  "resolve_lanes|induction|1|1|no|zb_resolve_check|BEAT=2 CHAN=3|smtbmc"
  "skid|induction|2|2|yes|zb_skid_check||sat"
  "stream|induction|4|4|yes|zb_stream_check|$RopSmall WINDOW=2|sat"
  "raw|induction|4|4|yes|zb_raw_check|$RopSmall WINDOW=2|sat"
  "window|induction|4|4|yes|zb_window_check|WINDOW=2|sat"
  "covers|cover|20|20|yes|zb_paths_cover|$RopSmall WINDOW=2|sat"
  "window_w4|induction|4|4|no|zb_window_check|WINDOW=4|sat"
  "stream_w4|induction|4|4|no|zb_stream_check|$RopSmall WINDOW=4|sat"
  "raw_w4|induction|4|4|no|zb_raw_check|$RopSmall WINDOW=4|sat"
  "layers|induction|4|4|yes|zb_layers_check|DEPTH_BITS=8 LAYERS=2|sat"
  "layers_k4|induction|4|4|no|zb_layers_check|DEPTH_BITS=8 LAYERS=4|sat"
)

# The defects: name | job it must fail | how (define NAME: a harness define; force PATH=VALUE:
# a DUT signal tied after flattening, its drivers cut) | the assertion expected to fail |
# for a sat induction job, the depth of the BMC from reset (default: its depth + 4).
defects=(
  "mul8_contract|mul8|define ZB_FORMAL_DEFECT_MUL8|ProductIsKTimesV"
  "premul_rounding|premul_c0|define ZB_FORMAL_DEFECT_PREMUL|PremulIsM"
  "blend_rounding|blend_c0|define ZB_FORMAL_DEFECT_BLEND|BlendIsSpec"
  "blend_product|blend_acc|define ZB_FORMAL_DEFECT_PRODUCT|ProductIsSpec"
  "resolve_saturation|resolve_c0|define ZB_FORMAL_DEFECT_RESOLVE|ResolveIsSpec"
  "skid_drops|skid|force dut.s_valid_d=1'b0|"
  "stream_skid_drops|stream|force dut.u_input.s_valid_d=1'b0|"
  "window_hits_lost|window|force dut.hit_q=6'b0|"
  "raw_depth_forward_off|raw|force dut.u_depth.dfwd_hit_q=1'b0||18"
  "raw_color_bypass_off|raw|force dut.u_color.u_forward.byp_hit_q=1'b0||18"
  "raw_accum_bypass_off|raw|force dut.u_accum.u_forward.byp_hit_q=1'b0||18"
  "raw_interlock_off|raw|force dut.u_window.hit_q=6'b0||18"
  "layers_merge_wrong_slot|layers|force dut.x9_kk_q=4'd2|"
)

field() { cut -d'|' -f$(( $2 + 1 )) <<<"$1"; }
selected() {
  local name=$1
  [[ ${#only[@]} -eq 0 ]] && return 0
  local o; for o in "${only[@]}"; do [[ $name == "$o"* ]] && return 0; done
  return 1
}
find_job() {
  local j; for j in "${jobs[@]}"; do [[ $(field "$j" 0) == "$1" ]] && { echo "$j"; return 0; }; done
  return 1
}

# The run list: "job line|defect name|defect how|expected assertion".
runs=()
if (( defect )); then
  for d in "${defects[@]}"; do
    dname=$(field "$d" 0)
    selected "$dname" || continue
    j=$(find_job "$(field "$d" 1)") || { echo "formal.sh: defect $dname names no job" >&2; exit 2; }
    runs+=("$j|$dname|$(field "$d" 2)|$(field "$d" 3)|$(field "$d" 4)")
  done
else
  for j in "${jobs[@]}"; do
    selected "$(field "$j" 0)" || continue
    (( ci )) && [[ $(field "$j" 4) != yes ]] && continue
    runs+=("$j|||")
  done
fi
if [[ ${#runs[@]} -eq 0 ]]; then
  echo "formal.sh: no job matches --only ${only[*]:-} (--list shows them)" >&2
  exit 2
fi
if (( list )); then
  for r in "${runs[@]}"; do
    printf '%-16s %-10s depth %-3s %-16s %-22s %s\n' "$(field "$r" 0)" "$(field "$r" 1)" \
      "$(field "$r" $(( ci ? 2 : 3 )))" "$(field "$r" 5)" "$(field "$r" 6)" \
      "$(field "$r" 7) $(field "$r" 8)$( [[ -n $(field "$r" 8) ]] && echo ": $(field "$r" 9)")$(
        [[ -n $(field "$r" 11) ]] && echo " (bmc $(field "$r" 11))")"
  done
  exit 0
fi

for tool in yosys yosys-smtbmc z3; do
  command -v "$tool" >/dev/null || { echo "formal.sh: $tool not found (scripts/setup.sh)" >&2; exit 1; }
done

cd "$root"
mkdir -p "$out"
rtl="rtl/zb_pkg.sv $(ls rtl/*.sv | grep -v '/zb_pkg.sv$' | tr '\n' ' ')"  # the package first
t0=$SECONDS
step() { printf 'formal: [%4ds] %s\n' $((SECONDS - t0)) "$*"; }

# Expand the harness parameters: TILE=n sets TILE_W and TILE_H.
chparams() {
  local p out_p=""
  for p in $1; do
    case $p in
      TILE=*) out_p+=" -set TILE_W ${p#TILE=} -set TILE_H ${p#TILE=}" ;;
      *=*) out_p+=" -set ${p%%=*} ${p#*=}" ;;
    esac
  done
  echo "$out_p"
}

# One solver call: run_smtbmc LOG VCD ARGS... ; prints PASSED, FAILED or TIMEOUT.
run_smtbmc() {
  local log=$1 vcd=$2; shift 2
  local rc=0
  timeout "$timeout_s" yosys-smtbmc -s z3 --noprogress "$@" --dump-vcd "$vcd" "$model" >"$log" 2>&1 || rc=$?
  if (( rc == 124 )); then echo TIMEOUT
  elif grep -q 'Status: PASSED' "$log"; then echo PASSED
  else echo FAILED
  fi
}

summary="$out/summary.csv"
if (( defect )); then
  echo "defect,group,method,depth,status,seconds,failed_assertion,counterexample" >"$summary"
else
  echo "group,method,depth,status,seconds,engine,parameters" >"$summary"
fi
failures=0
rows=()
# Yosys's `sat` on the job's RTLIL model: sat_run LOG VCD ARGS...; prints PASSED, FAILED,
# TIMEOUT or ERROR (FAILED: a model was found, i.e. a counterexample or, for -prove of a cover
# wire, its trace).
sat_run() {
  local log=$1 vcd=$2; shift 2
  local rc=0
  timeout "$timeout_s" yosys -q -l "$log" -p "read_rtlil $model; sat $* -dump_vcd $vcd -show-ports $top" \
    >/dev/null 2>&1 || rc=$?
  if (( rc == 124 )); then echo TIMEOUT
  elif grep -q '^ERROR' "$log"; then echo ERROR
  elif grep -q 'Induction step proven: SUCCESS' "$log"; then echo PASSED
  elif grep -q 'model found: FAIL' "$log"; then echo FAILED
  elif grep -q 'no model found: SUCCESS' "$log" && ! grep -q -- '-tempinduct' <<<"$*"; then echo PASSED
  else echo FAILED
  fi
}

# The second yosys pass of a job with memory taps: each tap wire takes the memory's words
# (as many as mapped.il holds, word 0 at the low end), then the sat backend's remaining steps.
memtap_pass() {
  [[ -n $memtaps ]] || return 0
  local wire path words w i conn=""
  while read -r wire path; do
    # The words' widths, in word order: lines `wire width W \<path>[i]`.
    words=$(P="\\$path[" awk '$1 == "wire" && $2 == "width" && index($4, ENVIRON["P"]) == 1 &&
        substr($4, length(ENVIRON["P"]) + 1) ~ /^[0-9]+\]$/ { n++ } END { print n + 0 }' "$dir/mapped.il")
    w=$(P="\\$path[0]" awk '$1 == "wire" && $2 == "width" && $4 == ENVIRON["P"] { print $3; exit }' "$dir/mapped.il")
    (( words > 0 )) || { echo "formal: $job: no memory $path in the model" >&2; return 1; }
    for (( i = 0; i < words; i++ )); do
      conn+="connect -nounset -set $wire[$(( (i + 1) * w - 1 )):$(( i * w ))] $path[$i]; "
    done
  done <<<"$memtaps"
  yosys -q -l "$dir/yosys_memtaps.log" -p "read_rtlil $dir/mapped.il; $conn
      opt -keepdc -fast; async2sync; chformal -cover -remove; chformal -assume -early;
      opt_clean; setundef -anyseq; opt -keepdc -fast; check; write_rtlil $model" >/dev/null 2>&1
}

for r in "${runs[@]}"; do
  name=$(field "$r" 0); method=$(field "$r" 1); top=$(field "$r" 5); params=$(field "$r" 6)
  engine=$(field "$r" 7)
  depth=$(field "$r" $(( ci ? 2 : 3 )))
  dname=$(field "$r" 8); dhow=$(field "$r" 9); dexpect=$(field "$r" 10); ddepth=$(field "$r" 11)
  job=$name; [[ -n $dname ]] && job="defect_$dname"
  dir="$out/$job"
  rm -rf "$dir"; mkdir -p "$dir"
  harness="tb/formal/$top.sv"
  [[ -f $harness ]] || { echo "formal.sh: $harness missing" >&2; exit 1; }

  defines="" force=""
  case $dhow in
    define\ *) defines="-D${dhow#define }" ;;
    force\ *) lhs=${dhow#force }; force="connect -set ${lhs%%=*} ${lhs#*=};" ;;
  esac
  # Taps sit in the harness or in the tb/formal/ headers it includes. A path ending in [*] is a
  # memory: its words, word 0 lowest, taken after memory_map (sat only).
  srcs="$harness"
  for f in $(sed -n 's|^ *`include "\([A-Za-z0-9_.]*\)".*|tb/formal/\1|p' "$harness"); do
    [[ -f $f ]] && srcs+=" $f"
  done
  taps=$(sed -n 's|^ *// formal-tap: *\([A-Za-z0-9_]*\) *\([][A-Za-z0-9_.]*\) *$|connect -nounset -set \1 \2;|p' $srcs)
  memtaps=$(sed -n 's|^ *// formal-tap: *\([A-Za-z0-9_]*\) *\([][A-Za-z0-9_.]*\)\[\*\] *$|\1 \2|p' $srcs)
  [[ -z $memtaps || $engine == sat ]] || { echo "formal.sh: $job: memory taps need the sat engine" >&2; exit 1; }
  # `// formal-cover: <wire> [length]` lines: the wires a cover job must reach (each within
  # its own length, at most the job's depth).
  covers=$(sed -n 's|^ *// formal-cover: *\([A-Za-z0-9_]*\) *\([0-9]*\) *$|\1:\2|p' "$harness")
  if [[ $engine == sat ]]; then
    model="$dir/model.il"
    backend="memory_map; opt -keepdc -fast; async2sync; chformal -cover -remove; chformal -assume -early;
      opt_clean; setundef -anyseq; opt -keepdc -fast; check; write_rtlil $model"
    # With memory taps: stop after memory_map (mapped.il), connect the words, then the rest.
    [[ -n $memtaps ]] && backend="memory_map; write_rtlil $dir/mapped.il"
  else
    model="$dir/model.smt2"
    backend="memory_nordff; async2sync; chformal -assume -early; opt_clean;
      setundef -anyseq; opt -keepdc -fast; check; hierarchy -simcheck; write_rtlil $dir/model.il;
      dffunmap; write_smt2 -wires $model"
  fi

  step "$job: $method ($engine), depth $depth${params:+, $params}${dname:+, defect: $dhow}${ddepth:+ (bmc $ddepth)}"
  start=$SECONDS
  note=""
  if ! yosys -q -l "$dir/yosys.log" -p "
      read_verilog -formal -sv -DSYNTHESIS -Itb/formal $defines $rtl $harness;
      chparam $(chparams "$params") $top;
      hierarchy -check -top $top; proc; flatten; rename -top $top;
      $force $taps
      prep -top $top; $backend" >/dev/null 2>&1 || ! memtap_pass; then
    status=FAILED
    note="yosys failed: $dir/yosys*.log"
    echo "formal: $job: $note" >&2
  elif ylog="$dir/$( [[ -n $memtaps ]] && echo yosys_memtaps || echo yosys).log" &&
       grep -q 'is used but has no driver' "$ylog"; then
    # setundef -anyseq would make such a wire a free input: the model is not the design.
    status=FAILED
    note="undriven wires in the model: $ylog"
    echo "formal: $job: $note" >&2
  elif dead=$(awk '/cell \$assert /{a=$3} /connect \EN 1.0/{if (a) print a} /end/{a=""}' "$dir/model.il") &&
       [[ -n $dead ]]; then
    status=FAILED
    note="assertions never enabled: $(tr '\n' ' ' <<<"$dead")"
    echo "formal: $job: $note" >&2
  elif [[ $engine == sat ]]; then
    case $method in
      induction)
        if (( defect )); then
          # A counterexample from reset: BMC past the induction depth (a few fragments deep),
          # or as deep as the defect needs (two fragments to a pixel, the second at its check).
          depth=${ddepth:-$((depth + 4))}
          s=$(sat_run "$dir/bmc.log" "$dir/bmc.vcd" -seq "$depth" -prove-asserts -set-assumes)
          [[ $s == PASSED ]] && status=bounded || { status=FAILED; note="$s: $dir/bmc.vcd"; }
        else
        s=$(sat_run "$dir/induction.log" "$dir/induction.vcd" -tempinduct -prove-asserts -set-assumes -maxsteps "$depth")
        if [[ $s == PASSED ]]; then status=proven
        elif grep -q 'model found: FAIL' "$dir/induction.log" && ! grep -q 'Trying induction' "$dir/induction.log"; then
          status=FAILED; note="base case $s: $dir/induction.vcd"
        else status=FAILED; note="induction did not close at depth $depth ($s)"; fi
        fi ;;
      bmc)
        s=$(sat_run "$dir/bmc.log" "$dir/bmc.vcd" -seq "$depth" -prove-asserts -set-assumes)
        if [[ $s == PASSED ]]; then status=bounded
        else status=FAILED; note="$s: $dir/bmc.vcd"; fi ;;
      cover)
        unreached=""
        for cl in $covers; do
          c=${cl%%:*} len=${cl#*:}
          [[ -n $len && $len -le $depth ]] || len=$depth
          s=$(sat_run "$dir/$c.log" "$dir/$c.vcd" -seq "$len" -set-assumes -prove "$c" 0)
          # A model of `c != 0` is the cover's trace.
          [[ $s == FAILED ]] || unreached+="$c "
        done
        [[ -n $covers ]] || unreached="(no formal-cover line in $harness)"
        if [[ -z $unreached ]]; then status=reached
        else status=FAILED; note="unreached within $depth: $unreached"; fi ;;
      *) echo "formal.sh: job $name: unknown method $method" >&2; exit 1 ;;
    esac
  else
    case $method in
      induction)
        # A defect run wants a counterexample from reset: the base case one step deeper
        # (where the assertions first act), and no inductive step.
        (( defect )) && depth=$((depth + 1))
        s=$(run_smtbmc "$dir/base.log" "$dir/base.vcd" -t "$depth")
        if [[ $s == PASSED ]] && (( defect )); then
          status=bounded
        elif [[ $s == PASSED ]]; then
          s=$(run_smtbmc "$dir/induction.log" "$dir/induction.vcd" -i -t "$depth")
          if [[ $s == PASSED ]]; then status=proven
          else status=FAILED; note="induction did not close at depth $depth ($s): $dir/induction.vcd"; fi
        else
          status=FAILED; note="base case $s: $dir/base.vcd"
        fi ;;
      bmc)
        s=$(run_smtbmc "$dir/bmc.log" "$dir/bmc.vcd" -t "$depth")
        if [[ $s == PASSED ]]; then status=bounded
        else status=FAILED; note="$s: $dir/bmc.vcd"; fi ;;
      cover)
        s=$(run_smtbmc "$dir/cover.log" "$dir/cover_%.vcd" -c -t "$depth")
        if [[ $s == PASSED ]]; then status=reached
        else
          status=FAILED
          note="$s: unreached: $(grep -o 'Unreached cover statement at [^ ]*' "$dir/cover.log" | sed 's/.* at //' | tr '\n' ' ')"
        fi ;;
      *) echo "formal.sh: job $name: unknown method $method" >&2; exit 1 ;;
    esac
  fi
  secs=$((SECONDS - start))
  if [[ -n $dname ]]; then
    # A defect is caught when its proof fails with a counterexample (smtbmc also names the
    # assertion, which must be the expected one).
    failed=$(grep -ho 'Assert failed in [^ ]*: [^ ]*' "$dir"/*.log 2>/dev/null | sed 's/.*: //' | sort -u | tr '\n' ' ' | sed 's/ $//' || true)
    cex=$(ls "$dir"/*.vcd 2>/dev/null | head -1 || true)
    if [[ $status == FAILED && -n $cex && ( -z $dexpect || " $failed " == *" $dexpect "* ) ]]; then
      dstatus=caught
    else
      dstatus=MISSED; failures=$((failures + 1))
    fi
    echo "$dname,$name,$method,$depth,$dstatus,$secs,$failed,$cex" >>"$summary"
    rows+=("| $dname | $name | $dhow | $dstatus | ${failed:-(sat: unnamed)} | $secs |")
    step "$job: $dstatus (${failed:+$failed, }counterexample ${cex:-none}) in ${secs}s"
  else
    [[ $status == FAILED ]] && failures=$((failures + 1))
    echo "$name,$method,$depth,$status,$secs,$engine,$params" >>"$summary"
    rows+=("| $name | $method | $engine | $depth | $status | $secs | ${params:-} | ${note:-} |")
    step "$job: $status in ${secs}s${note:+ ($note)}"
  fi
done

{
  echo "# zblend formal report"
  echo
  echo "$(date -u '+%Y-%m-%d %H:%M UTC'), $(yosys -V | cut -d' ' -f1-2), z3 $(z3 --version | cut -d' ' -f3);"
  echo "set: $( (( defect )) && echo defects || { (( ci )) && echo CI || echo full; })," \
       "total $((SECONDS - t0)) s, solver limit ${timeout_s} s per call."
  echo
  if (( defect )); then
    echo "| defect | group | injected | status | failed assertion | seconds |"
    echo "|---|---|---|---|---|---|"
  else
    echo "| group | method | engine | depth | status | seconds | parameters | note |"
    echo "|---|---|---|---|---|---|---|---|"
  fi
  printf '%s\n' "${rows[@]}"
  echo
  echo "Logs, models and VCDs: one folder per job beside this file (docs/formal.md)."
} >"$out/report.md"

step "summary: $summary, report: $out/report.md"
if (( failures )); then
  echo "formal: $failures job(s) FAILED" >&2
  exit 1
fi
