// The co-simulation top: one SystemC elaboration runs a whole suite at a
// list of rates, case after case, the engines reset between cases (SystemC
// cannot elaborate again after sc_stop, so run_cosim is called at most once
// per process).
#pragma once

#include <set>
#include <string>
#include <vector>

#include "cases.hpp"
#include "coverage.hpp"
#include "engines.hpp"
#include "scoreboard.hpp"

namespace contour::cosim {

struct Options {
  std::string suite = "smoke";
  std::vector<double> rates;           // command rates, pulses/s (empty: the suite's sweep)
  std::vector<std::string> cases;      // only these cases (empty: all)
  std::set<std::string> engines{"model", "core", "iss", "cpu"};
  std::string report_dir;              // report.html/json, junit.xml ("" = none)
  bool trace = false;                  // FST of the Verilog parts into report_dir (or .)
  bool free_clock = false;             // clock the core every cycle, not only after command pulses
  bool progress = false;               // progress bar on stderr
  std::vector<Fault> faults;           // test-only: corrupt engines' outputs
  double core_hz = 50e6, cpu_hz = 3e6;
  StepTiming timing;
  std::string command_line;            // for the report
};

// What one co-simulation gave: `passed` counts the acceptable() rows (PASS
// or FLAGGED), as the verdict line does; `not_run` the NOT RUN rows (an
// engine above its max_rate), which are neither.
struct CosimOutcome {
  std::vector<Row> rows;
  Coverage coverage;                   // functional coverage of the contract (coverage.hpp)
  std::size_t passed = 0, failed = 0, not_run = 0;
  double sim_seconds = 0, wall_seconds = 0;
  std::uint64_t core_clocks = 0;
  std::vector<std::string> files;      // written
  bool ok() const { return failed == 0 && !rows.empty(); }
};

// Elaborates, simulates and (with report_dir) writes the reports. Throws
// std::logic_error if called a second time in one process, UsageError
// (options.hpp) for a rate above the core's pin or a report path that is
// not a directory.
CosimOutcome run_cosim(const Options& opt);

}  // namespace contour::cosim
