// Test support: an engine's run of an arc (a RunResult: its pulses and the
// state it reports after each) against the independent arc oracle
// (arc_oracle.hpp). Only the result's data types come from the model; the
// expectation is the oracle's own.
#pragma once

#include <string>
#include <vector>

#include "interp/arc_oracle.hpp"
#include "interp/engine.hpp"  // RunResult, StepRecord: data types only

namespace contour::oracle {

// "" when the run is the oracle's walk and ends done at the end point;
// else what is wrong.
inline std::string check_run(const ArcExpect& a, std::int64_t xs, std::int64_t ys, std::int64_t xe,
                             std::int64_t ye, bool cw, const RunResult& r) {
  std::vector<Step> steps;
  for (const StepRecord& s : r.steps)
    steps.push_back({s.pulse.axis == Axis::X ? 0 : 1, s.pulse.sign, int(s.state.quadrant), s.state.x, s.state.y});
  std::string e = check_walk(a, xs, ys, xe, ye, cw, steps);
  if (e.empty() && !r.final_state.done) e = "not done at the end point";
  return e;
}

}  // namespace contour::oracle
