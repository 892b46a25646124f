// Stage 2 of the two-stage interpolator on the Verilog core: each cycle's
// chord, in steps, is loaded into the Verilated interp3_core (W = 24) and
// run with the command held high; its pulses are spread over the cycle
// exactly as planner::two_stage_model does (pulse j of N at
// t_start + j * T / N). Registered as PulseStage "rtl" by
// sim/cli/pulse_stage_rtl.cpp.
#pragma once

#include <vector>

#include "planner/two_stage.hpp"

namespace contour::rtl3 {

// Throws InputError for a chord beyond 2^24 - 1 steps on an axis (the same
// message as the model), std::runtime_error if the core gives a wrong
// number of pulses (a lost, doubled or extra pulse, or no end).
std::vector<planner::TimedPulse> rtl_pulse_stage(const std::vector<planner::StepChord>& chords, double cycle_s);

}  // namespace contour::rtl3
