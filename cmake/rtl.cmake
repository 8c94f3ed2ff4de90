# The RTL as the C++ side builds it: its sources, its widths (one set of -G parameters for every
# Verilated model and for the C++ mirrors), Verilator's options, and zblend_verilate(), the one
# place a model of zb_rop is Verilated (tb/rtlmodel/ for the testbench, tb/systemc/ with --sc).
# The package first: its types are used by every module after it.
file(GLOB ZBLEND_RTL CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/rtl/*.sv)
list(REMOVE_ITEM ZBLEND_RTL ${PROJECT_SOURCE_DIR}/rtl/zb_pkg.sv)
list(PREPEND ZBLEND_RTL ${PROJECT_SOURCE_DIR}/rtl/zb_pkg.sv)
set(ZBLEND_RTL_WAIVERS ${PROJECT_SOURCE_DIR}/rtl/lint_waivers.vlt)
# What Verilator builds: the simulation views (docs/rtl.md "Two builds, two views") in place of
# their synthesis views, rtl/sim/X.sv for rtl/X.sv. Everything else reads ZBLEND_RTL.
file(GLOB sim_views CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/rtl/sim/*.sv)
set(ZBLEND_RTL_SIM ${ZBLEND_RTL})
foreach(view IN LISTS sim_views)
  get_filename_component(name ${view} NAME)
  list(TRANSFORM ZBLEND_RTL_SIM REPLACE "^.*/rtl/${name}$" ${view})
endforeach()

# The widths (docs/sizing.md; `make plan-rtl` builds a tree with those `zblend plan` chooses).
set(ZBLEND_RTL_DEPTH_BITS 24 CACHE STRING "zb_rop DEPTH_BITS: depth width, 8 to 32")
set(ZBLEND_RTL_COV_SAMPLES 16 CACHE STRING "zb_rop COV_SAMPLES: coverage samples, 1, 2, 4, 8 or 16")
set(ZBLEND_RTL_TILE 64 CACHE STRING "zb_rop TILE_W and TILE_H: square tile, a power of two >= 2")
set(ZBLEND_RTL_WINDOW 8 CACHE STRING "zb_rop WINDOW: issue window slots, 2 to 16")
set(ZBLEND_RTL_BEAT 8 CACHE STRING "zb_rop BEAT: tile port pixels per clock, a power of two, 1 to the tile")
# Weighted blended OIT (docs/datapath.md "7. Accumulate blend"): the golden model's WboitFormat.
set(ZBLEND_RTL_ACC_BITS 16 CACHE STRING "zb_rop ACC_BITS: accumulation channel width, 8 to 32")
set(ZBLEND_RTL_REV_BITS 8 CACHE STRING "zb_rop REV_BITS: revealage width, 8 to 16")
set(ZBLEND_RTL_WEIGHT_BITS 4 CACHE STRING "zb_rop WEIGHT_BITS: depth weight range, 0 to 16")
# mlab-K (docs/datapath.md "8. Layers"): the layers a pixel the simulated zb_rop keeps, K at most.
set(ZBLEND_RTL_LAYERS 4 CACHE STRING "zb_rop LAYERS: mlab-K's layers a pixel, 0 (none) to 8")
if(NOT ZBLEND_RTL_DEPTH_BITS MATCHES "^[0-9]+$" OR ZBLEND_RTL_DEPTH_BITS LESS 8
   OR ZBLEND_RTL_DEPTH_BITS GREATER 32)
  message(FATAL_ERROR "ZBLEND_RTL_DEPTH_BITS=${ZBLEND_RTL_DEPTH_BITS}: choose 8 to 32")
endif()
if(NOT ZBLEND_RTL_COV_SAMPLES MATCHES "^(1|2|4|8|16)$")
  message(FATAL_ERROR "ZBLEND_RTL_COV_SAMPLES=${ZBLEND_RTL_COV_SAMPLES}: choose 1, 2, 4, 8 or 16")
endif()
if(NOT ZBLEND_RTL_TILE MATCHES "^(2|4|8|16|32|64|128|256|512|1024)$")
  message(FATAL_ERROR "ZBLEND_RTL_TILE=${ZBLEND_RTL_TILE}: choose a power of two from 2 to 1024")
endif()
if(NOT ZBLEND_RTL_WINDOW MATCHES "^([2-9]|1[0-6])$")
  message(FATAL_ERROR "ZBLEND_RTL_WINDOW=${ZBLEND_RTL_WINDOW}: choose 2 to 16")
endif()
if(NOT ZBLEND_RTL_BEAT MATCHES "^(1|2|4|8|16|32|64|128|256|512|1024)$" OR ZBLEND_RTL_BEAT GREATER ZBLEND_RTL_TILE)
  message(FATAL_ERROR "ZBLEND_RTL_BEAT=${ZBLEND_RTL_BEAT}: choose a power of two from 1 to the tile (${ZBLEND_RTL_TILE})")
endif()
foreach(width IN ITEMS "ACC_BITS;8;32" "REV_BITS;8;16" "WEIGHT_BITS;0;16" "LAYERS;0;8")
  list(GET width 0 name)
  list(GET width 1 lo)
  list(GET width 2 hi)
  if(NOT ZBLEND_RTL_${name} MATCHES "^[0-9]+$" OR ZBLEND_RTL_${name} LESS lo
     OR ZBLEND_RTL_${name} GREATER hi)
    message(FATAL_ERROR "ZBLEND_RTL_${name}=${ZBLEND_RTL_${name}}: choose ${lo} to ${hi}")
  endif()
endforeach()
set(ZBLEND_RTL_PARAMS -GWINDOW=${ZBLEND_RTL_WINDOW} -GBEAT=${ZBLEND_RTL_BEAT} -GDEPTH_BITS=${ZBLEND_RTL_DEPTH_BITS} -GCOV_SAMPLES=${ZBLEND_RTL_COV_SAMPLES}
    -GTILE_W=${ZBLEND_RTL_TILE} -GTILE_H=${ZBLEND_RTL_TILE} -GACC_BITS=${ZBLEND_RTL_ACC_BITS}
    -GREV_BITS=${ZBLEND_RTL_REV_BITS} -GWEIGHT_BITS=${ZBLEND_RTL_WEIGHT_BITS})
# The mutant netlist's sample (tb/mutation) is of zb_rop without the layers unit; every other
# model has them.
set(ZBLEND_RTL_CORE_PARAMS ${ZBLEND_RTL_PARAMS})
list(APPEND ZBLEND_RTL_PARAMS -GLAYERS=${ZBLEND_RTL_LAYERS})
# The same values for the C++ mirrors (tb/rtlmodel/rtl_params.h).
set(ZBLEND_RTL_DEFINES ZBLEND_RTL_DEPTH_BITS=${ZBLEND_RTL_DEPTH_BITS}
    ZBLEND_RTL_COV_SAMPLES=${ZBLEND_RTL_COV_SAMPLES} ZBLEND_RTL_TILE=${ZBLEND_RTL_TILE}
    ZBLEND_RTL_WINDOW=${ZBLEND_RTL_WINDOW} ZBLEND_RTL_BEAT=${ZBLEND_RTL_BEAT}
    ZBLEND_RTL_ACC_BITS=${ZBLEND_RTL_ACC_BITS} ZBLEND_RTL_REV_BITS=${ZBLEND_RTL_REV_BITS}
    ZBLEND_RTL_WEIGHT_BITS=${ZBLEND_RTL_WEIGHT_BITS} ZBLEND_RTL_LAYERS=${ZBLEND_RTL_LAYERS})

# Verilator's optimisation options, the model's threads and the C++ flags of its hot code:
# chosen by measurement (scripts/verilator_options.sh, docs/bench.md), overridable for it.
set(ZBLEND_VERILATOR_OPT -O3 --x-assign fast --x-initial fast CACHE STRING
    "Verilator optimisation options of the RTL model")
set(ZBLEND_VERILATOR_THREADS 1 CACHE STRING "Verilator --threads of the RTL model")
list(APPEND ZBLEND_RTL_DEFINES ZBLEND_VERILATOR_THREADS=${ZBLEND_VERILATOR_THREADS})
set(ZBLEND_VERILATOR_OPT_FAST "" CACHE STRING "C++ flags added to the model's hot code")
# gcc profile-guided optimisation of the speed build's model (scripts/pgo.sh, docs/bench.md):
# generate instruments its hot code, use compiles it with the profile a training run left in
# ZBLEND_PGO_DIR. Profiles name their objects by path: generate and use in one build tree.
set(ZBLEND_PGO "" CACHE STRING "PGO of the speed build's model: '' (none), generate or use")
set(ZBLEND_PGO_DIR ${PROJECT_BINARY_DIR}/pgo CACHE PATH "The PGO training run's profile")
if(NOT ZBLEND_PGO MATCHES "^(|generate|use)$")
  message(FATAL_ERROR "ZBLEND_PGO=${ZBLEND_PGO}: choose generate or use, or leave it empty "
                      "(scripts/pgo.sh runs both)")
endif()
if(ZBLEND_PGO STREQUAL "use")
  file(GLOB_RECURSE pgo_profiles ${ZBLEND_PGO_DIR}/*.gcda)
  if(NOT pgo_profiles)
    message(FATAL_ERROR "ZBLEND_PGO=use: no profile in ${ZBLEND_PGO_DIR}; build with "
                        "ZBLEND_PGO=generate and run a training render first (scripts/pgo.sh)")
  endif()
endif()

# zblend_verilate(TARGET PREFIX P DIRECTORY D [SYSTEMC] [BUG] [FAST] [COVERAGE]
#                 [FUNCTIONAL_COVERAGE] [TRACE]
#                 [MUTANTS NETLIST]): a static library TARGET holding zb_rop Verilated with the
# widths above: the assertion build (--assert: SVA and unique-case checks), or with FAST the
# speed build (no assertion code at all: ZB_NO_SVA, no --assert; docs/rtl.md "Two builds"). BUG adds the deliberate defects the checkers must catch, each switched on by a
# plusarg (+zb_bug_window, +zb_bug_accum; the blend's without either); SYSTEMC builds it with --sc. MUTANTS builds Yosys's
# netlist of zb_rop's mutants (tb/mutation/CMakeLists.txt) in its wrapper instead of rtl/: a
# generated netlist, so no -Wall, and no assertions (Yosys drops them). TRACE adds FST tracing
# and the waveform probe, model PREFIX_probe. COVERAGE counts lines, toggles and the RTL's
# covers; FUNCTIONAL_COVERAGE the covers only, with the coverage plan's module bound in.
function(zblend_verilate target)
  cmake_parse_arguments(V "SYSTEMC;BUG;FAST;COVERAGE;FUNCTIONAL_COVERAGE;TRACE" "PREFIX;DIRECTORY;MUTANTS" "DEFINES" ${ARGN})
  set(args --assert ${ZBLEND_VERILATOR_OPT} -Wall ${ZBLEND_RTL_PARAMS})
  set(sources ${PROJECT_SOURCE_DIR}/tb/rtlmodel/zb_rop_public.vlt ${ZBLEND_RTL_WAIVERS} ${ZBLEND_RTL_SIM})
  if(V_FAST)
    # Signals only the assertions read are unused here: the assertion build lints them.
    set(args ${ZBLEND_VERILATOR_OPT} -Wall -Wno-UNUSEDSIGNAL -Wno-UNUSEDPARAM +define+ZB_NO_SVA
        ${ZBLEND_RTL_PARAMS})
  endif()
  if(V_MUTANTS)
    set(args ${ZBLEND_VERILATOR_OPT} -Wno-fatal -Wno-lint -Wno-style -Wno-UNOPTFLAT
        ${ZBLEND_RTL_PARAMS})
    set(sources ${PROJECT_SOURCE_DIR}/tb/mutation/zb_rop_mutant.vlt
        ${PROJECT_SOURCE_DIR}/rtl/zb_pkg.sv ${V_MUTANTS}
        ${PROJECT_SOURCE_DIR}/tb/mutation/zb_rop_mutant.sv)
  endif()
  foreach(d IN LISTS V_DEFINES)
    list(APPEND args +define+${d})
  endforeach()
  if(V_BUG)
    list(APPEND args +define+ZB_INJECT_BLEND_BUG +define+ZB_INJECT_WINDOW_BUG
         +define+ZB_INJECT_ACCUM_BUG +define+ZB_INJECT_TILEOP_BUG +define+ZB_INJECT_LAYERS_BUG)
  endif()
  set(kind "")
  if(V_SYSTEMC)
    set(kind SYSTEMC)
  endif()
  set(extra "")
  if(V_TRACE)
    list(APPEND extra TRACE_FST)
  endif()
  if(V_COVERAGE)
    list(APPEND extra COVERAGE)
  elseif(V_FUNCTIONAL_COVERAGE)
    # The functional coverage plan's bins, bound to zb_rop (tb/cov/, docs/coverage.md); not in
    # the code coverage build, whose lines and toggles are zb_rop's alone.
    list(APPEND args --coverage-user)
    list(APPEND sources ${PROJECT_SOURCE_DIR}/tb/cov/zb_rop_cov.sv
         ${PROJECT_SOURCE_DIR}/tb/cov/zb_rop_cov_bind.sv)
  endif()
  set(opt_fast ${ZBLEND_VERILATOR_OPT_FAST})
  if(V_FAST AND ZBLEND_PGO STREQUAL "generate")
    list(APPEND opt_fast -fprofile-generate=${ZBLEND_PGO_DIR} -fprofile-update=atomic)
  elseif(V_FAST AND ZBLEND_PGO STREQUAL "use")
    list(APPEND opt_fast -fprofile-use=${ZBLEND_PGO_DIR} -fprofile-partial-training
         -Wno-missing-profile)
  endif()
  add_library(${target} STATIC)
  if(V_FAST AND ZBLEND_PGO STREQUAL "generate")
    target_link_options(${target} INTERFACE -fprofile-generate=${ZBLEND_PGO_DIR})
  endif()
  verilate(${target} ${kind} ${extra}
    SOURCES ${sources}
    TOP_MODULE zb_rop PREFIX ${V_PREFIX}
    THREADS ${ZBLEND_VERILATOR_THREADS} OPT_FAST ${opt_fast}
    DIRECTORY ${V_DIRECTORY}
    VERILATOR_ARGS ${args})
  if(V_SYSTEMC)
    verilator_link_systemc(${target})  # verilate() only sets VM_SC; this adds libsystemc
  endif()
  if(V_TRACE)
    # The testbench's probe (tb/rtlmodel/zb_wave_probe.sv), traced into the same FST as zb_rop.
    verilate(${target} TRACE_FST
      SOURCES ${PROJECT_SOURCE_DIR}/tb/rtlmodel/zb_wave_probe.sv
      TOP_MODULE zb_wave_probe PREFIX ${V_PREFIX}_probe
      DIRECTORY ${V_DIRECTORY}_probe
      VERILATOR_ARGS -Wall)
  endif()
  # Generated and Verilator runtime code: not held to the project's warning flags.
  target_compile_options(${target} PRIVATE -w -Wno-error)
  set_target_properties(${target} PROPERTIES INTERFACE_SYSTEM_INCLUDE_DIRECTORIES
    $<TARGET_PROPERTY:${target},INTERFACE_INCLUDE_DIRECTORIES>)
  if(V_COVERAGE OR V_FUNCTIONAL_COVERAGE)
    target_compile_definitions(${target} INTERFACE VM_COVERAGE=1)
  endif()
  if(ZBLEND_SANITIZE)
    # Verilator's trace buffer (verilated_trace.h, chgQData) reads 64-bit signals through 32-bit
    # aligned slots; the generated trace code inlines it. Only the alignment check is lifted
    # there: the rest of UBSan and all of ASan still cover the model.
    target_compile_options(${target} PRIVATE -fno-sanitize=alignment)
  endif()
endfunction()
