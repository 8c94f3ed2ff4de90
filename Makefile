# zblend: the entry point. `make help` lists the targets.
BUILD      ?= build
ASAN_BUILD ?= build-asan
TSAN_BUILD ?= build-tsan
JOBS       ?= $(shell nproc)
ZBLEND     := $(BUILD)/zblend
RUN_SIZE   ?= --width 640 --height 480

.DEFAULT_GOAL := build
.PHONY: help setup full-tree build run test test-release test-asan test-tsan regress conformance conformance-mutate kit kit-install mutate mutate-layers bench pgo bench-verilator profile-rtl synth formal systemc vp lint soak waves coverage fuzz fuzz-ci fuzz-build clean

help: ## List the targets
	@grep -E '^[a-z-]+:.*## ' $(MAKEFILE_LIST) | sed 's/:.*## /\t/' | awk -F'\t' '{printf "%-16s %s\n", $$1, $$2}'

setup: ## Install the missing Debian packages the tests and tools use (apt-get; make run installs fewer)
	@scripts/setup.sh test

$(BUILD)/CMakeCache.txt:
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release

# The tree with every target: one that `make run` configured with zblend's alone is configured
# again, whole.
full-tree: setup $(BUILD)/CMakeCache.txt
	@! grep -q '^ZBLEND_RUN_ONLY:BOOL=ON' $(BUILD)/CMakeCache.txt || \
	  cmake -S . -B $(BUILD) -DZBLEND_RUN_ONLY=OFF >/dev/null

build: full-tree ## Build the zblend command, tests and benchmarks
	@cmake --build $(BUILD) -j $(JOBS)
	@echo "zblend: $(ZBLEND)"

# Only what the render needs: the run group's packages and the zblend target (a new tree is
# configured with zblend's folders alone; an existing one is used as it is).
run: ## Render `cad` with every method on golden model and RTL, compared: out/run/
	@scripts/setup.sh run
	@[ -f $(BUILD)/CMakeCache.txt ] || cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release \
	  -DZBLEND_RUN_ONLY=ON >/dev/null
	@cmake --build $(BUILD) -j $(JOBS) --target zblend
	@$(ZBLEND) render --scene cad --method all $(RUN_SIZE) --backend both --out-dir out/run \
	  --stats out/run/stats.json
	@echo "images and table: out/run/"

vp: full-tree ## The virtual platform: cad, every method, both insides, 640x480, against zblend render: out/vp/
	@cmake --build $(BUILD) -j $(JOBS) --target zblend zblend_vp
	@tests/vp/test_vp_frames.sh $(BUILD)/zblend_vp $(ZBLEND) out/vp 640 480
	@echo "frames: out/vp/base/ (docs/systemc.md)"

test: ## Every test: the Release tree (CTest), ASan+UBSan, ThreadSanitizer, the fuzzers briefly
	@$(MAKE) --no-print-directory test-release
	@$(MAKE) --no-print-directory test-asan
	@$(MAKE) --no-print-directory test-tsan
	@$(MAKE) --no-print-directory fuzz-ci

test-release: build ## The Release tree's tests (CTest)
	ctest --test-dir $(BUILD) --output-on-failure -j $(JOBS)

test-asan: setup ## The tests built with AddressSanitizer and UndefinedBehaviorSanitizer
	@[ -f $(ASAN_BUILD)/CMakeCache.txt ] || cmake -S . -B $(ASAN_BUILD) \
	  -DCMAKE_BUILD_TYPE=RelWithDebInfo -DZBLEND_SANITIZE=ON
	@cmake --build $(ASAN_BUILD) -j $(JOBS)
	ctest --test-dir $(ASAN_BUILD) --output-on-failure -j $(JOBS)

# The threaded paths only (tests/tsan, docs/threads.md): zblend and its thread tests.
test-tsan: setup ## The threaded paths built with ThreadSanitizer and run on 2 to 4 threads
	@[ -f $(TSAN_BUILD)/CMakeCache.txt ] || cmake -S . -B $(TSAN_BUILD) \
	  -DCMAKE_BUILD_TYPE=RelWithDebInfo -DZBLEND_TSAN=ON
	@cmake --build $(TSAN_BUILD) -j $(JOBS)
	ctest --test-dir $(TSAN_BUILD) --output-on-failure -j $(JOBS)

