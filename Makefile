# zblend: the entry point. `make help` lists the targets.
BUILD      ?= build
ASAN_BUILD ?= build-asan
JOBS       ?= $(shell nproc)
ZBLEND     := $(BUILD)/zblend
RUN_SIZE   ?= --width 640 --height 480

.DEFAULT_GOAL := build
.PHONY: help setup build run test test-asan bench lint clean

help: ## List the targets
	@grep -E '^[a-z-]+:.*## ' $(MAKEFILE_LIST) | sed 's/:.*## /\t/' | expand -t 12

setup: ## Install the missing Debian packages (apt-get)
	@scripts/setup.sh

$(BUILD)/CMakeCache.txt:
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release

build: setup $(BUILD)/CMakeCache.txt ## Build the zblend command, tests and benchmarks
	@cmake --build $(BUILD) -j $(JOBS)
	@echo "zblend: $(ZBLEND)"

run: build ## Render the default scene `cad` with every method: out/run/*.png, summary.csv
	@$(ZBLEND) render --scene cad --method all $(RUN_SIZE) --out-dir out/run \
	  --stats out/run/stats.json
	@echo "images and table: out/run/"

test: build ## Run every test (CTest), then again under ASan and UBSan
	ctest --test-dir $(BUILD) --output-on-failure -j $(JOBS)
	@$(MAKE) --no-print-directory test-asan

test-asan: setup ## The tests built with AddressSanitizer and UndefinedBehaviorSanitizer
	@[ -f $(ASAN_BUILD)/CMakeCache.txt ] || cmake -S . -B $(ASAN_BUILD) \
	  -DCMAKE_BUILD_TYPE=RelWithDebInfo -DZBLEND_SANITIZE=ON
	@cmake --build $(ASAN_BUILD) -j $(JOBS) --target zblend_tests zblend
	ctest --test-dir $(ASAN_BUILD) --output-on-failure -j $(JOBS)

bench: build ## Benchmarks: golden datapath fragments/s, cad at 1024x768 with three-pass
	$(BUILD)/zblend_bench --benchmark_min_time=1

RTL       := $(sort $(wildcard rtl/*.sv))
LINT_ARGS := --lint-only -Wall rtl/lint_waivers.vlt $(RTL) --top-module zb_rop

lint: setup ## Verilator lint of the RTL (-Wall), for several parameter sets
	verilator $(LINT_ARGS)
	verilator $(LINT_ARGS) -GDEPTH_BITS=16 -GTILE_W=32 -GTILE_H=16
	verilator $(LINT_ARGS) -GDEPTH_BITS=32 +define+ZB_INJECT_BLEND_BUG
	@echo "lint: clean"

clean: ## Remove build trees and outputs
	rm -rf $(BUILD) $(ASAN_BUILD) out
