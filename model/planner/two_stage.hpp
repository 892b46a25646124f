// The two-stage interpolator: paper B's chords, one per control cycle, each
// spread into single-axis pulses by the 3-axis reference-pulse linear
// interpolator (Linear3, docs/algorithm.md, "Linear on three axes").
//
// Stage 1 (planner.hpp) gives the cycle end points in mm. Each is rounded to
// the nearest step (steps_per_mm), so rounding never accumulates; the
// difference of two consecutive rounded points is the cycle's chord in
// steps. Stage 2 runs one Linear3<24> move per chord and spreads its
// |dX| + |dY| + |dZ| pulses evenly over the cycle: pulse j (1-based) of N at
// t_start + j * T / N.
//
// The seam for other engines (the Verilog core): a PulseStage takes the
// chord list and the cycle and returns the pulses. "model" is built in;
// others register with PulseStageRegistrar (e.g. from sim/cli/).
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "interp/types.hpp"
#include "planner/planner.hpp"

namespace contour::planner {

struct StepChord {
  std::int64_t dx = 0, dy = 0, dz = 0;  // steps in this cycle
  friend bool operator==(const StepChord&, const StepChord&) = default;
};

struct TimedPulse {
  double t = 0;  // seconds from the program start
  Pulse pulse;
  friend bool operator==(const TimedPulse&, const TimedPulse&) = default;
};

// Rounded cycle end points (steps) and their differences.
std::vector<StepChord> chords_in_steps(const std::vector<Sample>& samples, double steps_per_mm);

using PulseStage = std::function<std::vector<TimedPulse>(const std::vector<StepChord>&, double cycle_s)>;

// The golden model of stage 2.
std::vector<TimedPulse> two_stage_model(const std::vector<StepChord>& chords, double cycle_s);

// Registered stage-2 engines by name; "model" is always there.
std::map<std::string, PulseStage>& pulse_stages();

struct PulseStageRegistrar {
  PulseStageRegistrar(const std::string& name, PulseStage stage) { pulse_stages()[name] = std::move(stage); }
};

}  // namespace contour::planner
