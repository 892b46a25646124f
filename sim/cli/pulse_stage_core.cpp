// Pulse stage "core" of `contour gcode FILE --pulses --engine core`: each
// cycle's chord runs on the Verilated 3-axis core (rtl/interp3, W = 24;
// tb/interp3/interp3_stage.hpp). This file binds the planner's chords to
// the stage's plain data. Without Verilator at configure time tb/ builds
// no harness and the stage is simply absent.
#if __has_include("interp3_stage.hpp")
#include "interp3_stage.hpp"
#include "planner/two_stage.hpp"

namespace contour::cli {
namespace {

std::vector<planner::TimedPulse> core_pulse_stage(const std::vector<planner::StepChord>& chords, double cycle_s) {
  std::vector<rtl3::Chord> in;
  in.reserve(chords.size());
  for (const planner::StepChord& c : chords) in.push_back({c.dx, c.dy, c.dz});
  std::vector<planner::TimedPulse> out;
  for (const rtl3::TimedStep& s : rtl3::run_chords(in, cycle_s)) out.push_back({s.t, s.pulse});
  return out;
}

const planner::PulseStageRegistrar kCore3{"core", core_pulse_stage};

}  // namespace
}  // namespace contour::cli
#endif
