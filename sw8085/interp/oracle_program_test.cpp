// The 8085 program (on the ISS) against the independent arc oracle
// (model/interp/arc_oracle.hpp): its pulses, read from OUT 10h, and the
// quadrant and position it publishes after each, checked against the
// geometry and the contract's rules, not against the golden model.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "interp/arc_oracle.hpp"
#include "sw8085/interp/host.hpp"

namespace contour::sw8085 {
namespace {

std::string check_arc(Host& h, std::int64_t xs, std::int64_t ys, std::int64_t xe, std::int64_t ye, bool cw) {
  const std::string name = "arc " + std::to_string(xs) + " " + std::to_string(ys) + " " + std::to_string(xe) + " " +
                           std::to_string(ye) + (cw ? " cw: " : " ccw: ");
  const oracle::ArcExpect a = oracle::expect_arc(xs, ys, xe, ye, cw);
  RunResult r;
  try {
    r = h.run(Move::arc(xs, ys, xe, ye, cw ? Sense::CW : Sense::CCW), nullptr, std::uint64_t(a.pulses) + 8);
  } catch (const std::exception& e) {
    return name + "the run stopped: " + e.what();
  }
  std::vector<oracle::Step> steps;
  for (const StepRecord& s : r.steps)
    steps.push_back({s.pulse.axis == Axis::X ? 0 : 1, s.pulse.sign, int(s.state.quadrant), s.state.x, s.state.y});
  std::string e = oracle::check_walk(a, xs, ys, xe, ye, cw, steps);
  if (e.empty() && !r.final_state.done) e = "not done at the end point";
  return e.empty() ? e : name + e;
}

// Every accepted arc between lattice points with |coordinates| <= 5 (ends
// to 6), both senses, and the short arc.
TEST(ProgramOracle, EverySmallArcBothSenses) {
  Host h;
  EXPECT_EQ(check_arc(h, 10, 0, 10, 2, false), "");
  EXPECT_EQ(check_arc(h, 10, 0, 10, -2, true), "");
  const int n = 5;
  int runs = 0, failed = 0;
  std::string first;
  for (int xs = -n; xs <= n; ++xs)
    for (int ys = -n; ys <= n; ++ys)
      for (int xe = -n - 1; xe <= n + 1; ++xe)
        for (int ye = -n - 1; ye <= n + 1; ++ye)
          for (bool cw : {false, true}) {
            if (!oracle::expect_arc(xs, ys, xe, ye, cw).accepted) continue;
            ++runs;
            if (std::string e = check_arc(h, xs, ys, xe, ye, cw); !e.empty() && failed++ < 3) first += e + "\n";
          }
  EXPECT_EQ(failed, 0) << first;
  EXPECT_GT(runs, 1500);
}

// Full circles of integer radius (8R pulses) and a large quarter across the
// program's multi-byte magnitudes.
TEST(ProgramOracle, FullCirclesAndALargeArc) {
  Host h;
  for (std::int64_t r : {2, 9, 200}) {
    EXPECT_EQ(check_arc(h, r, 0, r, 0, false), "");
    EXPECT_EQ(check_arc(h, 0, -r, 0, -r, true), "");
  }
  EXPECT_EQ(check_arc(h, 3000, 4000, -4000, 3000, false), "");
  EXPECT_EQ(check_arc(h, 70000, 0, 0, -70000, true), "");
}

}  // namespace
}  // namespace contour::sw8085
