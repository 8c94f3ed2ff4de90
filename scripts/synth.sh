#!/usr/bin/env bash
# zb_rop synthesis and place-and-route (make synth; docs/rtl.md "Synthesis").
#  1. Yosys generic synthesis of zb_rop (synth, check -assert, no latch, stat).
#  2. Yosys synth_ice40 of zb_rop alone: LUT4, carry, RAM and flip-flop counts.
#  3. Yosys synth_ice40 of the timing harness rtl/fpga/zb_rop_harness.sv (zb_rop's ports to and
#     from flops: one pin in, one pin out), then nextpnr-ice40 on HX8K per seed: utilisation,
#     maximum clock frequency and the critical path.
# Writes OUT/report.md, OUT/synth.csv (one row) and every tool's log in OUT.
set -euo pipefail

usage() {
  cat <<'EOF'
usage: scripts/synth.sh [options]
  --out DIR           output directory (default out/synth)
  --tile N            TILE_W = N, and TILE_H unless --tile-h (default 32: a 64x64 tile needs
                      more than HX8K's 32 block RAMs)
  --tile-h N          TILE_H (default 16: with the accumulation plane a 32x32 tile needs 51
                      block RAMs, 32x16 needs 31)
  --beat N            BEAT, tile port pixels a clock (default 1: one bank a plane, 28 block
                      RAMs; 2 takes 31 and some 600 logic cells more, which the HX8K lacks)
  --depth-bits N      DEPTH_BITS (default 24)
  --cov-samples N     COV_SAMPLES (default 16)
  --tile-ops N        TILE_OPS (default 0: zb_resolve's multipliers between the colour RAM's
                      read and the port take the HX8K to 45 MHz and 99 % of its cells; the
                      lab configuration takes 1, zb_rop's default)
  --set NAME=VALUE    another zb_rop parameter (ACC_BITS, WINDOW, CNT_W, ...), repeatable
  --freq MHZ          nextpnr target clock (default 100)
  --seeds "S1 S2..."  nextpnr placement seeds; the first is the reported one, all give the
                      spread (default "1 2 3")
  --require-mhz N     exit 3 when the first seed's maximum frequency is below N MHz
                      (default: report a missed target, do not fail)
  --no-pnr            stop after Yosys (no nextpnr)
  --keep-mem          generic synthesis keeps the tile memories as memory cells (counted
                      apart) instead of mapping them to flip-flops: for the lab configuration
                      (64x64, BEAT 8), whose planes are too large to map bit by bit
  -h, --help          this text
Exit status: 0 done; 1 a tool failed (synthesis error, check -assert, a latch); 2 usage;
3 below --require-mhz; 4 the harness needs more logic cells than the HX8K has (nextpnr's
packing counts them before placement; the report says how many).
EOF
}

root=$(cd "$(dirname "$0")/.." && pwd)
out=out/synth
tile=32
tile_h=16
beat=1
depth_bits=24
cov_samples=16
tile_ops=0
freq=100
seeds="1 2 3"
require_mhz=""
pnr=1
keep_mem=0
extra=""
extra_args=""
while [[ $# -gt 0 ]]; do
  case $1 in
    --out) out=${2:?}; shift 2 ;;
    --tile) tile=${2:?}; shift 2 ;;
    --tile-h) tile_h=${2:?}; shift 2 ;;
    --beat) beat=${2:?}; shift 2 ;;
    --depth-bits) depth_bits=${2:?}; shift 2 ;;
    --cov-samples) cov_samples=${2:?}; shift 2 ;;
    --tile-ops) tile_ops=${2:?}; shift 2 ;;
    --set) [[ ${2:-} =~ ^[A-Z_]+=[0-9]+$ ]] || { echo "synth.sh: --set needs NAME=NUMBER" >&2; exit 2; }
           extra+=" -set ${2%%=*} ${2#*=}"; extra_args+=" --set $2"; shift 2 ;;
    --freq) freq=${2:?}; shift 2 ;;
    --seeds) seeds=${2:?}; shift 2 ;;
    --require-mhz) require_mhz=${2:?}; shift 2 ;;
    --no-pnr) pnr=0; shift ;;
    --keep-mem) keep_mem=1; shift ;;
    -h|--help) usage; exit 0 ;;
    *) echo "synth.sh: unknown option '$1'" >&2; usage >&2; exit 2 ;;
  esac
