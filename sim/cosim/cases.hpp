// The co-simulation's test cases and suites: named sequences of moves (a
// path), and the command rates each suite sweeps.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "interp/engine.hpp"

namespace contour::cosim {

// One case: a path of moves run back to back (each move starts where the
// previous one ended; a line is relative to its start, an arc to its
// centre, as everywhere in the project).
struct Case {
  std::string name;   // short, for tables and file names
  std::string title;  // one line for the report
  std::vector<Move> moves;
  std::vector<double> rates;  // set by combined(): its suite's sweep
};

struct Suite {
  std::string name;
  std::string summary;
  std::vector<Case> cases;
  std::vector<double> rates;  // --sweep: command rates in pulses/s, ascending
};

// "paper", "smoke", "full". Throws std::invalid_argument naming the suite
// and listing the known ones.
const Suite& suite(const std::string& name);
std::vector<std::string> suite_names();

// One or more suites, "paper,smoke": their cases (a case in several once)
// and the union of their rates; each case keeps its own suite's sweep in
// Case::rates. Throws std::invalid_argument for an unknown name.
Suite combined(const std::string& names);

// The engines a co-simulation can run, in report order.
inline const std::vector<std::string>& engine_names() {
  static const std::vector<std::string> names = {"model", "core", "iss", "cpu"};
  return names;
}

// Above this rate the 8085 engines are not run (their rows say NOT RUN):
// paper A's target for the dedicated processor, and 60 times what the
// program can do.
inline constexpr double kMaxRate8085 = 250e3;
// Up to this rate the Verilog core must lose nothing (paper A's 250 kpps),
// unless its programmed output stage cannot carry it (core_carry_rate).
inline constexpr double kCoreRequiredRate = 250e3;
// The command line's bound on --rate (the model takes any rate).
inline constexpr double kMaxRate = 50e6;

// The highest command rate `engine` can be given: the model kMaxRate; the
// core core_hz / 2 (its command pin is sampled once a clock: a train above
// half the clock cannot be seen, a high and a low phase need a clock each);
// the 8085 engines kMaxRate8085.
double max_rate(const std::string& engine, double core_hz);
bool engine_runs_at(const std::string& engine, double rate_pps, double core_hz = 50e6);

// The command rate the core's output stage carries whatever the axes and
// directions: one STEP_LEN + STEP_SPACE per pulse, plus DIR_SETUP +
// DIR_HOLD when the direction changes (clocks of `core_hz`).
double core_carry_rate(double core_hz, std::uint32_t len, std::uint32_t space, std::uint32_t setup,
                       std::uint32_t hold);

// Where a move starts and its frame origin, on the path of a case.
struct Placed {
  Move move;
  std::int64_t start_x = 0, start_y = 0;    // absolute start point
  std::int64_t origin_x = 0, origin_y = 0;  // line: the start; arc: the centre
  std::int64_t end_x = 0, end_y = 0;        // absolute end point
};
std::vector<Placed> place(const std::vector<Move>& moves);

// "250k", "1M", "3.5k": rates as the report and the CLI print them.
std::string rate_label(double rate_pps);
// A computed rate to 4 significant digits: "416.7k", "381.4".
std::string rate_label_approx(double rate_pps);

}  // namespace contour::cosim
