# contour — paper A's interpolators: golden C++ model, Verilog core, 8085.
#
#   make run     the paper reproduction and the co-simulation report
#   make test    the whole suite (ctest: model, RTL, ISS, 8085, cosim, lint)
#   make build   configure and build everything; the CLI is build/contour
#   make bench   speed figures (Google Benchmark, callgrind; paper B: model/planner/bench_gcode.sh)
#   make synth   yosys + nextpnr-ice40: LCs, BRAMs, Fmax over seeds 1-5 (SEEDS=...) on HX8K and UP5K
#   make synth-analysis  the same for the analysis designs (what holds core's Fmax; rtl/proto's prototypes)
#   make lint    verilator --lint-only -Wall over rtl/ (every core's file list)
#   make formal  the formal proofs and their mutants (ctest -L formal)
#   make mutants planted bugs in model, RTL, 8085 program, board and host: each must be KILLED
#   make coverage line and toggle coverage of the interp_core regression
#   make install PREFIX=DIR  contour and contour-cosim into DIR/bin (default /usr/local)
#   make docs-plots  regenerate every plot committed under docs/
#   make deps    install what is missing (apt-get, npm ci); run by the above
#   make clean   remove build/
#
# Every target that builds first runs `make deps`, which is silent when all
# is installed.

BUILD   ?= build
# cmake's generated makefiles run make recursively: no "Entering directory" lines
MAKEFLAGS += --no-print-directory
JOBS    ?= 2
CMAKE   ?= cmake
CTEST_ARGS ?=
COV_FILTER ?= *

.PHONY: all deps configure build run test bench synth synth-analysis lint formal clean help

all: build

help:
	@sed -n '3,18p' Makefile

deps:
	@.ci/install-deps

# cmake's progress (stdout) is hidden; its warnings and errors (stderr, e.g.
# a missing tool, named with `make deps`) show.
configure: deps
	@$(CMAKE) -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release >/dev/null

build: configure
	@$(CMAKE) --build $(BUILD) -j$(JOBS)

# The paper reproduction: Fig. 2 and Fig. 5, Table 1 on the 8085 program,
# then the co-simulation of model, Verilog core and 8085 from 1 kpps to
# 250 kpps and beyond, with its report in $(BUILD)/report/.
run: build
	@echo "== paper A, Fig. 2: contour line 6 5"
	@$(BUILD)/contour line 6 5 --format steps
	@echo "== paper A, Fig. 5: contour arc 6 0 0 6 --ccw"
	@$(BUILD)/contour arc 6 0 0 6 --ccw --format steps
	@mkdir -p $(BUILD)/report
	@$(BUILD)/contour arc 6 0 0 6 --ccw --format svg -o $(BUILD)/report/fig5.svg
	@$(BUILD)/contour line 6 5 --format svg -o $(BUILD)/report/fig2.svg
	@echo "drawings: $(BUILD)/report/fig2.svg $(BUILD)/report/fig5.svg"
	@echo "== paper A, Table 1: contour table1"
	@$(BUILD)/contour table1
	@echo "== co-simulation: contour cosim --suite paper,smoke --sweep"
	@$(BUILD)/contour cosim --suite paper,smoke --sweep --report $(BUILD)/report
	@echo "report: $(BUILD)/report/report.html"

test: build
	@cd $(BUILD) && ctest -j$(JOBS) --no-tests=error --output-on-failure $(CTEST_ARGS)

bench: build
	@$(CMAKE) --build $(BUILD) -j$(JOBS) --target benches
	@$(BUILD)/model/bench/contour_bench
	@$(BUILD)/model/bench/interp_ipp
	@$(BUILD)/model/bench/iss_ipt
	@$(BUILD)/tb/cpu8085/cpu8085_tps
	@model/planner/bench_gcode.sh $(BUILD)/contour

synth: deps
	@$(MAKE) --no-print-directory -C rtl/synth BUILD=$(abspath $(BUILD))/synth

synth-analysis: deps
	@$(MAKE) --no-print-directory -C rtl/synth BUILD=$(abspath $(BUILD))/synth-analysis analysis

lint: deps
	@$(MAKE) --no-print-directory -C rtl lint

# The proofs of `make test` (ctest -L formal), then the long one: every
# accepted arc at W = 3 to its full depth (about 10 min, docs/rtl.md).
formal: configure
	@cd $(BUILD) && ctest -L formal --no-tests=error --output-on-failure $(CTEST_ARGS)
	@rtl/interp/formal/run_formal.sh $(BUILD)/formal/interp_arcs arcs:3:66

# Mutation check of the suite (long; not part of `test`): tb/mutants/list.txt.
.PHONY: mutants
mutants: configure
	@BUILD=$(BUILD) JOBS=$(JOBS) tb/mutants/run.sh

# The programs need nothing from the build tree once installed (the 8085
# program is embedded); ctest cli.install_relocated checks it.
PREFIX ?= /usr/local
.PHONY: install
install: build
	@$(CMAKE) --install $(BUILD) --prefix $(PREFIX)

clean:
	rm -rf $(BUILD)

# Line and toggle coverage of the interp_core regression (long, ~2.5 min;
# not part of `test`): tb/interp/coverage.sh, results in $(BUILD)/coverage.
.PHONY: coverage
coverage: configure
	@$(CMAKE) --build $(BUILD) -j$(JOBS) --target interp_rtl_cov
	@tb/interp/coverage.sh $(BUILD) '$(COV_FILTER)'

# Every plot committed under docs/, by the commands the docs give
# (model/plot/docs_plots.sh); the ctest docs_plots_reproducible fails when
# the committed files differ from what this makes.
.PHONY: docs-plots
docs-plots: configure
	@$(CMAKE) --build $(BUILD) -j$(JOBS) --target contour
	@model/plot/docs_plots.sh $(BUILD)/contour $(CURDIR)