done
for v in "$tile" "$tile_h" "$beat" "$depth_bits" "$cov_samples" "$tile_ops" "$freq" ${require_mhz:+"$require_mhz"} $seeds; do
  [[ $v =~ ^[0-9]+$ ]] || { echo "synth.sh: '$v' is not a number" >&2; exit 2; }
done

for tool in yosys nextpnr-ice40; do
  command -v "$tool" >/dev/null || { echo "synth.sh: $tool not found (scripts/setup.sh)" >&2; exit 1; }
done

cd "$root"
mkdir -p "$out"
rtl="rtl/zb_pkg.sv $(ls rtl/*.sv | grep -v '/zb_pkg.sv$' | tr '\n' ' ')"  # the package first
params="-set TILE_W $tile -set TILE_H $tile_h -set BEAT $beat -set DEPTH_BITS $depth_bits -set COV_SAMPLES $cov_samples -set TILE_OPS $tile_ops$extra"
latch_types='t:$dlatch t:$adlatch t:$dlatchsr t:$_DLATCH_* t:$_DLATCHSR_*'
t0=$SECONDS
step() { printf 'synth: [%4ds] %s\n' $((SECONDS - t0)) "$*"; }
fail() { echo "synth: FAILED: $*" >&2; exit 1; }

# Cell count of a `stat` type line ("     SB_LUT4    123"); 0 when absent. Last stat wins.
count() { awk -v t="$2" '$1 == t { n = $2 } END { print n + 0 }' "$1"; }

step "yosys: generic synthesis of zb_rop (TILE ${tile}x$tile_h, BEAT $beat, DEPTH_BITS $depth_bits, COV_SAMPLES $cov_samples, TILE_OPS $tile_ops)"
generic="synth -top zb_rop"
# synth up to its fine label, then its fine steps without memory_map.
[[ $keep_mem == 1 ]] && generic="synth -top zb_rop -run :fine; opt -fast -full; techmap; opt -fast; abc -fast; opt -fast"
yosys -l "$out/yosys_generic.log" -q -p "read_verilog -sv $rtl; chparam $params zb_rop;
  $generic; check -assert; tee -o $out/latches_generic.txt select -list $latch_types;
  select -assert-none $latch_types; tee -o $out/stat_generic.txt stat" >/dev/null \
  || fail "generic synthesis (see $out/yosys_generic.log)"
cells=$(awk '/Number of cells:/ { n = $4 } END { print n + 0 }' "$out/stat_generic.txt")
mem_cells=$(count "$out/stat_generic.txt" '$mem_v2')
step "  $cells cells ($mem_cells of them memories), check -assert clean, no latch"

step "yosys: synth_ice40 of zb_rop"
# hierarchy derives the parametrised top under a $paramod name: rename -top gives it its own.
yosys -l "$out/yosys_ice40.log" -q -p "read_verilog -sv $rtl; chparam $params zb_rop;
  hierarchy -top zb_rop; rename -top zb_rop; proc; select -assert-none $latch_types;
  synth_ice40 -top zb_rop; check -assert; tee -o $out/stat_ice40.txt stat" >/dev/null \
  || fail "synth_ice40 of zb_rop (see $out/yosys_ice40.log)"
s=$out/stat_ice40.txt
luts=$(count "$s" SB_LUT4)
carries=$(count "$s" SB_CARRY)
rams=$(count "$s" SB_RAM40_4K)
ffs=$(awk '$1 ~ /^SB_DFF/ { n += $2 } END { print n + 0 }' "$s")
step "  $luts SB_LUT4, $carries SB_CARRY, $rams SB_RAM40_4K, $ffs flip-flops"

