// The scoreboard: what each engine put out during one case at one command
// rate, compared pulse by pulse (axis, sign, order) and by final position
// with the golden model, plus the latency from each command pulse to its
// output pulse, pulses lost and overruns flagged. Pure C++: no SystemC, so
// that its rules are tested on their own.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "cases.hpp"
#include "interp/engine.hpp"

namespace contour::cosim {

// One output pulse as an engine emitted it.
struct OutPulse {
  double t_us = 0;    // simulated time, microseconds since the case started
  Pulse pulse;
  std::string state;  // the engine's state after it, when observable ("" otherwise)
};

// What an engine did during one case.
struct EngineRun {
  std::string engine;
  std::vector<OutPulse> out;
  bool overruns_known = false;  // the engine counts the command pulses it refused
  std::int64_t overruns = 0;
  bool position_known = false;  // the engine reports its own position at the end
  std::int64_t x = 0, y = 0;    // absolute, on the case's path
  std::string error;            // a simulation error (bus fault, timeout, ...)
  double t0_us = 0;             // SystemC time at which the case started (the pulses' t_us count from it)
  // Functional-coverage hooks: what the engine's host side did, counted by
  // the engine (coverage.hpp): "queue_full" (a move waited for room),
  // "push_refused" (the core refused a PUSH into its full queue),
  // "abort" (the core dropped a loaded and a queued move on ABORT).
  std::map<std::string, std::uint64_t> events;
};

// The golden model's answer for a case: every pulse, the state after it and
// the absolute position after it (pos[0] is the start).
struct Expected {
  std::vector<Pulse> pulses;
  std::vector<std::string> states;
  std::vector<std::size_t> move_of;  // index of the move each pulse belongs to
  std::vector<std::pair<std::int64_t, std::int64_t>> pos;
};
Expected expect(const Case& c);

struct Divergence {
  std::uint64_t index = 0;  // 1-based output pulse number
  std::string summary;      // one line: "pulse 3: model +X, core +Y"
  std::string context;      // a window of pulses on both sides, one per line
  double t_us = -1;         // the engine's diverging pulse, since the case started (-1: it gave none)
};

// PASS: the model's pulses, nothing lost. FLAGGED: the model's pulses, and
// every lost command pulse was flagged (allowed above an engine's limit).
// FAIL: anything else. NOT RUN: the engine cannot take the rate (above its
// max_rate); neither passed nor failed.
enum class Verdict { Pass, Flagged, Fail, NotRun };
// "PASS", "FLAGGED", "FAIL", "NOT RUN": the word of the reports.
const char* to_string(Verdict v);
// "PASS", "FLAGGED", "FAIL", "NOTRUN": the CSS class of a report cell.
const char* css_class(Verdict v);

// One line of the report: a case on an engine at a rate.
struct Row {
  std::string case_name, engine;
  double rate_pps = 0;
  std::uint64_t commands = 0;   // command pulses sent
  std::uint64_t expected = 0;   // output pulses of the model
  std::uint64_t pulses = 0;     // output pulses of the engine
  std::uint64_t mismatches = 0; // pulses that differ from the model's, extra pulses included
  std::uint64_t lost = 0;       // command pulses that gave no output pulse
  std::int64_t overruns = -1;   // flagged by the engine (-1: it has no counter)
  bool required = false;        // this engine must lose nothing at this rate
  Verdict verdict = Verdict::Fail;
  std::string note;
  bool has_latency = false;
  bool latency_exact = false;   // every output paired with its own command
  double lat_min_us = 0, lat_mean_us = 0, lat_max_us = 0;
  std::optional<Divergence> divergence;
  std::vector<Pulse> path;      // the engine's pulses, kept when it diverged (for the plot)
  // PASS, or FLAGGED (losses above the engine's limit, every one flagged):
  // not a failure. The verdict line counts these rows as PASSED.
  bool acceptable() const { return verdict == Verdict::Pass || verdict == Verdict::Flagged; }
  bool ran() const { return verdict != Verdict::NotRun; }
  double case_start_us = 0;     // SystemC time at which the case started (EngineRun::t0_us)
  double wall_seconds = 0;      // wall time of the case's simulation, shared among its engines
};

// The rate up to which `engine` must lose nothing: the model always, the
// core up to kCoreRequiredRate or what its output stage carries
// (`core_carry_pps`, core_carry_rate()), whichever is lower, the 8085
// engines up to kRequiredRate8085.
inline constexpr double kRequiredRate8085 = 1e3;
double keep_up_rate(const std::string& engine, double core_carry_pps);
// The core at its default output timing (50/50/10/10 clocks at 50 MHz).
inline constexpr double kDefaultCoreCarry = 50e6 / 120;
bool loss_forbidden(const std::string& engine, double rate_pps, double core_carry_pps = kDefaultCoreCarry);

// Judges one engine's run: `cmd_us` are the times of the command pulses.
Row judge(const Case& c, const Expected& exp, double rate_pps, const std::vector<double>& cmd_us,
          const EngineRun& run, double core_carry_pps = kDefaultCoreCarry);

// The row of an engine that could not take `rate_pps` (Verdict::NotRun).
Row not_run(const Case& c, const Expected& exp, const std::string& engine, double rate_pps, double max_pps);

}  // namespace contour::cosim