# The regression runner (docs/regressions.md): a group of tb/regressions.json on JOBS local
# processes; JUnit XML, HTML summary, failing tests again with waves. make test runs smoke.
GROUP        ?= nightly
REGRESS_ARGS ?=

regress: build ## Run GROUP (default nightly) of tb/regressions.json: out/regress/GROUP/summary.html, junit.xml
	python3 scripts/regress.py run $(GROUP) -j $(JOBS) --build $(BUILD) --out out/regress/$(GROUP) $(REGRESS_ARGS)

# The RTL's speed is measured beside BASELINE's build (built once in build-baseline; empty: none).
BASELINE ?= d91dc3f

bench: build ## Benchmarks: datapath, golden vs llvmpipe, memory, RTL (beside BASELINE's and PGO's), cost growth, render and lab against BASELINE: out/bench/
	@scripts/setup.sh bench
	@cmake --build $(BUILD) -j $(JOBS) --target zblend_bench zblend_bench_rtl zblend_bench_rtl_assert zblend_window_sweep
	@$(if $(BASELINE),scripts/bench_baseline.sh $(BASELINE) build-baseline -j $(JOBS))
	@scripts/pgo.sh -j $(JOBS) -d build-pgo
	@/usr/bin/python3 scripts/bench.py --build $(BUILD) --out out/bench $(if $(BASELINE),--baseline build-baseline/build) --pgo build-pgo

pgo: setup ## The speed build's model with gcc PGO, trained on cad: build-pgo/zblend, build-pgo/zblend_bench_rtl
	@scripts/pgo.sh -j $(JOBS) -d build-pgo

profile-rtl: ## Where the RTL simulation's time goes, per module (perf, --prof-cfuncs): out/profile/modules.csv
	@scripts/setup.sh profile
	@scripts/profile_rtl.sh -j $(JOBS)

bench-verilator: setup ## Verilator option sets measured against each other: out/bench/verilator_options.csv
	@scripts/verilator_options.sh -j $(JOBS)

systemc: full-tree ## Golden model and RTL as SystemC modules, co-simulated on cad (docs/systemc.md)
	@cmake --build $(BUILD) -j $(JOBS) --target zblend_systemc
	$(BUILD)/zblend_systemc --scene cad --method all $(RUN_SIZE)

synth: ## Yosys and nextpnr-ice40 on the datapath: cells, LUTs, RAMs, FFs, max clock on HX8K: out/synth/; the lab configuration's size: out/synth/lab/
	@scripts/setup.sh synth
	@scripts/synth.sh
	@scripts/synth.sh --tile 64 --tile-h 64 --beat 8 --tile-ops 1 --set LAYERS=4 --keep-mem --no-pnr --out out/synth/lab

formal: setup ## Formal proofs, full set, and the RTL's two views proven equal: out/formal/, out/equiv/ (make test runs --ci)
	@scripts/formal.sh --out out/formal
	@python3 scripts/equiv.py --out out/equiv

SOAK_FRAGMENTS ?= 50000000

soak: build ## Long RTL regression: 10^8 fragments of random and hazard streams, the blend exhaustively
	$(BUILD)/zblend_tb --suite random --seed 11 --fragments $(SOAK_FRAGMENTS) --backpressure 0.2
	$(BUILD)/zblend_tb --suite hazard --seed 12 --fragments $(SOAK_FRAGMENTS)
	$(BUILD)/zblend_tb --suite blend

# The checker's mutation score (docs/mutation.md): every mutant of the netlist against the
# smoke group, the survivors against the full group, then Yosys on what survives both.
MUTATE_ARGS ?=

