# contour — paper A's interpolators: golden C++ model, Verilog core, 8085.
#
#   make run     the paper reproduction and the co-simulation report
#   make test    the whole suite (ctest: model, RTL, ISS, 8085, cosim)
#   make build   configure and build everything; the CLI is build/contour
#   make bench   speed figures (Google Benchmark, callgrind)
#   make synth   yosys + nextpnr-ice40: LCs and Fmax on HX8K and UP5K
#   make lint    verilator --lint-only -Wall over rtl/
#   make deps    install what is missing (apt-get, npm ci); run by the above
#   make clean   remove build/
#
# Every target that builds first runs `make deps`, which is silent when all
# is installed.

BUILD   ?= build
JOBS    ?= 2
CMAKE   ?= cmake
CTEST_ARGS ?=

.PHONY: all deps configure build run test bench synth lint clean help

all: build

help:
	@sed -n '3,13p' Makefile

deps:
	@.ci/install-deps

configure: deps
	@$(CMAKE) -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release >/dev/null

build: configure
	@$(CMAKE) --build $(BUILD) -j$(JOBS)

run: build
	@sim/run.sh $(BUILD)

test: build
	@cd $(BUILD) && ctest -j$(JOBS) --output-on-failure $(CTEST_ARGS)

bench: build
	@$(CMAKE) --build $(BUILD) -j$(JOBS) --target benches
	@model/bench/run.sh $(BUILD)

synth: deps
	@$(MAKE) --no-print-directory -C rtl/synth BUILD=$(abspath $(BUILD))/synth

lint: deps
	@$(MAKE) --no-print-directory -C rtl lint

clean:
	rm -rf $(BUILD)