kept=yes
h_luts="" h_carries="" h_rams="" h_ffs=""
if [[ $pnr == 1 ]]; then  # the harness is only for place and route
  step "yosys: synth_ice40 of the harness rtl/fpga/zb_rop_harness.sv"
  yosys -l "$out/yosys_harness.log" -q -p "read_verilog -sv $rtl rtl/fpga/zb_rop_harness.sv;
    chparam $params zb_rop_harness; synth_ice40 -top zb_rop_harness -json $out/harness.json;
    check -assert; tee -o $out/stat_harness.txt stat" >/dev/null \
    || fail "synth_ice40 of the harness (see $out/yosys_harness.log)"
  h_luts=$(count "$out/stat_harness.txt" SB_LUT4)
  h_carries=$(count "$out/stat_harness.txt" SB_CARRY)
  h_rams=$(count "$out/stat_harness.txt" SB_RAM40_4K)
  h_ffs=$(awk '$1 ~ /^SB_DFF/ { n += $2 } END { print n + 0 }' "$out/stat_harness.txt")
  step "  harness: $h_luts SB_LUT4, $h_carries SB_CARRY, $h_ffs flip-flops (zb_rop alone: $luts, $carries, $ffs)"
  # The harness must keep all of zb_rop: its RAMs, flops and (within 5 %) LUTs and carries.
  if [[ $h_rams -ne $rams || $h_ffs -lt $ffs || $((h_luts * 100)) -lt $((luts * 95)) ||
        $((h_carries * 100)) -lt $((carries * 95)) ]]; then
    kept=no
    echo "synth: WARNING: the harness has less logic than zb_rop alone: part was optimised away" >&2
  fi
fi

fmax_list=()
lc="" lc_total="" ram_used="" ram_total="" fmax="" crit="" fits=yes
if [[ $pnr == 1 ]]; then
  # Packing alone counts the logic cells: a design that needs more than the part has is
  # reported as such, not as a placer error.
  nextpnr-ice40 --hx8k --package ct256 --json "$out/harness.json" --pcf-allow-unconstrained \
    --pack-only -l "$out/nextpnr_pack.log" >/dev/null 2>&1 || fail "nextpnr-ice40 --pack-only (see $out/nextpnr_pack.log)"
  read -r lc lc_total < <(sed -n 's/.*ICESTORM_LC: *\([0-9]*\)\/ *\([0-9]*\).*/\1 \2/p' "$out/nextpnr_pack.log" | tail -1)
  read -r ram_used ram_total < <(sed -n 's/.*ICESTORM_RAM: *\([0-9]*\)\/ *\([0-9]*\).*/\1 \2/p' "$out/nextpnr_pack.log" | tail -1)
  if (( lc > lc_total || ram_used > ram_total )); then
    fits=no
    pnr=0
    step "  does not fit the HX8K: $lc of $lc_total logic cells, $ram_used of $ram_total RAMs (no placement)"
  fi