mutate: build ## Mutation score: zb_rop's 1200 Yosys mutants, smoke group, equivalence proofs, full group: out/mutate/
	python3 scripts/mutate.py --build $(BUILD) --out out/mutate -j $(JOBS) $(MUTATE_ARGS)

# The conformance kit (docs/conformance.md): the whole suite exported, run on zb_rop under
# Verilator and Icarus Verilog, then under Verilator with the golden model in lock-step through
# DPI-C. make test runs a CI-sized part of it (ctest -L conformance).
CONF_DIR ?= out/conformance
CONF_SEED ?= 1
CONF_COVER = tb/cov/zb_rop_cov.sv tb/cov/zb_rop_cov_bind.sv tb/cov/zb_conf_cov_writer.sv \
             tb/cov/zb_conf_cov_writer.cpp
CONF_LIBS = $(BUILD)/conformance/libzbgolden_dpi.a $(BUILD)/conformance/libzbgolden_c.a \
            $(BUILD)/cmodel/libzbmodel.a
CONF_PY   = python3 scripts/conformance.py -j $(JOBS)
CONF_RUN  = $(CONF_PY) --suite $(CONF_DIR)/suite

conformance: build ## The conformance suite on zb_rop under Verilator, Icarus and DPI-C lock-step, its reach (golden and zb_rop's covers, cross-checked), the second DUT and its defect catalogue: out/conformance/
	$(ZBLEND) conformance export $(CONF_DIR)/suite
	@# The reach on the golden model, as the coverage run below drives the suite (gaps 20 %,
	@# zb_rop's resident tiles): printed, and written per test for the cross-check.
	$(ZBLEND) conformance reach --gap 20 --schedule resident --json $(CONF_DIR)/reach.json
	$(CONF_RUN) --sim verilator --out $(CONF_DIR)/verilator
	$(CONF_RUN) --sim verilator --out $(CONF_DIR)/verilator-pass --schedule pass --timing random --seed 2
	@# Icarus runs about 7000 cycles a second: zb_rop with a 32x32 tile (its HX8K size) there,
	@# so that a pass's tile load and store cost a quarter of the default's.
	$(CONF_RUN) --sim icarus --out $(CONF_DIR)/icarus --param TILE_W=32 --param TILE_H=32
	$(CONF_RUN) --sim verilator --out $(CONF_DIR)/lockstep --gap 20 --lockstep --golden-libs $(CONF_LIBS)
	@# The suite's reach on the functional coverage plan (docs/coverage.md): zb_rop with the
	@# plan's covers bound in, each test's counts written at its end: reach.html; at least 99 %
	@# of the kit-reachable bins, and the golden reach equal to the covers' test by test.
	$(CONF_RUN) --sim verilator --out $(CONF_DIR)/coverage --gap 20 \
	  --verilator-arg=--coverage-user --extra-sources $(CONF_COVER)
	python3 scripts/coverage_report.py $(CONF_DIR)/coverage --conformance \
	  --kit-bins conformance/kit_bins.json --reach $(CONF_DIR)/reach.json --min-reach 99
	@# The second DUT, full and pipelined, on both simulators; the seeded random tier on both DUTs.
	$(CONF_RUN) --sim verilator --out $(CONF_DIR)/ref-full --profile conformance/ref/profile_full.json
	$(CONF_RUN) --sim icarus --out $(CONF_DIR)/ref-full-icarus --profile conformance/ref/profile_full.json
	$(CONF_RUN) --sim verilator --out $(CONF_DIR)/ref-pipe --profile conformance/ref/profile_pipe.json
	$(ZBLEND) conformance export --seed $(CONF_SEED) $(CONF_DIR)/seed
	$(CONF_PY) --suite $(CONF_DIR)/seed --sim verilator --out $(CONF_DIR)/seed-rop \
	  --timing random --seed $(CONF_SEED)
	$(CONF_PY) --suite $(CONF_DIR)/seed --sim icarus --out $(CONF_DIR)/seed-ref \
	  --profile conformance/ref/profile_full.json --timing random --seed $(CONF_SEED)
	@# The defect catalogue, each defect against the whole suite: the tests that catch it.
	tests/conformance/test_ref_defects.sh $(CONF_DIR)/suite $(CONF_DIR)/defects $(ZBLEND) -j $(JOBS)

