// Stage 2 of the two-stage interpolator on the Verilog core: each cycle's
// chord, in steps, is loaded into the Verilated interp3_core (W = 24) and
// run with the command held high; its pulses are spread over the cycle
// (pulse j of N at t_start + j * T / N), the rule of paper B's stage 2
// (docs/algorithm.md). Plain data in and out: the engine binding in sim/
// converts the planner's chords (sim/cli/pulse_stage_core.cpp).
#pragma once

#include <cstdint>
#include <vector>

#include "interp/types.hpp"

namespace contour::rtl3 {

// One cycle's chord: the steps to make on each axis.
struct Chord {
  std::int64_t dx = 0, dy = 0, dz = 0;
};

// One output pulse and its time from the program start, in seconds.
struct TimedStep {
  double t = 0;
  Pulse pulse;
};

// Throws InputError for a chord beyond 2^24 - 1 steps on an axis (the same
// message as the model), std::runtime_error if the core gives a wrong
// number of pulses (a lost, doubled or extra pulse, or no end).
std::vector<TimedStep> run_chords(const std::vector<Chord>& chords, double cycle_s);

}  // namespace contour::rtl3