fi
if [[ $pnr == 1 ]]; then
  for seed in $seeds; do
    log=$out/nextpnr_seed$seed.log
    step "nextpnr-ice40: --hx8k --package ct256 --freq $freq --seed $seed"
    nextpnr-ice40 --hx8k --package ct256 --freq "$freq" --seed "$seed" --json "$out/harness.json" \
      --pcf-allow-unconstrained --timing-allow-fail --asc "$out/harness_seed$seed.asc" \
      --report "$out/nextpnr_seed$seed.json" -l "$log" >/dev/null 2>&1 \
      || fail "nextpnr-ice40 seed $seed (see $log)"
    # The final figure: the last "Max frequency for clock" line (after routing).
    f=$(sed -n "s/.*Max frequency for clock '[^']*': \([0-9.]*\) MHz.*/\1/p" "$log" | tail -1)
    [[ -n $f ]] || fail "no maximum frequency in $log"
    fmax_list+=("$f")
    step "  seed $seed: $f MHz"
  done
  first=${seeds%% *}
  log=$out/nextpnr_seed$first.log
  fmax=${fmax_list[0]}
  read -r lc lc_total < <(sed -n 's/.*ICESTORM_LC: *\([0-9]*\)\/ *\([0-9]*\).*/\1 \2/p' "$log" | tail -1)
  read -r ram_used ram_total < <(sed -n 's/.*ICESTORM_RAM: *\([0-9]*\)\/ *\([0-9]*\).*/\1 \2/p' "$log" | tail -1)
  # The routed critical path: the first "Critical path report for clock" of the last
  # (post-route) timing analysis, one line per hop: cumulative ns, cell (name cut at Yosys's
  # "_SB_"/"$" suffixes, which name the LUT but not the signal) and where a net goes. Runs of
  # carry-chain hops are folded into one line.
  crit=$out/critical_path.txt
  start=$(grep -n "Critical path report for clock" "$log" | tail -1 | cut -d: -f1)
  tail -n +"$start" "$log" | awk '
    function short(n) {
      sub(/^Info: */, "", n); sub(/^\$gbuf_/, "", n); sub(/(_SB_|\$|_DFFLC|_LC\.).*/, "", n)
      return n
    }
    NR == 1 { print "total ns  hop"; next }
    /ns logic, .* ns routing/ { flush(); sub(/^Info: */, ""); print; exit }
    $2 == "Source" || $4 == "Source" || / Source / {
      for (i = 1; i <= NF; i++) if ($i == "Source") break
      tot = $(i - 1); cell = $(i + 1); name = short(cell)
      kind = hops++ == 0 ? "ff" : "lut"   # a register-to-register path starts at a flop
      if (cell ~ /RAM/) kind = "ram"
      if (cell ~ /CARRY|COUT/) kind = "carry"
      if (cell ~ /gbuf|GLOBAL_BUFFER/) kind = "gbuf"
      if (kind == "carry") { if (!incarry) { cstart = tot; cn = 0 } incarry = 1; cn++; clast = tot; cname = name; next }
      flush(); printf "%8s  %-5s %s\n", tot, kind, name; next }
    / Setup / { for (i = 1; i <= NF; i++) if ($i == "Setup") break
      flush(); printf "%8s  %-5s %s\n", $(i - 1), "setup", short($(i + 1)) }
    function flush() { if (incarry) printf "%8s  carry %s (%d carry cells)\n", clast, cname, cn; incarry = 0 }
  ' >"$crit"
fi