# The layers unit's mutation score (docs/mutation.md "The layers unit"): its own netlist (zb_rop
# with LAYERS, mutations drawn from zb_layers, zb_layers_insert, zb_resolve_layers) in a tree of
# its own, the smoke group with the layers tests first. MUTATE_LAYERS_ARGS passes options.
MUT_LAYERS_BUILD ?= build-mut-layers
MUTATE_LAYERS_ARGS ?=
mutate-layers: setup ## Mutation score of the layers unit: its own Yosys sample, smoke group: out/mutate-layers/
	cmake -S . -B $(MUT_LAYERS_BUILD) -DCMAKE_BUILD_TYPE=Release -DZBLEND_LAYERS_MUTANTS=ON >/dev/null
	cmake --build $(MUT_LAYERS_BUILD) -j $(JOBS) --target zblend_tb_mut_layers
	python3 scripts/mutate.py --netlist layers --build $(MUT_LAYERS_BUILD) --out out/mutate-layers \
	  -j $(JOBS) $(MUTATE_LAYERS_ARGS)

# The suite's strength on zb_rop's mutants (docs/conformance.md "The suite's strength"): the
# mutation tool's 1200 mutants, each against the suite's d24-c16 tests until one kills it (about an
# hour on 2 cores). CONF_MUTATE_ARGS passes options (--resume, --sample 120, --mutants 1-50).
CONF_MUTATE_ARGS ?=
conformance-mutate: build ## The conformance suite as a test group on zb_rop's mutants: out/conformance/mutate/
	$(ZBLEND) conformance export $(CONF_DIR)/suite
	python3 scripts/conformance_mutate.py --build $(BUILD) --suite $(CONF_DIR)/suite \
	  --out $(CONF_DIR)/mutate -j $(JOBS) $(CONF_MUTATE_ARGS)

# The conformance kit alone, as an outside team installs it (docs/conformance.md "The kit"): its
# own tree without Verilator (ZBLEND_KIT_ONLY; fails if anything Verilated is built), laid out
# and archived with the suite in out/kit/, or installed under PREFIX.
KIT_BUILD ?= build-kit
PREFIX    ?= /usr/local

kit: ## The conformance kit alone, no Verilator: out/kit/zblend-conformance-kit-<version>.tar.gz, the suite's tarball
	@scripts/setup.sh kit
	@scripts/kit.sh -j $(JOBS) -d $(KIT_BUILD) --out out/kit

kit-install: ## The conformance kit installed under PREFIX (default /usr/local): bin/, lib/, include/, share/zblend-conformance/
	@scripts/setup.sh kit
	@scripts/kit.sh -j $(JOBS) -d $(KIT_BUILD) --install $(PREFIX)

# Only zblend is built, its log shown only if the build fails; render makes out/waves/.
waves: setup $(BUILD)/CMakeCache.txt ## Render `cad` on the RTL with a waveform and its GTKWave save file: out/waves/cad.fst, .gtkw
	@log=$$(cmake --build $(BUILD) -j $(JOBS) --target zblend 2>&1) || { printf '%s\n' "$$log"; exit 1; }
	@$(ZBLEND) render --scene cad --method three-pass --width 128 --height 96 --backend rtl \
	  --out out/waves/cad.png --waves out/waves/cad.fst
	@echo "open it: gtkwave out/waves/cad.gtkw  (its save file: signals by stage; or surfer out/waves/cad.fst)"

# The methods lab (docs/lab.md): the sweeps first, so that the lab's report takes them in.
LAB_DIR ?= out/lab

.PHONY: lab
lab: setup $(BUILD)/CMakeCache.txt ## Every method on every scene, and the sweeps: CSV, charts, report in out/lab/
	@cmake --build $(BUILD) -j $(JOBS) --target zblend
	$(ZBLEND) sweep all --out-dir $(LAB_DIR)/sweeps
	$(ZBLEND) lab --out-dir $(LAB_DIR) -j $(JOBS)
	@echo "report: $(LAB_DIR)/report.html ($(LAB_DIR)/report.md)"

