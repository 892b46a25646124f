// The co-simulation reports: report.html (verdict line first, tables, the
// first divergences, inline SVG plots), report.json and junit.xml.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "cases.hpp"
#include "coverage.hpp"
#include "scoreboard.hpp"

namespace contour::cosim {

struct Options;

// Line and toggle coverage of the core's regression from `make coverage`
// (tb/interp/coverage.sh): the points of a verilator_coverage .dat file.
struct RtlCoverage {
  std::string path;                 // the .dat read
  std::uint64_t lines = 0, lines_hit = 0, toggles = 0, toggles_hit = 0;
  std::vector<std::string> uncovered;  // "v_toggle/interp_dp__W8 interp_dp.v:57 d_q[25]", per point never hit
};
// Reads a merged .dat (points "C '...page\002v_line/...' count"); nothing
// when the file is missing or has no points.
std::optional<RtlCoverage> read_rtl_coverage(const std::string& dat_path);

struct ReportInput {
  std::string suite;
  const std::vector<Case>& cases;
  const std::vector<Expected>& exps;
  const std::vector<double>& rates;
  const std::vector<Row>& rows;
  std::string command;
  double sim_seconds = 0, wall_seconds = 0;
  const Options& opt;
  std::vector<std::string> traces = {};  // FST files written (--trace), linked from the page
  const Coverage* coverage = nullptr;     // functional coverage (nullptr: none shown)
  std::optional<RtlCoverage> rtl_coverage = {};  // from `make coverage`, when it was run
};

// "functional coverage: 36 of 36 bins (100.00%)" (and the bins missed).
std::string coverage_line(const Coverage& c);

// The command that re-runs one row on its own: `contour cosim --suite S
// --case X --rate R --engines model,E` with the run's output timing, clock
// and injected faults.
std::string rerun_command(const Row& r, const Options& opt);

// The report's JSON layout version (report.json "schema_version"): 2 adds
// it, "not_run", "rerun", "case_start_us", first_mismatch_pps.
inline constexpr int kReportSchemaVersion = 2;

// "100.00% PASS 40 PASSED, 0 FAILED" (or "... FAIL ..."; ", 4 NOT RUN"
// appended when some rows did not run; the percentage is of the rows that
// ran): the first line of every report and of the program's output.
std::string verdict_line(const std::vector<Row>& rows);

// Over the rates that ran: the highest rate up to which `engine` agreed
// on `case_name` at every rate (nothing lost, no pulse different), the
// lowest rate at which it lost command pulses, and the lowest at which a
// pulse differed from the model's (0 when there is none). A mismatch is
// not a loss: an injected swap loses nothing.
struct Limit {
  double agree_up_to = 0, first_loss = 0, first_mismatch = 0;
};
Limit limit_of(const std::vector<Row>& rows, const std::string& case_name, const std::string& engine);

// The model's pulse path of a case as the report draws it: in the first
// move's own frame (a line from its start, an arc from its centre), so that
// paper A's Fig. 5 runs from (6, 0) to (0, 6).
std::vector<std::pair<double, double>> drawn_pulse_path(const Case& c, const Expected& e);

// Writes DIR/report.html, DIR/report.json and DIR/junit.xml; returns the paths.
std::vector<std::string> write_reports(const std::string& dir, const ReportInput& in);

}  // namespace contour::cosim