spread=""
if [[ ${#fmax_list[@]} -gt 1 ]]; then
  spread=$(printf '%s\n' "${fmax_list[@]}" | sort -n | awk 'NR == 1 { lo = $1 } { hi = $1 }
    END { printf "%s..%s", lo, hi }')
fi

csv=$out/synth.csv
{
  echo "tile,tile_h,beat,depth_bits,cov_samples,generic_cells,sb_lut4,sb_carry,sb_ram40_4k,flip_flops,harness_lc,lc_total,ram_used,ram_total,target_mhz,fmax_mhz,seeds,fmax_per_seed"
  echo "$tile,$tile_h,$beat,$depth_bits,$cov_samples,$cells,$luts,$carries,$rams,$ffs,$lc,$lc_total,$ram_used,$ram_total,$freq,$fmax,${seeds// /;},$(IFS=';'; echo "${fmax_list[*]}")"
} >"$csv"

met="not run"
if [[ -n $fmax ]]; then
  met=$(awk -v f="$fmax" -v t="$freq" 'BEGIN { print (f >= t) ? "met" : "MISSED" }')
fi
rep=$out/report.md
{
  echo "# zb_rop synthesis report"
  echo
  echo "Command: \`scripts/synth.sh --tile $tile --tile-h $tile_h --beat $beat$extra_args --depth-bits $depth_bits --cov-samples $cov_samples --tile-ops $tile_ops --freq $freq --seeds \"$seeds\"$([[ $keep_mem == 1 ]] && echo " --keep-mem")$([[ $pnr == 0 && $fits == yes ]] && echo " --no-pnr")\`"
  echo "($(yosys -V | head -1); $(nextpnr-ice40 --version 2>&1 | head -1))."
  echo
  echo "| figure | value | source |"
  echo "|---|---|---|"
  if [[ $keep_mem == 1 ]]; then
    echo "| generic cells | $cells, of them $mem_cells memories kept whole | \`synth -top zb_rop -run :fine\`, then its fine steps without \`memory_map\`; \`check -assert; stat\` |"
  else
    echo "| generic cells | $cells | \`synth -top zb_rop; check -assert; stat\` |"
  fi
  echo "| SB_LUT4 | $luts | \`synth_ice40 -top zb_rop; stat\` |"
  echo "| SB_CARRY | $carries | same |"
  echo "| SB_RAM40_4K | $rams | same |"
  echo "| flip-flops (SB_DFF*) | $ffs | same |"
  echo "| latches | 0 (asserted) | \`select -assert-none\` latch cells |"
  if [[ -z $lc ]]; then
    # Not placed (--no-pnr): each logic cell holds one LUT4 and one flip-flop, so the larger
    # count is a lower bound on the cells; the HX8K has 7680 and 32 RAM blocks.
    need=$(( luts > ffs ? luts : ffs ))
    if (( need > 7680 || rams > 32 )); then verdict="**does not fit the HX8K**"; else verdict="not placed"; fi
    echo "| HX8K fit | $verdict: at least $need of 7680 logic cells (the larger of LUT4 and flip-flops), $rams of 32 RAM blocks | the counts above |"
  fi
  if [[ $fits == no ]]; then
    echo "| ICESTORM_LC (harness) | $lc / $lc_total: **does not fit** | nextpnr-ice40 --hx8k --pack-only |"
    echo "| ICESTORM_RAM | $ram_used / $ram_total | same |"
  fi
  if [[ $pnr == 1 ]]; then
    echo "| ICESTORM_LC (harness) | $lc / $lc_total | nextpnr-ice40 --hx8k, seed $first |"
    echo "| ICESTORM_RAM | $ram_used / $ram_total | same |"
    echo "| max clock | $fmax MHz ($met at $freq MHz) | same, after routing |"
    [[ -n $spread ]] && echo "| max clock per seed | $(paste -d: <(tr ' ' '\n' <<<"$seeds") <(printf '%s\n' "${fmax_list[@]}") | sed 's/:/: /' | paste -sd, | sed 's/,/, /g') MHz (spread $spread) | seeds $seeds |"
    echo
    echo "The timing top rtl/fpga/zb_rop_harness.sv (\`synth_ice40 -top zb_rop_harness\`): $h_luts SB_LUT4,"
    echo "$h_carries SB_CARRY, $h_rams SB_RAM40_4K, $h_ffs flip-flops, against zb_rop's own $luts, $carries,"
    echo "$rams, $ffs: its port flops and XOR tree add $((h_ffs - ffs)) flip-flops and $((h_luts - luts)) LUTs."
    if [[ $kept == yes ]]; then
      echo "It keeps all of zb_rop (same RAMs, at least its flops, LUTs and carries within 5 %)."
    else
      echo "WARNING: it has less logic than zb_rop alone: part of zb_rop was optimised away."
    fi
    echo
    echo "## Critical path (seed $first, nextpnr)"
    echo
    echo '```'
    cat "$crit"
    echo '```'
  fi
  echo
  echo "Logs: $out/yosys_*.log$([[ -n $lc ]] && echo ", $out/nextpnr_*.log")."
} >"$rep"

echo
printf '%-28s %s\n' "generic cells" "$cells" "SB_LUT4" "$luts" "SB_CARRY" "$carries" \
  "SB_RAM40_4K" "$rams" "flip-flops" "$ffs"
if [[ $pnr == 1 ]]; then
  printf '%-28s %s\n' "ICESTORM_LC (harness)" "$lc / $lc_total" "ICESTORM_RAM" "$ram_used / $ram_total" \
    "max clock, seed $first" "$fmax MHz ($met at $freq MHz)"
  [[ -n $spread ]] && printf '%-28s %s\n' "max clock, seeds $seeds" "${fmax_list[*]} MHz"
  echo "critical path: $crit"
elif [[ $fits == no ]]; then
  printf '%-28s %s\n' "ICESTORM_LC (harness)" "$lc / $lc_total: does not fit" \
    "ICESTORM_RAM" "$ram_used / $ram_total"
fi
echo "report: $rep, figures: $csv"
step "done"

if [[ $fits == no ]]; then
  echo "synth: the harness needs $lc of the HX8K's $lc_total logic cells ($ram_used of $ram_total RAMs): it does not fit" >&2
  exit 4
fi
if [[ -n $require_mhz && -n $fmax ]]; then
  if ! awk -v f="$fmax" -v r="$require_mhz" 'BEGIN { exit !(f >= r) }'; then
    echo "synth: $fmax MHz is below the required $require_mhz MHz" >&2
    exit 3
  fi
fi