# A model sized to a scene (docs/sizing.md): `zblend plan` picks the method and the widths, a
# build tree of their own Verilates zb_rop with them, and a render on golden model and that RTL,
# compared bit for bit, checks the choice. Only the zblend target is built there.
SCENE     ?= cad
MAX_ERROR ?= 8
PLAN_SIZE ?= $(RUN_SIZE)
PLAN_DIR   = out/plan-rtl/$(notdir $(SCENE))

.PHONY: plan-rtl
plan-rtl: setup $(BUILD)/CMakeCache.txt ## Size a model to SCENE within MAX_ERROR, build that RTL, check it
	@cmake --build $(BUILD) -j $(JOBS) --target zblend
	@set -e; mkdir -p $(PLAN_DIR); \
	$(ZBLEND) plan --scene $(SCENE) --max-error $(MAX_ERROR) $(PLAN_SIZE) --json $(PLAN_DIR)/plan.json; \
	key() { sed -n "s/^ *\"$$1\": \"\{0,1\}\([^\",]*\)\"\{0,1\},\{0,1\}$$/\1/p" $(PLAN_DIR)/plan.json; }; \
	d=$$(key ZBLEND_RTL_DEPTH_BITS); c=$$(key ZBLEND_RTL_COV_SAMPLES); t=$$(key ZBLEND_RTL_TILE); \
	m=$$(key render_method); tree=build-plan-d$$d-c$$c-t$$t; \
	if [ "$$c" != 16 ]; then echo "plan-rtl: $$m at $$c coverage samples: 'zblend render' draws" \
	  "16-sample frames, so it cannot drive that RTL (docs/sizing.md)" >&2; exit 1; fi; \
	echo "plan-rtl: $$m on zb_rop DEPTH_BITS=$$d COV_SAMPLES=$$c TILE_W=TILE_H=$$t in $$tree"; \
	scripts/lint_rtl.sh -GDEPTH_BITS=$$d -GCOV_SAMPLES=$$c -GTILE_W=$$t -GTILE_H=$$t; \
	echo "plan-rtl: zb_rop lints clean (verilator -Wall) with those parameters"; \
	[ -f $$tree/CMakeCache.txt ] || cmake -S . -B $$tree -DCMAKE_BUILD_TYPE=Release \
	  -DZBLEND_RTL_DEPTH_BITS=$$d -DZBLEND_RTL_COV_SAMPLES=$$c -DZBLEND_RTL_TILE=$$t >/dev/null; \
	cmake --build $$tree -j $(JOBS) --target zblend; \
	$$tree/zblend render --scene $(SCENE) --method $$m --backend both --depth-bits $$d \
	  $(PLAN_SIZE) --out-dir $(PLAN_DIR); \
	awk -F, -v m=$$m 'NR == 1 { for (i = 1; i <= NF; i++) col[$$i] = i; next } \
	  $$1 == m { printf "plan-rtl: RTL cycles %d streaming + %d tile = %d; %s mismatches\n", \
	      $$col["rtl_stream_cycles"], $$col["rtl_tile_cycles"], $$col["rtl_cycles"], \
	      $$col["mismatches"] }' $(PLAN_DIR)/summary.csv; \
	echo "plan-rtl: the scene touches $$(key scene_tiles_touched) of the frame's" \
	  "$$(key frame_tiles) tiles of $${t}x$$t; its passes load $$(key pass_tiles_loaded);" \
	  "the cost model expected $$(key rtl_cycles_expected) RTL cycles"

COV_BUILD ?= build-cov
COV_DIR   := out/coverage

coverage: full-tree ## Functional coverage closure of the plan (out/coverage/closure.html), then line and toggle coverage: out/coverage/
	@cmake --build $(BUILD) -j $(JOBS) --target zblend_tb_fcov
	@[ -f $(COV_BUILD)/CMakeCache.txt ] || cmake -S . -B $(COV_BUILD) \
	  -DCMAKE_BUILD_TYPE=Release -DZBLEND_RTL_COVERAGE=ON
	@cmake --build $(COV_BUILD) -j $(JOBS) --target zblend_tb
	@rm -rf $(COV_DIR)
	@# The plan's bins (tb/cov/coverage_plan.json, docs/coverage.md): the coverage group through
	@# zblend_tb_fcov, each RTL parameter set it names in a tree of its own (BUILD-SET).
	python3 scripts/regress.py run coverage --coverage -j $(JOBS) --build $(BUILD) \
	  --out $(COV_DIR)/functional
	@# Line and toggle coverage: the code_coverage group, counts merged into code/merged.dat and
	@# the sources annotated (docs/regressions.md).
	python3 scripts/regress.py run code_coverage --coverage -j $(JOBS) --build $(COV_BUILD) \
	  --out $(COV_DIR)/code
	@# Per kind of point (line includes branch points), from the merged counts.
	@tr '\001\002' '|=' < $(COV_DIR)/code/merged.dat | awk '/^C / { \
	    k = match($$0, /page=v_[a-z]+/) ? substr($$0, RSTART + 7, RLENGTH - 7) : "other"; \
	    if (k == "branch") k = "line"; n[k]++; if ($$NF > 0) hit[k]++ } \
	  END { for (k in n) printf "coverage: %-6s %5d of %5d points covered (%.1f%%)\n", \
	    k "s", hit[k], n[k], 100 * hit[k] / n[k] }' | sort
	@echo "open: $(COV_DIR)/code/annotated/zb_rop.sv (and the other .sv there); lines marked %00 never ran"
	@# The closure report last: its exit status is the target's (holes, or a reason a test
	@# contradicts, fail it).
	python3 scripts/coverage_report.py $(COV_DIR)/functional --group coverage --out $(COV_DIR)

# libFuzzer (clang) in a build tree of its own: docs/fuzzing.md.
FUZZ_BUILD      ?= build-fuzz
FUZZ_SECONDS    ?= 60
# make test's slice: counted in runs from a fixed seed, the same work on a loaded machine (about
# 15 s a target on 2 cores); make fuzz searches longer.
FUZZ_CI_RUNS    ?= obj=100000 gltf=60000 trace=250000 raster=2000
FUZZ_SEED       ?= 1

$(FUZZ_BUILD)/CMakeCache.txt:
	CC=clang CXX=clang++ cmake -S . -B $(FUZZ_BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DZBLEND_FUZZ=ON

fuzz-build: setup $(FUZZ_BUILD)/CMakeCache.txt
	@cmake --build $(FUZZ_BUILD) -j $(JOBS)

fuzz: fuzz-build ## Fuzz loaders, trace reader, rasterizer FUZZ_SECONDS each: out/fuzz/, crashes/
	@JOBS=$(JOBS) scripts/fuzz.sh $(FUZZ_BUILD) $(FUZZ_SECONDS) out/fuzz out/fuzz/crashes

fuzz-ci: fuzz-build ## The fuzzers FUZZ_CI_RUNS runs each from seed FUZZ_SEED and the seeds only (part of `make test`)
	@rm -rf out/fuzz-ci
	@JOBS=$(JOBS) FUZZ_RUNS="$(FUZZ_CI_RUNS)" FUZZ_SEED=$(FUZZ_SEED) scripts/fuzz.sh $(FUZZ_BUILD) $(FUZZ_SECONDS) out/fuzz-ci out/fuzz/crashes

lint: setup ## Verilator lint (-Wall) and Icarus elaboration of the RTL for every set of rtl/lint_sets.txt; the conformance testbench
	@scripts/lint_rtl.sh --all

clean: ## Remove build trees and outputs
	rm -rf $(BUILD) $(ASAN_BUILD) $(TSAN_BUILD) build-baseline $(COV_BUILD) $(FUZZ_BUILD) $(KIT_BUILD) out
